#pragma once
// Sharp-tool orthogonal cutting force (Merchant's force circle). Per unit width, for shear flow stress k_s,
// uncut chip thickness t0, shear angle phi, friction angle beta and rake a:
//
//   F_c = k_s t0 cos(beta - a) / (sin(phi) cos(phi + beta - a))
//   F_t = k_s t0 sin(beta - a) / (sin(phi) cos(phi + beta - a))
//
// This is the straight-rake term of Shao et al. 2013's Eqs. 1-2 and the r -> 0 limit of the Liu-Li model.
//
//   auto f = kerf::sharp_tool_force_per_width(k_s, t0_m, phi, beta, rake);   // N per m of width
#include <string>

namespace kerf {

struct ForcePerWidth {
  double cutting_N_per_m = 0.0;
  double thrust_N_per_m = 0.0;
};

/// Throws kerf::InputError when phi is not in (0, pi/2) or phi + beta - a is not in (-pi/2, pi/2)
/// (no chip can form: the shear plane would carry an infinite force).
ForcePerWidth sharp_tool_force_per_width(double shear_flow_stress_Pa, double uncut_chip_thickness_m,
                                         double shear_angle_rad, double friction_angle_rad, double rake_rad);

}  // namespace kerf
