// A toy force model added to the orthogonal kind the way docs/analytic-models.md says: its unit here (predict, its
// own parameter block with its field table, its own details, its CSV columns and report lines: kinds/force_model.hpp,
// kinds/model_params.hpp) and one registry line (a test-only registration at start-up, before any scene is read) -
// nothing else in the library changes - and the orthogonal scene reads its name and its parameter, predicts with it
// and writes its row, its columns and its report; `kerf-forces keys` (the key reference) lists its parameter.
#include <fmt/format.h>

#include <any>
#include <catch2/catch.hpp>
#include <cstdio>
#include <string>
#include <string_view>

#include "kerf/analytic/kinds/evaluate.hpp"
#include "kerf/analytic/kinds/model_params.hpp"
#include "kerf/analytic/kinds/predict.hpp"
#include "kerf/analytic/registry.hpp"
#include "kerf/error.hpp"
#include "kerf/field_table.hpp"

using Catch::Matchers::Contains;
using kerf::Json;

namespace {

constexpr double kToySpecificForce_Pa = 2e9;  // F_c = k_c w t0 (no physics: it tests the plumbing)

/// The toy's own parameters: its block, read from the scene's `models` (kinds/model_params.hpp).
struct ToyParams {
  double specific_force_Pa = kToySpecificForce_Pa;  ///< k_c
};

const kerf::FieldTable<ToyParams>& toy_fields() {
  static const kerf::FieldTable<ToyParams> table{
      kerf::number_field("toy_specific_force_MPa", kerf::units::kMPa, kerf::Range::positive(),
                         "the toy's specific force k_c (F_c = k_c w t0; models.force = toy_specific_force)",
                         &ToyParams::specific_force_Pa)};
  return table;
}

const kerf::ModelParams toy_params{.fields = [] { return kerf::scene_params_fields(toy_fields()); }};

/// The toy's own details, kept in the prediction for its columns and report lines.
struct ToyDetails {
  double specific_force_Pa = 0.0;
};

void predict_toy(const kerf::AnalyticScene& scene, const kerf::OxleyResult*, kerf::Prediction& p) {
  const double k_c = scene.params<ToyParams>().specific_force_Pa;
  p.cutting_force_N = k_c * scene.width_m * scene.uncut_chip_thickness_m;
  p.thrust_force_N = 0.5 * p.cutting_force_N;
  p.shear_angle_rad = 0.5;
  p.chip_ratio = 1.0;
  p.chip_thickness_m = scene.uncut_chip_thickness_m;
  p.state.temperature_K = scene.workpiece_temperature_K;
  p.warnings.push_back("toy force model");
  p.details = ToyDetails{k_c};
}

double toy_specific_force_MPa(const kerf::Prediction& p) {
  const auto* own = std::any_cast<ToyDetails>(&p.details);
  return own ? own->specific_force_Pa * 1e-6 : 0.0;
}

/// Its column's key, and its columns as a result table (kerf/result_table.hpp): the row, the docs' column table and
/// Python's key names come from it.
namespace toy_keys {
KERF_RESULT_KEY(toy_specific_force_MPa)
}  // namespace toy_keys

const kerf::ResultTable<kerf::PredictionReport>& toy_results() {
  static const kerf::ResultTable<kerf::PredictionReport> table{kerf::result_value<kerf::PredictionReport>(
      toy_keys::toy_specific_force_MPa, "MPa", "the toy's specific force k_c",
      [](const kerf::PredictionReport& r) { return toy_specific_force_MPa(r.p); })};
  return table;
}

void print_toy(std::FILE* text, const kerf::AnalyticScene& scene, const kerf::Prediction& p) {
  // The number as the row holds it.
  const double k_c = kerf::result_of(toy_results(), {scene, p}, toy_keys::toy_specific_force_MPa).get<double>();
  fmt::print(text, "toy part          k_c = {:.6g} MPa\n", k_c);
}

const kerf::OrthogonalForceModel toy_force_model{.predict = &predict_toy, .results = &toy_results, .print = &print_toy};

// The one registry line (in the library it would be a line of analytic/registry.cpp), with its parameter block.
[[maybe_unused]] const bool registered =
    kerf::register_analytic_model({"force", "toy_specific_force", "test-only toy: F_c = k_c w t0", "cut", -1,
                                   &kerf::build_orthogonal_scene, &toy_force_model, &toy_params});

Json toy_scene() {
  return Json::parse(R"({"material": "a2024_t351",
                         "tool": {"rake_deg": 10, "edge_radius_um": 2},
                         "cut": {"uncut_chip_thickness_um": 10, "width_mm": 1, "speed_m_per_min": 60,
                                 "friction_angle_deg": 30},
                         "models": {"force": "toy_specific_force"}})");
}

std::string column(const kerf::Columns& row, std::string_view name) {
  for (const auto& [key, value] : row)
    if (key == name) return value;
  return "(none)";
}

}  // namespace

