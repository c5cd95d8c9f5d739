#include "kerf/analytic/evaluate.hpp"

#include "kerf/analytic/critical_depth.hpp"
#include "kerf/analytic/predict.hpp"
#include "kerf/error.hpp"
#include "kerf/io.hpp"
#include "kerf/units.hpp"

namespace kerf {

bool is_trepanning_scene(const Json& document) {
  if (!document.is_object()) return false;
  const auto models = document.find("models");
  if (models == document.end() || !models->is_object()) return false;
  const auto force = models->find("force");
  return force != models->end() && force->is_string() && force->get<std::string>() == "trepanning";
}

Columns trepanning_columns(const TrepanningScene& scene, const TrepanningForces& forces) {
  Columns row;
  const auto add = [&](std::string name, double value) { row.emplace_back(std::move(name), csv_number(value)); };
  row.emplace_back("force_model", "trepanning");
  add("outer_diameter_mm", units::m_to_mm(scene.tool.outer_diameter_m));
  add("inner_diameter_mm", units::m_to_mm(scene.tool.inner_diameter_m));
  add("feed_rate_um_per_s", units::m_to_um(scene.cut.feed_rate_m_per_s));
  add("spindle_speed_rpm", scene.cut.spindle_speed_rev_per_s * 60.0);
  add("feed_per_rev_um", units::m_to_um(forces.feed_per_rev_m));
  add("axial_force_N", forces.axial_force_N);
  add("torque_N_m", forces.torque_N_m);
  add("axial_group_MPa", units::pa_to_mpa(scene.groups.axial_group_Pa));
  add("torque_group_MPa", units::pa_to_mpa(scene.groups.torque_group_Pa));
  if (scene.grits) {
    // Column names need no prediction: diagnostics only when the forces were computed (feed per rev > 0).
    const bool computed = forces.feed_per_rev_m > 0.0;
    const auto d = computed ? trepanning_grit_diagnostics(scene.tool, scene.cut, scene.groups, *scene.grits)
                            : TrepanningGritDiagnostics{};
    const auto optional_number = [&](std::string name, double value) {
      row.emplace_back(std::move(name), computed ? csv_number(value) : std::string());
    };
    optional_number("grit_count", d.grit_count);
    optional_number("cutting_edges", d.cutting_edges);
    optional_number("feed_per_edge_um", units::m_to_um(d.feed_per_edge_m));
    optional_number("grit_depth_um", units::m_to_um(d.grit_depth_m));
    optional_number("grit_normal_force_N", d.grit_normal_force_N);
    optional_number("grit_tangential_force_N", d.grit_tangential_force_N);
    // Each grit's depth against the ductile-brittle critical depth (Bifano), when the material has the data.
    std::string critical_nm, regime;
    if (const Json* brittle = scene.material.group("brittle");
        computed && brittle && brittle->contains("fracture_toughness_MPa_sqrt_m")) {
      const double critical = critical_depth_m(brittle_properties(scene.material, "material"));
      critical_nm = csv_number(units::m_to_nm(critical));
      regime = std::string(cutting_regime_name(classify_regime(d.grit_depth_m, critical)));
    }
    row.emplace_back("critical_depth_nm", critical_nm);
    row.emplace_back("grit_regime", regime);
  }
  return row;
}

Columns evaluate_scene_columns(const Json& document, MaterialCache* cache) {
  if (is_trepanning_scene(document)) {
    const TrepanningScene scene = parse_trepanning_scene(document);
    return trepanning_columns(scene, trepanning_forces(scene.tool, scene.cut, scene.groups));
  }
  const AnalyticScene scene = parse_analytic_scene(document, cache);
  return prediction_columns(scene, predict(scene));
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
  const Columns columns = is_trepanning_scene(document)
                              ? trepanning_columns(parse_trepanning_scene(document), TrepanningForces{})
                              : prediction_columns(parse_analytic_scene(document, cache), Prediction{});
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
