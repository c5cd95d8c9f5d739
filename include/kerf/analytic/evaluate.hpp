#pragma once
// One entry point for every analytic scene kind that kerf-forces runs: orthogonal cutting (models.force
// merchant, liu_li, oxley or auto; scene.hpp) and the fixed-abrasive trepanning drill (models.force =
// trepanning; trepanning_scene.hpp). Sweeps and comparisons call these and need not know the kind.
//
//   kerf::MaterialCache cache;
//   kerf::Columns row = kerf::evaluate_scene_columns(document, &cache);   // [("axial_force_N", "440.1"), ...]
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "kerf/analytic/scene.hpp"
#include "kerf/analytic/trepanning.hpp"
#include "kerf/analytic/trepanning_scene.hpp"
#include "kerf/json_reader.hpp"

namespace kerf {

using Columns = std::vector<std::pair<std::string, std::string>>;

/// True when the document's models.force is "trepanning".
bool is_trepanning_scene(const Json& document);

/// The CSV row of a trepanning prediction (pass default forces for the column names alone).
Columns trepanning_columns(const TrepanningScene& scene, const TrepanningForces& forces);

/// Parses, predicts and formats one scene of either kind. Throws InputError / ModelError like the models.
Columns evaluate_scene_columns(const Json& document, MaterialCache* cache);

/// The points of a sweep grid (row-major, `stride` between neighbours along the uncut chip thickness axis of
/// `n_along` values) where a force is below its value at the previous thickness (relative margin 1e-9): a model
/// that changed branch or left its domain. Points without a value (refused) are skipped.
///
///   auto falls = kerf::falling_points({1.0, 2.0, 1.5}, 1, 3);   // {2}
std::vector<std::size_t> falling_points(const std::vector<std::optional<double>>& force, std::size_t stride,
                                        std::size_t n_along);

/// The column names a scene's rows will have (its models fix them), without predicting.
std::vector<std::string> scene_column_names(const Json& document, MaterialCache* cache);

/// Refuses a varied key that the scene does not read (a sweep's --vary, Python's `vary`), before any point is
/// evaluated: applies `assignment` (key.path=value, the axis's first value) to a copy of the document and parses
/// it; a key the scene does not know is an InputError naming `option_name` and the key, with the parser's
/// did-you-mean, and so is a path that cannot be applied. A value the scene refuses is not: that point is
/// refused in the sweep like any other.
///
///   kerf::check_varied_key(base, "tool.edge_radius=0", "--vary", &cache);
///   // "--vary = tool.edge_radius: expected a known key (did you mean 'edge_radius_um'?); see docs/scenes.md"
void check_varied_key(Json document, const std::string& assignment, const std::string& option_name,
                      MaterialCache* cache);

}  // namespace kerf
