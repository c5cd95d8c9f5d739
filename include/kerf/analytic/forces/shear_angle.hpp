#pragma once
// Shear-angle relations of orthogonal cutting (angles in radians; a = rake, beta = mean friction angle).
//
//   phi_MEP  = pi/4 - (beta - a) / 2     Merchant, minimum energy           (Berezvai et al. 2019, Eq. 4)
//   phi_MSSP = pi/4 - (beta - a)         Lee-Shaffer / Krystof, max. shear   (Berezvai et al. 2019, Eq. 4)
//   tan phi  = r_c cos a / (1 - r_c sin a)   from the chip ratio r_c = t0 / t_chip  (Shao et al. 2013, Eq. 3)
//   beta     = atan(F_thrust / F_cutting) + a                                (Berezvai et al. 2019, Section 2)
//
//   double phi = kerf::shear_angle(kerf::ShearAngleModel::merchant, rake_rad, beta_rad);
//   double r_c = kerf::chip_ratio_from_shear_angle(phi, rake_rad);
#include <string_view>

namespace kerf {

enum class ShearAngleModel { merchant, lee_shaffer };

/// The scene names of the models: "merchant" (MEP) and "lee_shaffer" (MSSP).
std::string_view shear_angle_model_name(ShearAngleModel model);

/// phi from the friction angle; may be <= 0 or >= pi/2 for extreme beta - a: callers must check.
double shear_angle(ShearAngleModel model, double rake_rad, double friction_angle_rad);
/// phi from the chip ratio (atan2 form: valid also where r_c sin a >= 1), in (0, pi).
double shear_angle_from_chip_ratio(double chip_ratio, double rake_rad);
/// r_c = sin(phi) / cos(phi - a), the inverse of shear_angle_from_chip_ratio.
double chip_ratio_from_shear_angle(double shear_angle_rad, double rake_rad);
/// beta = atan(F_t / F_c) + a from measured mean forces.
double friction_angle_from_forces(double cutting_force, double thrust_force, double rake_rad);

}  // namespace kerf
