// A toy scene kind added the way docs/analytic-models.md says: its own class and builder here, and one registry
// line (a test-only registration) - nothing else in the library changes - and parse_scene, the CSV row, the
// report and the sweep (with its unknown-key check and its error column) all run it.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cstdio>
#include <string>

#include "kerf/analytic/kinds/evaluate.hpp"
#include "kerf/analytic/registry.hpp"
#include "kerf/analytic/sweep/sweep.hpp"
#include "kerf/error.hpp"

using kerf::Json;

namespace {

/// A "force model" F = specific force x width x depth (no physics: it tests the plumbing).
class ToyCase final : public kerf::AnalyticCase {
 public:
  explicit ToyCase(const Json& document) {
    kerf::ObjectReader root(document, "");
    root.ignore("material");
    auto cut = root.get_object("cut");
    width_mm_ = cut.get_number("width_mm", kerf::Range::positive(), "mm");
    depth_um_ = cut.get_number("depth_um", kerf::Range::positive(), "um");
    cut.finish();
    auto models = root.get_object("models");
    models.get_choice("force", {"toy"});
    specific_N_per_mm2_ = models.get_number_or("specific_force_N_per_mm2", 1000.0, kerf::Range::positive(), "N/mm^2");
    models.finish();
    root.finish();
  }
  void predict() override {
    if (depth_um_ > 100.0) throw kerf::ModelError("toy", "deeper than 100 um");
    force_N_ = specific_N_per_mm2_ * width_mm_ * depth_um_ * 1e-3;
  }
  void write_cells(kerf::CellWriter& out) const override {
    out.text("force_model", "toy");
    out.number("width_mm", width_mm_);
    out.number("cutting_force_N", force_N_);
  }
  void print(std::FILE* text, const std::string& scene_path) const override {
    std::fprintf(text, "%s: toy force %g N\n", scene_path.c_str(), force_N_);
  }
  void print_regime(std::FILE*, const std::string&) const override {}
  std::string_view comparison_title() const override { return "Toy model"; }

 private:
  double width_mm_ = 0.0, depth_um_ = 0.0, specific_N_per_mm2_ = 0.0, force_N_ = 0.0;
};

std::unique_ptr<kerf::AnalyticCase> build_toy(const Json& document, kerf::MaterialCache*) {
  return std::make_unique<ToyCase>(document);
}

// The one registry line (in the library it would be a line of analytic/registry.cpp).
void register_toy() {
  static const bool registered =
      kerf::register_analytic_model({"force", "toy", "test-only toy: F = specific force x width x depth",
                                     "cut.width_mm, cut.depth_um", -1, &build_toy});
  (void)registered;
}

Json toy_scene() {
  return Json::parse(R"({"material": "none", "cut": {"width_mm": 2, "depth_um": 10},
                         "models": {"force": "toy", "specific_force_N_per_mm2": 500}})");
}

}  // namespace

TEST_CASE("A toy scene kind plugs in through one registry line", "[registry][kinds]") {
  register_toy();
  CHECK_THROWS_AS(kerf::register_analytic_model({"force", "toy", "", "", -1, &build_toy}), std::logic_error);
  const auto& names = kerf::analytic_model_names("force");
  CHECK(std::find(names.begin(), names.end(), "toy") != names.end());

  // parse_scene picks the kind by models.force; the row comes from the kind.
  const kerf::Columns row = kerf::evaluate_scene_columns(toy_scene(), nullptr);
  REQUIRE(row.size() == 3);
  CHECK(row[0] == std::pair<std::string, std::string>{"force_model", "toy"});
  CHECK(row[2].first == "cutting_force_N");
  CHECK(std::stod(row[2].second) == Approx(500.0 * 2.0 * 10.0 * 1e-3));

  // The sweep runs it: its unknown-key check reads the kind's own keys, refused points keep their error.
  CHECK_THROWS_WITH(kerf::SweepGrid(toy_scene(), {kerf::parse_sweep_axis("cut.depth_mm=1,2")}, "--vary"),
                    Catch::Contains("--vary = cut.depth_mm: expected a known key (did you mean 'depth_um'?)"));
  const kerf::SweepGrid grid(toy_scene(), {kerf::parse_sweep_axis("cut.depth_um=50,200,-1")}, "--vary");
  const auto rows = grid.run();
  REQUIRE(rows.size() == 3);
  CHECK(rows[0].error.empty());
  CHECK(kerf::cell_number(rows[0].cells, 2) == Approx(500.0 * 2.0 * 50.0 * 1e-3));
  CHECK(rows[1].error == "model 'toy': deeper than 100 um");
  CHECK_THAT(rows[2].error, Catch::Contains("cut.depth_um"));
  const std::string csv = grid.csv_text(rows);
  CHECK(csv.substr(0, csv.find('\n')) == "cut.depth_um,force_model,width_mm,cutting_force_N,error");
}
