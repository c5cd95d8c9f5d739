// The 2D flat-joint contact: docs/physics-dem.md section 1 (Potyondy 2012, 2015).
#include "kerf/dem/flat_joint.hpp"

#include <algorithm>
#include <cmath>

#include "kerf/error.hpp"

namespace kerf::dem {

const FieldTable<FlatJointParams>& FlatJointParams::fields() {
  using P = FlatJointParams;
  static const FieldTable<P> table{
      number_field("bond_effective_modulus_GPa", units::kGPa, Range::positive(),
                   "bond effective modulus Ebar* (k_n = Ebar* / (R1 + R2))", &P::effective_modulus_pa),
      number_field("bond_stiffness_ratio", units::kNone, Range::positive(), "bond normal-to-shear stiffness ratio kappabar*",
                   &P::stiffness_ratio),
      number_field("tensile_strength_MPa", units::kMPa, Range::non_negative(), "bond tensile strength sigma_c",
                   &P::tensile_strength_pa),
      number_field("cohesion_MPa", units::kMPa, Range::non_negative(), "bond cohesion c", &P::cohesion_pa),
      number_field("friction_angle_deg", units::kDeg, Range{0.0, 90.0, false, true},
                   "bond friction angle phi (Coulomb envelope of bonded elements)", &P::friction_angle_rad),
      number_field("friction_coefficient", units::kNone, Range::non_negative(),
                   "friction of unbonded elements (and of the unbonded contact: one key)", &P::friction_coefficient),
      int_field("n_elements", 2, 16, "elements per interface N_r (>= 2, else bending never enters the strength test)",
                &P::n_elements),
      number_field("radius_multiplier", units::kNone, Range{0.0, 1.0, true, false},
                   "interface half-length R = lambda min(R1, R2)", &P::radius_multiplier)};
  return table;
}

FlatJointParams FlatJointParams::validated(const FlatJointParams& raw) {
  check_fields(fields(), raw);
  FlatJointParams p = raw;
  p.tan_friction_angle = std::tan(raw.friction_angle_rad);
  return p;
}

BondGeometry bond_geometry(const FlatJointParams& p, double r1_m, double r2_m, double thickness_m) {
  return interface_geometry(p.effective_modulus_pa, p.stiffness_ratio, p.radius_multiplier, r1_m, r2_m, thickness_m);
}

double flat_joint_bonded_energy(const FlatJointParams& p, const BondGeometry& geo, const BondKinematics& kin,
                                std::span<const double> shear_force_n, std::span<const std::uint8_t> bonded) {
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
    energy += 0.5 * shear_force_n[e] * shear_force_n[e] / (geo.shear_stiffness * area);
  }
  return energy;
}

}  // namespace kerf::dem
