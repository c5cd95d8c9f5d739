#include "kerf/report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <stdexcept>
#include <system_error>

#include "kerf/error.hpp"
#include "kerf/io.hpp"
#include "kerf/plot.hpp"

namespace kerf {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// Plot labels use PLplot escapes (#d subscript, #u superscript); text output drops them.
std::string plain(std::string text) {
  for (const char* escape : {"#d", "#u"}) {
    for (std::size_t at = text.find(escape); at != std::string::npos; at = text.find(escape)) text.erase(at, 2);
  }
  return text;
}

std::string number_text(double value) { return fmt::format("{:.4g}", value); }

std::string condition_text(const ConditionSpec& spec, const ConditionValue& value) {
  if (!spec.numeric || !value.si) return value.text;
  return number_text(*value.si / spec.unit.si);
}

std::string lower_first(std::string text) {
  if (!text.empty() && text[0] >= 'A' && text[0] <= 'Z') text[0] = static_cast<char>(text[0] - 'A' + 'a');
  return text;
}

/// "Spindle speed n0 = 90.5 rev/min, ..." (with PLplot escapes kept when `for_plot`).
std::string conditions_text(const ComparisonSpec& spec, const std::vector<ConditionValue>& values,
                            std::optional<std::size_t> skip = std::nullopt, bool for_plot = false) {
  std::string text;
  for (std::size_t c = 0; c < values.size(); ++c) {
    if (skip && *skip == c) continue;
    if (!text.empty()) text += ", ";
    const auto& cs = spec.conditions[c];
    text += fmt::format("{} = {}{}", for_plot ? cs.label : plain(cs.label), condition_text(cs, values[c]),
                        cs.numeric && !cs.unit.label.empty() ? " " + cs.unit.label : "");
  }
  return text;
}

Json basis_json(const WidthBasis& b) {
  switch (b.kind) {
    case WidthBasis::Kind::total: return {{"kind", "total"}, {"width_mm", b.width_m * 1e3}};
    case WidthBasis::Kind::per_unit_width: return {{"kind", "per_unit_width"}};
    case WidthBasis::Kind::not_applicable: break;
  }
  return {{"kind", "not_applicable"}};
}

Json metrics_json(const ErrorMetrics& m) {
  return {{"n", m.n},
          {"mean_abs_error_percent", m.mean_abs_error_percent},
          {"max_abs_error_percent", m.max_abs_error_percent},
          {"bias_percent", m.bias_percent},
          {"rms_error_percent", m.rms_error_percent}};
}

bool same_basis(const WidthBasis& a, const WidthBasis& b) {
  if (a.kind != b.kind) return false;
  return a.kind != WidthBasis::Kind::total || std::abs(a.width_m - b.width_m) <= 1e-9 * std::max(a.width_m, b.width_m);
}

}  // namespace

// ---- Width basis -------------------------------------------------------------------------------------

void WidthBasis::validate(const std::string& path) const {
  if (kind == Kind::total) check_number(width_m * 1e3, path + ".width_mm", Range::positive(), "mm");
}

std::string WidthBasis::describe() const {
  switch (kind) {
    case Kind::total: return fmt::format("total force over a {} mm width", number_text(width_m * 1e3));
    case Kind::per_unit_width: return "force per unit width";
    case Kind::not_applicable: break;
  }
  return "no width basis";
}

double to_per_unit_width(double value, const WidthBasis& from) {
  from.validate("width_basis");
  switch (from.kind) {
    case WidthBasis::Kind::total: return value / from.width_m;
    case WidthBasis::Kind::per_unit_width: return value;
    case WidthBasis::Kind::not_applicable: break;
  }
  throw InputError("width_basis", from.describe(), "a force with a width basis (total over a width, or per unit width)");
}

double convert_width_basis(double value, const WidthBasis& from, const WidthBasis& to) {
  const double per_width = to_per_unit_width(value, from);
  to.validate("width_basis");
  switch (to.kind) {
    case WidthBasis::Kind::total: return per_width * to.width_m;
    case WidthBasis::Kind::per_unit_width: return per_width;
    case WidthBasis::Kind::not_applicable: break;
  }
  throw InputError("width_basis", to.describe(), "a force with a width basis (total over a width, or per unit width)");
}

// ---- Conditions --------------------------------------------------------------------------------------

ConditionValue ConditionValue::number(double si_value) { return {fmt::format("{}", si_value), si_value}; }
ConditionValue ConditionValue::label(std::string text) { return {std::move(text), std::nullopt}; }

bool conditions_match(const ConditionValue& a, const ConditionValue& b, double relative_tolerance) {
  if (a.si.has_value() != b.si.has_value()) return false;
  if (!a.si) return a.text == b.text;
  return std::abs(*a.si - *b.si) <= relative_tolerance * std::max(std::abs(*a.si), std::abs(*b.si));
}

