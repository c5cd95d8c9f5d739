// Text forms shared by the report's rooms (report_internal.hpp).
#include <fmt/format.h>

#include "report_internal.hpp"

namespace kerf::report_detail {

std::string plain(std::string text) {
  for (const char* escape : {"#d", "#u"}) {
    for (std::size_t at = text.find(escape); at != std::string::npos; at = text.find(escape)) text.erase(at, 2);
  }
  return text;
}

std::string number_text(double value) {
  return fmt::format("{:.4g}", value);
}

std::string condition_text(const ConditionSpec& spec, const ConditionValue& value) {
  if (!spec.numeric || !value.si) return value.text;
  return number_text(*value.si / spec.unit.si);
}

std::string lower_first(std::string text) {
  if (!text.empty() && text[0] >= 'A' && text[0] <= 'Z') text[0] = static_cast<char>(text[0] - 'A' + 'a');
  return text;
}

std::string conditions_text(const ComparisonSpec& spec, const std::vector<ConditionValue>& values,
                            std::optional<std::size_t> skip, bool for_plot) {
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

double view_value(double value, const WidthBasis& basis, WidthView view) {
  return view == WidthView::as_published ? value : to_per_unit_width(value, basis);
}

}  // namespace kerf::report_detail
