#pragma once
// The seed-000 cutting validation (validation/soda_lime_cutting/): kerf-dem against the paper's DEM and
// experiments, through the report layer, with the acceptance bands of validation.json.
//
//   kerf::CuttingValidation v = kerf::run_soda_lime_cutting_validation("out/validation/soda_lime_cutting", "build/tools/kerf-dem");
#include <filesystem>
#include <string>
#include <vector>

namespace kerf {

struct CuttingValidation {
  std::vector<std::string> failures;         ///< one line per missed acceptance band; empty when passed
  std::vector<std::filesystem::path> files;  ///< the files written
  bool passed() const { return failures.empty(); }
};

/// Runs every condition with the kerf-dem program (finished replicates are reused), then writes the tables,
/// the two comparison reports and report.md/summary.json into `out_dir`.
CuttingValidation run_soda_lime_cutting_validation(const std::filesystem::path& out_dir, const std::filesystem::path& kerf_dem);

}  // namespace kerf
