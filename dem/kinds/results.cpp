// The result reference of the scene kinds (kerf-dem results; docs/dem-keys.md's result tables are its output) and
// the Python names of the result keys (kerf-dem results --python: python/kerf/result_keys.py), both from the result
// tables.
#include <fmt/format.h>

#include <functional>
#include <string>
#include <vector>

#include "kerf/dem/procedures/cut_results.hpp"
#include "kerf/dem/scene.hpp"

namespace kerf::dem {

namespace {

struct ResultSection {
  std::string name, where, python_class;
  std::function<std::string()> markdown;
  std::function<std::vector<std::string>()> keys;
};

const std::vector<ResultSection>& result_sections() {
  static const std::vector<ResultSection> list{
      {"results", "cut: one run's (with `--replicates`, the means over the replicates)", "CutResults",
       [] { return results_markdown(cut_results()) + results_markdown(cut_derived_results(), false); },
       cut_result_names},
      {"results.travel_windows",
       "cut: each stretch of `cut.window_mm` of travel (its forces also under their current "
       "names)",
       "TravelWindowResults", [] { return results_markdown(travel_window_results()); },
       [] { return result_keys(travel_window_results()); }},
      {"active_window", "cut, with an active window", "ActiveWindowResults",
       [] { return results_markdown(active_window_results()); }, [] { return result_keys(active_window_results()); }},
      {"forces.csv", "cut: one row per sample, as the cut goes (the columns in this order)", "ForcesCsvColumns",
       [] { return results_markdown(cut_forces_columns()); }, [] { return result_keys(cut_forces_columns()); }}};
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
      "\"\"\"The keys of kerf-dem's results in summary.json, generated from their result tables (kerf-dem results\n"
      "--python > python/kerf/result_keys.py; tests/cli/dem_results_cli.sh checks it is current). Read a result by\n"
      "its name here, never by a literal: a key renamed in its table then fails where it is read, by name.\"\"\"\n";
  for (const auto& s : result_sections())
    py += results_python_class(s.python_class, fmt::format("{}: {}.", s.name, s.where), s.keys());
  py += results_python_keys_function();
  return py;
}

}  // namespace kerf::dem
