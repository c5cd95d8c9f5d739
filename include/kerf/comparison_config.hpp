#pragma once
// A comparison described in JSON (what `kerf-forces compare` reads): which CSV files hold the measured and the
// predicted values, which columns are the conditions and quantities, their units, the width bases and views.
//
//   {
//     "title": "Soda-lime glass: experiment vs the paper's DEM (Yang et al. 2018)",
//     "conditions": [{"key": "surface", "label": "Surface", "text": true},
//                    {"key": "depth_of_cut", "label": "Depth of cut a#dc#u", "unit": "mm"}],
//     "quantities": [{"key": "main_force", "label": "Main force F#dc#u", "unit": "N"}],
//     "views": ["as_published", "per_unit_width"],
//     "measured": {"file": "../experiments/soda_lime_orthogonal_cutting.csv", "name": "experiment",
//                  "filter": {"source": "experiment"}, "width": {"column_mm": "width_mm"},
//                  "columns": {"surface": "surface", "depth_of_cut": "depth_of_cut_mm", "main_force": "main_force_N"}},
//     "predictions": [{...the same form...}]
//   }
//
// Units come from a fixed list (unit_names()); a data set's columns must be in the spec's units. "width" is
// {"column_mm": name} (total over the width in that column), {"mm": 25.4} (total over a stated width),
// "per_unit_width", or absent (no width basis: torques). File paths are relative to `base_directory`.
//
//   kerf::ComparisonConfig cfg = kerf::read_comparison_config("data/comparisons/soda_lime_dem_vs_experiment.json");
//   kerf::Comparison c = kerf::run_comparison(cfg);
//   kerf::write_report(c, "out/soda_lime");
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "kerf/report.hpp"

namespace kerf {

/// The units a comparison file may name: "mm", "um", "um/s", "mm/s", "m/min", "rpm", "N", "N m", "N/mm", "deg",
/// "K", "MPa", "GPa", "1/s", "um/rev", "".
const std::vector<std::string>& unit_names();
/// A scene key as a figure's axis label, its unit read from its suffix by the same table:
/// "cut.uncut_chip_thickness_um" -> "uncut chip thickness (µm)"; "cut.friction_coefficient" -> "friction coefficient".
std::string key_label(std::string_view key_path);
/// The unit with that name (InputError naming `path` and listing the valid names otherwise).
Unit unit_named(const std::string& name, const std::string& path);

struct ComparisonConfig {
  ComparisonSpec spec;
  DataSet measured;
  std::vector<DataSet> predictions;
};

/// Validates a comparison document and reads its CSV files. InputError names the JSON path or file:line: column.
ComparisonConfig parse_comparison_config(const Json& document, const std::filesystem::path& base_directory);
/// Reads a comparison file; relative CSV paths are relative to its directory.
ComparisonConfig read_comparison_config(const std::filesystem::path& file);
/// compare() on a configuration (no model curves: plots join the predicted points).
Comparison run_comparison(const ComparisonConfig& config);

}  // namespace kerf
