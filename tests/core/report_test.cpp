#include "kerf/report.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "file_text.hpp"
#include "kerf/error.hpp"

using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;
namespace fs = std::filesystem;

namespace {

kerf::ComparisonSpec depth_spec() {
  kerf::ComparisonSpec spec;
  spec.title = "Hand-made";
  spec.conditions = {{"surface", "Surface", {"", "", 1.0}, false},
                     {"depth_of_cut", "Depth of cut", {"mm", "mm", 1e-3}, true}};
  spec.quantities = {{"main_force", "Main force F#dc#u", {"N", "N", 1.0}, {"N/mm", "N_per_mm", 1e3}}};
  return spec;
}

kerf::DataRow row(const std::string& surface, double depth_mm, double value, std::size_t line = 0) {
  return {{kerf::ConditionValue::label(surface), kerf::ConditionValue::number(depth_mm * 1e-3)}, {value}, line};
}

fs::path fresh_directory(const std::string& name) {
  const fs::path dir = fs::path(KERF_BINARY_DIR) / "test_output" / name;
  fs::remove_all(dir);
  return dir;
}

bool has_leftovers(const fs::path& dir) {
  for (const auto& entry : fs::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (name.find(".tmp-") != std::string::npos || name.rfind(".staging-", 0) == 0) return true;
  }
  return false;
}

}  // namespace

TEST_CASE("Matching conditions: numbers within a relative tolerance, text exactly", "[report][match]") {
  using kerf::ConditionValue;
  CHECK(kerf::conditions_match(ConditionValue::number(90.5), ConditionValue::number(90.50001), 1e-6));
  CHECK_FALSE(kerf::conditions_match(ConditionValue::number(90.5), ConditionValue::number(90.6), 1e-6));
  CHECK(kerf::conditions_match(ConditionValue::number(90.5), ConditionValue::number(90.6), 2e-3));
  CHECK(kerf::conditions_match(ConditionValue::number(0.0), ConditionValue::number(0.0), 1e-6));
  CHECK(kerf::conditions_match(ConditionValue::label("grooved"), ConditionValue::label("grooved"), 1e-6));
  CHECK_FALSE(kerf::conditions_match(ConditionValue::label("grooved"), ConditionValue::label("regular"), 1e-6));
  CHECK_FALSE(kerf::conditions_match(ConditionValue::label("1"), ConditionValue::number(1.0), 1e-6));
}

TEST_CASE("Replicates: group mean and SD, and whether the prediction lies in the scatter", "[report][replicates]") {
  const auto spec = depth_spec();
  const kerf::DataSet measured{"measured",
                               "",
                               {"hand-made"},
                               {kerf::WidthBasis::total(1e-3)},
                               {row("regular", 0.1, 10, 2), row("regular", 0.1, 12, 3), row("regular", 0.1, 14, 4),
                                row("regular", 0.2, 20, 5), row("grooved", 0.1, 5, 6)}};
  // The grooved row has no prediction; 0.1 mm is predicted as 0.1000000001 mm (inside the tolerance).
  const kerf::DataSet predicted{"model",
                                "",
                                {},
                                {kerf::WidthBasis::total(1e-3)},
                                {row("regular", 0.1000000001, 13), row("regular", 0.2, 22), row("regular", 0.3, 30)}};
  const auto c = kerf::compare(spec, measured, {{predicted, {}}});
  const auto& r = c.result("main_force");
  REQUIRE(r.groups.size() == 2);
  const auto& a = r.groups[0];
  CHECK(a.measured.size() == 3);
  CHECK_THAT(a.measured_stats.mean, WithinRel(12.0, 1e-15));
  CHECK_THAT(a.measured_stats.standard_deviation, WithinRel(2.0, 1e-15));
  CHECK(a.has_scatter);
  CHECK(a.within_1sd);  // |13 - 12| <= 2
  CHECK(a.within_2sd);
  CHECK_THAT(a.error_percent, WithinRel(100.0 / 12.0, 1e-14));
  REQUIRE(a.row_error_percent.size() == 3);
  CHECK_THAT(a.row_error_percent[0], WithinRel(30.0, 1e-14));
  CHECK_THAT(a.row_error_percent[2], WithinRel(-100.0 / 14.0, 1e-14));
  CHECK(a.measured_lines == std::vector<std::size_t>{2, 3, 4});
  CHECK_FALSE(r.groups[1].has_scatter);
  CHECK_THAT(r.groups[1].error_percent, WithinRel(10.0, 1e-14));
  // Metrics over the two groups: errors 8.333 % and 10 %.
  CHECK(r.metrics.n == 2);
  CHECK_THAT(r.metrics.mean_abs_error_percent, WithinRel((100.0 / 12.0 + 10.0) / 2.0, 1e-14));
  CHECK_THAT(r.metrics.max_abs_error_percent, WithinRel(10.0, 1e-14));
  CHECK_THAT(r.metrics.bias_percent, WithinRel((100.0 / 12.0 + 10.0) / 2.0, 1e-14));
  CHECK(r.row_metrics.n == 4);
  CHECK(r.n_with_scatter == 1);
  CHECK(r.n_within_1sd == 1);
  REQUIRE(r.unmatched.size() == 1);
  CHECK(r.unmatched[0][0].text == "grooved");

  // A prediction 1.5 SD away: inside +-2 SD, outside +-1 SD.
  const kerf::DataSet off{"off", "", {}, {kerf::WidthBasis::total(1e-3)}, {row("regular", 0.1, 15)}};
  const auto c2 = kerf::compare(spec, measured, {{off, {}}});
  CHECK_FALSE(c2.result("main_force").groups[0].within_1sd);
  CHECK(c2.result("main_force").groups[0].within_2sd);
}