bool conditions_match(const std::vector<ConditionValue>& a, const std::vector<ConditionValue>& b,
                      double relative_tolerance) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (!conditions_match(a[i], b[i], relative_tolerance)) return false;
  }
  return true;
}

std::string ConditionSpec::header() const { return unit.suffix.empty() ? key : key + "_" + unit.suffix; }

std::string_view width_view_name(WidthView view) {
  return view == WidthView::as_published ? "as_published" : "per_unit_width";
}

void ComparisonSpec::validate() const {
  if (quantities.empty()) throw InputError("comparison.quantities", "(none)", "at least one quantity to compare");
  check_number(relative_tolerance, "comparison.relative_tolerance", Range{0.0, 0.5, false, true}, "");
  std::set<std::string> keys;
  for (const auto& c : conditions) {
    if (c.key.empty() || !keys.insert(c.key).second) {
      throw InputError("comparison.conditions", c.key.empty() ? "(empty)" : c.key, "unique, non-empty keys");
    }
    if (c.numeric && !(c.unit.si > 0.0)) {
      throw InputError("comparison.conditions." + c.key + ".unit", format_value(c.unit.si), "a positive SI size");
    }
  }
  for (const auto& q : quantities) {
    if (q.key.empty() || !keys.insert(q.key).second) {
      throw InputError("comparison.quantities", q.key.empty() ? "(empty)" : q.key, "unique, non-empty keys");
    }
    if (!(q.unit.si > 0.0) || !(q.per_width_unit.si > 0.0)) {
      throw InputError("comparison.quantities." + q.key + ".unit", format_value(q.unit.si), "a positive SI size");
    }
  }
}

// ---- Data sets ---------------------------------------------------------------------------------------

DataSet dataset_from_csv(const CsvTable& table, const ComparisonSpec& spec, const CsvBinding& b) {
  spec.validate();
  const std::string where = fmt::format("{} binding '{}'", table.source, b.name);
  if (b.condition_columns.size() != spec.conditions.size() || b.condition_si.size() != spec.conditions.size()) {
    throw InputError(where + ".condition_columns", fmt::format("{} columns", b.condition_columns.size()),
                     fmt::format("{} columns and unit sizes, one per condition", spec.conditions.size()));
  }
  if (b.quantity_columns.size() != spec.quantities.size() || b.quantity_si.size() != spec.quantities.size() ||
      b.bases.size() != spec.quantities.size()) {
    throw InputError(where + ".quantity_columns", fmt::format("{} columns", b.quantity_columns.size()),
                     fmt::format("{} columns, unit sizes and width bases, one per quantity", spec.quantities.size()));
  }
  std::vector<std::pair<std::size_t, std::string>> filters;
  for (const auto& [column, value] : b.row_filter) filters.emplace_back(table.column_index(column), value);
  std::vector<std::size_t> condition_index, quantity_index;
  for (const auto& c : b.condition_columns) condition_index.push_back(table.column_index(c));
  for (const auto& q : b.quantity_columns) {
    quantity_index.push_back(q.empty() ? std::numeric_limits<std::size_t>::max() : table.column_index(q));
  }
  const bool has_width_column = !b.width_column_mm.empty();
  const std::size_t width_index = has_width_column ? table.column_index(b.width_column_mm) : 0;

  DataSet set;
  set.name = b.name;
  set.source = table.source;
  set.citations = table.comments;
  set.bases = b.bases;
  std::optional<double> width_m;
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    bool keep = true;
    for (const auto& [column, value] : filters) keep = keep && table.text(r, column) == value;
    if (!keep) continue;
    DataRow row;
    row.line = table.row_lines[r];
    for (std::size_t c = 0; c < spec.conditions.size(); ++c) {
      if (spec.conditions[c].numeric) {
        row.conditions.push_back(ConditionValue::number(table.number(r, condition_index[c]) * b.condition_si[c]));
      } else {
        row.conditions.push_back(ConditionValue::label(table.text(r, condition_index[c])));
      }
    }
    for (std::size_t q = 0; q < spec.quantities.size(); ++q) {
      row.values.push_back(b.quantity_columns[q].empty() ? kNaN : table.number(r, quantity_index[q]) * b.quantity_si[q]);
    }
    if (has_width_column) {
      const double w = table.number(r, width_index) * 1e-3;
      if (!(w > 0.0) || (width_m && std::abs(*width_m - w) > 1e-9 * w)) {
        throw InputError(table.cell_location(r, width_index), table.text(r, width_index),
                         width_m ? fmt::format("the width of the other rows of '{}' ({} mm)", b.name,
                                               number_text(*width_m * 1e3))
                                 : std::string("a positive width in mm"));
      }
      width_m = w;
    }
    set.rows.push_back(std::move(row));
  }
  if (set.rows.empty()) throw InputError(where, "(no rows)", "at least one row passing the row filter");
  if (width_m) {
    for (auto& basis : set.bases) {
      if (basis.kind == WidthBasis::Kind::total) basis.width_m = *width_m;
    }
  }
  for (std::size_t q = 0; q < set.bases.size(); ++q) set.bases[q].validate(where + ".bases[" + std::to_string(q) + "]");
  return set;
}

