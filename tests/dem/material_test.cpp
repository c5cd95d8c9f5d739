// Reading micro-parameters: units converted once, unknown keys and bad values named with their path,
// the contact-model registry rejecting unknown names, bundled materials found through "base".
#include "kerf/dem/laws/material.hpp"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "kerf/dem/laws/contact_laws.hpp"
#include "kerf/error.hpp"

using namespace kerf::dem;
using Catch::Matchers::Contains;
using Catch::Matchers::WithinRel;

TEST_CASE("material: keys carry units, converted to SI once", "[material]") {
  const Material m = read_material(kerf::Json::parse(R"({"effective_modulus_GPa": 90, "tensile_strength_MPa": 80,
      "cohesion_MPa": 200, "friction_angle_deg": 30, "n_elements": 3, "stiffness_ratio": 2.5})"),
                                   "material");
  CHECK(std::get<LinearContactParams>(m.contact).effective_modulus_Pa == 90e9);
  CHECK(std::get<FlatJointParams>(m.joint).bond.tensile_strength_Pa == 80e6);
  CHECK(std::get<FlatJointParams>(m.joint).bond.cohesion_Pa == 200e6);
  CHECK_THAT(std::get<FlatJointParams>(m.joint).bond.friction_angle_rad, WithinRel(M_PI / 6, 1e-15));
  CHECK_THAT(std::get<FlatJointParams>(m.joint).tan_friction_angle, WithinRel(std::tan(M_PI / 6), 1e-15));
  CHECK(std::get<FlatJointParams>(m.joint).n_elements == 3);
  CHECK(std::get<LinearContactParams>(m.contact).stiffness_ratio == 2.5);
  CHECK(std::get<FlatJointParams>(m.joint).bond.stiffness_ratio == 3.1);  // the bond's own ratio is a separate key
}

TEST_CASE("material: errors name the field, the value and the expectation", "[material]") {
  try {
    read_material(kerf::Json::parse(R"({"tensile_strenght_MPa": 80})"), "material");
    FAIL("misspelt key accepted");
  } catch (const kerf::InputError& e) {
    CHECK(e.field() == "material.tensile_strenght_MPa");
    CHECK_THAT(std::string(e.what()), Contains("did you mean 'tensile_strength_MPa'"));
  }
  try {
    read_material(kerf::Json::parse(R"({"bond_model": "no_such_bond"})"), "material");
    FAIL("unknown bond model accepted");
  } catch (const kerf::InputError& e) {
    CHECK(e.field() == "material.bond_model");
    CHECK_THAT(e.expected(), Contains("'flat_joint'"));
  }
  CHECK_THROWS_AS(read_material(kerf::Json::parse(R"({"radius_multiplier": 1.5})"), "material"), kerf::InputError);
  // A law's key out of its range is named once, with its object's path (read by the law's table).
  CHECK_THROWS_WITH(read_material(kerf::Json::parse(R"({"tensile_strength_MPa": -1})"), "material"),
                    "material.tensile_strength_MPa = -1: expected a non-negative value in MPa");
  CHECK_THROWS_AS(read_material(kerf::Json::parse(R"({"base": "no_such_material"})"), "material"), kerf::InputError);
  // Seeded flaws need a length and a density: one without the other names the missing key.
  CHECK_THROWS_WITH(read_material(kerf::Json::parse(R"({"flaw_length_um": 100})"), "material"),
                    Contains("material.flaw_density_per_mm2 = 0"));
  CHECK_THROWS_WITH(read_material(kerf::Json::parse(R"({"flaw_density_per_mm2": 4})"), "material"),
                    Contains("material.flaw_length_um = 0"));
}

TEST_CASE("material: seeded flaws in SI, written only by a glass that has them", "[material]") {
  const Material m =
      read_material(kerf::Json::parse(R"({"flaw_length_um": 150, "flaw_density_per_mm2": 4})"), "material");
  CHECK_THAT(m.flaw_length_m, WithinRel(150e-6, 1e-15));
  CHECK_THAT(m.flaw_density_per_m2, WithinRel(4e6, 1e-15));
  const kerf::Json j = material_to_json(m);
  CHECK_THAT(j.at("flaw_length_um").get<double>(), WithinRel(150.0, 1e-15));
  CHECK_THAT(j.at("flaw_density_per_mm2").get<double>(), WithinRel(4.0, 1e-15));
  CHECK(same_micro_parameters(read_material(j, "material"), m));
  CHECK_FALSE(same_micro_parameters(Material{}, m));
  const kerf::Json plain = material_to_json(Material{});
  CHECK_FALSE(plain.contains("flaw_length_um"));
  CHECK_FALSE(plain.contains("flaw_density_per_mm2"));
}