TEST_CASE("Width bases convert through the force per unit width", "[report][width]") {
  using kerf::WidthBasis;
  CHECK_THAT(kerf::to_per_unit_width(25.4, WidthBasis::total(25.4e-3)), WithinRel(1000.0, 1e-14));  // N/m
  CHECK_THAT(kerf::to_per_unit_width(3.0, WidthBasis::per_unit_width()), WithinRel(3.0, 1e-15));
  CHECK_THAT(kerf::convert_width_basis(25.4, WidthBasis::total(25.4e-3), WidthBasis::total(1e-3)),
             WithinRel(1.0, 1e-14));
  CHECK_THAT(kerf::convert_width_basis(0.7, WidthBasis::per_unit_width(), WidthBasis::total(2e-3)),
             WithinRel(1.4e-3, 1e-14));
  CHECK_THROWS_AS(kerf::to_per_unit_width(1.0, WidthBasis::none()), kerf::InputError);
  CHECK_THROWS_AS(kerf::to_per_unit_width(1.0, WidthBasis::total(0.0)), kerf::InputError);
  CHECK(WidthBasis::total(25.4e-3).describe() == "total force over a 25.4 mm width");
}

TEST_CASE("Yang et al. 2018: experiment (25.4 mm) against the paper's DEM (1 mm) needs an explicit width view",
          "[report][width]") {
  const auto table =
      kerf::read_csv_file(std::string(KERF_SOURCE_DIR) + "/data/experiments/soda_lime_orthogonal_cutting.csv");
  auto spec = depth_spec();
  kerf::CsvBinding experiment{"experiment",
                              {"surface", "depth_of_cut_mm"},
                              {1.0, 1e-3},
                              {"main_force_N"},
                              {1.0},
                              {kerf::WidthBasis::total(0.0)},
                              {{"source", "experiment"}},
                              "width_mm"};
  kerf::CsvBinding dem = experiment;
  dem.name = "paper's DEM";
  dem.row_filter = {{"source", "paper_dem"}};
  const auto measured = kerf::dataset_from_csv(table, spec, experiment);
  const auto predicted = kerf::dataset_from_csv(table, spec, dem);
  CHECK(measured.bases[0] == kerf::WidthBasis::total(25.4e-3));
  CHECK(predicted.bases[0] == kerf::WidthBasis::total(1e-3));
  CHECK(measured.rows.size() == 12);
  CHECK(measured.citations.size() == 8);  // the table's '#' lines, the paper's full reference among them
  CHECK(measured.citations[1].rfind("Source: Yang et al. 2018, Table 6", 0) == 0);

  // No view chosen and the bases differ: refused.
  try {
    kerf::compare(spec, measured, {{predicted, {}}});
    FAIL("expected an InputError");
  } catch (const kerf::InputError& e) {
    CHECK(e.field() == "comparison.views (main_force)");
  }
  spec.views = {kerf::WidthView::as_published, kerf::WidthView::per_unit_width};
  const auto c = kerf::compare(spec, measured, {{predicted, {}}});
  const auto& direct = c.result("main_force");
  const auto& per_width = c.result("main_force_per_width");
  REQUIRE(direct.groups.size() == 4);
  // regular, 0.1 mm: experiment 17.8, 15.0, 16.7 N (mean 16.5); DEM 14.15, 15.40, 15.38 N (mean 14.977).
  const double exp_mean = (17.8 + 15.0 + 16.7) / 3.0, dem_mean = (14.15 + 15.40 + 15.38) / 3.0;
  CHECK_THAT(direct.groups[0].measured_stats.mean, WithinRel(exp_mean, 1e-12));
  CHECK_THAT(direct.groups[0].error_percent, WithinRel(100.0 * (dem_mean - exp_mean) / exp_mean, 1e-12));
  CHECK(direct.groups[0].predicted.size() == 3);
  CHECK_FALSE(direct.note.empty());
  // Per unit width: 16.5 N / 25.4 mm against 14.977 N / 1 mm: the DEM is 23 times the experiment.
  CHECK_THAT(per_width.groups[0].measured_stats.mean, WithinRel(exp_mean / 25.4e-3, 1e-12));
  CHECK_THAT(per_width.groups[0].error_percent,
             WithinRel(100.0 * (dem_mean / 1.0 - exp_mean / 25.4) / (exp_mean / 25.4), 1e-12));
  CHECK(per_width.unit.label == "N/mm");
  const auto csv = kerf::comparison_csv(c);
  CHECK(csv.find("main_force_per_width_measured_N_per_mm") != std::string::npos);
  const auto summary = kerf::summary_json(c);
  CHECK(summary["quantities"]["main_force"]["measured_width_basis"]["width_mm"].get<double>() == Approx(25.4));
  CHECK(summary["quantities"]["main_force_per_width"]["n"] == 4);
}

