// The comparison: measured replicates grouped by their conditions, matched with each prediction per quantity and
// view, with their statistics (kerf/report.hpp: compare).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "kerf/error.hpp"
#include "report_internal.hpp"

namespace kerf {

using namespace report_detail;

namespace {

bool same_basis(const WidthBasis& a, const WidthBasis& b) {
  if (a.kind != b.kind) return false;
  return a.kind != WidthBasis::Kind::total || std::abs(a.width_m - b.width_m) <= 1e-9 * std::max(a.width_m, b.width_m);
}

void check_shape(const ComparisonSpec& spec, const DataSet& set, const std::string& role) {
  if (set.bases.size() != spec.quantities.size()) {
    throw InputError(role + " '" + set.name + "'.bases", fmt::format("{} bases", set.bases.size()),
                     fmt::format("{}, one per quantity", spec.quantities.size()));
  }
  for (std::size_t i = 0; i < set.rows.size(); ++i) {
    const auto& r = set.rows[i];
    if (r.conditions.size() != spec.conditions.size() || r.values.size() != spec.quantities.size()) {
      throw InputError(fmt::format("{} '{}'.rows[{}]", role, set.name, i),
                       fmt::format("{} conditions and {} values", r.conditions.size(), r.values.size()),
                       fmt::format("{} conditions and {} values", spec.conditions.size(), spec.quantities.size()));
    }
    for (std::size_t c = 0; c < spec.conditions.size(); ++c) {
      if (spec.conditions[c].numeric != r.conditions[c].si.has_value()) {
        throw InputError(fmt::format("{} '{}'.rows[{}].{}", role, set.name, i, spec.conditions[c].key),
                         r.conditions[c].text, spec.conditions[c].numeric ? "a number" : "a text label");
      }
    }
  }
}

}  // namespace

namespace {

/// Measured rows with matching conditions are replicates: each group's row indices, in the order met.
std::vector<std::vector<std::size_t>> replicate_groups(const ComparisonSpec& spec, const DataSet& measured) {
  std::vector<std::vector<std::size_t>> groups;
  for (std::size_t i = 0; i < measured.rows.size(); ++i) {
    auto it = std::find_if(groups.begin(), groups.end(), [&](const auto& g) {
      return conditions_match(measured.rows[g.front()].conditions, measured.rows[i].conditions,
                              spec.relative_tolerance);
    });
    if (it == groups.end()) {
      groups.push_back({i});
    } else {
      it->push_back(i);
    }
  }
  return groups;
}

/// One replicate group of quantity q in view `view`: its measured values, the prediction's at its conditions,
/// their statistics and errors; no measured value: `measured` empty; no prediction: `predicted` empty.
GroupComparison compare_group(const ComparisonSpec& spec, const DataSet& measured, const DataSet& predicted,
                              const std::vector<std::size_t>& group, std::size_t q, WidthView view,
                              const std::string& key) {
  const WidthBasis& mb = measured.bases[q];
  const WidthBasis& pb = predicted.bases[q];
  GroupComparison gc;
  gc.conditions = measured.rows[group.front()].conditions;
  for (std::size_t i : group) {
    const double v = measured.rows[i].values[q];
    if (!std::isfinite(v)) continue;
    gc.measured.push_back(view_value(v, mb, view));
    gc.measured_rows.push_back(i);
    gc.measured_lines.push_back(measured.rows[i].line);
  }
  if (gc.measured.empty()) return gc;
  for (const auto& row : predicted.rows) {
    if (std::isfinite(row.values[q]) && conditions_match(row.conditions, gc.conditions, spec.relative_tolerance)) {
      gc.predicted.push_back(view_value(row.values[q], pb, view));
      gc.outside_model_range = gc.outside_model_range || row.outside_model_range;
    }
  }
  if (gc.predicted.empty()) return gc;
  gc.measured_stats = sample_statistics(gc.measured);
  gc.predicted_stats = sample_statistics(gc.predicted);
  const std::string field = fmt::format("{} at {}", key, conditions_text(spec, gc.conditions));
  gc.error_percent = relative_error_percent(gc.predicted_stats.mean, gc.measured_stats.mean, field);
  for (double m : gc.measured)
    gc.row_error_percent.push_back(relative_error_percent(gc.predicted_stats.mean, m, field));
  gc.has_scatter = gc.measured.size() >= 2;
  if (gc.has_scatter) {
    const double distance = std::abs(gc.predicted_stats.mean - gc.measured_stats.mean);
    gc.within_1sd = distance <= gc.measured_stats.standard_deviation;
    gc.within_2sd = distance <= 2.0 * gc.measured_stats.standard_deviation;
  }
  return gc;
}

/// Quantity q of prediction p in one view: its groups, unmatched conditions, note and metrics.
QuantityComparison compare_view(const ComparisonSpec& spec, const DataSet& measured, const DataSet& predicted,
                                const std::vector<std::vector<std::size_t>>& groups, std::size_t q, std::size_t p,
                                WidthView view) {
  const QuantitySpec& qs = spec.quantities[q];
  const WidthBasis& mb = measured.bases[q];
  const WidthBasis& pb = predicted.bases[q];
  const bool bases_agree = same_basis(mb, pb);
  const bool per_width = view == WidthView::per_unit_width;
  QuantityComparison r;
  r.quantity = q;
  r.prediction = p;
  r.view = view;
  r.key = per_width ? qs.key + "_per_width" : qs.key;
  r.unit = per_width ? qs.per_width_unit : qs.unit;
  r.measured_basis = per_width ? WidthBasis::per_unit_width() : mb;
  r.predicted_basis = per_width ? WidthBasis::per_unit_width() : pb;
  if (!per_width && !bases_agree) {
    r.note = fmt::format(
        "The width bases differ (measured: {}; predicted: {}). This view compares the numbers "
        "directly, as published, without scaling.",
        mb.describe(), pb.describe());
  } else if (per_width && !bases_agree) {
    r.note =
        fmt::format("Both sides divided by their widths (measured: {}; predicted: {}).", mb.describe(), pb.describe());
  }
  std::vector<double> group_errors, row_errors;
  for (const auto& g : groups) {
    GroupComparison gc = compare_group(spec, measured, predicted, g, q, view, r.key);
    if (gc.measured.empty()) continue;
    if (gc.predicted.empty()) {
      r.unmatched.push_back(gc.conditions);
      continue;
    }
    if (gc.has_scatter) {
      ++r.n_with_scatter;
      r.n_within_1sd += gc.within_1sd ? 1 : 0;
      r.n_within_2sd += gc.within_2sd ? 1 : 0;
    }
    group_errors.push_back(gc.error_percent);
    row_errors.insert(row_errors.end(), gc.row_error_percent.begin(), gc.row_error_percent.end());
    r.groups.push_back(std::move(gc));
  }
  if (r.groups.empty()) {
    throw InputError(fmt::format("prediction '{}'", predicted.name), "(no row matches a measurement)",
                     fmt::format("predictions of '{}' at measured conditions (relative tolerance {})", qs.key,
                                 spec.relative_tolerance));
  }
  r.metrics = metrics_of_errors(group_errors);
  r.row_metrics = metrics_of_errors(row_errors);
  return r;
}

}  // namespace

const QuantityComparison& Comparison::result(const std::string& key, std::size_t prediction) const {
  for (const auto& r : results) {
    if (r.key == key && r.prediction == prediction) return r;
  }
  throw InputError("comparison.quantity", key, "a compared quantity key");
}

Comparison compare(const ComparisonSpec& spec, const DataSet& measured, const std::vector<PredictedSet>& predictions) {
  spec.validate();
  check_shape(spec, measured, "measured");
  if (predictions.empty()) throw InputError("predictions", "(none)", "at least one prediction to compare");
  for (const auto& p : predictions) check_shape(spec, p.data, "prediction");
  for (auto view : spec.views) {
    if (view != WidthView::as_published && view != WidthView::per_unit_width) {
      throw InputError("comparison.views", "?", "as_published or per_unit_width");
    }
  }
  const auto groups = replicate_groups(spec, measured);
  Comparison out{spec, measured, predictions, {}};
  for (std::size_t p = 0; p < predictions.size(); ++p) {
    const DataSet& predicted = predictions[p].data;
    for (std::size_t q = 0; q < spec.quantities.size(); ++q) {
      const QuantitySpec& qs = spec.quantities[q];
      const WidthBasis& mb = measured.bases[q];
      const WidthBasis& pb = predicted.bases[q];
      std::vector<WidthView> views = spec.views;
      if (views.empty()) {
        if (!same_basis(mb, pb)) {
          throw InputError("comparison.views (" + qs.key + ")", "(none)",
                           fmt::format("an explicit choice: the width bases differ (measured: {}; '{}': {}); ask for "
                                       "as_published, per_unit_width or both",
                                       mb.describe(), predicted.name, pb.describe()));
        }
        views = {WidthView::as_published};
      }
      for (WidthView view : views) {
        if (view == WidthView::per_unit_width &&
            (mb.kind == WidthBasis::Kind::not_applicable || pb.kind == WidthBasis::Kind::not_applicable)) {
          // Torques and other non-width quantities have only the published view.
          if (std::find(views.begin(), views.end(), WidthView::as_published) == views.end()) {
            throw InputError("comparison.views (" + qs.key + ")", "per_unit_width",
                             "a force with a width basis on both sides");
          }
          continue;
        }
        out.results.push_back(compare_view(spec, measured, predicted, groups, q, p, view));
      }
    }
  }
  return out;
}

}  // namespace kerf
