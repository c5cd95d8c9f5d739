// The 2D parallel bond: Potyondy & Cundall 2004 (docs/references.md), Coulomb shear envelope as Itasca's
// linear parallel bond model.
#include "kerf/dem/parallel_bond.hpp"

#include <algorithm>

namespace kerf::dem {

const FieldTable<ParallelBondParams>& ParallelBondParams::fields() {
  using P = ParallelBondParams;
  static const FieldTable<P> table{
      number_field("bond_effective_modulus_GPa", units::kGPa, Range::positive(),
                   "bond effective modulus Ebar* (k_n = Ebar* / (R1 + R2))", &P::effective_modulus_pa),
      number_field("bond_stiffness_ratio", units::kNone, Range::positive(), "bond normal-to-shear stiffness ratio kappabar*",
                   &P::stiffness_ratio),
      number_field("tensile_strength_MPa", units::kMPa, Range::non_negative(),
                   "bond tensile strength sigma_c (largest normal stress at the periphery)", &P::tensile_strength_pa),
      number_field("cohesion_MPa", units::kMPa, Range::non_negative(), "bond cohesion c", &P::cohesion_pa),
      number_field("friction_angle_deg", units::kDeg, Range{0.0, 90.0, false, true},
                   "bond friction angle phi (shear strength c - sigma tan(phi))", &P::friction_angle_rad),
      number_field("radius_multiplier", units::kNone, Range{0.0, 1.0, true, false},
                   "bond half-width R = lambda min(R1, R2)", &P::radius_multiplier)};
  return table;
}

ParallelBondParams ParallelBondParams::validated(const ParallelBondParams& raw) {
  check_fields(fields(), raw);
  ParallelBondParams p = raw;
  p.tan_friction_angle = std::tan(raw.friction_angle_rad);
  return p;
}

BondGeometry bond_geometry(const ParallelBondParams& p, double r1_m, double r2_m, double thickness_m) {
  return interface_geometry(p.effective_modulus_pa, p.stiffness_ratio, p.radius_multiplier, r1_m, r2_m, thickness_m);
}

double bond_energy(const ParallelBondParams&, const BondGeometry& geo, const BondKinematics& kin,
                   const double* shear_force_n, const std::uint8_t* bonded) {
  if (!bonded[0]) return 0;
  const double len = 2 * geo.half_length_m, t = geo.thickness_m;
  const double area = len * t, inertia = t * len * len * len / 12.0;
  return 0.5 * geo.normal_stiffness * area * kin.gap_m * kin.gap_m +
         0.5 * geo.normal_stiffness * inertia * kin.rotation_rad * kin.rotation_rad +
         0.5 * shear_force_n[0] * shear_force_n[0] / (geo.shear_stiffness * area);
}

}  // namespace kerf::dem