TEST_CASE("A width column that changes within one data set is refused, naming the cell", "[report][width][errors]") {
  const auto table = kerf::parse_csv("surface,depth_mm,width_mm,f_N\nregular,0.1,25.4,10\nregular,0.2,1,11\n", "w.csv");
  const kerf::CsvBinding b{"mixed", {"surface", "depth_mm"},        {1.0, 1e-3}, {"f_N"},
                           {1.0},   {kerf::WidthBasis::total(0.0)}, {},          "width_mm"};
  CHECK_THROWS_WITH(kerf::dataset_from_csv(table, depth_spec(), b),
                    "w.csv:3: column 3 'width_mm' = 1: expected the width of the other rows of 'mixed' (25.4 mm)");
}

TEST_CASE("The report directory: summary, CSV and plots, written whole", "[report][files]") {
  const auto spec = depth_spec();
  const kerf::DataSet measured{
      "measured",
      "hand.csv",
      {"Source: hand-made"},
      {kerf::WidthBasis::total(1e-3)},
      {row("regular", 0.1, 10, 2), row("regular", 0.1, 12, 3), row("regular", 0.2, 20, 4), row("regular", 0.3, 28, 5)}};
  const kerf::DataSet predicted{"model",
                                "",
                                {},
                                {kerf::WidthBasis::total(1e-3)},
                                {row("regular", 0.1, 11), row("regular", 0.2, 19), row("regular", 0.3, 30)}};
  kerf::ModelCurve curve = [](const std::vector<kerf::ConditionValue>& c) {
    return std::vector<double>{*c[1].si * 1e5};
  };
  const auto c = kerf::compare(spec, measured, {{predicted, curve}});
  const fs::path dir = fresh_directory("report_files");
  const auto files = kerf::write_report(c, dir);
  CHECK(fs::exists(dir / "report.md"));
  CHECK(fs::exists(dir / "comparison.csv"));
  CHECK(fs::exists(dir / "summary.json"));
  CHECK(fs::exists(dir / "parity_main_force.png"));
  CHECK(fs::exists(dir / "main_force_vs_depth_of_cut.png"));
  CHECK_FALSE(has_leftovers(dir));
  const std::string png = kerf::testing::file_text(dir / "parity_main_force.png");
  CHECK(png.substr(1, 3) == "PNG");
  const auto summary = kerf::Json::parse(kerf::testing::file_text(dir / "summary.json"));
  const auto& q = summary["quantities"]["main_force"];
  CHECK(q["n"] == 3);
  CHECK_THAT(q["mean_abs_error_percent"].get<double>(), WithinRel((0.0 + 5.0 + 100.0 * 2.0 / 28.0) / 3.0, 1e-12));
  CHECK_THAT(q["max_abs_error_percent"].get<double>(), WithinRel(100.0 * 2.0 / 28.0, 1e-12));
  CHECK_THAT(q["bias_percent"].get<double>(), WithinRel((0.0 - 5.0 + 100.0 * 2.0 / 28.0) / 3.0, 1e-12));
  const auto table = kerf::parse_csv(kerf::testing::file_text(dir / "comparison.csv"), "comparison.csv");
  CHECK(table.header.at(2) == "surface");
  CHECK(table.header.at(3) == "depth_of_cut_mm");
  CHECK(table.has_column("main_force_measured_N"));
  CHECK(table.has_column("main_force_error_percent"));
  CHECK(table.rows.size() == 4);
  CHECK_THAT(table.number(0, table.column_index("main_force_error_percent")), WithinRel(10.0, 1e-12));
  const std::string md = kerf::testing::file_text(dir / "report.md");
  CHECK(md.find("> Source: hand-made") != std::string::npos);
  CHECK(md.find("![") != std::string::npos);
  CHECK(md.find("total force over a 1 mm width") != std::string::npos);
}

