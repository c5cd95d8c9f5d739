#include "kerf/analytic/sweep/scene_compare.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

#include "kerf/analytic/kinds/predict.hpp"
#include "kerf/analytic/kinds/scene.hpp"
#include "kerf/error.hpp"

using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;
using kerf::Json;

namespace {
Json planing_scene() {
  return Json::parse(R"({
    "material": "a2024_t351",
    "tool": {"rake_deg": 15, "edge_radius_um": 35},
    "cut": {"uncut_chip_thickness_um": 100, "width_mm": 2, "speed_m_per_min": 10, "friction_coefficient": 0.2},
    "models": {"force": "liu_li"}
  })");
}

double predicted_cutting_force(double t0_um) {
  auto doc = planing_scene();
  doc["cut"]["uncut_chip_thickness_um"] = t0_um;
  return kerf::predict(kerf::parse_analytic_scene(doc)).cutting_force_N;
}

std::filesystem::path write_csv(const std::string& name, const std::string& text) {
  const auto path = std::filesystem::temp_directory_path() / (std::to_string(::getpid()) + "-" + name);
  std::ofstream(path) << text;
  return path;
}
}  // namespace

TEST_CASE("Compare matches columns by name and measures the error of each row", "[compare]") {
  // Measurements 10 % below the model: every row's error is +1/0.9 - 1 = +11.1 %.
  std::string text = "# synthetic: the model's own forces times 0.9\nuncut_chip_thickness_um,cutting_force_N\n";
  for (double t0 : {50.0, 100.0, 150.0}) text += fmt::format("{},{}\n", t0, 0.9 * predicted_cutting_force(t0));
  const auto csv = write_csv("kerf_compare_planing.csv", text);
  const auto result = kerf::compare_scene(planing_scene(), csv, {});
  const auto& r = result.comparison.result("cutting_force");
  CHECK(r.metrics.n == 3);
  CHECK_THAT(r.metrics.mean_abs_error_percent, WithinRel(100.0 / 0.9 - 100.0, 1e-9));
  CHECK_THAT(r.metrics.bias_percent, WithinRel(100.0 / 0.9 - 100.0, 1e-9));
  std::filesystem::remove(csv);
}

TEST_CASE("Compare shows both width views when the measured width differs", "[compare][width]") {
  // Forces measured over 4 mm (twice the scene's width): as published the model is 50 % low, per unit width exact.
  std::string text = "uncut_chip_thickness_um,width_mm,cutting_force_N\n";
  for (double t0 : {50.0, 100.0}) text += fmt::format("{},4,{}\n", t0, 2.0 * predicted_cutting_force(t0));
  const auto csv = write_csv("kerf_compare_width.csv", text);
  const auto result = kerf::compare_scene(planing_scene(), csv, {});
  CHECK_THAT(result.comparison.result("cutting_force").metrics.bias_percent, WithinAbs(-50.0, 1e-9));
  CHECK_THAT(result.comparison.result("cutting_force_per_width").metrics.max_abs_error_percent, WithinAbs(0.0, 1e-9));
  std::filesystem::remove(csv);
}

TEST_CASE("Compare refuses what it cannot match or fit", "[compare]") {
  const auto csv = write_csv("kerf_compare_bad.csv", "uncut_chip_thickness_um,force\n100,5\n");
  CHECK_THROWS_AS(kerf::compare_scene(planing_scene(), csv, {}), kerf::InputError);
  kerf::SceneComparisonOptions misspelt;
  misspelt.mappings = {"cutting_force_N=forse"};
  CHECK_THROWS_AS(kerf::compare_scene(planing_scene(), csv, misspelt), kerf::InputError);
  kerf::SceneComparisonOptions fit;
  fit.mappings = {"cutting_force_N=force"};
  fit.fit = true;
  CHECK_THROWS_WITH(kerf::compare_scene(planing_scene(), csv, fit), Catch::Matchers::Contains("trepanning"));
  std::filesystem::remove(csv);
}
