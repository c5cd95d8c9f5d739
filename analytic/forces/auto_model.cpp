#include "kerf/analytic/forces/auto_model.hpp"

#include <string>
#include <string_view>

#include "kerf/analytic/kinds/scene.hpp"

namespace kerf {

namespace {

/// models.force = auto: oxley without friction data (where the material has a Johnson-Cook law), merchant for an
/// edge radius below kSharpEdgeRatio of t0, else liu_li.
std::string_view choose_force_model(const AnalyticScene& scene, std::string* reason) {
  if (!scene.friction_angle_rad && scene.shear_angle != ShearAngleSource::chip_ratio &&
      scene.material->group("johnson_cook")) {
    *reason = "no friction data: only oxley predicts without it";
    return "oxley";
  }
  if (scene.edge_radius_m < kSharpEdgeRatio * scene.uncut_chip_thickness_m) {
    *reason = "edge radius below 5 % of the uncut chip thickness: sharp-tool model";
    return "merchant";
  }
  *reason = "edge radius at least 5 % of the uncut chip thickness: edge-radius model";
  return "liu_li";
}

}  // namespace

// Its columns cover every choice (the kind writes the edge's and the Oxley solve's under auto).
const OrthogonalForceModel auto_force_model{.choose = &choose_force_model};

}  // namespace kerf