TEST_CASE("A failed report leaves the previous files whole and nothing half-written", "[report][files][errors]") {
  const auto spec = depth_spec();
  const kerf::DataSet measured{"measured", "", {}, {kerf::WidthBasis::total(1e-3)}, {row("regular", 0.1, 10)}};
  const kerf::DataSet first{"first", "", {}, {kerf::WidthBasis::total(1e-3)}, {row("regular", 0.1, 11)}};
  const kerf::DataSet second{"second", "", {}, {kerf::WidthBasis::total(1e-3)}, {row("regular", 0.1, 12)}};
  const fs::path dir = fresh_directory("report_atomic");
  kerf::write_report(kerf::compare(spec, measured, {{first, {}}}), dir);
  const std::string old_md = kerf::testing::file_text(dir / "report.md");
  // Block one target: the second report must not replace any file.
  fs::remove(dir / "summary.json");
  fs::create_directory(dir / "summary.json");
  CHECK_THROWS_AS(kerf::write_report(kerf::compare(spec, measured, {{second, {}}}), dir), kerf::InputError);
  CHECK(kerf::testing::file_text(dir / "report.md") == old_md);
  CHECK_FALSE(has_leftovers(dir));
  // A fresh directory with a blocked target gets no files at all.
  const fs::path empty = fresh_directory("report_atomic_empty");
  fs::create_directories(empty / "comparison.csv");
  CHECK_THROWS(kerf::write_report(kerf::compare(spec, measured, {{second, {}}}), empty));
  CHECK_FALSE(fs::exists(empty / "report.md"));
  CHECK_FALSE(fs::exists(empty / "summary.json"));
  CHECK_FALSE(has_leftovers(empty));
}

TEST_CASE("Comparisons refuse data that do not fit", "[report][errors]") {
  const auto spec = depth_spec();
  const kerf::DataSet measured{"measured", "", {}, {kerf::WidthBasis::total(1e-3)}, {row("regular", 0.1, 10)}};
  const kerf::DataSet elsewhere{"model", "", {}, {kerf::WidthBasis::total(1e-3)}, {row("regular", 0.5, 10)}};
  CHECK_THROWS_AS(kerf::compare(spec, measured, {{elsewhere, {}}}), kerf::InputError);
  const kerf::DataSet zero{"zero", "", {}, {kerf::WidthBasis::total(1e-3)}, {row("regular", 0.1, 0.0)}};
  CHECK_THROWS_AS(kerf::compare(spec, zero, {{measured, {}}}), kerf::InputError);  // relative to a zero measurement
  kerf::DataSet short_row = measured;
  short_row.rows[0].values.clear();
  CHECK_THROWS_AS(kerf::compare(spec, short_row, {{measured, {}}}), kerf::InputError);
  auto torque_spec = spec;
  torque_spec.views = {kerf::WidthView::per_unit_width};
  const kerf::DataSet torque{"t", "", {}, {kerf::WidthBasis::none()}, {row("regular", 0.1, 10)}};
  CHECK_THROWS_AS(kerf::compare(torque_spec, torque, {{torque, {}}}), kerf::InputError);
}
