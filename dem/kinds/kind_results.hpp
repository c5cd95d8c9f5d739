#pragma once
// What the scene kinds other than the cut report (internal to dem/kinds/): their result tables (kerf/result_table.hpp)
// of summary.json's "results" and of their CSV files, and each table's keys declared once as constants, which the
// tables and every C++ reader use (Python reads them by the names kerf-dem results --python generates:
// kerf.result_keys). The cut's are kerf/dem/procedures/cut_results.hpp.
#include <cmath>
#include <cstdint>
#include <string>

#include "kerf/dem/procedures/calibration.hpp"
#include "kerf/dem/procedures/cut_calibration.hpp"
#include "kerf/dem/procedures/lab_test.hpp"
#include "kerf/dem/procedures/toughness.hpp"
#include "kerf/result_table.hpp"

namespace kerf::dem::kinds {

/// A finished tension or compression test as its results see it (kinds/lab_test.cpp).
struct LabTestReport {
  bool tension;
  const LabTestResult& res;
};
/// A test's quasi-static check: the test again at `speed_m_per_s` (half the speed), `slow`, against `res`.
template <class Result>
struct QuasiStaticCheck {
  double speed_m_per_s;
  const Result& slow;
  const Result& res;
};
/// The largest change of the peak at half the speed for which a test counts as quasi-static (docs/dem.md: 2.3 %
/// in compression at 0.1 m/s was judged not quasi-static enough); the check's verdict on a change.
inline constexpr double kQuasiStaticTolerancePercent = 2.0;
inline const char* quasi_static_verdict(double change_percent) {
  return std::abs(change_percent) <= kQuasiStaticTolerancePercent ? "quasi-static" : "rate-dependent";
}
using LabTestCheck = QuasiStaticCheck<LabTestResult>;
/// The keys of a tension or compression test's "results" (lab_test_results()), and where its check goes.
namespace lab_test_keys {
KERF_RESULT_KEY(youngs_modulus_GPa)
KERF_RESULT_KEY(poissons_ratio)
KERF_RESULT_KEY(tensile_strength_MPa)
KERF_RESULT_KEY(compressive_strength_MPa)
KERF_RESULT_KEY(strain_at_peak)
KERF_RESULT_KEY(n_tension_cracks)
KERF_RESULT_KEY(n_shear_cracks)
KERF_RESULT_KEY(stop_reason)
KERF_RESULT_KEY(speed_m_per_s)
KERF_RESULT_KEY(specimen_width_mm)
KERF_RESULT_KEY(gauge_length_mm)
// The quasi-static check's results (lab_test_check_results()), beside the table's.
KERF_RESULT_KEY(quasi_static_check)
}  // namespace lab_test_keys
/// The keys of a tension or compression test's "quasi_static_check" (lab_test_check_results()).
namespace lab_test_check_keys {
KERF_RESULT_KEY(speed_m_per_s)
KERF_RESULT_KEY(peak_stress_MPa)
KERF_RESULT_KEY(peak_change_percent)
KERF_RESULT_KEY(youngs_modulus_change_percent)
KERF_RESULT_KEY(wall_time_s)
KERF_RESULT_KEY(tolerance_percent)
KERF_RESULT_KEY(verdict)
}  // namespace lab_test_check_keys
/// summary.json's "results" of a tension or compression test, and of its "quasi_static_check".
const ResultTable<LabTestReport>& lab_test_results();
const ResultTable<LabTestCheck>& lab_test_check_results();

/// A mean over packings and its standard error.
struct MeanSem {
  double mean, sem;
};
/// A toughness test over its packings as its results see them (kinds/toughness.cpp): the means of the packings'
/// K_IC (in MPa sqrt(m)), G_c, work of fracture and Irwin energy, the first packing's beam, the spec, and each
/// packing's results (toughness_packing_results).
struct ToughnessReport {
  MeanSem toughness_MPa_sqrt_m, fracture_energy, work_of_fracture, irwin_energy;
  int packings;
  const ToughnessResult& first;
  const ToughnessSpec& spec;
  const Json& per_packing;
};
using ToughnessCheck = QuasiStaticCheck<ToughnessResult>;  ///< the first packing's check
/// The keys of a toughness test's "results" (toughness_results()), and where its check goes.
namespace toughness_keys {
KERF_RESULT_KEY(fracture_toughness_MPa_sqrt_m)
KERF_RESULT_KEY(fracture_energy_J_per_m2)
KERF_RESULT_KEY(work_of_fracture_J_per_m2)
KERF_RESULT_KEY(irwin_energy_J_per_m2)
KERF_RESULT_KEY(fracture_energy_over_irwin_energy)
KERF_RESULT_KEY(youngs_modulus_for_irwin_GPa)
KERF_RESULT_KEY(packings)
KERF_RESULT_KEY(depth_W_mm)
KERF_RESULT_KEY(span_S_mm)
KERF_RESULT_KEY(length_mm)
KERF_RESULT_KEY(thickness_B_mm)
KERF_RESULT_KEY(notch_depth_a_mm)
KERF_RESULT_KEY(notch_over_depth)
KERF_RESULT_KEY(geometry_factor)
KERF_RESULT_KEY(speed_m_per_s)
KERF_RESULT_KEY(peak_window_um)
KERF_RESULT_KEY(per_packing)
KERF_RESULT_KEY(fracture_toughness_sem_MPa_sqrt_m)
KERF_RESULT_KEY(fracture_energy_sem_J_per_m2)
KERF_RESULT_KEY(work_of_fracture_sem_J_per_m2)
KERF_RESULT_KEY(irwin_energy_sem_J_per_m2)
// The first packing's quasi-static check (toughness_check_results()), beside the table's.
KERF_RESULT_KEY(quasi_static_check)
}  // namespace toughness_keys
/// The keys of each of a toughness test's "per_packing" (toughness_packing_results()), and the packing's seed beside
/// them.
namespace toughness_packing_keys {
KERF_RESULT_KEY(fracture_toughness_MPa_sqrt_m)
KERF_RESULT_KEY(fracture_energy_J_per_m2)
KERF_RESULT_KEY(work_of_fracture_J_per_m2)
KERF_RESULT_KEY(irwin_energy_J_per_m2)
KERF_RESULT_KEY(peak_load_N)
KERF_RESULT_KEY(raw_peak_load_N)
KERF_RESULT_KEY(raw_peak_toughness_MPa_sqrt_m)
KERF_RESULT_KEY(deflection_at_peak_um)
KERF_RESULT_KEY(external_work_J)
KERF_RESULT_KEY(broken_through)
KERF_RESULT_KEY(deflection_broken_through_um)
KERF_RESULT_KEY(n_cracks)
KERF_RESULT_KEY(n_notch_disks_removed)
KERF_RESULT_KEY(n_notch_joints_retired)
KERF_RESULT_KEY(stop_reason)
KERF_RESULT_KEY(steps)
KERF_RESULT_KEY(wall_time_s)
// The packing's seed (specimen.seed + k), beside the table's results.
KERF_RESULT_KEY(seed)
}  // namespace toughness_packing_keys
/// The keys of a toughness test's "quasi_static_check" (toughness_check_results()).
namespace toughness_check_keys {
KERF_RESULT_KEY(speed_m_per_s)
KERF_RESULT_KEY(peak_load_N)
KERF_RESULT_KEY(peak_change_percent)
KERF_RESULT_KEY(fracture_toughness_MPa_sqrt_m)
KERF_RESULT_KEY(fracture_energy_J_per_m2)
KERF_RESULT_KEY(fracture_energy_change_percent)
KERF_RESULT_KEY(tolerance_percent)
KERF_RESULT_KEY(verdict)
KERF_RESULT_KEY(wall_time_s)
}  // namespace toughness_check_keys
/// summary.json's "results" of a toughness test, each of its "per_packing", and its "quasi_static_check".
const ResultTable<ToughnessReport>& toughness_results();
const ResultTable<ToughnessResult>& toughness_packing_results();
const ResultTable<ToughnessCheck>& toughness_check_results();

/// The columns of a toughness test's curve.csv (toughness_curve_columns()).
namespace toughness_curve_keys {
KERF_RESULT_KEY(seed)
KERF_RESULT_KEY(time_s)
KERF_RESULT_KEY(deflection_um)
KERF_RESULT_KEY(load_N)
KERF_RESULT_KEY(smoothed_load_N)
KERF_RESULT_KEY(support_load_N)
KERF_RESULT_KEY(external_work_J)
KERF_RESULT_KEY(stored_elastic_energy_J)
KERF_RESULT_KEY(kinetic_energy_J)
KERF_RESULT_KEY(n_cracks)
}  // namespace toughness_curve_keys
/// One sample of a packing's curve as a line of the toughness test's curve.csv: the packing's seed and the sample.
struct ToughnessCurveRow {
  std::uint64_t seed;
  const ToughnessSample& s;
};
/// The toughness test's curve.csv's columns, in order: every packing's curve, one after the other.
const ResultTable<ToughnessCurveRow>& toughness_curve_columns();

/// A finished calibration (kind calibrate) as its results see it: the result, the targets, the calibrated
/// material's JSON and whether it had a toughness target.
struct CalibrateReport {
  const CalibrationResult& r;
  const MacroProperties& targets;
  const Json& material;
  bool toughness;
};
/// The keys of kind calibrate's "results" (calibrate_results()).
namespace calibrate_keys {
KERF_RESULT_KEY(converged)
KERF_RESULT_KEY(max_error_percent)
KERF_RESULT_KEY(evaluations)
KERF_RESULT_KEY(targets)
KERF_RESULT_KEY(achieved)
KERF_RESULT_KEY(calibrated_material)
KERF_RESULT_KEY(toughness_error_percent)
}  // namespace calibrate_keys
/// summary.json's "results" of kind calibrate.
const ResultTable<CalibrateReport>& calibrate_results();

/// The columns of kind calibrate's calibration_log.csv (calibration_log_columns()).
namespace calibration_log_keys {
KERF_RESULT_KEY(evaluation)
KERF_RESULT_KEY(effective_modulus_GPa)
KERF_RESULT_KEY(stiffness_ratio)
KERF_RESULT_KEY(tensile_strength_MPa)
KERF_RESULT_KEY(cohesion_MPa)
KERF_RESULT_KEY(youngs_modulus_GPa)
KERF_RESULT_KEY(poissons_ratio)
KERF_RESULT_KEY(macro_tensile_strength_MPa)
KERF_RESULT_KEY(macro_compressive_strength_MPa)
KERF_RESULT_KEY(max_error_percent)
KERF_RESULT_KEY(wall_time_s)
KERF_RESULT_KEY(fracture_energy_J_per_m2)
KERF_RESULT_KEY(macro_fracture_toughness_MPa_sqrt_m)
KERF_RESULT_KEY(toughness_error_percent)
}  // namespace calibration_log_keys
/// One evaluation as a line of calibration_log.csv, and whether the calibration has a toughness target.
struct CalibrationLogRow {
  const CalibrationEvaluation* e;  ///< null in the row a header is made for
  bool toughness;
};
/// calibration_log.csv's columns, in order: the four lab tests', then, with a toughness target, the toughness's (a
/// log without them reads as before).
const ResultTable<CalibrationLogRow>& calibration_log_columns();

/// A finished cut calibration (kind calibrate_cut) as its results see it: whether it converged, the target main
/// force and its source, the best evaluation, its standard error, every evaluation's row, the calibrated material.
struct CalibrateCutReport {
  bool converged;
  double target_main_force_N;
  const std::string& target_source;
  const CutCalibrationPoint& best;
  double sem;
  const Json& evaluations;
  const Json& material;
};
/// The keys of kind calibrate_cut's "results" of its own (calibrate_cut_results(); its main_force_N is the replicated
/// cut's, cut_keys).
namespace calibrate_cut_keys {
KERF_RESULT_KEY(converged)
KERF_RESULT_KEY(target_cutting_force_N)
KERF_RESULT_KEY(target_main_force_N)
KERF_RESULT_KEY(target_source)
KERF_RESULT_KEY(strength_factor)
KERF_RESULT_KEY(main_force_standard_error_N)
KERF_RESULT_KEY(relative_error_percent)
KERF_RESULT_KEY(evaluations)
KERF_RESULT_KEY(calibrated_material)
}  // namespace calibrate_cut_keys
/// summary.json's "results" of kind calibrate_cut (before name_cut_forces adds the forces' current names).
const ResultTable<CalibrateCutReport>& calibrate_cut_results();

/// One evaluation of a cut calibration (kind calibrate_cut): its row of summary.json's "evaluations" and its line of
/// calibration_log.csv.
struct CutCalibrationEvaluation {
  int evaluation;
  double strength_factor;
  double tensile_strength_Pa, cohesion_Pa;   ///< of the scaled material's joints
  double main_force_N, main_force_spread_N;  ///< the replicated cut's mean and its spread over the replicates
  double thrust_force_N, thrust_force_spread_N;
  double relative_error;  ///< of the mean main force against the target
  std::string directory;  ///< the evaluation's, in the run's
  double wall_time_s;
};
/// The keys of a cut calibration's evaluation of its own (the forces' are the replicated cut's: cut_results.hpp).
namespace cut_calibration_keys {
KERF_RESULT_KEY(evaluation)
KERF_RESULT_KEY(strength_factor)
KERF_RESULT_KEY(tensile_strength_MPa)
KERF_RESULT_KEY(cohesion_MPa)
KERF_RESULT_KEY(relative_error_percent)
KERF_RESULT_KEY(directory)
KERF_RESULT_KEY(wall_time_s)
}  // namespace cut_calibration_keys
/// Each of calibrate_cut's "evaluations" in summary.json (before name_cut_forces adds the forces' current names).
const ResultTable<CutCalibrationEvaluation>& calibrate_cut_evaluation_results();
/// calibrate_cut's calibration_log.csv's columns, in order: an evaluation's row but its directory, then its wall time.
const ResultTable<CutCalibrationEvaluation>& calibrate_cut_log_columns();
}  // namespace kerf::dem::kinds
