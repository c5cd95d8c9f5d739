// Reading micro-parameters: units converted once, unknown keys and bad values named with their path,
// the contact-model registry rejecting unknown names, bundled materials found through "base".
#include "kerf/dem/material.hpp"

#include <catch2/catch.hpp>
#include <cmath>

#include "kerf/dem/contact_models.hpp"
#include "kerf/error.hpp"

using namespace kerf::dem;
using Catch::Matchers::Contains;
using Catch::Matchers::WithinRel;

TEST_CASE("material: keys carry units, converted to SI once", "[material]") {
  const Material m = read_material(kerf::Json::parse(R"({"effective_modulus_GPa": 90, "tensile_strength_MPa": 80,
      "cohesion_MPa": 200, "friction_angle_deg": 30, "n_elements": 3, "stiffness_ratio": 2.5})"), "material");
  CHECK(m.contact.effective_modulus_pa == 90e9);
  CHECK(m.joint.tensile_strength_pa == 80e6);
  CHECK(m.joint.cohesion_pa == 200e6);
  CHECK_THAT(m.joint.friction_angle_rad, WithinRel(M_PI / 6, 1e-15));
  CHECK_THAT(m.joint.tan_friction_angle, WithinRel(std::tan(M_PI / 6), 1e-15));
  CHECK(m.joint.n_elements == 3);
  CHECK(m.contact.stiffness_ratio == 2.5);
  CHECK(m.joint.stiffness_ratio == 3.1);  // the bond's own ratio is a separate key
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
    read_material(kerf::Json::parse(R"({"bond_model": "parallel_bond"})"), "material");
    FAIL("unknown bond model accepted");
  } catch (const kerf::InputError& e) {
    CHECK(e.field() == "material.bond_model");
    CHECK_THAT(e.expected(), Contains("'flat_joint'"));
  }
  CHECK_THROWS_AS(read_material(kerf::Json::parse(R"({"radius_multiplier": 1.5})"), "material"), kerf::InputError);
  CHECK_THROWS_AS(read_material(kerf::Json::parse(R"({"base": "no_such_material"})"), "material"), kerf::InputError);
}

TEST_CASE("material: a bundled material is the base that other keys override", "[material]") {
  const Material m = read_material(kerf::Json::parse(R"({"base": "soda_lime_glass_fj", "local_damping": 0.5})"), "material");
  CHECK(m.name == "soda_lime_glass_fj");
  CHECK(m.local_damping == 0.5);
  CHECK(m.joint.cohesion_pa > m.joint.tensile_strength_pa);  // calibrated: c / sigma_c > 1
}

TEST_CASE("contact models: the registry knows linear and flat_joint", "[material]") {
  CHECK(contact_model_by_name("flat_joint", true, "x").model == ContactModel::flat_joint);
  CHECK(contact_model_by_name("linear", false, "x").model == ContactModel::linear);
  CHECK_THROWS_AS(contact_model_by_name("linear", true, "x"), kerf::InputError);  // not a bond model
}
