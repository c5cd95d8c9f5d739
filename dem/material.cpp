// Reading the micro-parameters of a material (units converted here, once).
#include "kerf/dem/material.hpp"

#include <cstdlib>

#include "kerf/dem/contact_models.hpp"
#include "kerf/error.hpp"
#include "kerf/material.hpp"
#include "kerf/units.hpp"

namespace kerf::dem {

Material read_material(const Json& object, const std::string& path) {
  if (!object.is_object()) throw InputError(path, json_value_text(object), "an object of material micro-parameters");
  Json merged = object;
  if (auto it = object.find("base"); it != object.end()) {
    // A library material (data/materials/, shared with the analytic models): its "dem" group holds the
    // micro-parameters; the scene's other keys override them.
    const MaterialRecord record = load_material(*it, path + ".base");
    Json base = record.require_group("dem", path + ".base", "the DEM (flat-joint micro-parameters)");
    for (auto& [key, value] : object.items())
      if (key != "base") base[key] = value;
    base["name"] = record.name;
    merged = base;
  }
  ObjectReader r(merged, path);
  Material m;
  using units::gpa_to_pa;
  using units::mpa_to_pa;
  m.name = r.get_string_or("name", "custom");
  m.density_kg_per_m3 = r.get_number_or("density_kg_per_m3", 2400, Range::positive(), "kg/m^3");
  m.contact.effective_modulus_pa =
      gpa_to_pa(r.get_number_or("effective_modulus_GPa", 107, Range::positive(), "GPa"));
  m.contact.stiffness_ratio = r.get_number_or("stiffness_ratio", 3.1, Range::positive(), "");
  m.joint.effective_modulus_pa =
      gpa_to_pa(r.get_number_or("bond_effective_modulus_GPa", 107, Range::positive(), "GPa"));
  m.joint.stiffness_ratio = r.get_number_or("bond_stiffness_ratio", 3.1, Range::positive(), "");
  m.joint.tensile_strength_pa = mpa_to_pa(r.get_number_or("tensile_strength_MPa", 200, Range::non_negative(), "MPa"));
  m.joint.cohesion_pa = mpa_to_pa(r.get_number_or("cohesion_MPa", 113, Range::non_negative(), "MPa"));
  m.joint.friction_angle_rad =
      units::deg_to_rad(r.get_number_or("friction_angle_deg", 25, Range{0.0, 90.0, false, true}, "deg"));
  const double mu = r.get_number_or("friction_coefficient", 0.577, Range::non_negative(), "");
  m.contact.friction_coefficient = mu;
  m.joint.friction_coefficient = mu;
  m.joint.n_elements = r.get_int_or("n_elements", 2, 2, 16);
  m.joint.radius_multiplier = r.get_number_or("radius_multiplier", 1.0, Range{0.0, 1.0, true, false}, "");
  m.local_damping = r.get_number_or("local_damping", 0.7, Range{0.0, 1.0, false, true}, "");
  contact_model_by_name(r.get_string_or("contact_model", "linear"), false, r.key_path("contact_model"));
  contact_model_by_name(r.get_string_or("bond_model", "flat_joint"), true, r.key_path("bond_model"));
  r.ignore("description");
  r.finish();
  m.contact = LinearContactParams::validated(m.contact, path);
  m.joint = FlatJointParams::validated(m.joint, path);
  return m;
}

Json library_material_json(const Material& m, const std::string& title, const std::string& description,
                           const std::string& source) {
  Json dem = Json::object();
  const Json plain = material_to_json(m);  // a named object: items() must not outlive it
  for (const auto& [key, value] : plain.items()) {
    if (key == "name") continue;
    dem[key] = value.is_number() ? Json{{"value", value}, {"source", source}} : value;
  }
  return Json{{"name", m.name}, {"title", title}, {"description", description}, {"dem", dem}};
}

Material read_scene_material(ObjectReader& scene) {
  static const Json empty = Json::object();
  const Json* material = scene.find("material");
  return read_material(material ? *material : empty, "material");
}

Json material_to_json(const Material& m) {
  return Json{{"name", m.name},
              {"density_kg_per_m3", m.density_kg_per_m3},
              {"effective_modulus_GPa", units::pa_to_gpa(m.contact.effective_modulus_pa)},
              {"stiffness_ratio", m.contact.stiffness_ratio},
              {"bond_effective_modulus_GPa", units::pa_to_gpa(m.joint.effective_modulus_pa)},
              {"bond_stiffness_ratio", m.joint.stiffness_ratio},
              {"tensile_strength_MPa", units::pa_to_mpa(m.joint.tensile_strength_pa)},
              {"cohesion_MPa", units::pa_to_mpa(m.joint.cohesion_pa)},
              {"friction_angle_deg", units::rad_to_deg(m.joint.friction_angle_rad)},
              {"friction_coefficient", m.contact.friction_coefficient},
              {"n_elements", m.joint.n_elements},
              {"radius_multiplier", m.joint.radius_multiplier},
              {"local_damping", m.local_damping},
              {"contact_model", "linear"},
              {"bond_model", "flat_joint"}};
}

}  // namespace kerf::dem