TEST_CASE("A toy force model plugs into the orthogonal kind through one registry line", "[registry][force]") {
  const auto scene = kerf::parse_analytic_scene(toy_scene());
  REQUIRE(scene.force);
  CHECK(scene.force->name == "toy_specific_force");
  CHECK_FALSE(scene.force_auto);

  // The CSV row: the toy's forces, none of the Liu-Li or Oxley columns (the toy asks for neither).
  const kerf::Columns row = kerf::evaluate_scene_columns(toy_scene(), nullptr);
  namespace k = kerf::prediction_keys;
  CHECK(column(row, k::force_model) == "toy_specific_force");
  CHECK(std::stod(column(row, k::cutting_force_N)) == Approx(kToySpecificForce_Pa * 1e-3 * 10e-6));
  CHECK(std::stod(column(row, k::thrust_force_N)) == Approx(0.5 * kToySpecificForce_Pa * 1e-3 * 10e-6));
  CHECK(column(row, kerf::edge_keys::lower_limit_deg) == "(none)");
  CHECK(column(row, kerf::oxley_keys::strain_rate_constant_C0) == "(none)");
  CHECK(column(row, k::warnings) == "toy force model");
  CHECK(column(row, toy_keys::toy_specific_force_MPa) == "2000");  // its own column, from its own details

  // The report names it; the key reference lists it with the other orthogonal models.
  auto scene_case = kerf::parse_scene(toy_scene(), nullptr);
  scene_case->predict();
  std::FILE* text = std::tmpfile();
  REQUIRE(text);
  scene_case->print(text, "toy.json");
  std::rewind(text);
  std::string report(4096, '\0');
  report.resize(std::fread(report.data(), 1, report.size(), text));
  std::fclose(text);
  CHECK_THAT(report, Contains("force model       toy_specific_force\n"));
  CHECK_THAT(report, Contains("toy part          k_c = 2000 MPa\n"));  // its own line
  CHECK_THAT(kerf::analytic_scene_keys_markdown("models"), Contains("`transition`, `toy_specific_force` |"));

  // auto still chooses among the built-in models (the toy has no say in it).
  Json doc = toy_scene();
  doc["models"]["force"] = "auto";
  CHECK(kerf::parse_analytic_scene(doc).force->name == "liu_li");
  CHECK(column(kerf::evaluate_scene_columns(doc, nullptr), toy_keys::toy_specific_force_MPa) == "(none)");  // its own
}

TEST_CASE("The models.force values of the orthogonal kind leave out the trepanning kind", "[registry][force]") {
  const std::string models = kerf::analytic_scene_keys_markdown("models");
  const std::string force_row = models.substr(models.find("| `force` |"));
  const std::string first_row = force_row.substr(0, force_row.find('\n'));
  CHECK_THAT(first_row, Contains("`auto`, `merchant`, `liu_li`, `oxley`"));
  CHECK_THAT(first_row, !Contains("`trepanning`,") && !Contains("`trepanning` |"));
  CHECK_THAT(first_row, Contains("`trepanning` is not a model of this scene"));
}

TEST_CASE("A toy force model's parameter is read from the scene, checked, listed and used", "[registry][force]") {
  // Its block's default where the scene gives none; the scene's value where it gives one.
  CHECK(kerf::parse_analytic_scene(toy_scene()).params<ToyParams>().specific_force_Pa == kToySpecificForce_Pa);
  Json doc = toy_scene();
  doc["models"]["toy_specific_force_MPa"] = 3000;
  const auto scene = kerf::parse_analytic_scene(doc);
  CHECK(scene.params<ToyParams>().specific_force_Pa == Approx(3e9));
  const kerf::Columns row = kerf::evaluate_scene_columns(doc, nullptr);
  CHECK(std::stod(column(row, kerf::prediction_keys::cutting_force_N)) ==
        Approx(3e9 * 1e-3 * 10e-6));  // F_c = k_c w t0 with its k_c
  CHECK(column(row, toy_keys::toy_specific_force_MPa) == "3000");

  // A bad value is an input error naming its key under models, with the range of its table.
  doc["models"]["toy_specific_force_MPa"] = -5;
  CHECK_THROWS_AS(kerf::parse_analytic_scene(doc), kerf::InputError);
  CHECK_THROWS_WITH(kerf::parse_analytic_scene(doc), Contains("models.toy_specific_force_MPa") && Contains("-5"));
  doc["models"]["toy_specific_force_MPa"] = "hard";
  CHECK_THROWS_WITH(kerf::parse_analytic_scene(doc), Contains("models.toy_specific_force_MPa"));

  // The key reference lists it among the models' keys, with its unit, range and default.
  CHECK_THAT(kerf::analytic_scene_keys_markdown("models"),
             Contains("| `toy_specific_force_MPa` | MPa | a positive value | 2000 | the toy's specific force k_c"));
  // The built-in models' keys keep their place: the toy's block comes after theirs, before the contact lengths.
  const std::string models = kerf::analytic_scene_keys_markdown("models");
  CHECK(models.find("`oxley_tolerance`") < models.find("`toy_specific_force_MPa`"));
  CHECK(models.find("`toy_specific_force_MPa`") < models.find("`contact_shear_angle`"));
}
