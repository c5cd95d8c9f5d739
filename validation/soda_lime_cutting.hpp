#pragma once
// The seed-000 cutting validation (validation/soda_lime_cutting/): kerf-dem against the paper's DEM and
// experiments, through the report layer, with the acceptance bands of validation.json.
//
//   kerf::CuttingValidation v = kerf::run_soda_lime_cutting_validation("out/validation/soda_lime_cutting");
#include <filesystem>
#include <string>
#include <vector>

namespace kerf {

struct CuttingValidation {
  std::vector<std::string> failures;         ///< one line per missed band; empty when passed
  std::vector<std::filesystem::path> files;  ///< the files written
  /// false: a reproduction of the paper's method (validation.json without bands), reported without pass or fail.
  bool judged = true;
  bool passed() const { return failures.empty(); }
};

/// Runs every condition of validation/<case_name>/validation.json with the DEM library (kerf/dem/scene.hpp,
/// as kerf-dem run --replicates does; finished replicates are reused), then writes the tables, the two comparison
/// reports and report.md/summary.json into `out_dir`. Cases: soda_lime_cutting (the Table-2-calibrated glass, a
/// reproduction) and soda_lime_cutting_cut_fitted (the glass whose bond strengths were fitted to one cut by kerf-dem
/// calibrate_cut, with bands). `replicates` (2-100) overrides validation.json's packings per condition; 0 keeps it.
CuttingValidation run_soda_lime_cutting_validation(const std::filesystem::path& out_dir,
                                                   const std::string& case_name = "soda_lime_cutting",
                                                   int replicates = 0);

}  // namespace kerf
