// The figures of a report: parity plots and each quantity against a condition (plan_figures).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "kerf/error.hpp"
#include "report_internal.hpp"

namespace kerf::report_detail {

namespace {

std::string axis_label(const std::string& label, const Unit& unit) {
  return unit.label.empty() ? label : fmt::format("{} ({})", label, unit.label);
}

std::string view_text(const QuantityComparison& r) {
  return r.view == WidthView::per_unit_width ? " per unit width" : "";
}

/// The results with distinct keys (one per quantity and view; the first prediction's), in order.
std::vector<const QuantityComparison*> distinct_keys(const Comparison& c) {
  std::vector<std::string> done;
  std::vector<const QuantityComparison*> firsts;
  for (const auto& r : c.results) {
    if (std::find(done.begin(), done.end(), r.key) != done.end()) continue;
    done.push_back(r.key);
    firsts.push_back(&r);
  }
  return firsts;
}

/// The parity plot of one quantity and view, every prediction on it.
PlannedFigure parity_figure(const Comparison& c, const QuantityComparison& r) {
  const QuantitySpec& qs = c.spec.quantities[r.quantity];
  PlannedFigure pf;
  pf.file = "parity_" + r.key + ".png";
  FigureSpec& fig = pf.figure;
  fig.title = fmt::format("{}{}", qs.label, view_text(r));
  fig.x_label = axis_label("measured", r.unit);
  fig.y_label = axis_label("predicted", r.unit);
  double lo = std::numeric_limits<double>::infinity(), hi = 0.0;
  for (const auto& rr : c.results) {
    if (rr.key != r.key) continue;
    PlotSeries within;
    within.label = c.predictions[rr.prediction].data.name;
    within.color = static_cast<int>(rr.prediction);
    within.marker = rr.prediction == 0 ? 0 : 5 + static_cast<int>(rr.prediction);  // filled, then hollow
    // Groups whose prediction lies outside its model's range: a series of their own, hollow, said in the legend.
    PlotSeries outside = within;
    outside.label = within.label + ", not valid here";
    outside.marker = 8 + static_cast<int>(rr.prediction) % 2;  // hollow diamond (or down-triangle)
    for (const auto& g : rr.groups) {
      PlotSeries& s = g.outside_model_range ? outside : within;
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
    if (!within.x.empty() || outside.x.empty()) fig.series.push_back(std::move(within));
    if (!outside.x.empty()) fig.series.push_back(std::move(outside));
  }
  const double span = hi - lo;
  lo = std::max(0.0, lo - 0.12 * span - 0.05 * std::abs(lo));
  hi = hi + 0.12 * span + 0.05 * std::abs(hi);
  fig.x_min = fig.y_min = lo;
  fig.x_max = fig.y_max = hi;
  fig.bands.push_back({"±10 %", {lo, hi}, {0.9 * lo, 0.9 * hi}, {1.1 * lo, 1.1 * hi}, 5});
  fig.series.insert(fig.series.begin(),
                    PlotSeries{"y = x", {lo, hi}, {lo, hi}, {}, {}, SeriesStyle::dashed_line, 5, 0});
  fig.legend_position = "outside_right";
  fig.width_px = 1500;
  fig.height_px = 1000;
  pf.caption =
      fmt::format("Parity plot of {}{}: predicted against measured{}, with the line y = x and a ±10 % band.",
                  plain(qs.label), view_text(r), r.n_with_scatter > 0 ? " (error bars: ±1 SD of the replicates)" : "");
  return pf;
}

/// Whether two condition lists agree in every condition but `vc`.
bool same_but(const ComparisonSpec& spec, const std::vector<ConditionValue>& a, const std::vector<ConditionValue>& b,
              std::size_t vc) {
  for (std::size_t k = 0; k < a.size(); ++k) {
    if (k != vc && !conditions_match(a[k], b[k], spec.relative_tolerance)) return false;
  }
  return true;
}

/// r's measured groups partitioned by their conditions other than `vc`; partitions of one group left out.
std::vector<std::vector<std::size_t>> partitions_along(const ComparisonSpec& spec, const QuantityComparison& r,
                                                       std::size_t vc) {
  std::vector<std::vector<std::size_t>> partitions;
  for (std::size_t gi = 0; gi < r.groups.size(); ++gi) {
    auto it = std::find_if(partitions.begin(), partitions.end(), [&](const auto& part) {
      return same_but(spec, r.groups[part.front()].conditions, r.groups[gi].conditions, vc);
    });
    if (it == partitions.end()) {
      partitions.push_back({gi});
    } else {
      it->push_back(gi);
    }
  }
  std::erase_if(partitions, [](const auto& part) { return part.size() < 2; });
  return partitions;
}

/// One prediction's series against condition `vc` at the fixed other conditions: its curve between x_lo and
/// x_hi, or its predicted points (dodged beside the measured ones when they carry error bars).
PlotSeries predicted_series(const Comparison& c, const QuantityComparison& rr, std::size_t vc,
                            const std::vector<ConditionValue>& fixed, double x_lo, double x_hi, std::size_t pi,
                            bool many_partitions, const std::string& suffix) {
  const ComparisonSpec& spec = c.spec;
  const ConditionSpec& cs = spec.conditions[vc];
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
    return line;
  }
  line.style = SeriesStyle::points;  // predicted points without a model behind them: no joining line
  line.marker = 5 + static_cast<int>(rr.prediction) + (many_partitions ? static_cast<int>(pi) : 0);
  for (const auto& g : rr.groups) {
    const auto& gc = g.conditions;
    if (!same_but(spec, gc, fixed, vc)) continue;
    line.x.push_back(*gc[vc].si / cs.unit.si);
    line.y.push_back(g.predicted_stats.mean / rr.unit.si);
    line.y_error.push_back(g.predicted.size() >= 2 ? g.predicted_stats.standard_deviation / rr.unit.si : kNaN);
  }
  // Predicted points with error bars sit beside the measured ones (dodged by 1.2 % of the range per
  // prediction) so that the bars stay readable; the tables and CSV carry the exact conditions.
  const bool has_bars =
      std::any_of(line.y_error.begin(), line.y_error.end(), [](double e) { return std::isfinite(e); });
  const double dodge = has_bars ? 0.012 * (x_hi - x_lo) * static_cast<double>(rr.prediction + 1) : 0.0;
  for (auto& x : line.x) x += dodge;
  sort_by_x(line);
  return line;
}

/// Quantity r against condition vc: per partition, the measured means and each prediction's series.
PlannedFigure condition_figure(const Comparison& c, const QuantityComparison& r, std::size_t vc,
                               const std::vector<std::vector<std::size_t>>& partitions) {
  const ComparisonSpec& spec = c.spec;
  const QuantitySpec& qs = spec.quantities[r.quantity];
  const ConditionSpec& cs = spec.conditions[vc];
  PlannedFigure pf;
  pf.file = fmt::format("{}_vs_{}.png", r.key, cs.key);
  FigureSpec& fig = pf.figure;
  fig.title = fmt::format("{}{} against {}", qs.label, view_text(r), lower_first(cs.label));
  fig.x_label = axis_label(cs.label, cs.unit);
  fig.y_label = axis_label(qs.label + view_text(r), r.unit);
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
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return *r.groups[a].conditions[vc].si < *r.groups[b].conditions[vc].si;
    });
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
      fig.series.push_back(predicted_series(c, rr, vc, fixed, x_lo, x_hi, pi, many_partitions, suffix));
      // Predictions outside their model's range: hollow diamonds on the model's values, said in the legend.
      PlotSeries outside;
      outside.label = c.predictions[rr.prediction].data.name + ", not valid here" + (many_partitions ? suffix : "");
      outside.color = fig.series.back().color;
      outside.marker = 8;
      for (const auto& g : rr.groups) {
        if (!g.outside_model_range || !same_but(spec, g.conditions, fixed, vc)) continue;
        outside.x.push_back(*g.conditions[vc].si / cs.unit.si);
        outside.y.push_back(g.predicted_stats.mean / rr.unit.si);
      }
      if (!outside.x.empty()) fig.series.push_back(std::move(outside));
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
  // Marks on this condition's axis, where they fall within the data's x range widened by its span (a mark far
  // outside it would squeeze the data into a corner).
  double x_lo = std::numeric_limits<double>::infinity(), x_hi = -x_lo;
  for (const auto& series : fig.series)
    for (double x : series.x) x_lo = std::min(x_lo, x), x_hi = std::max(x_hi, x);
  for (const auto& mark : spec.marks) {
    const double x = mark.value_si / cs.unit.si;
    if (mark.condition != cs.key || y_top <= 0.0 || x < x_lo - (x_hi - x_lo) || x > x_hi + (x_hi - x_lo)) continue;
    fig.series.push_back(PlotSeries{mark.label, {x, x}, {0.0, y_top}, {}, {}, SeriesStyle::dashed_line, 3, 0});
  }
  if (y_top > 0.0) fig.y_max = y_top * (1.0 + 0.09 * static_cast<double>(fig.series.size()) + 0.08);
  fig.legend_position = "best";
  pf.caption =
      fmt::format("{}{} against {}: measured{} and the model{}.", plain(qs.label), view_text(r),
                  lower_first(plain(cs.label)), r.n_with_scatter > 0 ? " means with ±1 SD error bars" : " points",
                  c.predictions.front().curve
                      ? " line"
                      : "'s predicted points (hollow; with replicate runs drawn slightly to the right, error "
                        "bars ±1 SD)");
  return pf;
}

}  // namespace

std::vector<PlannedFigure> plan_figures(const Comparison& c) {
  std::vector<PlannedFigure> figures;
  const auto keys = distinct_keys(c);
  for (const auto* r : keys) figures.push_back(parity_figure(c, *r));
  // Quantity against each numeric condition that varies while the others stay fixed.
  for (const auto* r : keys) {
    for (std::size_t vc = 0; vc < c.spec.conditions.size(); ++vc) {
      if (!c.spec.conditions[vc].numeric) continue;
      const auto partitions = partitions_along(c.spec, *r, vc);
      if (!partitions.empty()) figures.push_back(condition_figure(c, *r, vc, partitions));
    }
  }
  return figures;
}

}  // namespace kerf::report_detail
