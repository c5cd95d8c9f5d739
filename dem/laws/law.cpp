// What the contact laws share: the bond laws' stiffness-and-strength block (kerf/dem/laws/law.hpp).
#include "kerf/dem/laws/law.hpp"

namespace kerf::dem {

const FieldTable<BondStiffnessStrength>& BondStiffnessStrength::fields() {
  using B = BondStiffnessStrength;
  static const FieldTable<B> table{
      number_field("bond_effective_modulus_GPa", units::kGPa, Range::positive(),
                   "bond effective modulus Ebar* (k_n = Ebar* / (R1 + R2))", &B::effective_modulus_pa),
      number_field("bond_stiffness_ratio", units::kNone, Range::positive(),
                   "bond normal-to-shear stiffness ratio kappabar*", &B::stiffness_ratio),
      number_field("tensile_strength_MPa", units::kMPa, Range::non_negative(),
                   "bond tensile strength sigma_c (largest normal stress of an element or at the bond's periphery)",
                   &B::tensile_strength_pa),
      number_field("cohesion_MPa", units::kMPa, Range::non_negative(), "bond cohesion c", &B::cohesion_pa),
      number_field("friction_angle_deg", units::kDeg, Range{0.0, 90.0, false, true},
                   "bond friction angle phi (shear strength c - sigma tan(phi))", &B::friction_angle_rad),
      number_field("radius_multiplier", units::kNone, Range{0.0, 1.0, true, false},
                   "interface half-length R = lambda min(R1, R2)", &B::radius_multiplier)};
  return table;
}

}  // namespace kerf::dem