// ---- Comparison --------------------------------------------------------------------------------------

namespace {

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

double view_value(double value, const WidthBasis& basis, WidthView view) {
  return view == WidthView::as_published ? value : to_per_unit_width(value, basis);
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

  // Measured groups: rows with matching conditions are replicates.
  std::vector<std::vector<std::size_t>> groups;
  for (std::size_t i = 0; i < measured.rows.size(); ++i) {
    auto it = std::find_if(groups.begin(), groups.end(), [&](const auto& g) {
      return conditions_match(measured.rows[g.front()].conditions, measured.rows[i].conditions, spec.relative_tolerance);
    });
    if (it == groups.end()) {
      groups.push_back({i});
    } else {
      it->push_back(i);
    }
  }

  Comparison out{spec, measured, predictions, {}};
  for (std::size_t p = 0; p < predictions.size(); ++p) {
    const DataSet& predicted = predictions[p].data;
    for (std::size_t q = 0; q < spec.quantities.size(); ++q) {
      const QuantitySpec& qs = spec.quantities[q];
      const WidthBasis& mb = measured.bases[q];
      const WidthBasis& pb = predicted.bases[q];
      const bool bases_agree = same_basis(mb, pb);
      std::vector<WidthView> views = spec.views;
      if (views.empty()) {
        if (!bases_agree) {
          throw InputError("comparison.views (" + qs.key + ")", "(none)",
                           fmt::format("an explicit choice: the width bases differ (measured: {}; '{}': {}); ask for "
                                       "as_published, per_unit_width or both",
                                       mb.describe(), predicted.name, pb.describe()));
        }
        views = {WidthView::as_published};
      }
      for (WidthView view : views) {
        const bool per_width = view == WidthView::per_unit_width;
        if (per_width && (mb.kind == WidthBasis::Kind::not_applicable || pb.kind == WidthBasis::Kind::not_applicable)) {
          // Torques and other non-width quantities have only the published view.
          if (std::find(views.begin(), views.end(), WidthView::as_published) == views.end()) {
            throw InputError("comparison.views (" + qs.key + ")", "per_unit_width",
                             "a force with a width basis on both sides");
          }
          continue;
        }
        QuantityComparison r;
        r.quantity = q;
        r.prediction = p;
        r.view = view;
        r.key = per_width ? qs.key + "_per_width" : qs.key;
        r.unit = per_width ? qs.per_width_unit : qs.unit;
        r.measured_basis = per_width ? WidthBasis::per_unit_width() : mb;
        r.predicted_basis = per_width ? WidthBasis::per_unit_width() : pb;
        if (!per_width && !bases_agree) {
          r.note = fmt::format("The width bases differ (measured: {}; predicted: {}). This view compares the numbers "
                               "directly, as published, without scaling.",
                               mb.describe(), pb.describe());
        } else if (per_width && !bases_agree) {
          r.note = fmt::format("Both sides divided by their widths (measured: {}; predicted: {}).", mb.describe(),
                               pb.describe());
        }
        std::vector<double> group_errors, row_errors;
        for (const auto& g : groups) {
          GroupComparison gc;
          gc.conditions = measured.rows[g.front()].conditions;
          for (std::size_t i : g) {
            const double v = measured.rows[i].values[q];
            if (!std::isfinite(v)) continue;
            gc.measured.push_back(view_value(v, mb, view));
            gc.measured_rows.push_back(i);
            gc.measured_lines.push_back(measured.rows[i].line);
          }
          if (gc.measured.empty()) continue;
          for (const auto& row : predicted.rows) {
            if (std::isfinite(row.values[q]) && conditions_match(row.conditions, gc.conditions, spec.relative_tolerance)) {
              gc.predicted.push_back(view_value(row.values[q], pb, view));
            }
          }
          if (gc.predicted.empty()) {
            r.unmatched.push_back(gc.conditions);
            continue;
          }
          gc.measured_stats = sample_statistics(gc.measured);
          gc.predicted_stats = sample_statistics(gc.predicted);
          const std::string field = fmt::format("{} at {}", r.key, conditions_text(spec, gc.conditions));
          gc.error_percent = relative_error_percent(gc.predicted_stats.mean, gc.measured_stats.mean, field);
          for (double m : gc.measured) gc.row_error_percent.push_back(relative_error_percent(gc.predicted_stats.mean, m, field));
          gc.has_scatter = gc.measured.size() >= 2;
          if (gc.has_scatter) {
            const double distance = std::abs(gc.predicted_stats.mean - gc.measured_stats.mean);
            gc.within_1sd = distance <= gc.measured_stats.standard_deviation;
            gc.within_2sd = distance <= 2.0 * gc.measured_stats.standard_deviation;
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
        out.results.push_back(std::move(r));
      }
    }
  }
  return out;
}

// ---- Plots -------------------------------------------------------------------------------------------

namespace {

struct PlannedFigure {
  std::string file;
  std::string caption;
  FigureSpec figure;
};

std::string axis_label(const std::string& label, const Unit& unit) {
  return unit.label.empty() ? label : fmt::format("{} ({})", label, unit.label);
}

std::vector<PlannedFigure> plan_figures(const Comparison& c) {
  std::vector<PlannedFigure> figures;
  const auto& spec = c.spec;
  // One parity plot per quantity and view, every prediction on it.
  std::vector<std::string> done;
  for (const auto& r : c.results) {
    if (std::find(done.begin(), done.end(), r.key) != done.end()) continue;
    done.push_back(r.key);
    const QuantitySpec& qs = spec.quantities[r.quantity];
    PlannedFigure pf;
    pf.file = "parity_" + r.key + ".png";
    FigureSpec& fig = pf.figure;
    const std::string view_text = r.view == WidthView::per_unit_width ? " per unit width" : "";
    fig.title = fmt::format("{}{}", qs.label, view_text);
    fig.x_label = axis_label("measured", r.unit);
    fig.y_label = axis_label("predicted", r.unit);
    double lo = std::numeric_limits<double>::infinity(), hi = 0.0;
    for (const auto& rr : c.results) {
      if (rr.key != r.key) continue;
      PlotSeries s;
      s.label = c.predictions[rr.prediction].data.name;
      s.color = static_cast<int>(rr.prediction);
      s.marker = rr.prediction == 0 ? 0 : 5 + static_cast<int>(rr.prediction);  // filled, then hollow
      for (const auto& g : rr.groups) {
        const double x = g.measured_stats.mean / rr.unit.si, y = g.predicted_stats.mean / rr.unit.si;
        s.x.push_back(x);
        s.y.push_back(y);
        s.x_error.push_back(g.has_scatter ? g.measured_stats.standard_deviation / rr.unit.si : kNaN);
        s.y_error.push_back(g.predicted.size() >= 2 ? g.predicted_stats.standard_deviation / rr.unit.si : kNaN);
        lo = std::min({lo, x - (std::isfinite(s.x_error.back()) ? s.x_error.back() : 0.0),
                       y - (std::isfinite(s.y_error.back()) ? s.y_error.back() : 0.0)});
        hi = std::max({hi, x + (std::isfinite(s.x_error.back()) ? s.x_error.back() : 0.0),
                       y + (std::isfinite(s.y_error.back()) ? s.y_error.back() : 0.0)});
      }
      fig.series.push_back(std::move(s));
    }
    const double span = hi - lo;
    lo = std::max(0.0, lo - 0.12 * span - 0.05 * std::abs(lo));
    hi = hi + 0.12 * span + 0.05 * std::abs(hi);
    fig.x_min = fig.y_min = lo;
    fig.x_max = fig.y_max = hi;
    fig.bands.push_back({"±10 %", {lo, hi}, {0.9 * lo, 0.9 * hi}, {1.1 * lo, 1.1 * hi}, 5});
    fig.series.insert(fig.series.begin(), PlotSeries{"y = x", {lo, hi}, {lo, hi}, {}, {}, SeriesStyle::dashed_line, 5, 0});
    fig.legend_position = "outside_right";
    fig.width_px = 1500;
    fig.height_px = 1000;
    pf.caption = fmt::format("Parity plot of {}{}: predicted against measured{}, with the line y = x and a ±10 % band.",
                             plain(qs.label), view_text,
                             r.n_with_scatter > 0 ? " (error bars: ±1 SD of the replicates)" : "");
    figures.push_back(std::move(pf));
  }

  // Quantity against each numeric condition that varies while the others stay fixed.
  done.clear();
  for (const auto& r : c.results) {
    if (std::find(done.begin(), done.end(), r.key) != done.end()) continue;
    done.push_back(r.key);
    const QuantitySpec& qs = spec.quantities[r.quantity];
    for (std::size_t vc = 0; vc < spec.conditions.size(); ++vc) {
      const ConditionSpec& cs = spec.conditions[vc];
      if (!cs.numeric) continue;
      // Partition the measured groups by their other conditions.
      std::vector<std::vector<std::size_t>> partitions;
      for (std::size_t gi = 0; gi < r.groups.size(); ++gi) {
        auto others = [&](const std::vector<ConditionValue>& a, const std::vector<ConditionValue>& b) {
          for (std::size_t k = 0; k < a.size(); ++k) {
            if (k != vc && !conditions_match(a[k], b[k], spec.relative_tolerance)) return false;
          }
          return true;
        };
        auto it = std::find_if(partitions.begin(), partitions.end(),
                               [&](const auto& part) { return others(r.groups[part.front()].conditions, r.groups[gi].conditions); });
        if (it == partitions.end()) {
          partitions.push_back({gi});
        } else {
          it->push_back(gi);
        }
      }
      std::erase_if(partitions, [](const auto& part) { return part.size() < 2; });
      if (partitions.empty()) continue;

      PlannedFigure pf;
      pf.file = fmt::format("{}_vs_{}.png", r.key, cs.key);
      FigureSpec& fig = pf.figure;
      const std::string view_text = r.view == WidthView::per_unit_width ? " per unit width" : "";
      fig.title = fmt::format("{}{} against {}", qs.label, view_text, lower_first(cs.label));
      fig.x_label = axis_label(cs.label, cs.unit);
      fig.y_label = axis_label(qs.label + view_text, r.unit);
      fig.y_min = 0.0;
      const bool many_partitions = partitions.size() > 1;
      for (std::size_t pi = 0; pi < partitions.size(); ++pi) {
        const auto& part = partitions[pi];
        const auto& fixed = r.groups[part.front()].conditions;
        const std::string fixed_text = lower_first(conditions_text(spec, fixed, vc, /*for_plot=*/true));
        const std::string suffix = fixed_text.empty() ? "" : fmt::format(" ({})", fixed_text);
        PlotSeries m;
        m.label = "measured" + (many_partitions || !suffix.empty() ? suffix : "");
        m.color = many_partitions ? static_cast<int>(pi) : 0;
        m.marker = static_cast<int>(pi);
        std::vector<std::size_t> order = part;
        std::sort(order.begin(), order.end(),
                  [&](std::size_t a, std::size_t b) { return *r.groups[a].conditions[vc].si < *r.groups[b].conditions[vc].si; });
        for (std::size_t gi : order) {
          const auto& g = r.groups[gi];
          m.x.push_back(*g.conditions[vc].si / cs.unit.si);
          m.y.push_back(g.measured_stats.mean / r.unit.si);
          m.y_error.push_back(g.has_scatter ? g.measured_stats.standard_deviation / r.unit.si : kNaN);
        }
        const double x_lo = m.x.front(), x_hi = m.x.back();
        fig.series.push_back(std::move(m));
        for (const auto& rr : c.results) {
          if (rr.key != r.key) continue;
          const PredictedSet& prediction = c.predictions[rr.prediction];
          PlotSeries line;
          line.label = prediction.data.name + (many_partitions ? suffix : "");
          line.color = many_partitions ? static_cast<int>(pi) : static_cast<int>(rr.prediction) + 1;
          line.style = rr.prediction == 0 ? SeriesStyle::line : SeriesStyle::dashed_line;
          if (prediction.curve) {
            const int n = 80;
            for (int k = 0; k <= n; ++k) {
              const double x = x_lo + (x_hi - x_lo) * k / n;
              auto conditions = fixed;
              conditions[vc] = ConditionValue::number(x * cs.unit.si);
              const auto values = prediction.curve(conditions);
              if (values.size() != spec.quantities.size()) {
                throw InputError("prediction '" + prediction.data.name + "'.curve", fmt::format("{} values", values.size()),
                                 fmt::format("{} values, one per quantity", spec.quantities.size()));
              }
              line.x.push_back(x);
              line.y.push_back(view_value(values[rr.quantity], prediction.data.bases[rr.quantity], rr.view) / rr.unit.si);
            }
          } else {
            line.style = SeriesStyle::points;  // predicted points without a model behind them: no joining line
            line.marker = 5 + static_cast<int>(rr.prediction) + (many_partitions ? static_cast<int>(pi) : 0);
            std::vector<std::pair<double, std::size_t>> points;
            for (const auto& g : rr.groups) {
              const auto& gc = g.conditions;
              bool same = true;
              for (std::size_t k = 0; k < gc.size(); ++k) {
                if (k != vc && !conditions_match(gc[k], fixed[k], spec.relative_tolerance)) same = false;
              }
              if (!same) continue;
              line.x.push_back(*gc[vc].si / cs.unit.si);
              line.y.push_back(g.predicted_stats.mean / rr.unit.si);
              line.y_error.push_back(g.predicted.size() >= 2 ? g.predicted_stats.standard_deviation / rr.unit.si : kNaN);
            }
            // Predicted points with error bars sit beside the measured ones (dodged by 1.2 % of the range per
            // prediction) so that the bars stay readable; the tables and CSV carry the exact conditions.
            const bool has_bars = std::any_of(line.y_error.begin(), line.y_error.end(), [](double e) { return std::isfinite(e); });
            const double dodge = has_bars ? 0.012 * (x_hi - x_lo) * static_cast<double>(rr.prediction + 1) : 0.0;
            for (auto& x : line.x) x += dodge;
            sort_by_x(line);
          }
          fig.series.push_back(std::move(line));
        }
      }
      // Headroom above the data for the legend (forces start at zero).
      double y_top = 0.0;
      for (const auto& series : fig.series) {
        for (std::size_t k = 0; k < series.y.size(); ++k) {
          const double e = series.y_error.empty() || !std::isfinite(series.y_error[k]) ? 0.0 : series.y_error[k];
          if (std::isfinite(series.y[k])) y_top = std::max(y_top, series.y[k] + e);
        }
      }
      if (y_top > 0.0) fig.y_max = y_top * (1.0 + 0.09 * static_cast<double>(fig.series.size()) + 0.08);
      fig.legend_position = "best";
      pf.caption = fmt::format("{}{} against {}: measured{} and the model{}.", plain(qs.label), view_text,
                               lower_first(plain(cs.label)), r.n_with_scatter > 0 ? " means with ±1 SD error bars" : " points",
                               c.predictions.front().curve
                                   ? " line"
                                   : "'s predicted points (hollow; with replicate runs drawn slightly to the right, error "
                                     "bars ±1 SD)");
      figures.push_back(std::move(pf));
    }
  }
  return figures;
}

}  // namespace

// ---- Texts -------------------------------------------------------------------------------------------

std::string report_markdown(const Comparison& c, const ReportOptions& options,
                            const std::vector<std::string>& plot_files) {
  const auto& spec = c.spec;
  std::string md = fmt::format("# {}\n\n", spec.title.empty() ? "Force comparison" : spec.title);
  if (!spec.description.empty()) md += spec.description + "\n\n";

  md += "## Data\n\n";
  const auto describe_set = [&](const DataSet& set, const std::string& role) {
    md += fmt::format("**{}: {}**{}\n\n", role, set.name, set.source.empty() ? "" : fmt::format(" (`{}`)", set.source));
    if (&set != &c.measured && set.source == c.measured.source && set.citations == c.measured.citations) {
      md += "> (the same file and citation as the measured data)\n\n";
    } else if (!set.citations.empty()) {
      for (const auto& line : set.citations) md += "> " + line + "  \n";
      md += "\n";
    }
  };
  describe_set(c.measured, "Measured");
  for (std::size_t p = 0; p < c.predictions.size(); ++p) {
    describe_set(c.predictions[p].data, c.predictions.size() > 1 ? fmt::format("Prediction {}", p + 1) : "Prediction");
  }
  md += fmt::format("Rows are matched by their conditions ({}), numbers within a relative tolerance of {}. "
                    "Errors are (predicted − measured) / measured; rows with the same conditions are replicates, "
                    "compared through their mean, with ±1 SD (sample standard deviation) as the measured scatter.\n\n",
                    [&] {
                      std::string names;
                      for (const auto& cs : spec.conditions) {
                        names += (names.empty() ? "" : ", ") + plain(cs.label) +
                                 (cs.numeric && !cs.unit.label.empty() ? " in " + cs.unit.label : "");
                      }
                      return names;
                    }(),
                    spec.relative_tolerance);

  md += "## Width basis\n\n| quantity | measured | ";
  for (std::size_t p = 0; p < c.predictions.size(); ++p) md += fmt::format("{} | ", c.predictions[p].data.name);
  md += "views |\n|---|---|";
  for (std::size_t p = 0; p < c.predictions.size(); ++p) md += "---|";
  md += "---|\n";
  for (std::size_t q = 0; q < spec.quantities.size(); ++q) {
    md += fmt::format("| {} | {} | ", plain(spec.quantities[q].label), c.measured.bases[q].describe());
    for (const auto& p : c.predictions) md += p.data.bases[q].describe() + " | ";
    std::string views;
    for (const auto& r : c.results) {
      if (r.quantity == q && r.prediction == 0) views += (views.empty() ? "" : ", ") + std::string(width_view_name(r.view));
    }
    md += views + " |\n";
  }
  md += "\n";

  md += "## Agreement\n\n| quantity | view | prediction | n | mean abs error (%) | max abs error (%) | bias (%) | "
        "inside ±1 SD | inside ±2 SD |\n|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& r : c.results) {
    md += fmt::format("| {} ({}) | {} | {} | {} | {:.2f} | {:.2f} | {:+.2f} | {} | {} |\n",
                      plain(spec.quantities[r.quantity].label), r.unit.label, width_view_name(r.view),
                      c.predictions[r.prediction].data.name, r.metrics.n, r.metrics.mean_abs_error_percent,
                      r.metrics.max_abs_error_percent, r.metrics.bias_percent,
                      r.n_with_scatter ? fmt::format("{}/{}", r.n_within_1sd, r.n_with_scatter) : "–",
                      r.n_with_scatter ? fmt::format("{}/{}", r.n_within_2sd, r.n_with_scatter) : "–");
  }
  md += "\n";

  for (const auto& r : c.results) {
    const auto& qs = spec.quantities[r.quantity];
    md += fmt::format("### {} ({}), {} — {}\n\n", plain(qs.label), r.unit.label, width_view_name(r.view),
                      c.predictions[r.prediction].data.name);
    if (!r.note.empty()) md += r.note + "\n\n";
    md += "| ";
    for (const auto& cs : spec.conditions) {
      md += plain(cs.label) + (cs.numeric && !cs.unit.label.empty() ? " (" + cs.unit.label + ")" : "") + " | ";
    }
    md += fmt::format("measured ({}) | n | SD ({}) | predicted ({}) | error (%) | inside ±1 SD |\n|", r.unit.label,
                      r.unit.label, r.unit.label);
    for (std::size_t k = 0; k < spec.conditions.size() + 6; ++k) md += "---|";
    md += "\n";
    for (const auto& g : r.groups) {
      md += "| ";
      for (std::size_t k = 0; k < spec.conditions.size(); ++k) md += condition_text(spec.conditions[k], g.conditions[k]) + " | ";
      md += fmt::format("{} | {} | {} | {} | {:+.2f} | {} |\n", number_text(g.measured_stats.mean / r.unit.si),
                        g.measured.size(),
                        g.has_scatter ? number_text(g.measured_stats.standard_deviation / r.unit.si) : "–",
                        number_text(g.predicted_stats.mean / r.unit.si), g.error_percent,
                        g.has_scatter ? (g.within_1sd ? "yes" : "no") : "–");
    }
    md += fmt::format("\nn = {}, mean |error| = {:.2f} %, max |error| = {:.2f} %, bias = {:+.2f} %", r.metrics.n,
                      r.metrics.mean_abs_error_percent, r.metrics.max_abs_error_percent, r.metrics.bias_percent);
    if (r.metrics.n != r.row_metrics.n) {
      md += fmt::format(" (against each of the {} measured rows: mean |error| = {:.2f} %)", r.row_metrics.n,
                        r.row_metrics.mean_abs_error_percent);
    }
    md += ".\n\n";
    if (!r.unmatched.empty()) {
      md += "Measured without a prediction: ";
      for (std::size_t k = 0; k < r.unmatched.size(); ++k) {
        md += (k ? "; " : "") + conditions_text(spec, r.unmatched[k]);
      }
      md += ".\n\n";
    }
  }

  if (!plot_files.empty()) {
    md += "## Plots\n\n";
    const auto figures = plan_figures(c);
    for (const auto& f : figures) {
      if (std::find(plot_files.begin(), plot_files.end(), f.file) == plot_files.end()) continue;
      md += fmt::format("![{}]({})\n\n*{}*\n\n", plain(f.figure.title), f.file, f.caption);
    }
  }
  if (!options.extra_markdown.empty()) md += options.extra_markdown + (options.extra_markdown.back() == '\n' ? "" : "\n");
  return md;
}

std::string comparison_csv(const Comparison& c) {
  const auto& spec = c.spec;
  std::vector<std::string> header = {"prediction", "measured_source_line"};
  for (const auto& cs : spec.conditions) header.push_back(cs.header());
  // Columns per quantity and view (the same for every prediction).
  std::vector<const QuantityComparison*> first;
  for (const auto& r : c.results) {
    if (r.prediction == 0) first.push_back(&r);
  }
  for (const auto* r : first) {
    const std::string& u = r->unit.suffix;
    for (const std::string& col : {fmt::format("{}_measured_{}", r->key, u), fmt::format("{}_measured_mean_{}", r->key, u),
                                   fmt::format("{}_measured_sd_{}", r->key, u), fmt::format("{}_n_replicates", r->key),
                                   fmt::format("{}_predicted_{}", r->key, u), fmt::format("{}_error_percent", r->key),
                                   fmt::format("{}_mean_error_percent", r->key)}) {
      header.push_back(col);
    }
  }
  std::vector<std::string> escaped;
  for (const auto& h : header) escaped.push_back(csv_escape(h));
  std::string text = csv_line(escaped);
  for (std::size_t p = 0; p < c.predictions.size(); ++p) {
    for (std::size_t i = 0; i < c.measured.rows.size(); ++i) {
      const DataRow& row = c.measured.rows[i];
      std::vector<std::string> fields = {csv_escape(c.predictions[p].data.name),
                                         row.line ? std::to_string(row.line) : ""};
      for (std::size_t k = 0; k < spec.conditions.size(); ++k) {
        const auto& cs = spec.conditions[k];
        fields.push_back(cs.numeric && row.conditions[k].si ? csv_number(*row.conditions[k].si / cs.unit.si)
                                                             : csv_escape(row.conditions[k].text));
      }
      for (const auto* first_r : first) {
        const QuantityComparison* r = nullptr;
        for (const auto& rr : c.results) {
          if (rr.prediction == p && rr.key == first_r->key) r = &rr;
        }
        const GroupComparison* group = nullptr;
        std::size_t replicate = 0;
        if (r) {
          for (const auto& g : r->groups) {
            for (std::size_t k = 0; k < g.measured_rows.size(); ++k) {
              if (g.measured_rows[k] == i) {
                group = &g;
                replicate = k;
              }
            }
          }
        }
        if (!group) {
          const double v = row.values[first_r->quantity];
          fields.push_back(std::isfinite(v) ? csv_number(view_value(v, c.measured.bases[first_r->quantity], first_r->view) /
                                                          first_r->unit.si)
                                            : "");
          for (int k = 0; k < 6; ++k) fields.emplace_back("");
          continue;
        }
        const double s = r->unit.si;
        fields.push_back(csv_number(group->measured[replicate] / s));
        fields.push_back(csv_number(group->measured_stats.mean / s));
        fields.push_back(group->has_scatter ? csv_number(group->measured_stats.standard_deviation / s) : "");
        fields.push_back(std::to_string(group->measured.size()));
        fields.push_back(csv_number(group->predicted_stats.mean / s));
        fields.push_back(csv_number(group->row_error_percent[replicate]));
        fields.push_back(csv_number(group->error_percent));
      }
      text += csv_line(fields);
    }
  }
  return text;
}

Json summary_json(const Comparison& c, const ReportOptions& options) {
  const auto& spec = c.spec;
  const auto quantities_of = [&](std::size_t p) {
    Json q = Json::object();
    for (const auto& r : c.results) {
      if (r.prediction != p) continue;
      Json entry = metrics_json(r.metrics);
      entry["label"] = plain(spec.quantities[r.quantity].label);
      entry["unit"] = r.unit.label;
      entry["view"] = width_view_name(r.view);
      entry["measured_width_basis"] = basis_json(r.measured_basis);
      entry["predicted_width_basis"] = basis_json(r.predicted_basis);
      entry["n_measured_rows"] = r.row_metrics.n;
      entry["per_measured_row"] = metrics_json(r.row_metrics);
      entry["n_with_scatter"] = r.n_with_scatter;
      entry["n_within_1sd"] = r.n_within_1sd;
      entry["n_within_2sd"] = r.n_within_2sd;
      entry["n_unmatched"] = r.unmatched.size();
      if (!r.note.empty()) entry["note"] = r.note;
      q[r.key] = std::move(entry);
    }
    return q;
  };
  Json predictions = Json::array();
  for (std::size_t p = 0; p < c.predictions.size(); ++p) {
    const auto& d = c.predictions[p].data;
    predictions.push_back({{"name", d.name}, {"source", d.source}, {"citations", d.citations}, {"quantities", quantities_of(p)}});
  }
  Json conditions = Json::array();
  for (const auto& cs : spec.conditions) conditions.push_back(cs.header());
  Json out = {{"title", spec.title},
              {"measured", {{"name", c.measured.name}, {"source", c.measured.source}, {"citations", c.measured.citations}}},
              {"conditions", conditions},
              {"match_relative_tolerance", spec.relative_tolerance},
              {"error_definition", "(predicted - measured) / measured, percent; replicates compared through their mean"},
              {"quantities", quantities_of(0)},
              {"predictions", predictions}};
  if (!options.extra_summary.empty()) out["extra"] = options.extra_summary;
  return out;
}

// ---- Writing -----------------------------------------------------------------------------------------

std::vector<std::filesystem::path> write_report(const Comparison& c, const std::filesystem::path& out_dir,
                                                const ReportOptions& options) {
  namespace fs = std::filesystem;
  fs::create_directories(out_dir);
  remove_stale_temporaries(out_dir);  // a killed report's staging directory and temporaries
  std::random_device entropy;
  const fs::path staging = out_dir / fmt::format(".staging-{:08x}", entropy());
  std::vector<std::string> names;
  try {
    fs::create_directory(staging);
    std::vector<std::string> plot_files;
    if (options.plots) {
      for (const auto& f : plan_figures(c)) {
        render_png(f.figure, staging / f.file);
        plot_files.push_back(f.file);
      }
    }
    Json summary = summary_json(c, options);
    summary["files"] = plot_files;
    write_file_atomically(staging / "report.md", report_markdown(c, options, plot_files));
    write_file_atomically(staging / "comparison.csv", comparison_csv(c));
    write_file_atomically(staging / "summary.json", summary.dump(2) + "\n");
    names = {"report.md", "comparison.csv", "summary.json"};
    names.insert(names.end(), plot_files.begin(), plot_files.end());
    // Check every target before replacing any, so that a blocked target leaves the old report whole.
    for (const auto& name : names) {
      const fs::path target = out_dir / name;
      if (fs::exists(target) && !fs::is_regular_file(target)) {
        throw InputError(target.string(), "(not a regular file)", "a path the report can write a file to");
      }
    }
  } catch (...) {
    std::error_code ignored;
    fs::remove_all(staging, ignored);
    throw;
  }
  std::vector<fs::path> written;
  for (const auto& name : names) {
    std::error_code error;
    fs::rename(staging / name, out_dir / name, error);
    if (error) {
      std::error_code ignored;
      fs::remove_all(staging, ignored);
      throw OutputError((out_dir / name).string(), fmt::format("cannot move it into place: {}", error.message()));
    }
    written.push_back(out_dir / name);
  }
  std::error_code ignored;
  fs::remove_all(staging, ignored);
  return written;
}

}  // namespace kerf
