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
                    "cut.width_mm = wide: expected a positive value in mm (a number)");
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

// Issue 24: hostile documents.
TEST_CASE("Nesting deeper than kMaxJsonDepth is an input error, and the deep value is never echoed", "[json]") {
  const std::string deep = std::string(100000, '[') + std::string(100000, ']');
  try {
    (void)kerf::parse_json_text(deep, "deep.json");
    FAIL("no error");
  } catch (const InputError& e) {
    const std::string what = e.what();
    CHECK(what.find("deep.json = (arrays and objects nested deeper than 64") == 0);
    CHECK(what.size() < 600);
  }
  const std::string ok = std::string(kerf::kMaxJsonDepth, '[') + std::string(kerf::kMaxJsonDepth, ']');
  CHECK_NOTHROW(kerf::parse_json_text(ok, "ok.json"));
  CHECK_THROWS_AS(kerf::parse_override_value(std::string(1000, '[') + std::string(1000, ']')), InputError);
}

TEST_CASE("A number beyond a double names its key, as an input error", "[json]") {
  try {
    (void)kerf::parse_json_text(R"({"tool": {"edge_radius_um": 2, "rake_deg": 1e999}})", "scene.json");
    FAIL("no error");
  } catch (const InputError& e) {
    CHECK(e.field() == "tool.rake_deg");
    CHECK(e.value() == "1e999");
  }
  try {
    (void)kerf::parse_json_text(R"({"list": [1, 2, -1e400]})", "scene.json");
    FAIL("no error");
  } catch (const InputError& e) {
    CHECK(e.field() == "list[2]");
  }
  // Through --set the text stays a string and the key's reader refuses it as it refuses any non-number.
  CHECK(kerf::parse_override_value("1e999").is_string());
}

TEST_CASE("A number that a unit conversion takes to 0 or infinity names the user's key", "[json]") {
  const Json cut = {{"width_mm", 1e-322}, {"speed_m_per_min", 1e308}};
  ObjectReader reader(cut, "cut");
  CHECK_THROWS_WITH(reader.get_si("width_mm", Range::positive(), "mm", [](double mm) { return mm * 1e-3; }),
                    Catch::Matchers::StartsWith("cut.width_mm = 9.88131e-323: expected a value in mm that stays"));
  CHECK(reader.get_si("speed_m_per_min", Range::positive(), "m/min", [](double v) { return v / 60; }) > 0);
}

TEST_CASE("A directory given as a JSON file is an input error saying so", "[json]") {
  CHECK_THROWS_WITH(kerf::read_json_file(KERF_SOURCE_DIR "/data"),
                    Catch::Matchers::EndsWith("expected a JSON file, not a directory"));
}

TEST_CASE("Messages are one line: control characters are escaped", "[json]") {
  const Json scene = {{"material", std::string("gl\0a\ns\x1b[31ms\xc2\x85", 14)}};
  ObjectReader reader(scene, "");
  try {
    reader.get_choice("material", {"glass"});
    FAIL("no error");
  } catch (const InputError& e) {
    const std::string what = e.what();
    CHECK(what.find("material = gl\\x00a\\ns\\x1b[31ms\\u0085: expected one of 'glass'") == 0);
    CHECK(what.find_first_of(std::string("\n\r\x1b\0", 4)) == std::string::npos);
  }
  CHECK(kerf::printable("a\tb\x7f") == "a\\tb\\x7f");
  CHECK(kerf::printable("caf\xc3\xa9") == "caf\xc3\xa9");  // UTF-8 letters stay
}
