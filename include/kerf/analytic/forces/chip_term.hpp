#pragma once
// models.force = merchant and liu_li as units of the orthogonal kind (kinds/force_model.hpp): the chip term of the
// Liu-Li integral (forces/liu_li.hpp, the physics; Merchant is its r = 0 limit) plus the wave model's ploughing term
// under a rounded edge (forces/ploughing.hpp), which the transition model runs for its ductile layer. The unit owns
// their parameters (the friction closure, the lower limit, the ploughing model, models.quadrature) with their field
// tables (the block chip_term_params, kinds/model_params.hpp), the edge's details (ChipTermDetails, kept in
// Prediction::chip_term), its CSV columns and report lines. Their registry lines: analytic/registry.cpp.
//
//   kerf::Prediction p = kerf::predict(scene);            // scene.force_model() == liu_li_force_model
//   double h_s = p.chip_term.liu_li->ploughed_thickness_m;
#include <cstdio>
#include <optional>

#include "kerf/analytic/forces/liu_li.hpp"
#include "kerf/analytic/forces/ploughing.hpp"
#include "kerf/analytic/forces/quadrature.hpp"
#include "kerf/analytic/kinds/force_model.hpp"
#include "kerf/analytic/kinds/model_params.hpp"
#include "kerf/field_table.hpp"

namespace kerf {

/// The chip term's parameters in a scene.
struct ChipTermParams {
  LiuLiParams liu_li;  ///< closure, lower limit, margin and quadrature (the geometry is filled at each prediction)
  PloughingModel ploughing = PloughingModel::wave;  ///< the force under the edge below the stagnation point
};

/// Its keys among the scene's `models` (friction_closure, lower_limit, ploughing, lower_limit_margin_deg) and the
/// object models.quadrature: the scene reads them, and `kerf-forces keys` lists them.
const FieldTable<ChipTermParams>& chip_term_fields();
const FieldTable<QuadratureSettings>& quadrature_fields();
/// The block of those tables, which the merchant and liu_li lines carry (scene.params<ChipTermParams>()).
extern const ModelParams chip_term_params;

/// The chip term's details in a prediction (Prediction::chip_term): its columns and report lines, and the kind's
/// shared ploughing columns, read them.
struct ChipTermDetails {
  std::optional<LiuLiResult> liu_li;  ///< the edge integral (its total is the chip force alone); none: Merchant
  /// The ploughing term under the edge (models.ploughing = wave with an edge radius): added to the chip term in the
  /// prediction's cutting_force_N and thrust_force_N.
  std::optional<EdgePloughingResult> ploughing;
  double friction_factor = 0.0;  ///< the ploughing model's f (given, or sin(2 beta)), with `ploughing`
};

extern const OrthogonalForceModel merchant_force_model, liu_li_force_model;

/// The chip term the Merchant, Liu-Li and transition units share, with the ploughing term under a rounded edge;
/// `sharp`: Merchant, the r = 0 limit, without the edge's details.
void predict_chip_forces(const AnalyticScene& scene, const OxleyResult* oxley, bool sharp, Prediction& p);

/// The keys of the edge's columns, one constant each (the identifier is the key).
namespace edge_keys {
KERF_RESULT_KEY(friction_closure)
KERF_RESULT_KEY(lower_limit_rule)
KERF_RESULT_KEY(lower_limit_deg)
KERF_RESULT_KEY(upper_limit_deg)
KERF_RESULT_KEY(stagnation_angle_deg)
KERF_RESULT_KEY(pole_deg)
KERF_RESULT_KEY(ploughed_thickness_um)
KERF_RESULT_KEY(edge_cutting_force_N)
KERF_RESULT_KEY(edge_thrust_force_N)
KERF_RESULT_KEY(ploughing_model)
KERF_RESULT_KEY(friction_factor)
KERF_RESULT_KEY(ploughing_attack_angle_deg)
}  // namespace edge_keys

/// The edge integral's and the ploughing term's CSV columns, in the row's order (null, an empty cell, where the
/// prediction has no edge or no ploughing term): the kind writes them for a model that carries them
/// (OrthogonalForceModel::edge_columns) and under `auto` (kinds/predict.hpp, prediction_model_results).
const ResultTable<PredictionReport>& edge_results();
/// The edge integral's lines and the ploughing part's of the text report, where the prediction has an edge.
void print_edge_details(std::FILE* text, const AnalyticScene& scene, const Prediction& p);

}  // namespace kerf
