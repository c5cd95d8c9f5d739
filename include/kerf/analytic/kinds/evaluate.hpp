#pragma once
// One interface for every analytic scene kind that kerf-forces runs: orthogonal cutting (models.force merchant,
// liu_li, oxley or auto; scene.hpp, orthogonal_kind.cpp) and the fixed-abrasive trepanning drill
// (models.force = trepanning; trepanning_scene.hpp, trepanning_kind.cpp). parse_scene picks the kind through
// the registry line of the scene's models.force (registry.cpp): the CLI, the sweep, comparisons and Python
// call the interface and never ask which kind a scene is. How to add a kind: docs/analytic-models.md.
//
//   kerf::MaterialCache cache;
//   auto scene = kerf::parse_scene(document, &cache);     // InputError naming the first bad field
//   scene->predict();                                     // ModelError when a model fails
//   kerf::Columns row = kerf::scene_columns(*scene);      // [("axial_force_N", "440.1"), ...]
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "kerf/analytic/kinds/cells.hpp"
#include "kerf/analytic/kinds/scene.hpp"
#include "kerf/json_reader.hpp"

namespace kerf {

/// A parsed analytic scene of some kind, and after predict() its prediction.
class AnalyticCase {
 public:
  virtual ~AnalyticCase() = default;
  /// Runs the kind's models. Throws InputError for input the models cannot accept, ModelError when one fails.
  virtual void predict() = 0;
  /// The CSV row in column order. Before predict(): the column names (the scene's model choices fix them),
  /// with the cells of an empty prediction.
  virtual void write_cells(CellWriter& out) const = 0;
  /// The human-readable report of `kerf-forces predict` (after predict()).
  virtual void print(std::FILE* text, const std::string& scene_path) const = 0;
  /// The report of `kerf-forces regime`: the ductile-brittle critical depth and the regime of the scene's cut.
  virtual void print_regime(std::FILE* text, const std::string& scene_path) const = 0;
  /// The guards that fired and the validity warnings, as lists (after predict(); empty where the kind has none).
  virtual std::vector<std::string> guard_names() const { return {}; }
  virtual std::vector<std::string> warnings() const { return {}; }
  /// What a comparison report calls the model ("Analytic force model").
  virtual std::string_view comparison_title() const = 0;
  /// The width the forces act over (a comparison scales measured forces to it); none where the forces do not
  /// scale with a width (trepanning's axial force and torque).
  virtual std::optional<double> force_width_m() const { return std::nullopt; }
  /// Whether `kerf-forces compare --fit` can calibrate the kind's lumped groups (scene_compare.cpp).
  virtual bool fits_lumped_groups() const { return false; }
};

/// The scene of the kind its models.force names (no models.force: orthogonal cutting, force auto). A kerf-dem
/// scene (one with a "kind") is refused first. Throws InputError naming the first bad field.
std::unique_ptr<AnalyticCase> parse_scene(const Json& document, MaterialCache* cache);

/// The two kinds' builders (registry.cpp names them on its force lines).
std::unique_ptr<AnalyticCase> build_orthogonal_scene(const Json& document, MaterialCache* cache);
std::unique_ptr<AnalyticCase> build_trepanning_scene(const Json& document, MaterialCache* cache);

/// The case's CSV row as (name, text) pairs.
Columns scene_columns(const AnalyticCase& scene);

/// Parses, predicts and formats one scene of any kind. Throws InputError / ModelError like the models.
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
/// The same for a scene already parsed (not predicted).
std::vector<std::string> scene_column_names(const AnalyticCase& scene);

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
