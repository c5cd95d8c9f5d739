#include "kerf/analytic/forces/merchant.hpp"

#include <cmath>
#include <numbers>

#include "kerf/error.hpp"
#include "kerf/units.hpp"

namespace kerf {

ForcePerWidth sharp_tool_force_per_width(double shear_flow_stress_Pa, double uncut_chip_thickness_m,
                                         double shear_angle_rad, double friction_angle_rad, double rake_rad) {
  const double half_pi = std::numbers::pi / 2.0;
  if (!(shear_angle_rad > 0.0 && shear_angle_rad < half_pi)) {
    throw InputError("shear_angle_deg", format_value(units::rad_to_deg(shear_angle_rad)),
                     "a shear angle in (0, 90) deg; friction angle minus rake is too large for this shear-angle "
                     "model (use a smaller friction angle or a measured chip ratio)");
  }
  const double resultant_angle = shear_angle_rad + friction_angle_rad - rake_rad;
  if (!(std::abs(resultant_angle) < half_pi)) {
    throw InputError("friction_angle_deg", format_value(units::rad_to_deg(friction_angle_rad)),
                     "phi + beta - rake below 90 deg (otherwise no chip can form)");
  }
  const double shear_force = shear_flow_stress_Pa * uncut_chip_thickness_m / std::sin(shear_angle_rad);
  const double resultant = shear_force / std::cos(resultant_angle);
  return {resultant * std::cos(friction_angle_rad - rake_rad), resultant * std::sin(friction_angle_rad - rake_rad)};
}

}  // namespace kerf
