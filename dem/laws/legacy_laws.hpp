#pragma once
// The contact laws as the engine states up to "KERFDEM6" and the calibration logs up to "KERFCAL3" stored them:
// the raw bytes of the law variants, their index included (kerf 4a34e1f and before). Frozen copies of that
// build's parameter structs and law lists, in its order, so that such a checkpoint still reads whatever the
// law list and the parameter structs of this build are: each alternative is translated to a record by name
// (serial.hpp). Internal to dem/; never written.
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

namespace kerf::dem::legacy {

/// FlatJointParams of 4a34e1f, member for member.
struct FlatJoint6 {
  double effective_modulus_Pa, stiffness_ratio, tensile_strength_Pa, cohesion_Pa, friction_angle_rad;
  double friction_coefficient;  ///< the residual friction of unbonded elements
  int n_elements;
  double radius_multiplier, tan_friction_angle;
};
/// ParallelBondParams of 4a34e1f.
struct ParallelBond6 {
  double effective_modulus_Pa, stiffness_ratio, tensile_strength_Pa, cohesion_Pa, friction_angle_rad;
  double radius_multiplier, tan_friction_angle;
};
/// LinearContactParams of 4a34e1f.
struct Linear6 {
  double effective_modulus_Pa, stiffness_ratio, friction_coefficient;
};

/// The law lists of 4a34e1f, in its order (the stored index is into these).
using BondLaw6 = std::variant<FlatJoint6, ParallelBond6>;
using ContactLaw6 = std::variant<Linear6>;
static_assert(sizeof(BondLaw6) == 80 && sizeof(ContactLaw6) == 32,
              "the stored variants' sizes of 4a34e1f (x86-64, libstdc++): an old checkpoint is read byte for byte");

/// A law by its registry name and its field table's keys with their SI values (the struct members, to the
/// bit): what a checkpoint stores since "KERFDEM7" / "KERFCAL4", and what an old one is translated to.
struct LawRecord {
  std::string name;
  std::vector<std::pair<std::string, double>> values;
};

/// Keys added to the bond laws' tables after the records began (KERFDEM7 / KERFCAL4): absent from an older record,
/// they keep their defaults, which give the law of the build that wrote it (no Weibull strengths).
inline bool key_added_later(std::string_view key) {
  return key == "strength_weibull_modulus" || key == "strength_reference_half_length_um";
}

// The translations, keyed as this build's field tables key them. A key renamed in a law's table is renamed here.
inline LawRecord record_of(const FlatJoint6& p) {
  return {"flat_joint",
          {{"bond_effective_modulus_GPa", p.effective_modulus_Pa},
           {"bond_stiffness_ratio", p.stiffness_ratio},
           {"tensile_strength_MPa", p.tensile_strength_Pa},
           {"cohesion_MPa", p.cohesion_Pa},
           {"friction_angle_deg", p.friction_angle_rad},
           {"residual_friction_coefficient", p.friction_coefficient},
           {"n_elements", static_cast<double>(p.n_elements)},
           {"radius_multiplier", p.radius_multiplier}}};
}
inline LawRecord record_of(const ParallelBond6& p) {
  return {"parallel_bond",
          {{"bond_effective_modulus_GPa", p.effective_modulus_Pa},
           {"bond_stiffness_ratio", p.stiffness_ratio},
           {"tensile_strength_MPa", p.tensile_strength_Pa},
           {"cohesion_MPa", p.cohesion_Pa},
           {"friction_angle_deg", p.friction_angle_rad},
           {"radius_multiplier", p.radius_multiplier}}};
}
inline LawRecord record_of(const Linear6& p) {
  return {"linear",
          {{"effective_modulus_GPa", p.effective_modulus_Pa},
           {"stiffness_ratio", p.stiffness_ratio},
           {"friction_coefficient", p.friction_coefficient}}};
}

}  // namespace kerf::dem::legacy
