// The scene-kind registry: one line per kind; a scene names its kind and only that one is constructed.
#include <array>
#include <cstdlib>
#include <string_view>
#include <utility>

#include "common.hpp"
#include "kerf/error.hpp"

namespace kerf::dem {

namespace {
using Factory = std::unique_ptr<SceneKind> (*)();
constexpr std::array<std::pair<std::string_view, Factory>, 7> kKinds{{
    {"specimen", kinds::make_specimen_kind},
    {"tension", kinds::make_tension_kind},
    {"compression", kinds::make_compression_kind},
    {"calibrate", kinds::make_calibrate_kind},
    {"cut", kinds::make_cut_kind},
    {"calibrate_cut", kinds::make_calibrate_cut_kind},
    {"toughness", kinds::make_toughness_kind},
}};
}  // namespace

std::vector<std::string> scene_kind_names() {
  std::vector<std::string> names;
  for (const auto& [name, factory] : kKinds) names.emplace_back(name);
  return names;
}

std::unique_ptr<SceneKind> make_scene_kind(const std::string& name, const std::string& path) {
  for (const auto& [known, factory] : kKinds)
    if (known == name) return factory();
  // A kind for the test suite only (a result of known distribution), not listed among the kinds.
  if (const char* tests = std::getenv("KERF_DEM_TEST_KINDS");
      tests && std::string_view(tests) == "1" && name == "synthetic")
    return kinds::make_synthetic_kind();
  throw InputError(path, name, describe_choices(name, scene_kind_names()));
}

}  // namespace kerf::dem
