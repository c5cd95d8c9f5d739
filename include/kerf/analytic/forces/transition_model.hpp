#pragma once
// models.force = transition as a unit of the orthogonal kind (kinds/force_model.hpp): the ductile model (Liu-Li with
// an edge radius, Merchant without) at min(h, l), plus the fracture part above l (forces/transition.hpp, the
// physics); its parameters (the block transition_model_params), its details, its CSV columns and its report lines.
// Its registry line: analytic/registry.cpp.
//
//   kerf::Prediction p = kerf::predict(scene);            // scene.force_model() == transition_force_model
//   double l_m = kerf::transition_details(p)->ductile_layer_m;
#include "kerf/analytic/forces/merchant.hpp"
#include "kerf/analytic/forces/transition.hpp"
#include "kerf/analytic/kinds/force_model.hpp"
#include "kerf/analytic/kinds/model_params.hpp"
#include "kerf/field_table.hpp"

namespace kerf {

/// The two parts of the totals (docs/models.md).
struct TransitionDetails {
  double ductile_layer_m = 0.0;  ///< l = lambda d_c
  ForcePerWidth layer;           ///< the ductile model at min(h, l): the edge's part, depth-independent above l
  ForcePerWidth fracture;        ///< zero at and below l
};

extern const OrthogonalForceModel transition_force_model;

/// Its parameters' field tables: its key among the scene's `models` (fracture, a choice among the registry's
/// fracture lines), and the object models.transition (transition_fields(), forces/transition.hpp, where the physics
/// validates with it). The scene reads them, and `kerf-forces keys` lists them.
const FieldTable<TransitionParams>& transition_model_fields();
/// The block of those tables, which its registry line carries (scene.params<TransitionParams>()).
extern const ModelParams transition_model_params;

/// The details of a transition prediction; nullptr for a prediction of another model (or none yet).
const TransitionDetails* transition_details(const Prediction& p);

/// The keys of its own columns, one constant each (the identifier is the key).
namespace transition_keys {
KERF_RESULT_KEY(fracture_model)
KERF_RESULT_KEY(ductile_layer_um)
KERF_RESULT_KEY(layer_cutting_force_N)
KERF_RESULT_KEY(layer_thrust_force_N)
KERF_RESULT_KEY(fracture_cutting_force_N)
KERF_RESULT_KEY(fracture_thrust_force_N)
}  // namespace transition_keys

/// Its own CSV columns, in the row's order (zero before a prediction): its registry line carries them
/// (OrthogonalForceModel::results).
const ResultTable<PredictionReport>& transition_results();

}  // namespace kerf
