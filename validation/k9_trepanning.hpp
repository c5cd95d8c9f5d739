#pragma once
// The K9 trepanning validation case (validation/k9_trepanning/): Yu et al. 2023's Table 4 against Eqs. 21-22.
//
// The case directory holds scene.json (the scene with the calibrated groups), k9_trepanning.csv (Table 4 with
// its citation), validation.json (column names, weighting, acceptance bands) and a README. The run:
//   1. fits K_F and K_M to the paper's theory column: one value of each must reproduce all rows within
//      theory_column_max_abs_error_percent (2 %);
//   2. fits them to the measured rows (least squares, relative residuals) with leave-one-out cross-validation:
//      mean |error| must be at most the paper's own (axial 5.0 %, torque 6.7 %);
//   3. writes a report (report.hpp) comparing the measured rows with the fitted model, its leave-one-out
//      predictions and the paper's theory column, plus a calibration section.
// The model, its fit and what the groups imply are the analytic library's (kerf/analytic/trepanning/trepanning.hpp:
// calibrate_trepanning, implied_trepanning_material); this case reads the table, applies the bands and writes the
// report.
//
//   kerf::TrepanningValidation v = kerf::run_k9_trepanning_validation("out/k9_trepanning");
//   if (!v.passed()) for (auto& f : v.failures) fmt::print("{}\n", f);
#include <filesystem>
#include <string>
#include <vector>

#include "kerf/analytic/trepanning/trepanning.hpp"
#include "kerf/analytic/trepanning/trepanning_scene.hpp"
#include "kerf/metrics.hpp"

namespace kerf {

struct TrepanningAcceptance {
  double theory_column_max_abs_error_percent = 2.0;
  double axial_mean_abs_error_percent = 5.0;
  double torque_mean_abs_error_percent = 6.7;
};

struct TrepanningValidation {
  TrepanningScene scene;
  TrepanningAcceptance acceptance;
  TrepanningCalibration measured_fit;      ///< groups fitted to the measured rows (with leave-one-out)
  TrepanningCalibration theory_fit;        ///< groups fitted to the paper's theory column
  ErrorMetrics paper_axial, paper_torque;  ///< the paper's theory column against the measured rows
  ImpliedTrepanningMaterial implied_measured, implied_theory;  ///< at the material's brittle.hardness_GPa
  std::vector<std::string> failures;         ///< one line per missed acceptance band; empty when passed
  std::vector<std::filesystem::path> files;  ///< the report files written
  bool passed() const { return failures.empty(); }
};

/// Runs a trepanning validation case. With an empty `out_dir` nothing is written (the checks still run).
TrepanningValidation run_trepanning_validation(const std::filesystem::path& case_dir,
                                               const std::filesystem::path& out_dir);

/// The bundled case: <data directory>/../validation/k9_trepanning.
std::filesystem::path k9_trepanning_case_directory();
TrepanningValidation run_k9_trepanning_validation(const std::filesystem::path& out_dir);

}  // namespace kerf
