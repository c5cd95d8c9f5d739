#pragma once
// The micro-parameters of a bonded-particle material, read from JSON with units in the key names.
//
//   Material m = read_material(json.at("material"), "material");  // unknown keys are rejected
//   Material s = read_scene_material(scene_reader);  // a scene's "material", or seed 000 Table 1
//
// Keys (all optional, defaults are seed 000 Table 1): density_kg_per_m3, effective_modulus_GPa,
// stiffness_ratio, bond_effective_modulus_GPa, bond_stiffness_ratio, tensile_strength_MPa, cohesion_MPa,
// friction_angle_deg, friction_coefficient (disk-disk friction and residual friction of unbonded
// elements), n_elements, radius_multiplier, local_damping, contact_model ("linear"), bond_model
// ("flat_joint"), base (name of a file data/materials/<base>.json whose values the other keys override).
#include <string>

#include "kerf/dem/flat_joint.hpp"
#include "kerf/dem/linear_contact.hpp"
#include "kerf/json_reader.hpp"

namespace kerf::dem {

struct Material {
  std::string name = "custom";
  double density_kg_per_m3 = 2400;
  LinearContactParams contact;  ///< unjointed disk-disk and disk-wall contacts
  FlatJointParams joint;        ///< bonded contacts
  double local_damping = 0.7;   ///< Cundall's alpha (physics-dem.md section 1)
};

/// Reads and validates a material object. "base" names a library material (kerf::load_material) whose "dem"
/// group the other keys override.
Material read_material(const Json& object, const std::string& path);

/// A scene's "material" object, or the defaults (seed 000 Table 1) when the scene has none: what kerf-dem
/// and the cut benchmark's --scene read.
Material read_scene_material(ObjectReader& scene);

/// The JSON form read_material accepts (every key written).
Json material_to_json(const Material& m);

/// A material file for data/materials/ (the library shared with the analytic models): name, title,
/// description and a "dem" group whose every number carries `source` as its provenance.
Json library_material_json(const Material& m, const std::string& title, const std::string& description,
                           const std::string& source);

}  // namespace kerf::dem
