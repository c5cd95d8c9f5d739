// kerf-forces: quick cutting-force predictions and parameter sweeps from a scene file.
//
// `kerf-forces --help` lists the subcommands and `kerf-forces SUBCOMMAND --help` their options (the option table in
// main() is where each is described).
//
// Exit status: 0 success, 2 usage or input error (the message names the field, value and what was
// expected), 3 a model failed on valid input or a result would not be finite, 4 an output cannot be written
// (checked before any work), 1 anything else.
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <omp.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "kerf/analytic/kinds/evaluate.hpp"
#include "kerf/analytic/kinds/predict.hpp"
#include "kerf/analytic/kinds/scene.hpp"
#include "kerf/analytic/registry.hpp"
#include "kerf/analytic/sweep/scene_compare.hpp"
#include "kerf/analytic/sweep/sweep.hpp"
#include "kerf/comparison_config.hpp"
#include "kerf/error.hpp"
#include "kerf/io.hpp"
#include "kerf/material.hpp"
#include "kerf/plot.hpp"
#include "kerf/report.hpp"
#include "kerf/units.hpp"
#include "kerf/version.hpp"

namespace {

using kerf::Json;

Json load_scene_document(const std::string& path, const std::vector<std::string>& overrides) {
  Json document = kerf::read_json_file(path);
  for (const auto& assignment : overrides) kerf::apply_override(document, assignment);
  return document;
}

/// Where the human-readable text goes: standard error when the CSV goes to standard output (`--csv -`), so that
/// `kerf-forces predict SCENE --csv - > out.csv` writes nothing but the CSV there.
std::FILE* text_stream(const std::string& csv) {
  return csv == "-" ? stderr : stdout;
}

void write_row_csv(const std::string& csv, const kerf::Columns& columns) {
  std::vector<std::string> header, values;
  for (const auto& [name, value] : columns) header.push_back(name), values.push_back(value);
  kerf::write_file_atomically(csv, kerf::csv_line(header) + kerf::csv_line(values));
}

int run_predict(const std::string& scene_path, const std::vector<std::string>& overrides, const std::string& csv) {
  const auto scene = kerf::parse_scene(load_scene_document(scene_path, overrides), nullptr);
  scene->predict();
  scene->print(text_stream(csv), scene_path);
  if (!csv.empty()) write_row_csv(csv, kerf::scene_columns(*scene));
  return 0;
}

int run_regime(const std::string& scene_path, const std::vector<std::string>& overrides) {
  kerf::parse_scene(load_scene_document(scene_path, overrides), nullptr)->print_regime(stdout, scene_path);
  return 0;
}

/// One line per compared quantity: its error metrics, the percentages `width` characters wide.
void print_metrics(const kerf::Comparison& comparison, int width) {
  for (const auto& r : comparison.results) {
    const auto& m = r.metrics;
    fmt::print("{:<28} n = {:<3} mean |error| {:{}.2f} %   max |error| {:{}.2f} %   bias {:+{}.2f} %\n", r.key, m.n,
               m.mean_abs_error_percent, width, m.max_abs_error_percent, width, m.bias_percent, width);
  }
}

int run_compare(const std::string& scene_path, const std::vector<std::string>& overrides,
                const std::string& experiments, const kerf::SceneComparisonOptions& options,
                const std::string& out_dir) {
  const Json document = load_scene_document(scene_path, overrides);
  kerf::SceneComparison result = kerf::compare_scene(document, experiments, options);
  result.comparison.spec.description = fmt::format("Scene {} against {}.", scene_path, experiments);
  const auto files = kerf::write_report(result.comparison, out_dir, result.report);
  print_metrics(result.comparison, 6);
  if (result.calibration) {
    const auto& c = *result.calibration;
    fmt::print(
        "fitted            K_F = {:.6g} MPa (leave-one-out mean |error| {:.2f} %), K_M = {:.6g} MPa "
        "(leave-one-out {:.2f} %)\n",
        kerf::units::pa_to_mpa(c.axial.value_Pa), c.axial.loo.mean_abs_error_percent,
        kerf::units::pa_to_mpa(c.torque.value_Pa), c.torque.loo.mean_abs_error_percent);
  }
  if (!result.unused_columns.empty()) {
    fmt::print("unused columns    {} (neither a condition nor a quantity; --map binds them)\n",
               fmt::join(result.unused_columns, ", "));
  }
  for (const auto& row : result.rows) {
    if (row.guards.empty() && (row.regime.empty() || row.regime == "ductile")) continue;
    fmt::print("line {:<12} regime {}, guards {}\n", row.line, row.regime.empty() ? "-" : row.regime,
               row.guards.empty() ? "none" : fmt::format("{}", fmt::join(row.guards, ";")));
  }
  fmt::print("report            {} ({} files)\n", out_dir, files.size());
  return 0;
}

int run_report(const std::string& config_path, const std::string& out_dir) {
  const kerf::Comparison comparison = kerf::run_comparison(kerf::read_comparison_config(config_path));
  const auto files = kerf::write_report(comparison, out_dir);
  print_metrics(comparison, 7);
  fmt::print("report            {} ({} files)\n", out_dir, files.size());
  return 0;
}

int run_sweep(const std::string& scene_path, const std::vector<std::string>& overrides,
              const std::vector<std::string>& vary_specs, const std::string& csv, const std::string& plot) {
  if (!plot.empty()) kerf::check_figure_path(plot, "--plot");
  Json base = load_scene_document(scene_path, overrides);
  std::vector<kerf::SweepAxis> axes;
  for (const auto& spec : vary_specs) axes.push_back(kerf::parse_sweep_axis(spec, "--vary"));
  const kerf::SweepGrid grid(std::move(base), std::move(axes), "--vary");
  kerf::Progress progress("sweep", grid.size());
  const std::vector<kerf::SweepRow> rows = grid.run(false, [&](std::size_t n) { progress.advance(n); });
  progress.finish();
  kerf::write_file_atomically(csv, grid.csv_text(rows));
  if (!plot.empty()) kerf::plot_sweep(grid, rows, plot, scene_path);
  const auto n_failed = std::count_if(rows.begin(), rows.end(), [](const auto& row) { return !row.error.empty(); });
  fmt::print(stderr, "kerf-forces: {} points written to {} ({} refused with an error, see the 'error' column)\n",
             grid.size(), csv, n_failed);
  fmt::print(stderr, "kerf-forces: {}\n", kerf::sweep_summary(grid, rows));
  for (const auto& warning : kerf::falling_force_warnings(grid, rows)) {
    fmt::print(stderr, "kerf-forces: warning: {}\n", warning);
  }
  return 0;
}

int list_models() {
  for (const auto& m : kerf::analytic_models()) {
    fmt::print("models.{:<17} {:<17} {}{}\n", m.kind, m.name, m.summary,
               m.needs.empty() ? "" : fmt::format(" [needs {}]", m.needs));
  }
  return 0;
}

int list_materials() {
  for (const auto& m : kerf::library_materials()) {
    if (!m.record) {
      fmt::print("{:<20} (invalid: {})\n", m.name, m.error);
      continue;
    }
    std::vector<std::string> groups;
    for (const auto& [group, values] : m.record->groups.items()) groups.push_back(group);
    fmt::print("{:<20} {} [{}]\n", m.name, m.record->title, fmt::join(groups, ", "));
  }
  return 0;
}

}  // namespace

