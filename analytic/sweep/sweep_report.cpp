// The sweep's reports beside its CSV: the figure (kerf-forces sweep --plot) and the warnings about forces that
// fall as the chip thickens.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "kerf/analytic/kinds/evaluate.hpp"
#include "kerf/analytic/kinds/predict.hpp"
#include "kerf/analytic/sweep/sweep.hpp"
#include "kerf/comparison_config.hpp"
#include "kerf/error.hpp"
#include "kerf/plot.hpp"

namespace kerf {

std::vector<std::optional<double>> column_numbers(const SweepGrid& grid, const std::vector<SweepRow>& rows,
                                                  std::string_view name) {
  std::vector<std::optional<double>> values(rows.size());
  const auto& names = grid.column_names();
  const auto column = std::find(names.begin(), names.end(), name);
  if (column == names.end()) return values;
  const auto c = static_cast<std::size_t>(column - names.begin());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (rows[i].error.empty()) values[i] = cell_number(rows[i].cells, c);
  }
  return values;
}

std::vector<std::optional<std::string>> column_texts(const SweepGrid& grid, const std::vector<SweepRow>& rows,
                                                     std::string_view name) {
  std::vector<std::optional<std::string>> values(rows.size());
  const auto& names = grid.column_names();
  const auto column = std::find(names.begin(), names.end(), name);
  if (column == names.end()) return values;
  const auto c = static_cast<std::size_t>(column - names.begin());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (!rows[i].error.empty()) continue;
    const auto fields = split_cells(rows[i].cells);
    if (c >= fields.size()) continue;
    std::string_view field = fields[c];
    if (field.size() >= 2 && field.front() == '"' && field.back() == '"') field = field.substr(1, field.size() - 2);
    values[i] = std::string(field);
  }
  return values;
}

namespace {
/// Counts in first-seen order, so that the summary reads in the sweep's own order.
class Tally {
 public:
  void add(std::string_view item) {
    const auto it = std::find_if(counts_.begin(), counts_.end(), [&](const auto& c) { return c.first == item; });
    if (it == counts_.end())
      counts_.emplace_back(std::string(item), 1);
    else
      ++it->second;
  }
  bool empty() const { return counts_.empty(); }
  std::size_t count(std::string_view item) const {
    const auto it = std::find_if(counts_.begin(), counts_.end(), [&](const auto& c) { return c.first == item; });
    return it == counts_.end() ? 0 : it->second;
  }
  std::string text() const {
    std::string out;
    for (const auto& [name, n] : counts_) out += fmt::format("{}{} {}", out.empty() ? "" : ", ", n, name);
    return out;
  }

 private:
  std::vector<std::pair<std::string, std::size_t>> counts_;
};
}  // namespace

std::string sweep_summary(const SweepGrid& grid, const std::vector<SweepRow>& rows) {
  const auto& names = grid.column_names();
  const auto index_of = [&](std::string_view name) {
    return static_cast<std::size_t>(std::find(names.begin(), names.end(), name) - names.begin());
  };
  const std::size_t regime_c = index_of("regime"), range_c = index_of("within_model_range"),
                    guard_c = index_of("guards");
  const auto unquoted = [](std::string_view field) {
    return field.size() >= 2 && field.front() == '"' ? field.substr(1, field.size() - 2) : field;
  };
  // One pass over the rows, each split once (a sweep may hold millions of them).
  Tally regimes, ranges, guards;
  std::size_t refused = 0;
  for (const auto& row : rows) {
    if (!row.error.empty()) {
      ++refused;
      continue;
    }
    const auto fields = split_cells(row.cells);
    if (regime_c < fields.size()) {
      const auto regime = unquoted(fields[regime_c]);
      regimes.add(regime.empty() ? "without d_c" : regime);
    }
    if (range_c < fields.size()) ranges.add(unquoted(fields[range_c]) == "no" ? "outside" : "within");
    if (guard_c >= fields.size()) continue;
    std::string_view list = unquoted(fields[guard_c]);
    if (list.empty()) guards.add("none");
    while (!list.empty()) {
      const auto end = std::min(list.find(';'), list.size());
      guards.add(list.substr(0, end));
      list.remove_prefix(std::min(end + 1, list.size()));
    }
  }
  std::string line = fmt::format("{} points: {} refused", rows.size(), refused);
  if (!regimes.empty()) line += "; regime " + regimes.text();
  if (!ranges.empty()) {
    line += fmt::format("; within the model's range {}, outside {}", ranges.count("within"), ranges.count("outside"));
  }
  if (!guards.empty()) line += "; guards " + guards.text();
  return line;
}

