// What the contact laws share: the bond laws' stiffness-and-strength block (kerf/dem/laws/law.hpp).
#include "kerf/dem/laws/law.hpp"

namespace kerf::dem {

const FieldTable<BondStiffnessStrength>& BondStiffnessStrength::fields() {
  using B = BondStiffnessStrength;
  static const FieldTable<B> table{
      number_field("bond_effective_modulus_GPa", units::kGPa, Range::positive(),
                   "bond effective modulus Ebar* (k_n = Ebar* / (R1 + R2))", &B::effective_modulus_Pa),
      number_field("bond_stiffness_ratio", units::kNone, Range::positive(),
                   "bond normal-to-shear stiffness ratio kappabar*", &B::stiffness_ratio),
      number_field("tensile_strength_MPa", units::kMPa, Range::non_negative(),
                   "bond tensile strength sigma_c (largest normal stress of an element or at the bond's periphery)",
                   &B::tensile_strength_Pa),
      number_field("cohesion_MPa", units::kMPa, Range::non_negative(), "bond cohesion c", &B::cohesion_Pa),
      number_field("friction_angle_deg", units::kDeg, Range{0.0, 90.0, false, true},
                   "bond friction angle phi (shear strength c - sigma tan(phi))", &B::friction_angle_rad),
      number_field("radius_multiplier", units::kNone, Range{0.0, 1.0, true, false},
                   "interface half-length R = lambda min(R1, R2)", &B::radius_multiplier),
      number_field("strength_weibull_modulus", units::kNone, Range{0.0, 100.0, false, false},
                   "Weibull modulus m of the joints' strengths, each joint's sigma_c and c times its own factor "
                   "drawn when the specimen is made (0: every joint the same; docs/physics-dem.md)",
                   &B::strength_weibull_modulus),
      number_field("strength_reference_half_length_um", units::kUm, Range::positive(),
                   "half-length R_ref of the joints whose mean strengths are sigma_c and c (Weibull strengths: "
                   "a joint of half-length R has mean factor (R_ref / R)^(1/m); the default, the smallest joint of "
                   "the bundled glasses' 10-13 um disks)",
                   &B::strength_reference_half_length_m)};
  return table;
}

}  // namespace kerf::dem
