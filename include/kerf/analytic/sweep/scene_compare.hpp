#pragma once
// `kerf-forces compare`: holds a scene against an experiment CSV through the report layer (report.hpp).
//
// Each measured row's conditions are written into the scene (a CSV column whose name ends in a unit, such as
// depth_nm, is converted to the scene key's unit; a unit of another kind is refused; a column without a unit
// suffix is taken in the key's unit), the scene is predicted, and the predicted quantities are compared with the
// measured ones. Columns are matched by name: a CSV column named like a prediction column (cutting_force_N,
// thrust_force_N, axial_force_N, torque_N_m) is a measured quantity; a CSV column named like a key of the scene's
// `tool` or `cut` is a condition. `mappings` name the others: "cut.feed_rate_um_per_s=feed_rate_um_s" (a condition:
// scene key path = CSV column) or "axial_force_N=axial_force_test_N" (a quantity: prediction column = CSV
// column). With `fit`, a trepanning scene's two lumped groups are fitted to the measured rows first (with
// leave-one-out errors in the report).
//
//   kerf::SceneComparisonOptions options;
//   options.mappings = {"cut.feed_rate_um_per_s=feed_rate_um_s", "axial_force_N=axial_force_test_N",
//                       "torque_N_m=torque_test_Nm"};
//   options.fit = true;
//   kerf::SceneComparison c = kerf::compare_scene(document, "data/experiments/k9_trepanning.csv", options);
//   kerf::write_report(c.comparison, "out/k9", c.report);
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "kerf/analytic/trepanning/trepanning.hpp"
#include "kerf/json_reader.hpp"
#include "kerf/report.hpp"

namespace kerf {

struct SceneComparisonOptions {
  std::vector<std::string> mappings;
  bool fit = false;
  /// The width the measured forces act over, when the CSV has no width_mm column (default: the scene's).
  std::optional<double> measured_width_mm;
  /// Whether a CSV none of whose columns sets a condition is compared anyway, every row a measurement at the
  /// scene's own condition (replicates of one point); without it such a CSV is an InputError naming its columns.
  bool pool = false;
};

/// What the prediction of one measured row said besides its numbers.
struct RowDiagnostics {
  std::size_t line = 0;  ///< the row's line in the CSV
  std::string
      regime;  ///< "ductile", "transition", "brittle" (a grit's, for trepanning); empty without a critical depth
  std::vector<std::string> guards;    ///< the names of the guards that fired; empty when none
  std::vector<std::string> warnings;  ///< the prediction's validity warnings, one text each
};

struct SceneComparison {
  Comparison comparison;
  ReportOptions report;                              ///< the fit and notes, for report.md and summary.json
  std::optional<TrepanningCalibration> calibration;  ///< with fit on a trepanning scene
  std::vector<std::string> notes;                    ///< how columns were matched, what was assumed
  std::vector<std::string> unused_columns;           ///< CSV columns bound to nothing
  std::vector<RowDiagnostics> rows;                  ///< per measured row, in the CSV's order
};

SceneComparison compare_scene(const Json& scene_document, const std::filesystem::path& experiments_csv,
                              const SceneComparisonOptions& options);

}  // namespace kerf