// Long (~90 lines) for a reason: the CLI's option table, one block per subcommand, each calling one library
// function (the work is in analytic/).
int main(int argc, char** argv) {
  CLI::App app{"kerf-forces: analytic cutting-force predictions (ductile regime) and sweeps"};
  app.require_subcommand(1);
  app.set_version_flag("--version", kerf::version_line("kerf-forces"));
  std::string scene_path, csv, plot;
  std::vector<std::string> overrides, vary;
  int threads = 0;

  const auto scene_command = [&](const std::string& name, const std::string& description) {
    auto* command = app.add_subcommand(name, description);
    command->add_option("scene", scene_path, "scene file (JSON)")->required();
    command->add_option("--set", overrides, "override a scene value: key.path=value (repeatable)");
    return command;
  };
  auto* predict = scene_command("predict", "predict the forces of one scene");
  predict->add_option("--csv", csv, "also write the result as one CSV row to this file");

  auto* sweep = scene_command("sweep", "evaluate a grid of scenes (cartesian product of --vary axes)");
  sweep->add_option("--vary", vary, "an axis: key.path=START:STOP:COUNT[:log] or key.path=A,B,C (repeatable)")
      ->required();
  sweep->add_option("--csv", csv, "CSV file to write")->required();
  sweep->add_option("--plot", plot,
                    "also a figure (.png or .svg with a PDF beside it, or .pdf): cutting and thrust force against the "
                    "first varied key, a line per value of the second");
  sweep->add_option("--threads", threads, "threads (default: all cores)")->check(CLI::Range(1, 1024));

  std::string experiments, out_dir;
  kerf::SceneComparisonOptions options;
  auto* compare = scene_command("compare", "hold a scene against measured forces: report.md, CSV, JSON, plots");
  compare->add_option("--experiments", experiments, "experiment CSV ('#' lines are its citation)")->required();
  compare->add_option("--map", options.mappings,
                      "bind a CSV column: scene.key.path=column (a condition) or prediction_column=column");
  compare->add_flag("--fit", options.fit, "fit the trepanning model's lumped groups to the measured rows first");
  compare->add_flag("--pool", options.pool,
                    "compare a CSV none of whose columns sets a condition: every row a measurement at the scene's own "
                    "condition (without it such a CSV is refused)");
  compare->add_option("--measured-width-mm", options.measured_width_mm, "width the measured forces act over (mm)")
      ->check(CLI::PositiveNumber);
  compare->add_option("--out", out_dir, "directory for the report")->required();

  std::string config_path;
  auto* report = app.add_subcommand("report", "compare CSV data sets described in a comparison file (JSON)");
  report->add_option("comparison", config_path, "comparison file (JSON), e.g. data/comparisons/*.json")->required();
  report->add_option("--out", out_dir, "directory for the report")->required();

  auto* regime = scene_command("regime", "ductile-brittle critical depth and the regime of the scene's cut");

  auto* models = app.add_subcommand("models", "list the registered models");
  auto* materials = app.add_subcommand("materials", "list the bundled material library");
  std::string section;
  auto* keys = app.add_subcommand("keys", "print the Markdown key table of the scene sections (docs/scenes.md)");
  keys->add_option("section", section,
                   "one section (" + fmt::format("{}", fmt::join(kerf::analytic_scene_sections(), ", ")) + ")");

  bool results_python = false;
  auto* results = app.add_subcommand(
      "results", "print the Markdown tables of a prediction's columns, orthogonal and trepanning (docs/scenes.md)");
  results->add_flag("--python", results_python,
                    "print them as the Python module kerf.prediction_keys instead (python/kerf/prediction_keys.py)");

  const auto error = [](const std::string& what, int status) {
    fmt::print(stderr, "kerf-forces: error: {}\n", kerf::printable(what));
    return status;
  };
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help
    return error(e.what(), kerf::kExitInputError);
  }
  try {
    if (threads > 0) omp_set_num_threads(threads);
    // The outputs are checked before any work: an unwritable place fails now, not after the sweep.
    for (const auto* command : {predict, sweep}) {
      if (*command && command->count("--csv") > 0) {
        if (csv.empty()) throw kerf::InputError("--csv", "\"\"", "a file name (leave --csv out for no CSV)");
        kerf::check_writable_file(csv);
      }
    }
    if ((*compare || *report) && out_dir.empty()) throw kerf::InputError("--out", "\"\"", "a directory name");
    if (*compare || *report) kerf::check_writable_directory(out_dir);
    if (*predict) return run_predict(scene_path, overrides, csv);
    if (*sweep) return run_sweep(scene_path, overrides, vary, csv, plot);
    if (*compare) return run_compare(scene_path, overrides, experiments, options, out_dir);
    if (*regime) return run_regime(scene_path, overrides);
    if (*report) return run_report(config_path, out_dir);
    if (*models) return list_models();
    if (*materials) return list_materials();
    if (*keys) {
      fmt::print("{}", kerf::analytic_scene_keys_markdown(section));
      return 0;
    }
    if (*results) {
      fmt::print("{}", results_python ? kerf::prediction_keys_python() : kerf::prediction_columns_markdown());
      return 0;
    }
  } catch (const std::exception&) {
    return kerf::report_error("kerf-forces");
  }
  return 0;
}
