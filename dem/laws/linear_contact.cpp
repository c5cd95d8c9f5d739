// Linear contact with Coulomb friction: docs/physics-dem.md section 1 (unjointed contacts).
#include "kerf/dem/laws/linear_contact.hpp"

#include <algorithm>
#include <cmath>

namespace kerf::dem {

const FieldTable<LinearContactParams>& LinearContactParams::fields() {
  using P = LinearContactParams;
  static const FieldTable<P> table{
      number_field("effective_modulus_GPa", units::kGPa, Range::positive(),
                   "contact effective modulus E* (k_n = 2 min(R) t E* / (R1 + R2))", &P::effective_modulus_Pa),
      number_field("stiffness_ratio", units::kNone, Range::positive(), "contact normal-to-shear stiffness ratio kappa*",
                   &P::stiffness_ratio),
      number_field("friction_coefficient", units::kNone, Range::non_negative(),
                   "Coulomb friction mu of disk-disk and disk-wall contacts", &P::friction_coefficient)};
  return table;
}

LinearContactParams LinearContactParams::validated(const LinearContactParams& raw) {
  check_fields(fields(), raw);
  return raw;
}

double linear_normal_stiffness(const LinearContactParams& p, double r1_m, double r2_m, double thickness_m) {
  const double r_min = r2_m > 0 ? std::min(r1_m, r2_m) : r1_m;
  return 2.0 * r_min * thickness_m * p.effective_modulus_Pa / (r1_m + r2_m);
}

ContactResult contact_update(const LinearContactParams& p, double r1_m, double r2_m, double thickness_m,
                             double overlap_m, double shear_increment_m, double& shear_force_N) {
  if (overlap_m <= 0) {
    shear_force_N = 0;
    return {};
  }
  const double kn = linear_normal_stiffness(p, r1_m, r2_m, thickness_m);
  const double fn = kn * overlap_m;
  const double limit = p.friction_coefficient * fn;
  shear_force_N = std::clamp(shear_force_N - kn / p.stiffness_ratio * shear_increment_m, -limit, limit);
  return {fn, shear_force_N};
}

double contact_energy(const LinearContactParams& p, double r1_m, double r2_m, double thickness_m, double overlap_m,
                      double shear_force_N) {
  if (overlap_m <= 0) return 0;
  const double kn = linear_normal_stiffness(p, r1_m, r2_m, thickness_m);
  return 0.5 * kn * overlap_m * overlap_m + 0.5 * shear_force_N * shear_force_N * p.stiffness_ratio / kn;
}

}  // namespace kerf::dem