TEST_CASE("material: a bundled material is the base that other keys override", "[material]") {
  const Material m =
      read_material(kerf::Json::parse(R"({"base": "soda_lime_glass_fj", "local_damping": 0.5})"), "material");
  CHECK(m.name == "soda_lime_glass_fj");
  CHECK(m.local_damping == 0.5);
  CHECK(std::get<FlatJointParams>(m.joint).bond.cohesion_Pa >
        std::get<FlatJointParams>(m.joint).bond.tensile_strength_Pa);  // calibrated: c / sigma_c > 1
}

TEST_CASE("contact laws: the registry constructs laws by name", "[material]") {
  CHECK(std::holds_alternative<FlatJointParams>(law_by_name<BondLaw>("flat_joint", "x")));
  CHECK(std::holds_alternative<LinearContactParams>(law_by_name<ContactLaw>("linear", "x")));
  CHECK_THROWS_AS(law_by_name<BondLaw>("linear", "x"), kerf::InputError);  // not a bond law
  try {
    law_by_name<ContactLaw>("flat_joint", "material.contact_model");
    FAIL("a bond law accepted as a contact law");
  } catch (const kerf::InputError& e) {
    CHECK(e.field() == "material.contact_model");
    CHECK_THAT(e.expected(), Contains("'linear'"));
  }
  // Every registered law reads back its own name, and its defaults pass its own validation.
  for (const auto& name : law_names<BondLaw>()) {
    const BondLaw law = law_by_name<BondLaw>(name, "x");
    CHECK(law_name(law) == name);
    std::visit([](const auto& p) { CHECK_NOTHROW(std::decay_t<decltype(p)>::validated(p)); }, law);
  }
  CHECK(law_names<BondLaw>().front() == "flat_joint");  // the default bond law
  CHECK(law_names<ContactLaw>().front() == "linear");
}

TEST_CASE("material: to_json reads back to the same micro-parameters, every key documented", "[material]") {
  const Material m = read_material(kerf::Json::parse(R"({"base": "soda_lime_glass_fj", "n_elements": 4})"), "material");
  const kerf::Json j = material_to_json(m);
  const Material back = read_material(j, "material");
  // Every value back to within the rounding of the unit conversion (GPa and deg to SI and back).
  const kerf::Json k = material_to_json(back);
  CHECK(k.size() == j.size());
  for (const auto& [key, value] : j.items()) {
    if (value.is_number())
      CHECK_THAT(k.at(key).get<double>(), WithinRel(value.get<double>(), 1e-15));
    else
      CHECK(k.at(key) == value);
  }
  CHECK(std::get<FlatJointParams>(back.joint).n_elements == 4);
  const std::string md = material_keys_markdown();
  for (const auto& [key, value] : j.items())
    if (key != "name") CHECK_THAT(md, Contains("`" + key + "`"));
}

namespace {
template <class S>
std::vector<std::string> keys_of(const kerf::FieldTable<S>& table) {
  std::vector<std::string> keys;
  for (const auto& field : table) std::visit([&](const auto& f) { keys.emplace_back(f.key); }, field);
  return keys;
}
template <class V>
std::vector<std::vector<std::string>> law_keys() {
  return [&]<std::size_t... I>(std::index_sequence<I...>) {
    return std::vector<std::vector<std::string>>{keys_of(std::variant_alternative_t<I, V>::fields())...};
  }
  (std::make_index_sequence<std::variant_size_v<V>>{});
}
}  // namespace

TEST_CASE(
    "material: each key belongs to one law (issue 39): friction_coefficient is the contact's, "
    "residual_friction_coefficient the flat joint's",
    "[material]") {
  // No key of a contact law is a key of a bond law or of the material itself, so no key sets two things.
  const std::vector<std::string> own = keys_of(Material::fields());
  for (const auto& contact : law_keys<ContactLaw>())
    for (const auto& key : contact) {
      CHECK(std::find(own.begin(), own.end(), key) == own.end());
      for (const auto& bond : law_keys<BondLaw>()) CHECK(std::find(bond.begin(), bond.end(), key) == bond.end());
    }
  const Material m = read_material(kerf::Json::parse(R"({"friction_coefficient": 0.2})"), "material");
  CHECK(std::get<LinearContactParams>(m.contact).friction_coefficient == 0.2);
  CHECK(std::get<FlatJointParams>(m.joint).residual_friction_coefficient ==
        FlatJointParams{}.residual_friction_coefficient);
  const Material r = read_material(kerf::Json::parse(R"({"residual_friction_coefficient": 0.3})"), "material");
  CHECK(std::get<LinearContactParams>(r.contact).friction_coefficient == LinearContactParams{}.friction_coefficient);
  CHECK(std::get<FlatJointParams>(r.joint).residual_friction_coefficient == 0.3);
  // Both laws' block of stiffness and strength is one table: the bond laws' keys for it are the same.
  for (const auto& bond : law_keys<BondLaw>())
    for (const auto& key : keys_of(BondStiffnessStrength::fields()))
      CHECK(std::find(bond.begin(), bond.end(), key) != bond.end());
}
