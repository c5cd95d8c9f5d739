// The report's summary.json: the metrics per quantity, view and prediction.
#include <fmt/format.h>

#include "report_internal.hpp"

namespace kerf {

using namespace report_detail;

namespace {

Json basis_json(const WidthBasis& b) {
  switch (b.kind) {
    case WidthBasis::Kind::total:
      return {{"kind", "total"}, {"width_mm", b.width_m * 1e3}};
    case WidthBasis::Kind::per_unit_width:
      return {{"kind", "per_unit_width"}};
    case WidthBasis::Kind::not_applicable:
      break;
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

}  // namespace

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
    predictions.push_back(
        {{"name", d.name}, {"source", d.source}, {"citations", d.citations}, {"quantities", quantities_of(p)}});
  }
  Json conditions = Json::array();
  for (const auto& cs : spec.conditions) conditions.push_back(cs.header());
  Json out = {
      {"title", spec.title},
      {"measured", {{"name", c.measured.name}, {"source", c.measured.source}, {"citations", c.measured.citations}}},
      {"conditions", conditions},
      {"match_relative_tolerance", spec.relative_tolerance},
      {"error_definition", "(predicted - measured) / measured, percent; replicates compared through their mean"},
      {"quantities", quantities_of(0)},
      {"predictions", predictions}};
  if (!options.extra_summary.empty()) out["extra"] = options.extra_summary;
  return out;
}

}  // namespace kerf
