// The trepanning kind's scene (analytic/trepanning/trepanning_scene.cpp), read from the K9 validation case's.
#include "kerf/analytic/trepanning/trepanning_scene.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>

#include "kerf/error.hpp"
#include "kerf/json_reader.hpp"

using Catch::Matchers::WithinRel;
namespace fs = std::filesystem;

namespace {
const fs::path kCase = fs::path(KERF_SOURCE_DIR) / "validation" / "k9_trepanning";
}

TEST_CASE("Trepanning scenes take groups or hardness, half angle and friction, and errors name the field",
          "[trepanning][scene]") {
  kerf::Json doc = kerf::read_json_file((kCase / "scene.json").string());
  const auto scene = kerf::parse_trepanning_scene(doc);
  CHECK_THAT(scene.tool.outer_diameter_m, WithinRel(0.132, 1e-15));
  CHECK_THAT(scene.cut.spindle_speed_rev_per_s, WithinRel(90.5 / 60.0, 1e-15));
  CHECK_THAT(scene.groups.axial_group_Pa, WithinRel(10739e6, 1e-15));

  kerf::Json physical = doc;
  physical["models"]["trepanning"] = {{"half_angle_deg", 60}, {"friction_coefficient", 0.0}};
  const auto from_material = kerf::parse_trepanning_scene(physical);  // H from k9_glass.json (7.2 GPa)
  CHECK_THAT(from_material.groups.axial_group_Pa, WithinRel(7.2e9 * std::sqrt(3.0), 1e-12));
  CHECK_THAT(from_material.groups.torque_group_Pa, WithinRel(7.2e9, 1e-12));

  const auto field_of = [](const kerf::Json& d) -> std::string {
    try {
      kerf::parse_trepanning_scene(d);
    } catch (const kerf::InputError& e) {
      return e.field();
    }
    return "(no error)";
  };
  kerf::Json bad = doc;
  bad["tool"]["inner_diameter_mm"] = 140;
  CHECK(field_of(bad) == "tool.inner_diameter_mm");
  bad = doc;
  bad["cut"]["spindle_speed_rpm"] = 0;
  CHECK(field_of(bad) == "cut.spindle_speed_rpm");
  bad = doc;
  bad["cut"]["feed_rate_um_per_s"] = -5;
  CHECK(field_of(bad) == "cut.feed_rate_um_per_s");
  bad = doc;
  bad["models"]["trepanning"]["axial_grup_MPa"] = 1;
  CHECK(field_of(bad) == "models.trepanning.axial_grup_MPa");
  bad = doc;
  bad["models"]["force"] = "liu_li";
  CHECK(field_of(bad) == "models.force");
}
