// The softening flat joint: the flat joint with a linear tensile softening per element
// (kerf/dem/laws/softening_flat_joint.hpp).
#include "kerf/dem/laws/softening_flat_joint.hpp"

#include <cmath>

#include "kerf/error.hpp"

namespace kerf::dem {

const FieldTable<SofteningFlatJointParams>& SofteningFlatJointParams::fields() {
  using P = SofteningFlatJointParams;
  static const FieldTable<P> table = inherited_fields(
      FlatJointParams::fields(),
      FieldTable<P>{number_field("fracture_energy_J_per_m2", units::kSi("J/m^2"), Range::non_negative(),
                                 "fracture energy G_f per element area beyond sigma_c^2 / (2 k_n): the tensile stress "
                                 "falls linearly to zero over the opening 2 G_f / sigma_c after the strength (0: the "
                                 "flat joint)",
                                 &P::fracture_energy_J_per_m2)});
  return table;
}

SofteningFlatJointParams SofteningFlatJointParams::validated(const SofteningFlatJointParams& raw) {
  check_fields(fields(), raw);
  SofteningFlatJointParams p = raw;
  static_cast<FlatJointParams&>(p) = FlatJointParams::validated(raw);
  p.softening_opening_m =
      raw.bond.tensile_strength_Pa > 0 ? 2 * raw.fracture_energy_J_per_m2 / raw.bond.tensile_strength_Pa : 0.0;
  return p;
}

double softening_flat_joint_bonded_energy(const SofteningFlatJointParams& p, const BondGeometry& geo,
                                          const BondKinematics& kin, std::span<const double> shear_force_N,
                                          std::span<const std::uint8_t> bonded, std::span<const double> damage) {
  const int nr = p.n_elements;
  const double le = 2.0 * geo.half_length_m / nr;
  const double area = le * geo.thickness_m;
  const double theta = kin.rotation_rad;
  double energy = 0;
  for (int e = 0; e < nr; ++e) {
    if (!bonded[e]) continue;
    // 1/2 k_n t int g^2 dxi over the element + 1/2 F_s^2 / (k_s A_e), written as the flat joint's energy.
    const double xi_e = flat_joint_element_centroid(geo, nr, e);
    const double ge = kin.gap_m - theta * xi_e;
    const double all = le * ge * ge + theta * theta * le * le * le / 12.0;
    const double d = damage[e];
    if (d == 0) {
      energy += 0.5 * geo.normal_stiffness * geo.thickness_m * all;
      energy += 0.5 * shear_force_N[e] * shear_force_N[e] / (geo.shear_stiffness * area);
      continue;
    }
    // Damaged: the closed part [c, d] at k_n (g linear: int g^2 = (d - c)(g_c^2 + g_c g_d + g_d^2) / 3), the
    // open part at (1 - D) k_n, the shear at (1 - D) k_s.
    const ClosedPart part = element_closed_part(kin.gap_m, theta, -geo.half_length_m + e * le, le);
    const double gc = kin.gap_m - theta * part.start_m, gd = kin.gap_m - theta * part.end_m;
    const double closed =
        part.end_m > part.start_m ? (part.end_m - part.start_m) * (gc * gc + gc * gd + gd * gd) / 3 : 0.0;
    energy += 0.5 * geo.normal_stiffness * geo.thickness_m * (closed + (1 - d) * (all - closed));
    if (d < 1) energy += 0.5 * shear_force_N[e] * shear_force_N[e] / ((1 - d) * geo.shear_stiffness * area);
  }
  return energy;
}

}  // namespace kerf::dem
