#include "kerf/analytic/forces/glass_edge.hpp"

#include "kerf/analytic/forces/transition_model.hpp"
#include "kerf/analytic/kinds/predict.hpp"
#include "kerf/analytic/kinds/scene.hpp"
#include "kerf/units.hpp"

namespace kerf {

EdgeForce edge_force_per_width(const Json& material, const EdgeTool& tool) {
  // The transition model at a depth far beyond any layer (1 mm), without its fracture part: its force is the
  // layer's alone. The speed is a placeholder: the hardness flow stress is rate-independent.
  const Json scene_document = {
      {"material", material},
      {"tool",
       {{"rake_deg", units::rad_to_deg(tool.rake_rad)}, {"edge_radius_um", units::m_to_um(tool.edge_radius_m)}}},
      {"cut",
       {{"uncut_chip_thickness_um", 1000.0},
        {"width_mm", 1.0},
        {"speed_m_per_min", 60.0},
        {"friction_coefficient", tool.friction_coefficient}}},
      {"models",
       {{"force", "transition"}, {"fracture", "none"}, {"transition", {{"ductile_layer_factor", tool.layer_factor}}}}}};
  const AnalyticScene scene = parse_analytic_scene(scene_document);
  const Prediction p = predict(scene);
  const TransitionDetails& details = *transition_details(p);
  return {.force = details.layer,
          .ductile_layer_m = details.ductile_layer_m,
          .critical_depth_m = *scene.critical_depth_m,
          .flow_stress_Pa = p.flow.total_Pa};
}

}  // namespace kerf
