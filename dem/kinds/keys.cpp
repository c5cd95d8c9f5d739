// The key reference of the scene sections (kerf-dem keys; docs/dem-keys.md's key tables are its output).
#include <fmt/format.h>

#include <functional>
#include <utility>

#include "common.hpp"
#include "kerf/dem/laws/material.hpp"
#include "kerf/dem/procedures/lab_test.hpp"
#include "kerf/dem/procedures/toughness.hpp"
#include "kerf/dem/study/study.hpp"
#include "kerf/error.hpp"
#include "kerf/key_sections.hpp"

namespace kerf::dem {

namespace {

const std::vector<SceneKeySection>& sections() {
  static const std::vector<SceneKeySection> list{
      {"material", "every kind; or `{\"base\": \"NAME\"}` and overrides: a library material of data/materials/",
       material_keys_markdown},
      {"specimen", "every kind; or `{\"file\": \"specimen.json\"}`, a specimen saved by kind `specimen`",
       [] { return fields_markdown(specimen_fields()); }},
      {"engine", "every kind: settings applied to the specimen once built",
       [] { return fields_markdown(engine_fields()); }},
      {"loading", "tension, compression, calibrate", [] { return fields_markdown(loading_fields()); }},
      {"cut", "cut, calibrate_cut", [] { return fields_markdown(cut_fields()); }},
      {"tool", "cut, calibrate_cut", [] { return fields_markdown(tool_fields()); }},
      {"grooves", "cut, calibrate_cut", [] { return fields_markdown(groove_fields()); }},
      {"active_window", "cut: a steady-state cut, integrating only the disks around the tool",
       [] { return fields_markdown(active_window_fields()); }},
      {"edge_zone", "cut, with an active window: the tool's edge as a sub-grid model (docs/dem.md, \"The edge zone\")",
       [] { return fields_markdown(edge_zone_fields()); }},
      {"calibration", "calibrate", kinds::calibrate_keys_markdown},
      {"calibration.targets", "calibrate", kinds::calibrate_targets_keys_markdown},
      {"calibration.toughness",
       "calibrate: the fifth test, a notched beam (its own keys, then the toughness section's)",
       kinds::calibrate_toughness_keys_markdown},
      {"calibration", "calibrate_cut", kinds::calibrate_cut_keys_markdown},
      {"toughness", "toughness: the notched beam in three-point bending",
       [] { return fields_markdown(toughness_fields()); }},
      {"output", "every kind", [] { return fields_markdown(output_fields()); }},
      {"study", "a study file of `kerf-dem study`, not a scene", study_keys_markdown},
      {"study.replicates", "a study file: the packings per condition", study_replicates_keys_markdown}};
  return list;
}

}  // namespace

std::vector<std::string> scene_sections() {
  return key_section_names(sections());
}

std::string scene_keys_markdown(const std::string& section) {
  return key_sections_markdown(sections(), section);
}

}  // namespace kerf::dem
