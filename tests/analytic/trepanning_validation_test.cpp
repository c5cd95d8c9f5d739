#include "kerf/analytic/trepanning/trepanning_validation.hpp"

#include <catch2/catch.hpp>
#include <filesystem>

#include "kerf/analytic/trepanning/trepanning_scene.hpp"
#include "kerf/error.hpp"

using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;
namespace fs = std::filesystem;

namespace {
const fs::path kCase = fs::path(KERF_SOURCE_DIR) / "validation" / "k9_trepanning";
}

TEST_CASE("K9 trepanning validation: the acceptance bands hold on Table 4", "[trepanning][validation]") {
  const auto v = kerf::run_trepanning_validation(kCase, {});  // checks only, nothing written
  INFO((v.failures.empty() ? std::string() : v.failures.front()));
  CHECK(v.passed());
  CHECK(v.theory_fit.axial.fit.max_abs_error_percent <= v.acceptance.theory_column_max_abs_error_percent);
  CHECK(v.theory_fit.torque.fit.max_abs_error_percent <= v.acceptance.theory_column_max_abs_error_percent);
  CHECK(v.measured_fit.axial.fit.mean_abs_error_percent <= 5.0);
  CHECK(v.measured_fit.torque.fit.mean_abs_error_percent <= 6.7);
  // The paper's own theory column against the measurements: 4.92 % and 6.75 % recomputed from the printed
  // values (the paper quotes 5.0 % and 6.7 %; its printed torque error for row 3, -3.86 %, is -4.09 % from its values).
  CHECK_THAT(v.paper_axial.mean_abs_error_percent, WithinAbs(4.92, 0.01));
  CHECK_THAT(v.paper_torque.mean_abs_error_percent, WithinAbs(6.75, 0.01));
  // The scene's groups are the fitted ones, rounded to 1 MPa.
  CHECK_THAT(v.scene.groups.axial_group_Pa, WithinRel(v.measured_fit.groups.axial_group_Pa, 1e-4));
  CHECK_THAT(v.scene.groups.torque_group_Pa, WithinRel(v.measured_fit.groups.torque_group_Pa, 1e-4));
  CHECK_FALSE(v.implied_measured.physical);  // H = 7.2 GPa would need mu < 0
}

TEST_CASE("K9 trepanning validation writes its report", "[trepanning][validation][files]") {
  const fs::path out = fs::path(KERF_BINARY_DIR) / "test_output" / "k9_trepanning";
  fs::remove_all(out);
  const auto v = kerf::run_trepanning_validation(kCase, out);
  CHECK(v.passed());
  CHECK(fs::exists(out / "report.md"));
  CHECK(fs::exists(out / "summary.json"));
  CHECK(fs::exists(out / "parity_axial_force.png"));
  CHECK(fs::exists(out / "torque_vs_feed_rate.png"));
  const auto summary = kerf::read_json_file((out / "summary.json").string());
  CHECK(summary["quantities"]["axial_force"]["n"] == 8);
  CHECK(summary["quantities"]["axial_force"]["mean_abs_error_percent"].get<double>() <= 5.0);
  CHECK(summary["quantities"]["torque"]["mean_abs_error_percent"].get<double>() <= 6.7);
  CHECK(summary["extra"]["acceptance"]["passed"] == true);
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
