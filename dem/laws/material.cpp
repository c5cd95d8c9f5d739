// Reading the micro-parameters of a material (units converted here, once).
#include "kerf/dem/laws/material.hpp"

#include "kerf/error.hpp"
#include "kerf/material.hpp"

namespace kerf::dem {

namespace {
constexpr double per_mm2_to_per_m2(double v) {
  return v * 1e6;
}
constexpr double per_m2_to_per_mm2(double v) {
  return v * 1e-6;
}
constexpr FieldUnit kPerMm2{"1/mm^2", per_mm2_to_per_m2, per_m2_to_per_mm2};
}  // namespace

const FieldTable<Material>& Material::fields() {
  static const FieldTable<Material> table{
      number_field("density_kg_per_m3", units::kSi("kg/m^3"), Range::positive(), "particle density",
                   &Material::density_kg_per_m3),
      number_field("local_damping", units::kNone, Range{0.0, 1.0, false, true},
                   "Cundall's local damping alpha (docs/physics-dem.md section 1)", &Material::local_damping),
      number_field("viscous_damping_ratio", units::kNone, Range::closed(0.0, 1.0),
                   "critical damping ratio of the dashpots beside every contact and bond (normal and shear; 0: none)",
                   &Material::viscous_damping_ratio),
      number_field("flaw_length_um", units::kUm, Range::non_negative(),
                   "length of each seeded flaw, a straight crack whose joints start broken (0: no flaws)",
                   &Material::flaw_length_m),
      number_field("flaw_density_per_mm2", kPerMm2, Range::non_negative(),
                   "seeded flaws per unit area of every specimen (centres and orientations uniform at random)",
                   &Material::flaw_density_per_m2)};
  return table;
}

Material read_material(const Json& object, const std::string& path) {
  if (!object.is_object()) throw InputError(path, json_value_text(object), "an object of material micro-parameters");
  Json merged = object;
  if (auto it = object.find("base"); it != object.end()) {
    // A library material (data/materials/, shared with the analytic models): its "dem" group holds the
    // micro-parameters; the scene's other keys override them.
    const MaterialRecord record = load_material(*it, path + ".base", "dem");
    Json base = record.require_group("dem", path + ".base", "the DEM (flat-joint micro-parameters)");
    for (auto& [key, value] : object.items())
      if (key != "base") base[key] = value;
    base["name"] = record.name;
    merged = base;
  }
  ObjectReader r(merged, path);
  Material m;
  m.name = r.get_string_or("name", m.name);
  m = read_fields(r, Material::fields(), m);
  m.contact = law_by_name<ContactLaw>(r.get_string_or("contact_model", std::string(law_name(m.contact))),
                                      r.key_path("contact_model"));
  m.joint =
      law_by_name<BondLaw>(r.get_string_or("bond_model", std::string(law_name(m.joint))), r.key_path("bond_model"));
  read_law(r, m.contact);
  read_law(r, m.joint);
  r.ignore("description");
  r.finish();
  if ((m.flaw_length_m > 0) != (m.flaw_density_per_m2 > 0))
    throw InputError(r.key_path(m.flaw_length_m > 0 ? "flaw_density_per_mm2" : "flaw_length_um"), "0",
                     "a positive value when the other flaw key is positive (both 0: no flaws)");
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
  Json j = fields_to_json(Material::fields(), m);
  if (m.flaw_density_per_m2 <= 0) {  // a glass without flaws writes what it wrote before flaws existed
    j.erase("flaw_length_um");
    j.erase("flaw_density_per_mm2");
  }
  j["name"] = m.name;
  j.update(law_to_json(m.joint));
  j.update(law_to_json(m.contact));  // the two laws' keys are distinct (material_keys_markdown's test checks it)
  j["contact_model"] = law_name(m.contact);
  j["bond_model"] = law_name(m.joint);
  return j;
}

bool same_micro_parameters(const Material& a, const Material& b) {
  return a.density_kg_per_m3 == b.density_kg_per_m3 && a.local_damping == b.local_damping &&
         a.viscous_damping_ratio == b.viscous_damping_ratio && a.flaw_length_m == b.flaw_length_m &&
         a.flaw_density_per_m2 == b.flaw_density_per_m2 && a.contact == b.contact && a.joint == b.joint;
}

const BondStiffnessStrength& joint_bond(const Material& m) {
  return std::visit([](const auto& law) -> const BondStiffnessStrength& { return law.bond; }, m.joint);
}

CalibratedParams calibrated_params(const Material& m) {
  return std::visit(
      [](const auto& c, const auto& j) {
        CalibratedParams p{c.effective_modulus_Pa, c.stiffness_ratio,          j.bond.effective_modulus_Pa,
                           j.bond.stiffness_ratio, j.bond.tensile_strength_Pa, j.bond.cohesion_Pa};
        if constexpr (requires { j.fracture_energy_J_per_m2; }) p.fracture_energy_J_per_m2 = j.fracture_energy_J_per_m2;
        return p;
      },
      m.contact, m.joint);
}

std::string material_keys_markdown() {
  return fmt::format(
      "The material's own keys (besides `name`, `description` and `base`, the name of a library material whose "
      "`dem` group the other keys override):\n\n{}\n`contact_model` (default `{}`) and `bond_model` (default `{}`) "
      "choose the laws; each law reads its own keys from the same object (no key belongs to two laws):\n\n"
      "Unbonded contact laws (`contact_model`):\n\n{}Bond laws (`bond_model`):\n\n{}",
      fields_markdown(Material::fields()), law_name(ContactLaw{}), law_name(BondLaw{}), laws_markdown<ContactLaw>(),
      laws_markdown<BondLaw>());
}

}  // namespace kerf::dem
