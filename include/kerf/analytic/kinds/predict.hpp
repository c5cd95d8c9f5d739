#pragma once
// Runs the models a scene names and gathers one prediction: forces for the scene's width, the state the
// flow stress was evaluated at, contact lengths, the Liu-Li or Oxley details, guards and validity warnings.
//
//   kerf::Prediction p = kerf::predict(scene);
//   auto row = kerf::prediction_columns(scene, p);   // [("cutting_force_N", "12.5"), ...] for CSV
#include <any>
#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "kerf/analytic/flow_stress/flow_stress.hpp"
#include "kerf/analytic/forces/chip_term.hpp"
#include "kerf/analytic/forces/oxley_model.hpp"
#include "kerf/analytic/guards.hpp"
#include "kerf/analytic/kinds/cells.hpp"
#include "kerf/analytic/kinds/scene.hpp"
#include "kerf/result_table.hpp"

namespace kerf {

struct Prediction {
  std::string_view force_model;  ///< the name of the force model that ran (its registry line's)
  double cutting_force_N = 0.0;
  double thrust_force_N = 0.0;
  double width_m = 0.0;
  double uncut_chip_thickness_m = 0.0;
  double shear_angle_rad = 0.0;
  /// The one friction angle of the prediction: Oxley's lambda, or the friction closure's beta at the nominal rake
  /// (the scene's for the constant closure); it sets the forces, stagnation angle and contact lengths.
  double friction_angle_rad = 0.0;
  bool has_friction = false;
  double chip_ratio = 0.0;
  double chip_thickness_m = 0.0;
  DeformationState state;
  FlowStress flow;
  /// (column, value); no value where the model is not applicable (Guard::contact_length_not_applicable)
  std::vector<std::pair<std::string, std::optional<double>>> contact_lengths_m;
  // The details of the two units that several force models run, each declared and written by its unit (its columns
  // and report lines), kept here because no one force model owns them: the chip term's, which merchant, liu_li, the
  // transition model (its layer) and auto's choice run, and whose ploughing part the shared columns
  // ploughing_*_force_N read; and the Oxley solve's, which force oxley and deformation oxley under any force model
  // run (predict solves it before the force model).
  ChipTermDetails chip_term;          ///< forces/chip_term.hpp
  std::optional<OxleyDetails> oxley;  ///< forces/oxley_model.hpp
  /// The force model's own details (its unit's write_cells and print read them: kinds/force_model.hpp).
  std::any details;
  std::string regime;  ///< "ductile", "transition" or "brittle" against the critical depth; empty without one
  /// False where the force model does not hold (a ductile model above d_c; transition beyond 0.2 mm): the CSV's
  /// within_model_range, the figures' hollow points.
  bool within_model_range = true;
  Guards guards;
  std::vector<std::string> warnings;
};

/// Throws InputError for input the models cannot accept and ModelError when a solver fails.
Prediction predict(const AnalyticScene& scene);

/// The keys of an orthogonal prediction's row (its CSV, kerf.predict's dict) and report: one constant each.
namespace prediction_keys {
KERF_RESULT_KEY(force_model)
KERF_RESULT_KEY(material)
KERF_RESULT_KEY(rake_deg)
KERF_RESULT_KEY(edge_radius_um)
KERF_RESULT_KEY(clearance_deg)
KERF_RESULT_KEY(speed_m_per_min)
KERF_RESULT_KEY(workpiece_temperature_K)
KERF_RESULT_KEY(scene_friction_angle_deg)
KERF_RESULT_KEY(uncut_chip_thickness_um)
KERF_RESULT_KEY(width_mm)
KERF_RESULT_KEY(cutting_force_N)
KERF_RESULT_KEY(thrust_force_N)
KERF_RESULT_KEY(ploughing_cutting_force_N)
KERF_RESULT_KEY(ploughing_thrust_force_N)
KERF_RESULT_KEY(cutting_force_N_per_mm)
KERF_RESULT_KEY(thrust_force_N_per_mm)
KERF_RESULT_KEY(shear_angle_deg)
KERF_RESULT_KEY(friction_angle_deg)
KERF_RESULT_KEY(chip_ratio)
KERF_RESULT_KEY(chip_thickness_um)
KERF_RESULT_KEY(flow_stress_MPa)
KERF_RESULT_KEY(shear_flow_stress_MPa)
KERF_RESULT_KEY(johnson_cook_stress_MPa)
KERF_RESULT_KEY(hall_petch_stress_MPa)
KERF_RESULT_KEY(dislocation_stress_MPa)
KERF_RESULT_KEY(hardness_flow_stress_MPa)
KERF_RESULT_KEY(strain)
KERF_RESULT_KEY(strain_rate_per_s)
KERF_RESULT_KEY(temperature_K)
KERF_RESULT_KEY(feed_um_per_rev)
KERF_RESULT_KEY(depth_of_cut_um)
KERF_RESULT_KEY(maximum_chip_thickness_um)
KERF_RESULT_KEY(equivalent_chip_thickness_um)
KERF_RESULT_KEY(engaged_edge_length_mm)
KERF_RESULT_KEY(critical_depth_nm)
KERF_RESULT_KEY(regime)
KERF_RESULT_KEY(within_model_range)
KERF_RESULT_KEY(guards)
KERF_RESULT_KEY(warnings)
}  // namespace prediction_keys

/// A prediction as its row and report see it: the scene and the prediction.
struct PredictionReport {
  const AnalyticScene& scene;
  const Prediction& p;
};
/// The row's columns before the models' own (the inputs echoed, the forces, the chip, the flow stress and its
/// state), in order; a column the scene's models leave out is not present, an empty cell is null.
const ResultTable<PredictionReport>& prediction_results();
/// The row's columns after the models' own: the turning cut's, the critical depth and the verdicts.
const ResultTable<PredictionReport>& prediction_verdict_results();
/// The models' own tables a scene's row carries, in the row's order between the shared columns (with the scene's
/// contact lengths) and the verdicts: the chip term's edge columns (a force model with edge_columns, or auto:
/// forces/chip_term.hpp), the Oxley solve's (a scene that solves Oxley, or auto: forces/oxley_model.hpp) and the
/// force model's own (OrthogonalForceModel::results); nullptr for a unit the scene's models leave out. They follow
/// the models the scene asked for ('auto' may choose differently point by point), so every row of a sweep has the
/// same columns.
std::array<const ResultTable<PredictionReport>*, 3> prediction_model_results(const AnalyticScene& scene);

/// The columns as a Markdown table (kerf-forces results; docs/scenes.md holds it).
std::string prediction_columns_markdown();
/// The columns as the Python module kerf.prediction_keys (kerf-forces results --python;
/// python/kerf/prediction_keys.py).
std::string prediction_keys_python();

/// One CSV row: (column name with unit, formatted value). The column set depends only on the scene's
/// model choices, so every row of a sweep has the same columns.
Columns prediction_columns(const AnalyticScene& scene, const Prediction& p);
/// The same row written cell by cell (what prediction_columns gathers; the sweep writes it straight to CSV).
void write_prediction_cells(const AnalyticScene& scene, const Prediction& p, CellWriter& out);

}  // namespace kerf
