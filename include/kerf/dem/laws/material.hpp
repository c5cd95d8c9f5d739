#pragma once
// The micro-parameters of a bonded-particle material, read from JSON with units in the key names.
//
//   Material m = read_material(json.at("material"), "material");  // unknown keys are rejected
//   Material s = read_scene_material(scene_reader);  // a scene's "material", or Yang et al. 2018, Table 1
//
// Keys (all optional, defaults are Yang et al. 2018, Table 1): the material's own (name, density_kg_per_m3,
// local_damping), contact_model and bond_model (the laws, kerf/dem/laws/contact_laws.hpp; defaults "linear" and
// "flat_joint"), the keys of the two laws (their field tables; each key belongs to one law: friction_coefficient
// is the unbonded contact's, residual_friction_coefficient the flat joint's), and base (name of a file
// data/materials/<base>.json whose values the other keys override). material_keys_markdown() is the complete
// reference (docs/dem-keys.md).
#include <string>

#include "kerf/dem/laws/contact_laws.hpp"
#include "kerf/field_table.hpp"
#include "kerf/json_reader.hpp"

namespace kerf::dem {

struct Material {
  std::string name = "custom";
  double density_kg_per_m3 = 2400;
  ContactLaw contact;          ///< unjointed disk-disk and disk-wall contacts
  BondLaw joint;               ///< bonded contacts
  double local_damping = 0.7;  ///< Cundall's alpha (docs/physics-dem.md section 1)
  /// Critical damping ratio beta of a dashpot beside each contact's and bond's normal and shear springs,
  /// c = 2 beta sqrt(m_eff k) (PFC's dashpots; LAMMPS BPM's damping). 0: none.
  double viscous_damping_ratio = 0;
  /// Seeded flaws (docs/physics-dem.md section 6; dem/procedures/flaws.cpp): straight cracks of this length, at
  /// this number per unit area, placed at random in every specimen the genesis builds; the joints they cross
  /// start broken (closed cracks: compression and friction, no tension). 0: none.
  double flaw_length_m = 0;
  double flaw_density_per_m2 = 0;

  /// The material's own keys (density, damping); the laws' keys are in their own tables.
  static const FieldTable<Material>& fields();
};

/// Reads and validates a material object. "base" names a library material (kerf::load_material) whose "dem"
/// group the other keys override.
Material read_material(const Json& object, const std::string& path);

/// A scene's "material" object, or the defaults (Yang et al. 2018, Table 1) when the scene has none: what kerf-dem
/// and the cut benchmark's --scene read.
Material read_scene_material(ObjectReader& scene);

/// The JSON form read_material accepts (every key written).
Json material_to_json(const Material& m);

/// Whether two materials have the same micro-parameters, every number to the bit (the name aside).
bool same_micro_parameters(const Material& a, const Material& b);

/// The stiffness-and-strength block of the material's bond law, whichever law it is.
const BondStiffnessStrength& joint_bond(const Material& m);

/// The micro-parameters that calibration moves, which the law concepts require of every law of the registry
/// (E* and kappa* of the unbonded contact; Ebar*, kappabar*, sigma_c and c of the bond's BondStiffnessStrength).
struct CalibratedParams {
  double contact_modulus_Pa, contact_stiffness_ratio;
  double bond_modulus_Pa, stiffness_ratio, tensile_strength_Pa, cohesion_Pa;
  double fracture_energy_J_per_m2 = 0;  ///< of a softening joint; 0 for a law without one
};
CalibratedParams calibrated_params(const Material& m);

/// The key reference of a material object: its own keys, then every law's, as Markdown tables.
std::string material_keys_markdown();

/// A material file for data/materials/ (the library shared with the analytic models): name, title,
/// description and a "dem" group whose every number carries `source` as its provenance.
Json library_material_json(const Material& m, const std::string& title, const std::string& description,
                           const std::string& source);

}  // namespace kerf::dem