// Long (~90 lines) for a reason: one figure assembled in the order it is drawn (axes, title and width, one series
// per force and second-axis value, the line-style key); the parts share the figure under construction.
void plot_sweep(const SweepGrid& grid, const std::vector<SweepRow>& rows, const std::string& path,
                const std::string& /*scene_path: the CSV and the command name it*/) {
  const Json& base = grid.base();
  MaterialCache& materials = grid.materials();
  const std::size_t n_points = grid.size();
  if (grid.axes()[0].numbers.empty()) {
    throw InputError("--plot", path,
                     fmt::format("a numeric first --vary key to draw against ({} is categorical: "
                                 "put a numeric key first)",
                                 grid.axes()[0].key));
  }
  const bool x_log = grid.axes()[0].log_spacing;
  std::vector<std::string> axis_paths;
  std::vector<std::vector<double>> axis_values;
  for (const auto& axis : grid.axes()) axis_paths.push_back(axis.key), axis_values.push_back(axis.numbers);
  const auto coordinate = [&](std::size_t i, std::size_t a) { return axis_values[a][grid.value_index(i, a)]; };
  // The two force columns' numbers, read once.
  std::vector<std::vector<std::optional<double>>> force_numbers;
  for (const std::string_view force : {prediction_keys::cutting_force_N, prediction_keys::thrust_force_N})
    force_numbers.push_back(column_numbers(grid, rows, force));
  const auto in_range = column_texts(grid, rows, "within_model_range");
  const auto outside = [&](std::size_t i) { return in_range[i] && *in_range[i] == "no"; };
  FigureSpec fig;
  fig.x_log = x_log;
  fig.x_label = key_label(axis_paths[0]);
  std::string material;
  try {
    const auto& record = materials.get(base.at("material"), "material");
    // The title, where it fits above the plot beside the legend; else the library name.
    material = record.title.empty() || record.title.size() > 40 ? record.name : record.title;
  } catch (const std::exception&) {
    material = "material?";  // the scene's own errors are the sweep's to report, not the figure's
  }
  // The scene's file name is the CSV's and the command's; the material is what a reader needs (the legend names each
  // when they are swept).
  const auto material_axis =
      static_cast<std::size_t>(std::find(axis_paths.begin(), axis_paths.end(), "material") - axis_paths.begin());
  fig.title = material_axis < axis_paths.size() ? "by material" : material;
  // The width the forces are for: the scene's, stated; per mm of width where the width is swept.
  const auto width_axis =
      static_cast<std::size_t>(std::find(axis_paths.begin(), axis_paths.end(), "cut.width_mm") - axis_paths.begin());
  const Json* width = nullptr;
  if (base.contains("cut") && base["cut"].is_object() && base["cut"].contains("width_mm"))
    width = &base["cut"]["width_mm"];
  const bool per_mm = width_axis < axis_paths.size();
  if (per_mm) {
    fig.y_label = "force per mm of width (N/mm)";
  } else if (width && width->is_number()) {
    fig.y_label = fmt::format("force for a width of {:g} mm (N)", width->get<double>());
  } else {
    fig.y_label = "force for the cut's engaged width (N)";
  }
  // Colours 0-4 and 6: grey (5) is the line-style key's.
  constexpr std::array<int, 6> kColors = {0, 1, 2, 3, 4, 6};
  const std::size_t n_second =
      grid.axes().size() > 1 ? std::min<std::size_t>(kColors.size(), grid.axes()[1].values.size()) : 1;
  std::vector<PlotSeries> keys;
  bool any_outside = false;
  for (std::size_t k = 0; k < n_second; ++k) {
    bool drawn = false;
    for (const bool dashed :
         {false, true}) {  // the cutting force, then the thrust (a column the scene lacks: no values)
      PlotSeries series;
      series.style = dashed ? SeriesStyle::dashed_line : SeriesStyle::line;
      series.color = kColors[k];
      // A marker at each computed point: filled within the model's range, hollow outside it.
      PlotSeries within_marks, outside_marks;
      within_marks.color = outside_marks.color = kColors[k];
      within_marks.marker = dashed ? 1 : 0;
      outside_marks.marker = within_marks.marker + 5;
      for (std::size_t i = 0; i < n_points; ++i) {
        if (axis_values.size() > 1 && grid.value_index(i, 1) != k) continue;
        bool first_of_the_rest = true;  // further axes: their first value
        for (std::size_t a = 2; a < axis_values.size(); ++a)
          first_of_the_rest = first_of_the_rest && grid.value_index(i, a) == 0;
        if (!first_of_the_rest) continue;
        const auto& value = force_numbers[dashed ? 1 : 0][i];
        if (!value) continue;  // refused, or no such column
        series.x.push_back(coordinate(i, 0));
        series.y.push_back(*value / (per_mm ? coordinate(i, width_axis) : 1.0));
        PlotSeries& marks = outside(i) ? outside_marks : within_marks;
        marks.x.push_back(series.x.back());
        marks.y.push_back(series.y.back());
      }
      if (series.x.empty()) continue;
      drawn = true;
      any_outside = any_outside || !outside_marks.x.empty();
      fig.series.push_back(std::move(series));
      for (auto* marks : {&within_marks, &outside_marks})
        if (!marks->x.empty()) fig.series.push_back(std::move(*marks));
    }
    if (drawn && axis_values.size() > 1) {
      const std::string label = key_label(axis_paths[1]);
      const auto open = label.rfind(" (");
      PlotSeries key;
      if (axis_values[1].empty()) {  // a categorical key: its value as written
        key.label = fmt::format("{} = {}", label, grid.axes()[1].texts[k]);
      } else {
        key.label = open == std::string::npos ? fmt::format("{} = {:g}", label, axis_values[1][k])
                                              : fmt::format("{} = {:g} {}", label.substr(0, open), axis_values[1][k],
                                                            label.substr(open + 2, label.size() - open - 3));
      }
      key.style = SeriesStyle::line;
      key.color = kColors[k];
      key.legend_only = true;
      keys.push_back(std::move(key));
    }
  }
  if (fig.series.empty()) throw InputError("--plot", path, "a sweep with cutting_force_N or thrust_force_N values");
  // The critical depth, where the first key is the depth of cut and the material has one: a mark per value (per
  // material, named, where the material is swept).
  if (axis_paths[0] == "cut.uncut_chip_thickness_um") {
    const auto critical = column_numbers(grid, rows, "critical_depth_nm");
    std::vector<std::pair<double, std::size_t>> marks;  // d_c [nm] and a point that has it
    for (std::size_t i = 0; i < n_points; ++i)
      if (critical[i] &&
          std::none_of(marks.begin(), marks.end(), [&](const auto& m) { return m.first == *critical[i]; }))
        marks.emplace_back(*critical[i], i);
    // Where it falls within the data's x range widened by its span (in decades on a log axis): a mark far
    // outside it would squeeze the data into a corner.
    double x_lo = std::numeric_limits<double>::infinity(), x_hi = -x_lo, y_lo = 0.0, y_hi = 0.0;
    for (const auto& s : fig.series) {
      for (double x : s.x) x_lo = std::min(x_lo, x), x_hi = std::max(x_hi, x);
      for (double y : s.y) y_lo = std::min(y_lo, y), y_hi = std::max(y_hi, y);
    }
    const auto scale = [&](double x) { return x_log ? std::log10(x) : x; };
    int mark_color = 3;  // red, then purple, ... (the series take the palette from its start)
    for (const auto& [dc_nm, point] : marks) {
      if (!(x_hi >= x_lo) ||
          std::fabs(scale(dc_nm * 1e-3) - 0.5 * (scale(x_lo) + scale(x_hi))) > 1.5 * (scale(x_hi) - scale(x_lo)))
        continue;
      PlotSeries line;
      line.label = fmt::format("d#dc#u = {:.3g} nm", dc_nm);
      if (material_axis < axis_paths.size())
        line.label += " (" + grid.axes()[material_axis].texts[grid.value_index(point, material_axis)] + ")";
      line.style = SeriesStyle::line;
      line.color = mark_color++;
      line.x = {dc_nm * 1e-3, dc_nm * 1e-3};
      line.y = {y_lo, y_hi};
      fig.series.push_back(std::move(line));
    }
  }
  for (const auto& [label, dashed] : {std::pair{"cutting force", false}, std::pair{"thrust force", true}}) {
    PlotSeries key;
    key.label = label;
    key.style = dashed ? SeriesStyle::dashed_line : SeriesStyle::line;
    key.color = 5;
    key.legend_only = true;
    keys.push_back(std::move(key));
  }
  for (const bool hollow : {false, true}) {
    if (hollow && !any_outside) break;
    PlotSeries key;
    key.label = hollow ? "model not valid" : "model valid";
    key.style = SeriesStyle::points;
    key.color = 5;
    key.marker = hollow ? 5 : 0;
    key.legend_only = true;
    keys.push_back(std::move(key));
  }
  fig.series.insert(fig.series.end(), keys.begin(), keys.end());
  fig.legend_position = "outside_right";
  render_png(fig, path);
}

