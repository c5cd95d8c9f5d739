#include "kerf/analytic/kinds/predict.hpp"

#include <fmt/format.h>

#include <cctype>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "kerf/analytic/forces/chip_term.hpp"
#include "kerf/analytic/forces/critical_depth.hpp"
#include "kerf/analytic/forces/oxley_model.hpp"
#include "kerf/analytic/registry.hpp"
#include "kerf/analytic/trepanning/trepanning_results.hpp"
#include "kerf/error.hpp"
#include "kerf/io.hpp"
#include "kerf/units.hpp"

namespace kerf {

namespace {

// Berezvai et al. 2019 validated the contact-length models for A2024-T351 up to h = 0.1 mm (chip segmentation
// above); the limit is that material's, so the warning is too.
constexpr double kContactLengthValidatedThickness_m = 0.1e-3;
constexpr const char* kContactLengthValidatedMaterial = "a2024_t351";

/// A ductile-regime force model warns, and names the model to use, above the critical depth; a model that spans
/// the transition (its validated_depth_m) warns beyond the depth it was held against.
void add_regime(const AnalyticScene& scene, Prediction& p) {
  if (!scene.critical_depth_m) return;
  const double depth = scene.uncut_chip_thickness_m, critical = *scene.critical_depth_m;
  const CuttingRegime regime = classify_regime(depth, critical);
  p.regime = cutting_regime_name(regime);
  if (const double held = scene.force_model().validated_depth_m; held > 0.0) {
    if (depth > held) {
      p.within_model_range = false;
      p.warnings.push_back(
          fmt::format("uncut chip thickness {:.4g} um is beyond {:.3g} um, the deepest cut the "
                      "{} model was held against (docs/models.md)",
                      units::m_to_um(depth), units::m_to_um(held), p.force_model));
    }
    return;
  }
  if (regime == CuttingRegime::ductile) return;
  p.within_model_range = false;
  p.warnings.push_back(fmt::format(
      "uncut chip thickness {:.4g} nm is above the ductile-brittle critical depth d_c = {:.3g} nm (Bifano): {} "
      "regime, where this ductile-regime model does not hold; use models.force = transition (0.01 um to 0.2 mm), "
      "the DEM (kerf-dem) for cuts of tens of um and more, or the trepanning model for abrasive drilling",
      units::m_to_nm(depth), units::m_to_nm(critical), p.regime));
}

/// The parts every force model shares (width, thickness, the turning guard, the regime, the Oxley solve the
/// scene asked for), then the model of the scene's registry line.
Prediction predict_forces(const AnalyticScene& scene) {
  Prediction p;
  p.force_model = scene.force->name;
  p.width_m = scene.width_m;
  p.uncut_chip_thickness_m = scene.uncut_chip_thickness_m;
  p.has_friction = scene.friction_angle_rad.has_value();
  p.friction_angle_rad = scene.friction_angle_rad.value_or(0.0);
  if (scene.turning) round_nose_chip(scene.turning->geometry, &p.guards);  // records the turning guard
  add_regime(scene, p);
  const std::optional<OxleyResult> oxley = solve_scene_oxley(scene, p);
  scene.force_model().predict(scene, oxley ? &*oxley : nullptr, p);
  return p;
}

/// A force or state that overflowed (a width of 1e308 mm, a chip of 1e308 um) is refused by name, with the
/// inputs it came from, instead of being written as inf or nan.
void require_finite(const AnalyticScene& scene, const Prediction& p) {
  namespace k = prediction_keys;
  const std::pair<std::string_view, double> results[] = {
      {k::cutting_force_N, p.cutting_force_N},  {k::thrust_force_N, p.thrust_force_N},
      {k::shear_angle_deg, p.shear_angle_rad},  {k::chip_thickness_um, p.chip_thickness_m},
      {k::flow_stress_MPa, p.flow.total_Pa},    {k::strain_rate_per_s, p.state.strain_rate_per_s},
      {k::temperature_K, p.state.temperature_K}};
  for (const auto& [name, value] : results) {
    if (std::isfinite(value)) continue;
    throw ModelError("predict", fmt::format("{} is {} for cut.uncut_chip_thickness_um = {}, cut.width_mm = {}, "
                                            "cut.speed_m_per_min = {}: the inputs lie beyond what a double holds",
                                            name, value, format_value(units::m_to_um(scene.uncut_chip_thickness_m)),
                                            format_value(units::m_to_mm(scene.width_m)),
                                            format_value(units::m_per_s_to_m_per_min(scene.speed_m_per_s))));
  }
  if (!std::isfinite(p.cutting_force_N / units::m_to_mm(p.width_m)))
    throw ModelError("predict",
                     fmt::format("{} is not finite for cut.width_mm = {}", prediction_keys::cutting_force_N_per_mm,
                                 format_value(units::m_to_mm(scene.width_m))));
}
}  // namespace

/// Contact lengths (Berezvai et al. 2019, Eqs. 1-4) with the prediction's own friction angle. A variant outside its
/// domain (no positive shear angle or length) is not applicable: its cell stays empty, the guard and a warning say
/// why, and the rest of the prediction stands.
void add_contact_lengths(const AnalyticScene& scene, double friction_angle_rad, Prediction& p) {
  const double t0 = scene.uncut_chip_thickness_m;
  for (const auto& request : scene.contact_lengths) {
    const double phi = shear_angle(request.shear_angle, scene.rake_rad, friction_angle_rad);
    if (const auto why = contact_length_outside_domain(request.model, phi, friction_angle_rad, scene.rake_rad)) {
      p.guards.raise(Guard::contact_length_not_applicable);
      p.warnings.push_back(fmt::format("{}: not applicable ({} shear angle): {}", request.column,
                                       request.shear_angle == ShearAngleModel::merchant ? "MEP" : "MSSP", *why));
      p.contact_lengths_m.emplace_back(request.column, std::nullopt);
      continue;
    }
    p.contact_lengths_m.emplace_back(request.column,
                                     contact_length(request.model, t0, phi, friction_angle_rad, scene.rake_rad));
  }
  if (!scene.contact_lengths.empty() && t0 > kContactLengthValidatedThickness_m &&
      scene.material->name == kContactLengthValidatedMaterial) {
    p.warnings.push_back(
        "contact-length models were validated up to h = 0.1 mm (Berezvai et al. 2019: chip segmentation above)");
  }
}

/// The sharp-tool models (Merchant, Oxley) ignore the edge: say so when it is not small against t0.
void warn_if_edge_ignored(const AnalyticScene& scene, const char* model_and_remedy, Prediction& p) {
  const double ratio = scene.edge_radius_m / scene.uncut_chip_thickness_m;
  if (ratio <= kSharpEdgeRatio) return;
  p.warnings.push_back(
      fmt::format("edge radius is {:.0f} % of the uncut chip thickness: {}", 100.0 * ratio, model_and_remedy));
}

Prediction predict(const AnalyticScene& scene) {
  Prediction p = predict_forces(scene);
  require_finite(scene, p);
  return p;
}

namespace {

namespace k = prediction_keys;
using R = PredictionReport;

/// An input echoed back (a CSV cell rounds it to 15 significant digits), already in its key's unit.
template <class Get>
ResultField<R> input_value(std::string_view key, std::string_view unit, std::string_view doc, Get get) {
  ResultField<R> f = result_value<R>(key, unit, doc, get);
  f.input_echo = true;
  return f;
}

/// The ploughing part of the totals (zero where the model adds none; null for Oxley, which ignores the edge).
bool chip_model(const R& r) {
  return !r.scene.force_model().solves_oxley;
}
ForcePerWidth plough(const R& r) {
  return r.p.chip_term.ploughing ? r.p.chip_term.ploughing->force : ForcePerWidth{};
}

}  // namespace

const ResultTable<PredictionReport>& prediction_results() {
  static const ResultTable<R> table{
      // The inputs, converted back from SI.
      result_value<R>(k::force_model, "", "the force model that ran (models.force; auto's choice)",
                      [](const R& r) { return std::string(r.p.force_model); }),
      result_value<R>(k::material, "", "the material's name", [](const R& r) { return r.scene.material->name; }),
      result_input<R>(k::rake_deg, units::kDeg, "tool rake angle", [](const R& r) { return r.scene.rake_rad; }),
      result_input<R>(k::edge_radius_um, units::kUm, "tool edge radius",
                      [](const R& r) { return r.scene.edge_radius_m; }),
      result_input<R>(k::clearance_deg, units::kDeg, "tool clearance angle",
                      [](const R& r) { return r.scene.clearance_rad; }),
      input_value(k::speed_m_per_min, "m/min", "cutting speed",
                  [](const R& r) { return units::m_per_s_to_m_per_min(r.scene.speed_m_per_s); }),
      input_value(k::workpiece_temperature_K, "K", "workpiece temperature",
                  [](const R& r) { return r.scene.workpiece_temperature_K; }),
      result_or_null<R>(
          k::scene_friction_angle_deg, "deg", "the scene's friction angle (empty: none given)",
          [](const R& r) { return r.scene.friction_angle_rad.has_value(); },
          [](const R& r) { return units::rad_to_deg(r.scene.friction_angle_rad.value_or(0.0)); }),
      result_input<R>(k::uncut_chip_thickness_um, units::kUm, "uncut chip thickness t0",
                      [](const R& r) { return r.p.uncut_chip_thickness_m; }),
      result_input<R>(k::width_mm, units::kMm, "width of cut", [](const R& r) { return r.p.width_m; }),
      // The forces over the width, their ploughing part, per mm of width.
      result_value<R>(k::cutting_force_N, "N", "cutting force over the width",
                      [](const R& r) { return r.p.cutting_force_N; }),
      result_value<R>(k::thrust_force_N, "N", "thrust force over the width",
                      [](const R& r) { return r.p.thrust_force_N; }),
      result_or_null<R>(k::ploughing_cutting_force_N, "N", "the ploughing part of the cutting force (empty for Oxley)",
                        chip_model, [](const R& r) { return plough(r).cutting_N_per_m * r.p.width_m; }),
      result_or_null<R>(k::ploughing_thrust_force_N, "N", "the ploughing part of the thrust force (empty for Oxley)",
                        chip_model, [](const R& r) { return plough(r).thrust_N_per_m * r.p.width_m; }),
      result_value<R>(k::cutting_force_N_per_mm, "N/mm", "cutting force per mm of width",
                      [](const R& r) { return r.p.cutting_force_N / units::m_to_mm(r.p.width_m); }),
      result_value<R>(k::thrust_force_N_per_mm, "N/mm", "thrust force per mm of width",
                      [](const R& r) { return r.p.thrust_force_N / units::m_to_mm(r.p.width_m); }),
      // The chip.
      result_number<R>(k::shear_angle_deg, units::kDeg, "shear angle", [](const R& r) { return r.p.shear_angle_rad; }),
      result_or_null<R>(
          k::friction_angle_deg, "deg", "the prediction's friction angle (empty: none)",
          [](const R& r) { return r.p.has_friction; },
          [](const R& r) { return units::rad_to_deg(r.p.friction_angle_rad); }),
      result_value<R>(k::chip_ratio, "", "chip ratio t0 / t_c", [](const R& r) { return r.p.chip_ratio; }),
      result_number<R>(k::chip_thickness_um, units::kUm, "chip thickness t_c",
                       [](const R& r) { return r.p.chip_thickness_m; }),
      // The flow stress, its parts (those of the scene's flow-stress model) and the state it was evaluated at.
      result_number<R>(k::flow_stress_MPa, units::kMPa, "flow stress", [](const R& r) { return r.p.flow.total_Pa; }),
      result_number<R>(k::shear_flow_stress_MPa, units::kMPa, "shear flow stress k_s",
                       [](const R& r) { return r.p.flow.shear_Pa; }),
      result_if(result_number<R>(k::johnson_cook_stress_MPa, units::kMPa, "its Johnson-Cook part",
                                 [](const R& r) { return r.p.flow.johnson_cook_Pa; }),
                [](const R& r) { return static_cast<bool>(r.scene.flow_stress.johnson_cook); }),
      result_if(result_number<R>(k::hall_petch_stress_MPa, units::kMPa, "its Hall-Petch part",
                                 [](const R& r) { return r.p.flow.hall_petch_Pa; }),
                [](const R& r) { return static_cast<bool>(r.scene.flow_stress.hall_petch); }),
      result_if(result_number<R>(k::dislocation_stress_MPa, units::kMPa, "its dislocation part",
                                 [](const R& r) { return r.p.flow.dislocation_Pa; }),
                [](const R& r) { return static_cast<bool>(r.scene.flow_stress.dislocation); }),
      result_if(result_number<R>(k::hardness_flow_stress_MPa, units::kMPa, "the flow stress from the hardness",
                                 [](const R& r) { return r.p.flow.hardness_Pa; }),
                [](const R& r) { return static_cast<bool>(r.scene.flow_stress.hardness); }),
      result_value<R>(k::strain, "", "effective strain", [](const R& r) { return r.p.state.strain; }),
      result_value<R>(k::strain_rate_per_s, "1/s", "strain rate",
                      [](const R& r) { return r.p.state.strain_rate_per_s; }),
      result_value<R>(k::temperature_K, "K", "temperature", [](const R& r) { return r.p.state.temperature_K; })};
  return table;
}

const ResultTable<PredictionReport>& prediction_verdict_results() {
  const auto turning = [](const R& r) { return r.scene.turning.has_value(); };
  static const ResultTable<R> table{
      // A round-nose turning cut's chip.
      result_if(result_number<R>(k::feed_um_per_rev, units::kUm, "turning: feed per revolution",
                                 [](const R& r) { return r.scene.turning->geometry.feed_m_per_rev; }),
                turning),
      result_if(result_number<R>(k::depth_of_cut_um, units::kUm, "turning: depth of cut",
                                 [](const R& r) { return r.scene.turning->geometry.depth_of_cut_m; }),
                turning),
      result_if(result_number<R>(k::maximum_chip_thickness_um, units::kUm, "turning: the chip's largest thickness",
                                 [](const R& r) { return r.scene.turning->chip.maximum_thickness_m; }),
                turning),
      result_if(result_number<R>(k::equivalent_chip_thickness_um, units::kUm, "turning: the equivalent chip thickness",
                                 [](const R& r) { return r.scene.turning->chip.equivalent_thickness_m; }),
                turning),
      result_if(result_number<R>(k::engaged_edge_length_mm, units::kMm, "turning: the engaged edge length",
                                 [](const R& r) { return r.scene.turning->chip.engaged_edge_length_m; }),
                turning),
      // The verdicts.
      result_or_null<R>(
          k::critical_depth_nm, "nm", "the ductile-brittle critical depth d_c (empty without one)",
          [](const R& r) { return r.scene.critical_depth_m.has_value(); },
          [](const R& r) { return units::m_to_nm(r.scene.critical_depth_m.value_or(0.0)); }),
      result_value<R>(k::regime, "", "ductile, transition or brittle against d_c (empty without one)",
                      [](const R& r) { return r.p.regime; }),
      result_value<R>(k::within_model_range, "", "yes, or no where the force model does not hold",
                      [](const R& r) { return std::string(r.p.within_model_range ? "yes" : "no"); }),
      result_value<R>(k::guards, "", "the guards that fired", [](const R& r) { return r.p.guards.names(); }),
      result_value<R>(k::warnings, "", "the warnings, joined by '; '", [](const R& r) {
        std::string warnings;
        for (const auto& w_text : r.p.warnings) warnings += (warnings.empty() ? "" : "; ") + w_text;
        return warnings;
      })};
  return table;
}

std::array<const ResultTable<PredictionReport>*, 3> prediction_model_results(const AnalyticScene& scene) {
  const OrthogonalForceModel& force = scene.force_model();
  return {force.edge_columns || scene.force_auto ? &edge_results() : nullptr,
          scene.params<OxleyModelParams>().material || scene.force_auto ? &oxley_results() : nullptr,
          force.results ? &force.results() : nullptr};
}

// The CSV's column list, in column order: the shared columns (prediction_results), the scene's contact lengths, then
// each unit's (the chip term's edge, the Oxley solve's, the force model's own), then the turning cut's and the
// verdicts.
void write_prediction_cells(const AnalyticScene& scene, const Prediction& p, CellWriter& w) {
  const R report{scene, p};
  write_result_cells(prediction_results(), report, w);
  for (std::size_t i = 0; i < scene.contact_lengths.size(); ++i) {
    const bool has = i < p.contact_lengths_m.size() && p.contact_lengths_m[i].second.has_value();
    w.optional_number(scene.contact_lengths[i].column, has, has ? units::m_to_mm(*p.contact_lengths_m[i].second) : 0.0);
  }
  for (const ResultTable<R>* unit : prediction_model_results(scene))
    if (unit) write_result_cells(*unit, report, w);
  write_result_cells(prediction_verdict_results(), report, w);
}

namespace {

/// The registry's orthogonal force models of which `carries` holds, in its order: "`a`, `b` and `c`".
std::string force_models_where(bool (*carries)(const OrthogonalForceModel&)) {
  std::vector<std::string_view> names;
  for (const auto& m : analytic_models())
    if (m.kind == "force" && m.orthogonal && carries(*m.orthogonal)) names.push_back(m.name);
  std::string list;
  for (std::size_t i = 0; i < names.size(); ++i)
    list += fmt::format("{}`{}`", i == 0 ? "" : i + 1 == names.size() ? " and " : ", ", names[i]);
  return list;
}

bool carries_edge(const OrthogonalForceModel& m) {
  return m.edge_columns || m.choose;
}
bool solves_oxley(const OrthogonalForceModel& m) {
  return m.solves_oxley || m.choose;
}

/// The registry's orthogonal force models with columns of their own, in its order.
std::vector<const AnalyticModelInfo*> models_with_columns() {
  std::vector<const AnalyticModelInfo*> models;
  for (const auto& m : analytic_models())
    if (m.kind == "force" && m.orthogonal && m.orthogonal->results) models.push_back(&m);
  return models;
}

/// A Python class name of a model's name: "transition" -> "TransitionColumns".
std::string columns_class(std::string_view model) {
  std::string name;
  bool upper = true;
  for (const char c : model) {
    if (c == '_') {
      upper = true;
      continue;
    }
    name += upper ? static_cast<char>(std::toupper(static_cast<unsigned char>(c))) : c;
    upper = false;
  }
  return name + "Columns";
}

}  // namespace

std::string prediction_columns_markdown() {
  std::string md =
      results_markdown(prediction_results()) +
      "| `contact_length_<name>_mm` | mm | the contact lengths the scene asks for (`cut.contact_lengths`), one "
      "column each (empty: not applicable) |\n"
      "| ... | | the models' own columns, the tables below: the chip term's edge, the Oxley solve's, the force "
      "model's |\n" +
      results_markdown(prediction_verdict_results(), false);
  md += fmt::format("\nThe chip term's edge columns (`models.force` {}; empty where the prediction has no edge):\n\n",
                    force_models_where(&carries_edge)) +
        results_markdown(edge_results());
  md += fmt::format(
            "\nThe Oxley solve's columns (`models.force` {}, or `models.deformation = oxley`; empty where the "
            "prediction has no solve):\n\n",
            force_models_where(&solves_oxley)) +
        results_markdown(oxley_results());
  for (const AnalyticModelInfo* m : models_with_columns())
    md += fmt::format("\n`models.force = {}`'s own columns:\n\n", m->name) + results_markdown(m->orthogonal->results());
  return md +
         "\nA trepanning scene's row (`models.force = trepanning`; the grit columns with "
         "`models.trepanning.grits`):\n\n" +
         results_markdown(trepanning_results());
}

std::string prediction_keys_python() {
  std::vector<std::string> keys = result_keys(prediction_results());
  for (auto& key : result_keys(prediction_verdict_results())) keys.push_back(std::move(key));
  std::string py =
      "\"\"\"The columns of kerf-forces' predictions (their CSV row, kerf.predict's dict), generated from their "
      "result tables\n(kerf-forces results --python > python/kerf/prediction_keys.py; tests/cli/forces_results_cli.sh "
      "checks it is\ncurrent): the orthogonal prediction's shared columns, its models' own (a class per unit), the "
      "trepanning\nprediction's.\"\"\"\n" +
      results_python_class("PredictionColumns",
                           "The shared columns of an orthogonal prediction, in the row's order (the models' own "
                           "between the flow state and the turning cut's).",
                           keys) +
      results_python_class(
          "EdgeColumns",
          "The chip term's edge columns, in the row's order (models.force " + force_models_where(&carries_edge) + ").",
          result_keys(edge_results())) +
      results_python_class("OxleyColumns",
                           "The Oxley solve's columns, in the row's order (models.force " +
                               force_models_where(&solves_oxley) + ", or models.deformation = oxley).",
                           result_keys(oxley_results()));
  for (const AnalyticModelInfo* m : models_with_columns())
    py += results_python_class(columns_class(m->name),
                               fmt::format("models.force = {}'s own columns, in the row's order.", m->name),
                               result_keys(m->orthogonal->results()));
  return py +
         results_python_class("TrepanningColumns",
                              "The columns of a trepanning prediction, in the row's order (the grit columns with "
                              "models.trepanning.grits).",
                              result_keys(trepanning_results())) +
         results_python_keys_function();
}

Columns prediction_columns(const AnalyticScene& scene, const Prediction& p) {
  ColumnCollector row;
  write_prediction_cells(scene, p, row);
  return std::move(row.columns);
}

}  // namespace kerf
