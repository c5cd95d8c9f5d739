#include "kerf/json_reader.hpp"

#include <catch2/catch.hpp>

#include "kerf/error.hpp"

using kerf::InputError;
using kerf::Json;
using kerf::ObjectReader;
using kerf::Range;

TEST_CASE("ObjectReader reads numbers and names the field of a bad one", "[json]") {
  const Json tool = {{"rake_deg", 95.0}, {"edge_radius_um", 2.0}};
  ObjectReader reader(tool, "tool");
  CHECK(reader.get_number("edge_radius_um", Range::non_negative(), "um") == 2.0);
  try {
    reader.get_number("rake_deg", Range::open(-90, 90), "deg");
    FAIL("no error");
  } catch (const InputError& e) {
    CHECK(std::string(e.what()) == "tool.rake_deg = 95: expected a value in (-90, 90) deg");
    CHECK(e.field() == "tool.rake_deg");
  }
}

TEST_CASE("Unknown keys are errors that suggest the near miss", "[json]") {
  const Json tool = {{"rake_dg", 5.0}};
  ObjectReader reader(tool, "tool");
  CHECK_FALSE(reader.get_optional_number("rake_deg", Range::any(), "deg").has_value());
  try {
    reader.finish();
    FAIL("no error");
  } catch (const InputError& e) {
    CHECK(std::string(e.what()).find("did you mean 'rake_deg'?") != std::string::npos);
    CHECK(e.field() == "tool.rake_dg");
  }
}

TEST_CASE("Choices list the valid names", "[json]") {
  const Json models = {{"force", "liu_lee"}};
  ObjectReader reader(models, "models");
  try {
    reader.get_choice("force", {"merchant", "oxley", "liu_li"});
    FAIL("no error");
  } catch (const InputError& e) {
    CHECK(std::string(e.what()) ==
          "models.force = liu_lee: expected one of 'merchant', 'oxley', 'liu_li' (did you mean 'liu_li'?)");
  }
}

TEST_CASE("Missing required keys and wrong types are named", "[json]") {
  const Json cut = {{"width_mm", "wide"}};
  ObjectReader reader(cut, "cut");
  CHECK_THROWS_WITH(reader.get_number("speed_m_per_min", Range::positive(), "m/min"),
                    "cut.speed_m_per_min = (missing): expected a value for this required key");
  CHECK_THROWS_WITH(reader.get_number("width_mm", Range::positive(), "mm"),
                    "cut.width_mm = wide: expected a positive value in mm");
}

TEST_CASE("Non-finite numbers are rejected", "[json]") {
  CHECK_THROWS_AS(kerf::check_number(std::nan(""), "x", Range::any(), ""), InputError);
  CHECK_THROWS_AS(kerf::check_number(HUGE_VAL, "x", Range::any(), ""), InputError);
}

TEST_CASE("Overrides set dotted paths and parse JSON values", "[json]") {
  Json scene = {{"tool", {{"rake_deg", 0.0}}}};
  kerf::apply_override(scene, "tool.rake_deg=-5");
  kerf::apply_override(scene, "models.force=liu_li");
  kerf::apply_override(scene, "cut.terms=[\"a\",\"b\"]");
  CHECK(scene["tool"]["rake_deg"].get<double>() == -5.0);
  CHECK(scene["models"]["force"].get<std::string>() == "liu_li");
  CHECK(scene["cut"]["terms"].size() == 2);
  CHECK_THROWS_AS(kerf::apply_override(scene, "no_equals_sign"), InputError);
  CHECK_THROWS_AS(kerf::apply_override(scene, "tool.rake_deg.x=1"), InputError);
}
