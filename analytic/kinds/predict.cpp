#include "kerf/analytic/kinds/predict.hpp"

#include <fmt/format.h>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "kerf/analytic/forces/chip_term.hpp"
#include "kerf/analytic/forces/critical_depth.hpp"
#include "kerf/analytic/forces/oxley_model.hpp"
#include "kerf/analytic/registry.hpp"
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
  const std::pair<const char*, double> results[] = {
      {"cutting_force_N", p.cutting_force_N},  {"thrust_force_N", p.thrust_force_N},
      {"shear_angle_deg", p.shear_angle_rad},  {"chip_thickness_um", p.chip_thickness_m},
      {"flow_stress_MPa", p.flow.total_Pa},    {"strain_rate_per_s", p.state.strain_rate_per_s},
      {"temperature_K", p.state.temperature_K}};
  for (const auto& [name, value] : results) {
    if (std::isfinite(value)) continue;
    throw ModelError("predict", fmt::format("{} is {} for cut.uncut_chip_thickness_um = {}, cut.width_mm = {}, "
                                            "cut.speed_m_per_min = {}: the inputs lie beyond what a double holds",
                                            name, value, format_value(units::m_to_um(scene.uncut_chip_thickness_m)),
                                            format_value(units::m_to_mm(scene.width_m)),
                                            format_value(units::m_per_s_to_m_per_min(scene.speed_m_per_s))));
  }
  if (!std::isfinite(p.cutting_force_N / units::m_to_mm(p.width_m)))
    throw ModelError("predict", fmt::format("cutting_force_N_per_mm is not finite for cut.width_mm = {}",
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

// The CSV's column list, in column order, one cell a line: the shared columns, then each unit's (the chip term's
// edge, the Oxley solve's, the force model's own), then the turning cut's and the verdicts.
void write_prediction_cells(const AnalyticScene& scene, const Prediction& p, CellWriter& w) {
  const double width_mm = units::m_to_mm(p.width_m);

  // The inputs, converted back from SI (CellWriter::input rounds them to 15 significant digits).
  w.text("force_model", p.force_model);
  w.text("material", scene.material->name);
  w.input("rake_deg", units::rad_to_deg(scene.rake_rad));
  w.input("edge_radius_um", units::m_to_um(scene.edge_radius_m));
  w.input("clearance_deg", units::rad_to_deg(scene.clearance_rad));
  w.input("speed_m_per_min", units::m_per_s_to_m_per_min(scene.speed_m_per_s));
  w.input("workpiece_temperature_K", scene.workpiece_temperature_K);
  w.optional_number("scene_friction_angle_deg", scene.friction_angle_rad.has_value(),
                    units::rad_to_deg(scene.friction_angle_rad.value_or(0.0)));
  w.input("uncut_chip_thickness_um", units::m_to_um(p.uncut_chip_thickness_m));
  w.input("width_mm", width_mm);
  w.number("cutting_force_N", p.cutting_force_N);
  w.number("thrust_force_N", p.thrust_force_N);
  // The ploughing part of the totals (zero where the model adds none; empty for Oxley, which ignores the edge).
  const bool chip_model = !scene.force_model().solves_oxley;
  const ForcePerWidth plough = p.ploughing ? p.ploughing->force : ForcePerWidth{};
  w.optional_number("ploughing_cutting_force_N", chip_model, plough.cutting_N_per_m * p.width_m);
  w.optional_number("ploughing_thrust_force_N", chip_model, plough.thrust_N_per_m * p.width_m);
  w.number("cutting_force_N_per_mm", p.cutting_force_N / width_mm);
  w.number("thrust_force_N_per_mm", p.thrust_force_N / width_mm);
  w.number("shear_angle_deg", units::rad_to_deg(p.shear_angle_rad));
  w.optional_number("friction_angle_deg", p.has_friction, units::rad_to_deg(p.friction_angle_rad));
  w.number("chip_ratio", p.chip_ratio);
  w.number("chip_thickness_um", units::m_to_um(p.chip_thickness_m));
  w.number("flow_stress_MPa", units::pa_to_mpa(p.flow.total_Pa));
  w.number("shear_flow_stress_MPa", units::pa_to_mpa(p.flow.shear_Pa));
  if (scene.flow_stress.johnson_cook) w.number("johnson_cook_stress_MPa", units::pa_to_mpa(p.flow.johnson_cook_Pa));
  if (scene.flow_stress.hall_petch) w.number("hall_petch_stress_MPa", units::pa_to_mpa(p.flow.hall_petch_Pa));
  if (scene.flow_stress.dislocation) w.number("dislocation_stress_MPa", units::pa_to_mpa(p.flow.dislocation_Pa));
  if (scene.flow_stress.hardness) w.number("hardness_flow_stress_MPa", units::pa_to_mpa(p.flow.hardness_Pa));
  w.number("strain", p.state.strain);
  w.number("strain_rate_per_s", p.state.strain_rate_per_s);
  w.number("temperature_K", p.state.temperature_K);
  for (std::size_t i = 0; i < scene.contact_lengths.size(); ++i) {
    const bool has = i < p.contact_lengths_m.size() && p.contact_lengths_m[i].second.has_value();
    w.optional_number(scene.contact_lengths[i].column, has, has ? units::m_to_mm(*p.contact_lengths_m[i].second) : 0.0);
  }
  // The columns follow the models the scene asked for ('auto' may choose differently point by point).
  if (scene.force_model().edge_columns || scene.force_auto) write_edge_cells(scene, p, w);  // chip_term.hpp
  if (scene.oxley.material || scene.force_auto) write_oxley_cells(p, w);                    // oxley_model.hpp
  if (scene.force_model().write_cells) scene.force_model().write_cells(scene, p, w);        // the model's own
  if (scene.turning) {
    w.number("feed_um_per_rev", units::m_to_um(scene.turning->geometry.feed_m_per_rev));
    w.number("depth_of_cut_um", units::m_to_um(scene.turning->geometry.depth_of_cut_m));
    w.number("maximum_chip_thickness_um", units::m_to_um(scene.turning->chip.maximum_thickness_m));
    w.number("equivalent_chip_thickness_um", units::m_to_um(scene.turning->chip.equivalent_thickness_m));
    w.number("engaged_edge_length_mm", units::m_to_mm(scene.turning->chip.engaged_edge_length_m));
  }
  w.optional_number("critical_depth_nm", scene.critical_depth_m.has_value(),
                    units::m_to_nm(scene.critical_depth_m.value_or(0.0)));
  w.text("regime", p.regime);
  w.text("within_model_range", p.within_model_range ? "yes" : "no");
  w.text("guards", p.guards.names());
  std::string warnings;
  for (const auto& w_text : p.warnings) warnings += (warnings.empty() ? "" : "; ") + w_text;
  w.text("warnings", warnings);
}

Columns prediction_columns(const AnalyticScene& scene, const Prediction& p) {
  ColumnCollector row;
  write_prediction_cells(scene, p, row);
  return std::move(row.columns);
}

}  // namespace kerf
