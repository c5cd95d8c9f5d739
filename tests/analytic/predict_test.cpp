// An orthogonal prediction's row is its result tables (kinds/predict.hpp): the shared columns, the scene's contact
// lengths, the tables of the model units the scene's models carry (the chip term's edge, the Oxley solve's, the force
// model's own: forces/chip_term.hpp, forces/oxley_model.hpp, OrthogonalForceModel::results), the verdicts. A column
// written outside its unit's table, a table the row leaves out or a column out of its order fails here, for every
// bundled scene and every force model of the registry (the test-only toy of toy_force_model_test.cpp among them).
#include "kerf/analytic/kinds/predict.hpp"

#include <algorithm>
#include <catch2/catch.hpp>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "kerf/analytic/forces/chip_term.hpp"
#include "kerf/analytic/forces/oxley_model.hpp"
#include "kerf/analytic/forces/transition_model.hpp"
#include "kerf/analytic/kinds/evaluate.hpp"
#include "kerf/analytic/registry.hpp"
#include "kerf/io.hpp"

namespace fs = std::filesystem;
using kerf::Json;
using kerf::PredictionReport;
using kerf::ResultTable;

namespace {

/// The keys of `table` that the row of `report` carries (result_if), appended to `names`.
void append_present(const ResultTable<PredictionReport>& table, const PredictionReport& report,
                    std::vector<std::string>& names) {
  for (const auto& f : table)
    if (!f.present || f.present(report)) names.push_back(f.key);
}

std::vector<std::string> names_of(const kerf::Columns& row) {
  std::vector<std::string> names;
  for (const auto& [name, text] : row) names.push_back(name);
  return names;
}

/// The row's column names as the tables declare them: the shared columns, the contact lengths, `units` (each unit's
/// table), the verdicts.
std::vector<std::string> declared(const kerf::AnalyticScene& scene, const kerf::Prediction& p,
                                  const std::vector<const ResultTable<PredictionReport>*>& units) {
  const PredictionReport report{scene, p};
  std::vector<std::string> names;
  append_present(kerf::prediction_results(), report, names);
  for (const auto& request : scene.contact_lengths) names.push_back(request.column);
  for (const auto* unit : units) append_present(*unit, report, names);
  append_present(kerf::prediction_verdict_results(), report, names);
  return names;
}

/// The bundled orthogonal scenes (data/scenes/*.json without a DEM kind; no trepanning scene lies there).
std::vector<fs::path> bundled_orthogonal_scenes() {
  std::vector<fs::path> scenes;
  for (const auto& entry : fs::directory_iterator(fs::path(KERF_SOURCE_DIR) / "data" / "scenes"))
    if (entry.path().extension() == ".json" && !kerf::read_json_file(entry.path().string()).contains("kind"))
      scenes.push_back(entry.path());
  std::sort(scenes.begin(), scenes.end());
  return scenes;
}

/// The row (after predict) and the column names the kind writes before predict (a sweep's header).
struct Written {
  kerf::Columns row;
  std::vector<std::string> header;
};
Written write(const Json& doc) {
  auto scene_case = kerf::parse_scene(doc, nullptr);
  kerf::ColumnCollector header;
  scene_case->write_cells(header);
  scene_case->predict();
  kerf::ColumnCollector row;
  scene_case->write_cells(row);
  return {std::move(row.columns), names_of(header.columns)};
}

}  // namespace

TEST_CASE("A bundled scene's row is its tables' columns, in their order", "[predict][results]") {
  const auto scenes = bundled_orthogonal_scenes();
  REQUIRE(scenes.size() >= 5);
  for (const auto& path : scenes) {
    INFO(path.filename().string());
    const Json doc = kerf::read_json_file(path.string());
    const kerf::AnalyticScene scene = kerf::parse_analytic_scene(doc);
    const kerf::Prediction p = kerf::predict(scene);
    std::vector<const ResultTable<PredictionReport>*> units;
    for (const auto* unit : kerf::prediction_model_results(scene))
      if (unit) units.push_back(unit);
    const Written written = write(doc);
    CHECK(names_of(written.row) == declared(scene, p, units));
    CHECK(written.header == names_of(written.row));  // the names before predict: the same columns
  }
}

