#include "kerf/comparison_config.hpp"

#include <catch2/catch.hpp>

#include "kerf/error.hpp"
#include "kerf/material.hpp"

using Catch::Matchers::WithinRel;

namespace {
const std::filesystem::path kFile =
    std::filesystem::path(KERF_SOURCE_DIR) / "data/comparisons/soda_lime_dem_vs_experiment.json";

std::string field_of(const kerf::Json& doc) {
  try {
    kerf::parse_comparison_config(doc, kFile.parent_path());
  } catch (const kerf::InputError& e) {
    return e.field();
  }
  return "(no error)";
}
}  // namespace

TEST_CASE("The bundled Yang et al. 2018 comparison reads and compares in both width views", "[comparison_config]") {
  const auto cfg = kerf::read_comparison_config(kFile);
  CHECK(cfg.measured.rows.size() == 12);
  REQUIRE(cfg.predictions.size() == 1);
  CHECK(cfg.measured.bases[0] == kerf::WidthBasis::total(25.4e-3));
  CHECK(cfg.predictions[0].bases[1] == kerf::WidthBasis::total(1e-3));
  const auto c = kerf::run_comparison(cfg);
  // 4 condition groups x 3 replicates; thrust, grooved 0.2 mm: experiment 5.6, 6.4, 5.4 N; DEM 2.98, 2.95, 1.06 N.
  const auto& thrust = c.result("thrust_force");
  REQUIRE(thrust.groups.size() == 4);
  const auto& g = thrust.groups[3];
  CHECK(g.conditions[0].text == "grooved");
  CHECK_THAT(g.measured_stats.mean, WithinRel(17.4 / 3.0, 1e-12));
  CHECK_THAT(g.predicted_stats.mean, WithinRel(6.99 / 3.0, 1e-12));
  CHECK(g.has_scatter);
  CHECK_FALSE(g.within_2sd);
  CHECK(c.result("thrust_force_per_width").groups.size() == 4);
}

TEST_CASE("Comparison files name the bad field", "[comparison_config][errors]") {
  const kerf::Json good = kerf::read_json_file(kFile.string());
  kerf::Json bad = good;
  bad["quantities"][0]["unit"] = "kgf";
  CHECK(field_of(bad) == "quantities[0].unit");
  bad = good;
  bad["views"] = {"per_width"};
  CHECK(field_of(bad) == "views[0]");
  bad = good;
  bad["measured"]["columns"]["main_force"] = "main_force";
  CHECK(field_of(bad).find("soda_lime_orthogonal_cutting.csv: column") != std::string::npos);
  bad = good;
  bad["measured"]["colums"] = kerf::Json::object();
  CHECK(field_of(bad) == "measured.colums");
  bad = good;
  bad["measured"]["width"] = "per_width";
  CHECK(field_of(bad) == "measured.width");
  bad = good;
  bad.erase("views");  // bases differ: an explicit view is required, but only compare() knows
  CHECK(field_of(bad) == "(no error)");
  CHECK_THROWS_AS(kerf::run_comparison(kerf::parse_comparison_config(bad, kFile.parent_path())), kerf::InputError);
}
