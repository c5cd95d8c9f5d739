#pragma once
// The report layer's shared pieces (src/report/, not a public header): text forms of numbers, labels and
// conditions, the width views, and the figures a report plans. kerf/report.hpp is the public interface.
#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "kerf/plot.hpp"
#include "kerf/report.hpp"

namespace kerf::report_detail {

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// Plot labels use PLplot escapes (#d subscript, #u superscript); text output drops them.
std::string plain(std::string text);
std::string number_text(double value);  ///< "{:.4g}"
std::string condition_text(const ConditionSpec& spec, const ConditionValue& value);
std::string lower_first(std::string text);
/// "Spindle speed n0 = 90.5 rev/min, ..." (with PLplot escapes kept when `for_plot`).
std::string conditions_text(const ComparisonSpec& spec, const std::vector<ConditionValue>& values,
                            std::optional<std::size_t> skip = std::nullopt, bool for_plot = false);
/// A value as the view shows it: as published, or divided by its basis's width.
double view_value(double value, const WidthBasis& basis, WidthView view);

/// A figure of the report: its file name, caption and what it draws (figures.cpp).
struct PlannedFigure {
  std::string file;
  std::string caption;
  FigureSpec figure;
};
/// The parity plot of each quantity and view, then each quantity against each numeric condition that varies
/// while the others stay fixed.
std::vector<PlannedFigure> plan_figures(const Comparison& c);

}  // namespace kerf::report_detail
