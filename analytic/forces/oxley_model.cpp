#include "kerf/analytic/forces/oxley_model.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "kerf/analytic/kinds/cells.hpp"
#include "kerf/analytic/kinds/model_fields.hpp"
#include "kerf/analytic/kinds/predict.hpp"
#include "kerf/analytic/kinds/scene_keys.hpp"
#include "kerf/error.hpp"
#include "kerf/units.hpp"

namespace kerf {

namespace {

constexpr FieldUnit kMPerMin{"m/min", units::m_per_min_to_m_per_s, units::m_per_s_to_m_per_min};

// The OxleyCut's members (solve_oxley names them under its argument `cut`) and the scene's keys that set them.
constexpr SceneKeyOf kSceneKeys[] = {{"cut.uncut_chip_thickness_m", "cut.uncut_chip_thickness_um", units::kUm, "m"},
                                     {"cut.width_m", "cut.width_mm", units::kMm, "m"},
                                     {"cut.speed_m_per_s", "cut.speed_m_per_min", kMPerMin, "m/s"},
                                     {"cut.workpiece_temperature_K", "cut.workpiece_temperature_K", units::kNone, ""}};

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
  warn_if_edge_ignored(scene,
                       "extended Oxley assumes a sharp tool (use models.force = liu_li with deformation = oxley)", p);
  if (scene.friction_angle_rad && std::fabs(*scene.friction_angle_rad - oxley.friction_angle_rad) > kSameAngle_rad) {
    p.warnings.push_back(
        fmt::format("extended Oxley predicts its own friction angle {:.4g} deg; the scene's {:.4g} deg "
                    "({}) is not used",
                    units::rad_to_deg(oxley.friction_angle_rad), units::rad_to_deg(*scene.friction_angle_rad),
                    scene.friction_origin));
  }
  add_contact_lengths(scene, p.friction_angle_rad, p);
}

}  // namespace

const FieldTable<OxleyModelParams>& oxley_model_fields() {
  static const FieldTable<OxleyModelParams> table{number_at<OxleyModelParams>(
      "oxley_tolerance", units::kSi("(relative)"), Range::closed(1e-15, 1e-2),
      "relative tolerance of the extended-Oxley solver", [](auto& s) -> auto& { return s.solver.tolerance; })};
  return table;
}

const ModelParams oxley_model_params{.fields = [] { return scene_params_fields(oxley_model_fields()); }};

const OrthogonalForceModel oxley_force_model{.predict = &predict_oxley_forces, .solves_oxley = true};

DeformationState shear_plane_state_of(const OxleyResult& oxley) {
  return {oxley.shear_plane_strain, oxley.shear_plane_strain_rate_per_s, oxley.shear_plane_temperature_K};
}

std::optional<OxleyResult> solve_scene_oxley(const AnalyticScene& scene, Prediction& p) {
  const OxleyModelParams& solve = scene.params<OxleyModelParams>();
  if (!solve.material) return std::nullopt;
  const OxleyParams& params = *solve.material;
  const OxleySolverOptions& options = solve.solver;
  const OxleyCut cut{.rake_rad = scene.rake_rad,
                     .uncut_chip_thickness_m = scene.uncut_chip_thickness_m,
                     .width_m = scene.width_m,
                     .speed_m_per_s = scene.speed_m_per_s,
                     .workpiece_temperature_K = scene.workpiece_temperature_K};
  OxleyResult oxley = naming_scene_keys(kSceneKeys, [&] { return solve_oxley(params, cut, options); });
  refuse_unphysical_oxley(oxley, params, options);
  p.guards.merge(oxley.guards);
  p.oxley = OxleyDetails{oxley.strain_rate_constant_C0,
                         oxley.delta,
                         oxley.interface_temperature_K,
                         oxley.contact_length_m,
                         std::max(oxley.residual_shear, oxley.residual_normal),
                         oxley.shear_angle_roots};
  if (oxley.shear_angle_roots > 1) {
    p.warnings.push_back(
        fmt::format("extended Oxley: {} solutions in the shear angle; the minimum-force branch "
                    "(phi = {:.4g} deg) is reported",
                    oxley.shear_angle_roots, units::rad_to_deg(oxley.shear_angle_rad)));
  }
  return oxley;
}

const ResultTable<PredictionReport>& oxley_results() {
  namespace k = oxley_keys;
  using R = PredictionReport;
  const auto solved = [](const R& r) { return r.p.oxley.has_value(); };
  static const ResultTable<R> table{
      result_or_null<R>(k::strain_rate_constant_C0, "", "Oxley's strain-rate constant C0 of the solve", solved,
                        [](const R& r) { return r.p.oxley->strain_rate_constant_C0; }),
      result_or_null<R>(k::secondary_zone_ratio_delta, "", "the secondary zone's thickness ratio delta", solved,
                        [](const R& r) { return r.p.oxley->delta; }),
      result_or_null<R>(k::interface_temperature_K, "K", "the tool-chip interface temperature", solved,
                        [](const R& r) { return r.p.oxley->interface_temperature_K; }),
      result_or_null<R>(k::contact_length_oxley_mm, "mm", "the tool-chip contact length of the solve", solved,
                        [](const R& r) { return units::m_to_mm(r.p.oxley->contact_length_m); }),
      result_or_null<R>(k::oxley_residual, "", "the larger relative residual of the two Oxley conditions", solved,
                        [](const R& r) { return r.p.oxley->residual; }),
      result_or_null<R>(k::oxley_shear_angle_roots, "",
                        "the branches found in the shear angle (the minimum-force one is reported)", solved,
                        [](const R& r) { return static_cast<double>(r.p.oxley->shear_angle_roots); })};
  return table;
}

void print_oxley_details(std::FILE* text, const AnalyticScene& scene, const Prediction& p) {
  namespace k = oxley_keys;
  if (!p.oxley) return;
  // The numbers as the CSV row holds them (oxley_results).
  const PredictionReport report{scene, p};
  const auto value = [&report](std::string_view key) { return result_of(oxley_results(), report, key).get<double>(); };
  fmt::print(text, "oxley             C0 = {:.4g}, delta = {:.4g}, interface T = {:.5g} K, contact length {:.6g} mm\n",
             value(k::strain_rate_constant_C0), value(k::secondary_zone_ratio_delta), value(k::interface_temperature_K),
             value(k::contact_length_oxley_mm));
}

}  // namespace kerf
