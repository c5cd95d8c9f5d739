#include "kerf/analytic/kinds/evaluate.hpp"

#include "kerf/analytic/registry.hpp"
#include "kerf/error.hpp"

namespace kerf {

std::unique_ptr<AnalyticCase> parse_scene(const Json& document, MaterialCache* cache) {
  refuse_dem_scene(document);
  // The kind is the registry's for the scene's models.force (absent or not a force line's name: the "auto"
  // line's, whose parser reports a bad name with the valid ones).
  std::string force = "auto";
  if (document.is_object()) {
    const auto models = document.find("models");
    if (models != document.end() && models->is_object()) {
      const auto named = models->find("force");
      if (named != models->end() && named->is_string()) force = named->get<std::string>();
    }
  }
  const AnalyticModelInfo* line = registered_line(analytic_models(), "force", force);
  if (!line || !line->build) line = registered_line(analytic_models(), "force", "auto");
  return line->build(document, cache);
}

Columns scene_columns(const AnalyticCase& scene) {
  ColumnCollector row;
  scene.write_cells(row);
  return std::move(row.columns);
}

Columns evaluate_scene_columns(const Json& document, MaterialCache* cache) {
  const auto scene = parse_scene(document, cache);
  scene->predict();
  return scene_columns(*scene);
}

std::vector<std::size_t> falling_points(const std::vector<std::optional<double>>& force, std::size_t stride,
                                        std::size_t n_along) {
  std::vector<std::size_t> out;
  if (stride == 0 || n_along == 0) return out;
  for (std::size_t i = stride; i < force.size(); ++i) {
    if ((i / stride) % n_along == 0) continue;  // the first thickness of its line
    const auto& now = force[i];
    const auto& before = force[i - stride];
    if (now && before && *now < *before * (1.0 - 1e-9)) out.push_back(i);
  }
  return out;
}

std::vector<std::string> scene_column_names(const Json& document, MaterialCache* cache) {
  return scene_column_names(*parse_scene(document, cache));
}

std::vector<std::string> scene_column_names(const AnalyticCase& scene) {
  const Columns columns = scene_columns(scene);
  std::vector<std::string> names;
  for (const auto& column : columns) names.push_back(column.first);
  return names;
}

void check_varied_key(Json document, const std::string& assignment, const std::string& option_name,
                      MaterialCache* cache) {
  apply_override(document, assignment, option_name);  // a path through a non-object fails every point alike
  const std::string key = assignment.substr(0, assignment.find('='));
  try {
    scene_column_names(document, cache);
  } catch (const InputError& e) {
    // The reader names the first unknown key on the path: the key itself, or a section above it ("tools").
    const bool unknown =
        e.expected().starts_with("a known key") && (key == e.field() || key.starts_with(e.field() + "."));
    if (unknown) throw InputError(option_name, key, e.expected());
  } catch (const ModelError&) {
    // the point's own failure, refused in the sweep
  }
}

}  // namespace kerf
