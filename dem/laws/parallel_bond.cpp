// The 2D parallel bond: Potyondy & Cundall 2004 (docs/references.md), Coulomb shear envelope as Itasca's
// linear parallel bond model.
#include "kerf/dem/laws/parallel_bond.hpp"

#include <algorithm>

namespace kerf::dem {

const FieldTable<ParallelBondParams>& ParallelBondParams::fields() {
  using P = ParallelBondParams;
  static const FieldTable<P> table = embedded_fields(BondStiffnessStrength::fields(), &P::bond);
  return table;
}

ParallelBondParams ParallelBondParams::validated(const ParallelBondParams& raw) {
  check_fields(fields(), raw);
  ParallelBondParams p = raw;
  p.tan_friction_angle = std::tan(raw.bond.friction_angle_rad);
  return p;
}

BondGeometry bond_geometry(const ParallelBondParams& p, double r1_m, double r2_m, double thickness_m) {
  return interface_geometry(p.bond, r1_m, r2_m, thickness_m);
}

double bond_energy(const ParallelBondParams&, const BondGeometry& geo, const BondKinematics& kin,
                   const double* shear_force_N, const std::uint8_t* bonded) {
  if (!bonded[0]) return 0;
  const double len = 2 * geo.half_length_m, t = geo.thickness_m;
  const double area = len * t, inertia = t * len * len * len / 12.0;
  return 0.5 * geo.normal_stiffness * area * kin.gap_m * kin.gap_m +
         0.5 * geo.normal_stiffness * inertia * kin.rotation_rad * kin.rotation_rad +
         0.5 * shear_force_N[0] * shear_force_N[0] / (geo.shear_stiffness * area);
}

}  // namespace kerf::dem
