// The K9 trepanning validation case (validation/k9_trepanning.cpp): its bands hold and it writes its report.
#include "k9_trepanning.hpp"

#include <catch2/catch.hpp>
#include <filesystem>

#include "kerf/json_reader.hpp"

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
