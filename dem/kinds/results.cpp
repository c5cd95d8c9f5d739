// The result reference of the scene kinds (kerf-dem results; docs/dem-keys.md's result tables are its output) and
// the Python names of the result keys (kerf-dem results --python: python/kerf/result_keys.py), both from the result
// tables.
#include <fmt/format.h>

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "common.hpp"
#include "kerf/dem/output/output.hpp"
#include "kerf/dem/procedures/cut_results.hpp"
#include "kerf/dem/scene.hpp"
#include "kind_results.hpp"

namespace kerf::dem {

namespace {

struct ResultSection {
  std::string name, where, python_class;
  std::function<std::string()> markdown;
  std::function<std::vector<std::string>()> keys;
};

/// The section of one result table: `table()`'s rows and keys.
template <class R>
ResultSection section(std::string name, std::string where, std::string python_class, const ResultTable<R>& (*table)()) {
  return {std::move(name), std::move(where), std::move(python_class), [table] { return results_markdown(table()); },
          [table] { return result_keys(table()); }};
}

/// The name of a section nested in "results" under `key`: "results.<key>".
std::string within_results(std::string_view key) {
  return "results." + std::string(key);
}

const std::vector<ResultSection>& result_sections() {
  static const std::vector<ResultSection> list{
      {"results", "cut: one run's (with `--replicates`, the means over the replicates)", "CutResults",
       [] { return results_markdown(cut_results()) + results_markdown(cut_derived_results(), false); },
       cut_result_names},
      section(within_results(cut_keys::travel_windows),
              "cut: each stretch of `cut.window_mm` of travel (its forces also under their current names)",
              "TravelWindowResults", travel_window_results),
      section("active_window", "cut, with an active window", "ActiveWindowResults", active_window_results),
      section("results", "tension, compression", "LabTestResults", kinds::lab_test_results),
      section(within_results(kinds::lab_test_keys::quasi_static_check),
              "tension, compression, with `loading.quasi_static_check`: the test again at half the speed",
              "LabTestCheckResults", kinds::lab_test_check_results),
      section("results", "toughness: the means over the packings (`--replicates N`)", "ToughnessResults",
              kinds::toughness_results),
      section(within_results(kinds::toughness_keys::per_packing), "toughness: each packing's",
              "ToughnessPackingResults", kinds::toughness_packing_results),
      section(within_results(kinds::toughness_keys::quasi_static_check),
              "toughness, with `toughness.quasi_static_check`: the first packing again at half the speed",
              "ToughnessCheckResults", kinds::toughness_check_results),
      section("results", "calibrate", "CalibrateResults", kinds::calibrate_results),
      section("results", "calibrate_cut (each `main_force_*` also under its current name, `cutting_force_*`)",
              "CalibrateCutResults", kinds::calibrate_cut_results),
      section(within_results(kinds::calibrate_cut_keys::evaluations),
              "calibrate_cut: each evaluation's row (each `main_force_*` also as `cutting_force_*`)",
              "CalibrateCutEvaluationResults", kinds::calibrate_cut_evaluation_results),
      section("forces.csv", "cut: one row per sample, as the cut goes (the columns in this order)", "ForcesCsvColumns",
              cut_forces_columns),
      section("cracks.csv",
              "cut, tension, compression, toughness: one row per broken element (the columns in this order)",
              "CracksColumns", cracks_columns),
      section("curve.csv", "tension, compression: one row per sample (the columns in this order)", "CurveColumns",
              lab_test_curve_columns),
      section("curve.csv",
              "toughness: one row per sample, each packing's curve after the other (the columns in this order)",
              "ToughnessCurveColumns", kinds::toughness_curve_columns),
      section("calibration_log.csv", "calibrate: one row per evaluation (the columns in this order)",
              "CalibrationLogColumns", kinds::calibration_log_columns),
      section("calibration_log.csv", "calibrate_cut: one row per evaluation (the columns in this order)",
              "CalibrateCutLogColumns", kinds::calibrate_cut_log_columns)};
  return list;
}

}  // namespace

std::string scene_results_markdown() {
  std::string md;
  for (const auto& s : result_sections()) md += fmt::format("#### `{}`\n\n{}\n\n{}\n", s.name, s.where, s.markdown());
  return md;
}

std::string result_keys_python() {
  std::string py =
      "\"\"\"The keys of kerf-dem's results in summary.json and the columns of its CSV files, generated from their\n"
      "result tables (kerf-dem results --python > python/kerf/result_keys.py; tests/cli/dem_results_cli.sh checks it\n"
      "is current). Read a result or a column by its name here, never by a literal: a key renamed in its table then\n"
      "fails where it is read, by name.\"\"\"\n";
  for (const auto& s : result_sections())
    py += results_python_class(s.python_class, fmt::format("{}: {}.", s.name, s.where), s.keys());
  py += results_python_keys_function();
  return py;
}

}  // namespace kerf::dem
