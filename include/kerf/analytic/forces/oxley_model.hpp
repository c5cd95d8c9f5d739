#pragma once
// models.force = oxley as a unit of the orthogonal kind (kinds/force_model.hpp), and the extended-Oxley solve a scene
// asks for (force oxley, or deformation oxley under another force model): the solve (forces/oxley.hpp, the physics)
// as a force model, its parameters and their field table (the block oxley_model_params), its details, its CSV
// columns and its report line. Its registry lines (force and deformation oxley): analytic/registry.cpp.
//
//   kerf::Prediction p = kerf::predict(scene);            // scene.force_model() == oxley_force_model
//   if (p.oxley) fmt::print("C0 = {}\n", p.oxley->strain_rate_constant_C0);
#include <cstdio>
#include <optional>

#include "kerf/analytic/flow_stress/flow_stress.hpp"
#include "kerf/analytic/forces/oxley.hpp"
#include "kerf/analytic/kinds/force_model.hpp"
#include "kerf/analytic/kinds/model_params.hpp"
#include "kerf/field_table.hpp"

namespace kerf {

/// A scene's Oxley parameters.
struct OxleyModelParams {
  /// The material's johnson_cook, thermal and oxley groups: read by the scene where its force or deformation model
  /// solves Oxley (none: the scene solves none).
  std::optional<OxleyParams> material;
  OxleySolverOptions solver;  ///< models.oxley_tolerance; the search ranges are the solver's own
};

/// Its keys among the scene's `models` (oxley_tolerance): the scene reads them, and `kerf-forces keys` lists them.
const FieldTable<OxleyModelParams>& oxley_model_fields();
/// The block of that table (scene.params<OxleyModelParams>()), carried by the registry's deformation line `oxley`.
extern const ModelParams oxley_model_params;

/// What a prediction keeps of the solve (Prediction::oxley): under force oxley and deformation oxley alike.
struct OxleyDetails {
  double strain_rate_constant_C0 = 0.0;
  double delta = 0.0;
  double interface_temperature_K = 0.0;
  double contact_length_m = 0.0;
  double residual = 0.0;      ///< the larger relative residual of the two Oxley conditions
  int shear_angle_roots = 0;  ///< branches found; the minimum-force one is reported
};

extern const OrthogonalForceModel oxley_force_model;

/// The extended-Oxley solve (sharp tool at t0) where the scene's force or deformation model needs it: its details,
/// guards and a warning for several branches go into `p`; nullopt where the scene asked for none. An input the
/// solver refuses names the scene's key; a solve without a physical solution is a ModelError.
std::optional<OxleyResult> solve_scene_oxley(const AnalyticScene& scene, Prediction& p);

/// The zone-AB state of a solve: where deformation oxley evaluates the flow stress.
DeformationState shear_plane_state_of(const OxleyResult& oxley);

/// The keys of the solve's columns, one constant each (the identifier is the key).
namespace oxley_keys {
KERF_RESULT_KEY(strain_rate_constant_C0)
KERF_RESULT_KEY(secondary_zone_ratio_delta)
KERF_RESULT_KEY(interface_temperature_K)
KERF_RESULT_KEY(contact_length_oxley_mm)
KERF_RESULT_KEY(oxley_residual)
KERF_RESULT_KEY(oxley_shear_angle_roots)
}  // namespace oxley_keys

/// The solve's CSV columns, in the row's order (null, an empty cell, where the prediction has no solve): the kind
/// writes them where the scene solves Oxley or chooses its force model point by point (kinds/predict.hpp,
/// prediction_model_results).
const ResultTable<PredictionReport>& oxley_results();
/// Its line of the text report, where the prediction has a solve.
void print_oxley_details(std::FILE* text, const AnalyticScene& scene, const Prediction& p);

}  // namespace kerf
