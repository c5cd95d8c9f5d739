// The 2D flat-joint contact: docs/physics-dem.md section 1 (Potyondy 2012, 2015).
#include "kerf/dem/laws/flat_joint.hpp"

#include <algorithm>
#include <cmath>

#include "kerf/error.hpp"

namespace kerf::dem {

const FieldTable<FlatJointParams>& FlatJointParams::fields() {
  using P = FlatJointParams;
  static const FieldTable<P> table = embedded_fields(
      BondStiffnessStrength::fields(), &P::bond,
      {number_field("residual_friction_coefficient", units::kNone, Range::non_negative(),
                    "friction of unbonded elements (the linear contact's is friction_coefficient)",
                    &P::residual_friction_coefficient),
       int_field("n_elements", 2, 16, "elements per interface N_r (>= 2, else bending never enters the strength test)",
                 &P::n_elements)});
  return table;
}

FlatJointParams FlatJointParams::validated(const FlatJointParams& raw) {
  check_fields(fields(), raw);
  FlatJointParams p = raw;
  p.tan_friction_angle = std::tan(raw.bond.friction_angle_rad);
  return p;
}

BondGeometry bond_geometry(const FlatJointParams& p, double r1_m, double r2_m, double thickness_m) {
  return interface_geometry(p.bond, r1_m, r2_m, thickness_m);
}

double flat_joint_bonded_energy(const FlatJointParams& p, const BondGeometry& geo, const BondKinematics& kin,
                                std::span<const double> shear_force_N, std::span<const std::uint8_t> bonded) {
  const int nr = p.n_elements;
  const double le = 2.0 * geo.half_length_m / nr;
  const double area = le * geo.thickness_m;
  double energy = 0;
  for (int e = 0; e < nr; ++e) {
    if (!bonded[e]) continue;
    const double xi_e = flat_joint_element_centroid(geo, nr, e);
    const double ge = kin.gap_m - kin.rotation_rad * xi_e;
    // 1/2 k_n t int g^2 dxi over the element, + 1/2 F_s^2 / (k_s A_e).
    energy += 0.5 * geo.normal_stiffness * geo.thickness_m *
              (le * ge * ge + kin.rotation_rad * kin.rotation_rad * le * le * le / 12.0);
    energy += 0.5 * shear_force_N[e] * shear_force_N[e] / (geo.shear_stiffness * area);
  }
  return energy;
}

}  // namespace kerf::dem