TEST_CASE("Each force model's row carries its units' tables", "[predict][results][registry]") {
  const Json liu_li = kerf::read_json_file(std::string(KERF_SOURCE_DIR) + "/data/scenes/psic_liu_li.json");
  const Json oxley = kerf::read_json_file(std::string(KERF_SOURCE_DIR) + "/data/scenes/aisi1045_oxley.json");
  const Json transition = kerf::read_json_file(std::string(KERF_SOURCE_DIR) + "/data/scenes/soda_lime_transition.json");
  const auto& edge = kerf::edge_results();
  const auto& solve = kerf::oxley_results();
  // Which shared units each model's row carries, and whether a table of its own follows them (its registry line's,
  // OrthogonalForceModel::results).
  struct Case {
    const Json* scene;
    std::vector<const ResultTable<PredictionReport>*> units;
    bool own = false;
  };
  const std::map<std::string, Case> cases = {
      {"auto", {&liu_li, {&edge, &solve}}},
      {"merchant", {&liu_li, {}}},
      {"liu_li", {&liu_li, {&edge}}},
      {"oxley", {&oxley, {&solve}}},
      {"transition", {&transition, {&edge}, true}},
      {"toy_specific_force", {&liu_li, {}, true}}};  // the test-only toy (toy_force_model_test.cpp)
  std::set<std::string> seen;
  for (const auto& m : kerf::analytic_models()) {
    if (m.kind != "force" || !m.orthogonal) continue;
    const std::string name(m.name);
    INFO("models.force = " << name);
    REQUIRE(cases.count(name) == 1);  // a new force model: say here which units its row carries
    seen.insert(name);
    Json doc = *cases.at(name).scene;
    doc["models"]["force"] = name;
    std::vector<const ResultTable<PredictionReport>*> units = cases.at(name).units;
    CHECK(static_cast<bool>(m.orthogonal->results) == cases.at(name).own);
    if (m.orthogonal->results) units.push_back(&m.orthogonal->results());
    const kerf::AnalyticScene scene = kerf::parse_analytic_scene(doc);
    const Written written = write(doc);
    CHECK(names_of(written.row) == declared(scene, kerf::predict(scene), units));
    CHECK(written.header == names_of(written.row));
  }
  CHECK(seen.size() == cases.size());
}

TEST_CASE("The model units' columns carry their unit's suffix, each key one column of the row", "[predict][results]") {
  std::vector<const ResultTable<PredictionReport>*> units = {&kerf::edge_results(), &kerf::oxley_results()};
  for (const auto& m : kerf::analytic_models())
    if (m.kind == "force" && m.orthogonal && m.orthogonal->results) units.push_back(&m.orthogonal->results());
  std::set<std::string> keys;
  for (const auto* shared : {&kerf::prediction_results(), &kerf::prediction_verdict_results()})
    for (const auto& f : *shared) keys.insert(f.key);
  for (const auto* unit : units) {
    for (const auto& f : *unit) {
      INFO(f.key);
      CHECK(keys.insert(f.key).second);
      CHECK(f.key.ends_with(kerf::result_unit_suffix(f.unit)));
    }
  }
}

TEST_CASE("kerf-forces results lists each unit's columns, and Python names them", "[predict][results]") {
  const std::string md = kerf::prediction_columns_markdown();
  const std::string py = kerf::prediction_keys_python();
  CHECK(md.find("`models.force` `auto`, `liu_li` and `transition`") != std::string::npos);
  CHECK(md.find("`models.force = transition`'s own columns") != std::string::npos);
  CHECK(md.find("`models.force = toy_specific_force`'s own columns") != std::string::npos);  // registered by a test
  for (const auto* table : {&kerf::edge_results(), &kerf::oxley_results(), &kerf::transition_results()}) {
    for (const auto& f : *table) {
      INFO(f.key);
      CHECK(md.find("| `" + f.key + "` |") != std::string::npos);
      CHECK(py.find("    " + f.key + " = \"" + f.key + "\"\n") != std::string::npos);
    }
  }
  for (const char* cls :
       {"class EdgeColumns:", "class OxleyColumns:", "class TransitionColumns:", "class ToySpecificForceColumns:"})
    CHECK(py.find(cls) != std::string::npos);
}