std::vector<std::string> falling_force_warnings(const SweepGrid& grid, const std::vector<SweepRow>& rows) {
  std::vector<std::string> out;
  const auto& axes = grid.axes();
  for (std::size_t a = 0; a < axes.size(); ++a) {
    if (axes[a].key != "cut.uncut_chip_thickness_um") continue;
    const std::size_t stride = grid.stride(a);
    const std::size_t n_h = axes[a].values.size();
    for (const std::string_view force : {prediction_keys::cutting_force_N, prediction_keys::thrust_force_N}) {
      const std::vector<std::optional<double>> values = column_numbers(grid, rows, force);
      const std::vector<std::size_t> falls = falling_points(values, stride, n_h);
      if (falls.empty()) continue;
      const std::size_t i = falls.front(), j = i - stride;
      const auto x = [&](std::size_t point) { return axes[a].numbers[grid.value_index(point, a)]; };
      out.push_back(
          fmt::format("{} falls as cut.uncut_chip_thickness_um grows at {} point(s), first from {:.6g} N "
                      "at {:.6g} um to {:.6g} N at {:.6g} um: the model may have changed branch or left "
                      "its domain there",
                      force, falls.size(), *values[j], x(j), *values[i], x(i)));
    }
  }
  return out;
}

}  // namespace kerf
