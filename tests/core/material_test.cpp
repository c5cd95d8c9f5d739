#include "kerf/material.hpp"

#include <catch2/catch.hpp>

#include "kerf/error.hpp"

using kerf::Json;

TEST_CASE("Every library material loads and every number carries its provenance", "[material]") {
  const auto names = kerf::library_material_names();
  REQUIRE(names.size() >= 7);
  for (const auto& name : names) {
    INFO(name);
    const auto record = kerf::load_material(Json(name), "material");
    CHECK(record.name == name);
    std::size_t n_numbers = 0;
    for (const auto& [group, values] : record.groups.items()) {
      for (const auto& [key, value] : values.items()) {
        if (!value.is_number()) continue;
        ++n_numbers;
        INFO(group << "." << key);
        CHECK(record.provenance.count(group + "." + key) == 1);
      }
    }
    CHECK(n_numbers > 0);
  }
}

TEST_CASE("The bundled library holds the materials the toolkit promises", "[material]") {
  const auto names = kerf::library_material_names();
  for (const char* required :
       {"aisi_1045", "ti6al4v", "a2024_t351", "ofhc_copper", "psic", "soda_lime_glass", "k9_glass"}) {
    CHECK(std::find(names.begin(), names.end(), required) != names.end());
  }
}

TEST_CASE("Library files must give a source or an assumption", "[material]") {
  const Json bare = {{"name", "x"}, {"elastic", {{"youngs_modulus_GPa", 70}}}};
  CHECK_THROWS_AS(kerf::material_from_json(bare, "material", true), kerf::InputError);
  CHECK_NOTHROW(kerf::material_from_json(bare, "material", false));
}

TEST_CASE("Unknown material names and groups are errors that help", "[material]") {
  CHECK_THROWS_WITH(kerf::load_material(Json("psci"), "material"), Catch::Matchers::Contains("did you mean 'psic'?"));
  const Json wrong_group = {{"name", "x"}, {"johnson_cok", Json::object()}};
  CHECK_THROWS_WITH(kerf::material_from_json(wrong_group, "material", false),
                    Catch::Matchers::Contains("did you mean 'johnson_cook'?"));
}
