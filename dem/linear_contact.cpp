// Linear contact with Coulomb friction: physics-dem.md section 1 (unjointed contacts).
#include "kerf/dem/linear_contact.hpp"

#include <algorithm>
#include <cmath>

#include "kerf/error.hpp"
#include "kerf/units.hpp"

namespace kerf::dem {

LinearContactParams LinearContactParams::validated(const LinearContactParams& raw, const std::string& path) {
  const std::string prefix = path.empty() ? "" : path + ".";
  if (!(std::isfinite(raw.effective_modulus_pa) && raw.effective_modulus_pa > 0))
    throw InputError(prefix + "effective_modulus_GPa", format_value(units::pa_to_gpa(raw.effective_modulus_pa)),
                     "a positive value in GPa");
  if (!(std::isfinite(raw.stiffness_ratio) && raw.stiffness_ratio > 0))
    throw InputError(prefix + "stiffness_ratio", format_value(raw.stiffness_ratio), "a positive value (k_n / k_s)");
  if (!(std::isfinite(raw.friction_coefficient) && raw.friction_coefficient >= 0))
    throw InputError(prefix + "friction_coefficient", format_value(raw.friction_coefficient), "a non-negative value");
  return raw;
}

double linear_normal_stiffness(const LinearContactParams& p, double r1_m, double r2_m, double thickness_m) {
  const double r_min = r2_m > 0 ? std::min(r1_m, r2_m) : r1_m;
  return 2.0 * r_min * thickness_m * p.effective_modulus_pa / (r1_m + r2_m);
}

LinearContactResult linear_contact_update(const LinearContactParams& p, double r1_m, double r2_m, double thickness_m,
                                          double overlap_m, double shear_increment_m, double& shear_force_n) {
  if (overlap_m <= 0) {
    shear_force_n = 0;
    return {};
  }
  const double kn = linear_normal_stiffness(p, r1_m, r2_m, thickness_m);
  const double fn = kn * overlap_m;
  const double limit = p.friction_coefficient * fn;
  shear_force_n = std::clamp(shear_force_n - kn / p.stiffness_ratio * shear_increment_m, -limit, limit);
  return {fn, shear_force_n};
}

}  // namespace kerf::dem
