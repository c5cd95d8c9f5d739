#include "kerf/analytic/kinds/predict.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "kerf/analytic/forces/critical_depth.hpp"
#include "kerf/analytic/forces/merchant.hpp"
#include "kerf/analytic/registry.hpp"
#include "kerf/error.hpp"
#include "kerf/io.hpp"
#include "kerf/units.hpp"

namespace kerf {

namespace {

// Oxley's strain-rate constant C0 lies in 2-10 (Oxley 1989); its middle is used to estimate the primary-zone
// strain rate when the scene neither gives one nor asks for an Oxley solve.
constexpr double kTypicalStrainRateConstant = 5.0;
// Berezvai et al. 2019 validated the contact-length models for A2024-T351 up to h = 0.1 mm (chip segmentation
// above); the limit is that material's, so the warning is too.
constexpr double kContactLengthValidatedThickness_m = 0.1e-3;
constexpr const char* kContactLengthValidatedMaterial = "a2024_t351";
// Two friction angles closer than this are the same (rounding of the closures' identities).
constexpr double kSameAngle_rad = 1e-9;

/// Shear-plane strain and Oxley's strain-rate estimate for a sharp tool (physics-analytic.md §3).
DeformationState shear_plane_state(const AnalyticScene& scene, double shear_angle_rad) {
  const double a = scene.rake_rad, phi = shear_angle_rad;
  const double shear_strain = std::cos(a) / (std::sin(phi) * std::cos(phi - a));
  DeformationState state;
  state.strain = shear_strain / std::sqrt(3.0);
  if (scene.given_strain_rate_per_s) {
    state.strain_rate_per_s = *scene.given_strain_rate_per_s;
  } else {
    const double shear_velocity = scene.speed_m_per_s * std::cos(a) / std::cos(phi - a);
    const double shear_plane_length = scene.uncut_chip_thickness_m / std::sin(phi);
    state.strain_rate_per_s = kTypicalStrainRateConstant * shear_velocity / shear_plane_length / std::sqrt(3.0);
  }
  state.temperature_K = scene.workpiece_temperature_K;
  return state;
}

void check_shear_angle(double phi, const AnalyticScene& scene) {
  if (phi > 0.0 && phi < std::numbers::pi / 2.0) return;
  const char* model = scene.shear_angle == ShearAngleSource::merchant      ? "merchant"
                      : scene.shear_angle == ShearAngleSource::lee_shaffer ? "lee_shaffer"
                                                                           : "chip_ratio";
  throw InputError("models.shear_angle", model,
                   fmt::format("a model giving a shear angle in (0, 90) deg; it gives {:.3g} deg for rake {:.3g} deg "
                               "and friction angle {:.3g} deg (friction minus rake too large: lower the friction or "
                               "give a measured cut.chip_ratio)",
                               units::rad_to_deg(phi), units::rad_to_deg(scene.rake_rad),
                               units::rad_to_deg(scene.friction_angle_rad.value_or(0.0))));
}

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
      p.warnings.push_back(fmt::format("uncut chip thickness {:.4g} um is beyond {:.3g} um, the deepest cut the "
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

DeformationState shear_plane_state_of(const OxleyResult& oxley) {
  return {oxley.shear_plane_strain, oxley.shear_plane_strain_rate_per_s, oxley.shear_plane_temperature_K};
}

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

/// The friction angle of a Merchant or Liu-Li prediction: the friction closure's beta at the nominal rake and
/// shear angle (the scene's beta for the constant closure; with the matching shear-angle rule the closures give
/// it back). A closure that implies beta < 0 (friction pulling the chip down the rake face: a chip ratio or
/// shear-angle rule the closure cannot match) is refused, naming what set the shear angle.
double prediction_friction_angle(const AnalyticScene& scene, double shear_angle_rad) {
  const double given = scene.friction_angle_rad.value_or(0.0);
  const double beta = local_friction_angle(scene.liu_li.closure, given, scene.rake_rad, shear_angle_rad);
  if (scene.liu_li.closure == FrictionClosure::constant) return beta;
  const std::string closure(friction_closure_name(scene.liu_li.closure));
  if (beta < 0.0) {
    const bool measured = scene.shear_angle == ShearAngleSource::chip_ratio;
    throw InputError(measured ? "cut.chip_ratio" : "models.friction_closure",
                     measured ? format_value(*scene.chip_ratio) : closure,
                     fmt::format("a shear angle and friction closure giving a friction angle >= 0: shear angle {:.4g} "
                                 "deg with the {} closure at rake {:.4g} deg gives beta = {:.4g} deg (the friction "
                                 "would pull the chip down the rake face)",
                                 units::rad_to_deg(shear_angle_rad), closure, units::rad_to_deg(scene.rake_rad),
                                 units::rad_to_deg(beta)));
  }
  return beta;
}

/// The ploughing model's friction factor: the scene's cut.friction_factor, else sin(2 beta) from the prediction's
/// one friction angle (Lee & Shaffer 1951; 0 for beta <= 0, 1, sticking, for beta >= 45 deg).
double ploughing_friction_factor(const AnalyticScene& scene, double friction_angle_rad) {
  return scene.friction_factor ? *scene.friction_factor : friction_factor_from_friction_angle(friction_angle_rad);
}

/// The sharp-tool models (Merchant, Oxley) ignore the edge: say so when it is not small against t0.
void warn_if_edge_ignored(const AnalyticScene& scene, const char* model_and_remedy, Prediction& p) {
  const double ratio = scene.edge_radius_m / scene.uncut_chip_thickness_m;
  if (ratio <= kSharpEdgeRatio) return;
  p.warnings.push_back(
      fmt::format("edge radius is {:.0f} % of the uncut chip thickness: {}", 100.0 * ratio, model_and_remedy));
}

/// Extended Oxley without a physical solution is a model failure (ModelError, exit 3) naming why: the solver's
/// nearest state (a condition not met, phi or delta on a bound of its range, a zone at the melting temperature)
/// is not a prediction. solve_oxley itself returns that state with its guards, for studies of the equations.
void refuse_unphysical_oxley(const OxleyResult& r, const OxleyParams& params, const OxleySolverOptions& options) {
  std::vector<std::string> why;
  if (!r.converged) {
    why.push_back(fmt::format("no exact solution in the search ranges (relative residuals {:.2g} and {:.2g})",
                              r.residual_shear, r.residual_normal));
  }
  if (r.shear_angle_at_bound) {
    why.push_back(fmt::format("phi at its bound ({:.4g} deg; search range {:.4g}-{:.4g} deg)",
                              units::rad_to_deg(r.shear_angle_rad), units::rad_to_deg(options.phi_min_rad),
                              units::rad_to_deg(options.phi_max_rad)));
  }
  if (r.delta_at_bound) {
    why.push_back(fmt::format("delta at its bound ({:.4g}; range {:.4g}-{:.4g}): the minimum of F_c lies outside",
                              r.delta, options.delta_min, options.delta_max));
  }
  const double melt_K = params.johnson_cook.melting_temperature_K;
  if (r.interface_temperature_K >= melt_K || r.shear_plane_temperature_K >= melt_K) {
    why.push_back(fmt::format("temperature at melting (interface {:.5g} K, shear zone {:.5g} K, T_melt {:.5g} K)",
                              r.interface_temperature_K, r.shear_plane_temperature_K, melt_K));
  }
  if (why.empty()) return;
  std::string reason = "no physical solution for this cut: ";
  for (std::size_t i = 0; i < why.size(); ++i) reason += (i ? "; " : "") + why[i];
  throw ModelError("oxley", reason);
}

/// models.force = oxley: forces, shear angle and friction angle are Oxley's own; the flow stress reported is
/// the Johnson-Cook stress in zone AB.
void predict_oxley_forces(const AnalyticScene& scene, const OxleyResult* solved, Prediction& p) {
  const OxleyResult& oxley = *solved;  // the scene solves Oxley for this model (oxley_force_model.solves_oxley)
  p.cutting_force_N = oxley.cutting_force_N;
  p.thrust_force_N = oxley.thrust_force_N;
  p.shear_angle_rad = oxley.shear_angle_rad;
  p.friction_angle_rad = oxley.friction_angle_rad;  // Oxley's own lambda, whatever the scene gave
  p.has_friction = true;
  p.chip_thickness_m = oxley.chip_thickness_m;
  p.chip_ratio = scene.uncut_chip_thickness_m / oxley.chip_thickness_m;
  p.state = shear_plane_state_of(oxley);
  p.flow.johnson_cook_Pa = p.flow.total_Pa = oxley.shear_plane_flow_stress_Pa;
  p.flow.shear_Pa = oxley.shear_plane_shear_stress_Pa;
  warn_if_edge_ignored(scene, "extended Oxley assumes a sharp tool (use models.force = liu_li with deformation = oxley)",
                       p);
  if (scene.friction_angle_rad && std::fabs(*scene.friction_angle_rad - oxley.friction_angle_rad) > kSameAngle_rad) {
    p.warnings.push_back(fmt::format("extended Oxley predicts its own friction angle {:.4g} deg; the scene's {:.4g} deg "
                                     "({}) is not used",
                                     units::rad_to_deg(oxley.friction_angle_rad),
                                     units::rad_to_deg(*scene.friction_angle_rad), scene.friction_origin));
  }
  add_contact_lengths(scene, p.friction_angle_rad, p);
}

/// The extended-Oxley solve (sharp tool at t0) when the scene's force or deformation model needs it: its
/// details, guards and a warning for several branches go into `p`; nullopt when the scene asked for none.
std::optional<OxleyResult> solve_scene_oxley(const AnalyticScene& scene, Prediction& p) {
  if (!scene.oxley) return std::nullopt;
  const OxleyCut cut{.rake_rad = scene.rake_rad,
                     .uncut_chip_thickness_m = scene.uncut_chip_thickness_m,
                     .width_m = scene.width_m,
                     .speed_m_per_s = scene.speed_m_per_s,
                     .workpiece_temperature_K = scene.workpiece_temperature_K};
  OxleyResult oxley = solve_oxley(*scene.oxley, cut, scene.oxley_options);
  refuse_unphysical_oxley(oxley, *scene.oxley, scene.oxley_options);
  p.guards.merge(oxley.guards);
  p.oxley = OxleyDetails{oxley.strain_rate_constant_C0, oxley.delta, oxley.interface_temperature_K,
                         oxley.contact_length_m, std::max(oxley.residual_shear, oxley.residual_normal),
                         oxley.shear_angle_roots};
  if (oxley.shear_angle_roots > 1) {
    p.warnings.push_back(fmt::format("extended Oxley: {} solutions in the shear angle; the minimum-force branch "
                                     "(phi = {:.4g} deg) is reported",
                                     oxley.shear_angle_roots, units::rad_to_deg(oxley.shear_angle_rad)));
  }
  return oxley;
}

/// The nominal shear angle and chip ratio of a Merchant or Liu-Li prediction (from the chip ratio, or the
/// scene's shear-angle rule), checked, with the chip thickness.
void nominal_shear_angle(const AnalyticScene& scene, Prediction& p) {
  if (scene.shear_angle == ShearAngleSource::chip_ratio) {
    p.chip_ratio = *scene.chip_ratio;
    p.shear_angle_rad = shear_angle_from_chip_ratio(p.chip_ratio, scene.rake_rad);
  } else {
    const auto model =
        scene.shear_angle == ShearAngleSource::merchant ? ShearAngleModel::merchant : ShearAngleModel::lee_shaffer;
    p.shear_angle_rad = shear_angle(model, scene.rake_rad, scene.friction_angle_rad.value_or(0.0));
    p.chip_ratio = chip_ratio_from_shear_angle(p.shear_angle_rad, scene.rake_rad);
  }
  check_shear_angle(p.shear_angle_rad, scene);
  p.chip_thickness_m = scene.uncut_chip_thickness_m / p.chip_ratio;
}

/// The deformation state the flow stress is evaluated at, by models.deformation.
DeformationState deformation_state(const AnalyticScene& scene, const OxleyResult* oxley, double shear_angle_rad) {
  switch (scene.deformation) {
    case DeformationModel::given: return *scene.given_state;
    case DeformationModel::room_temperature: return shear_plane_state(scene, shear_angle_rad);
    case DeformationModel::oxley: return shear_plane_state_of(*oxley);
  }
  return {};
}

void predict_merchant_forces(const AnalyticScene& scene, const OxleyResult* oxley, Prediction& p) {
  predict_chip_forces(scene, oxley, true, p);
}

void predict_liu_li_forces(const AnalyticScene& scene, const OxleyResult* oxley, Prediction& p) {
  predict_chip_forces(scene, oxley, false, p);
}

/// models.force = auto: the cheapest valid model for the scene as read.
std::string_view choose_force_model(const AnalyticScene& scene, std::string* reason) {
  if (!scene.friction_angle_rad && scene.shear_angle != ShearAngleSource::chip_ratio &&
      scene.material->group("johnson_cook")) {
    *reason = "no friction data: only oxley predicts without it";
    return "oxley";
  }
  if (scene.edge_radius_m < kSharpEdgeRatio * scene.uncut_chip_thickness_m) {
    *reason = "edge radius below 5 % of the uncut chip thickness: sharp-tool model";
    return "merchant";
  }
  *reason = "edge radius at least 5 % of the uncut chip thickness: edge-radius model";
  return "liu_li";
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
  const std::pair<const char*, double> results[] = {{"cutting_force_N", p.cutting_force_N},
                                                    {"thrust_force_N", p.thrust_force_N},
                                                    {"shear_angle_deg", p.shear_angle_rad},
                                                    {"chip_thickness_um", p.chip_thickness_m},
                                                    {"flow_stress_MPa", p.flow.total_Pa},
                                                    {"strain_rate_per_s", p.state.strain_rate_per_s},
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

// The chip term the Merchant, Liu-Li and transition units share (force_model.hpp); Merchant is its r = 0 limit,
// without the edge details.
void predict_chip_forces(const AnalyticScene& scene, const OxleyResult* oxley, bool sharp, Prediction& p) {
  const double t0 = scene.uncut_chip_thickness_m;
  nominal_shear_angle(scene, p);

  // One friction angle for the whole prediction: the closure's value at the nominal rake (the scene's beta for
  // the constant closure). It sets the rake-face force, the stagnation angle, the contact lengths and the
  // printed value, for Merchant and Liu-Li alike, so that Liu-Li's r -> 0 limit is Merchant on the same scene.
  const double beta = prediction_friction_angle(scene, p.shear_angle_rad);
  p.friction_angle_rad = beta;
  p.has_friction = true;

  p.state = deformation_state(scene, oxley, p.shear_angle_rad);
  p.flow = flow_stress(scene.flow_stress, p.state, &p.guards);
  const double k_s = p.flow.shear_Pa;

  LiuLiParams params = scene.liu_li;
  params.rake_rad = scene.rake_rad;
  params.edge_radius_m = sharp ? 0.0 : scene.edge_radius_m;  // Merchant: r = 0
  params.chip_ratio = p.chip_ratio;
  params.friction_angle_rad = beta;
  const LiuLiResult liu_li = liu_li_force_per_width(params, k_s, t0, &p.guards);
  if (sharp) {
    warn_if_edge_ignored(scene, "the sharp-tool model ignores it (use models.force = liu_li)", p);
  } else {
    p.liu_li = liu_li;
  }
  if (liu_li.rake_face_ploughs) {
    p.warnings.push_back(fmt::format("rake {:.4g} deg lies below the {} cut-off {:.4g} deg: no chip forms, the whole "
                                     "cut is ploughed (chip force zero)",
                                     units::rad_to_deg(scene.rake_rad),
                                     lower_limit_rule_name(scene.liu_li.lower_limit),
                                     units::rad_to_deg(liu_li.cut_off_rad)));
  }
  // The ploughing term under the edge: the wave model on the chord of the arc below h_p = min(t0, h_s).
  ForcePerWidth ploughing;
  if (p.liu_li && scene.ploughing == PloughingModel::wave && params.edge_radius_m > 0.0) {
    p.friction_factor = ploughing_friction_factor(scene, beta);
    const EdgePloughingParams plough{.edge_radius_m = params.edge_radius_m, .friction_factor = p.friction_factor};
    p.ploughing = edge_ploughing_force_per_width(plough, k_s, liu_li.ploughed_thickness_m, &p.guards);
    ploughing = p.ploughing->force;
  }
  p.cutting_force_N = (liu_li.total.cutting_N_per_m + ploughing.cutting_N_per_m) * scene.width_m;
  p.thrust_force_N = (liu_li.total.thrust_N_per_m + ploughing.thrust_N_per_m) * scene.width_m;

  if (scene.friction_angle_rad && std::fabs(beta - *scene.friction_angle_rad) > kSameAngle_rad) {
    p.warnings.push_back(fmt::format(
        "the {} friction closure at the nominal rake gives beta = {:.4g} deg with this shear angle ({}); it is used "
        "for the forces, the stagnation angle and the contact lengths, not the scene's {:.4g} deg ({})",
        friction_closure_name(scene.liu_li.closure), units::rad_to_deg(beta),
        scene.shear_angle == ShearAngleSource::chip_ratio ? "from cut.chip_ratio" : "from models.shear_angle",
        units::rad_to_deg(*scene.friction_angle_rad), scene.friction_origin));
  }
  add_contact_lengths(scene, beta, p);
}

// The built-in force models, as their registry lines (analytic/registry.cpp) carry them.
const OrthogonalForceModel merchant_force_model{.predict = &predict_merchant_forces};
const OrthogonalForceModel liu_li_force_model{.predict = &predict_liu_li_forces, .edge_columns = true};
const OrthogonalForceModel oxley_force_model{.predict = &predict_oxley_forces, .solves_oxley = true};
const OrthogonalForceModel auto_force_model{.choose = &choose_force_model};

Prediction predict(const AnalyticScene& scene) {
  Prediction p = predict_forces(scene);
  require_finite(scene, p);
  return p;
}

// Long (~85 lines) for a reason: the CSV's column list, in column order, one cell a line; split, the order would be
// spread over functions.
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
    w.optional_number(scene.contact_lengths[i].column, has,
                      has ? units::m_to_mm(*p.contact_lengths_m[i].second) : 0.0);
  }
  // The columns follow the models the scene asked for ('auto' may choose differently point by point).
  if (scene.force_model().edge_columns || scene.force_auto) {
    const bool has = p.liu_li.has_value();
    const LiuLiResult l = p.liu_li.value_or(LiuLiResult{});
    w.text("friction_closure", friction_closure_name(scene.liu_li.closure));
    w.text("lower_limit_rule", lower_limit_rule_name(scene.liu_li.lower_limit));
    w.optional_number("lower_limit_deg", has, units::rad_to_deg(l.lower_limit_rad));
    w.optional_number("upper_limit_deg", has, units::rad_to_deg(l.upper_limit_rad));
    w.optional_number("stagnation_angle_deg", has, units::rad_to_deg(l.stagnation_angle_rad));
    w.optional_number("pole_deg", has && l.pole_rad, units::rad_to_deg(l.pole_rad.value_or(0.0)));
    w.optional_number("ploughed_thickness_um", has, units::m_to_um(l.ploughed_thickness_m));
    w.optional_number("edge_cutting_force_N", has, l.edge.cutting_N_per_m * p.width_m);
    w.optional_number("edge_thrust_force_N", has, l.edge.thrust_N_per_m * p.width_m);
    w.text("ploughing_model", ploughing_model_name(scene.ploughing));
    const bool ploughs = p.ploughing.has_value();
    w.optional_number("friction_factor", ploughs, p.friction_factor);
    w.optional_number("ploughing_attack_angle_deg", ploughs,
                      units::rad_to_deg(p.ploughing.value_or(EdgePloughingResult{}).factors.attack_angle_rad));
  }
  if (scene.oxley || scene.force_auto) {
    const bool has = p.oxley.has_value();
    const OxleyDetails o = p.oxley.value_or(OxleyDetails{});
    w.optional_number("strain_rate_constant_C0", has, o.strain_rate_constant_C0);
    w.optional_number("secondary_zone_ratio_delta", has, o.delta);
    w.optional_number("interface_temperature_K", has, o.interface_temperature_K);
    w.optional_number("contact_length_oxley_mm", has, units::m_to_mm(o.contact_length_m));
    w.optional_number("oxley_residual", has, o.residual);
    w.optional_number("oxley_shear_angle_roots", has, o.shear_angle_roots);
  }
  if (scene.force_model().write_cells) scene.force_model().write_cells(scene, p, w);  // the model's own
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
