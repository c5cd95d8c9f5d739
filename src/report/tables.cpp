// The report's table: comparison.csv, one row per measured row and prediction.
#include <fmt/format.h>

#include <cmath>

#include "kerf/io.hpp"
#include "report_internal.hpp"

namespace kerf {

using namespace report_detail;

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
    for (const std::string& col :
         {fmt::format("{}_measured_{}", r->key, u), fmt::format("{}_measured_mean_{}", r->key, u),
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
          fields.push_back(
              std::isfinite(v)
                  ? csv_number(view_value(v, c.measured.bases[first_r->quantity], first_r->view) / first_r->unit.si)
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

}  // namespace kerf
