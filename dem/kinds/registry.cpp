// The scene-kind registry: the library's kinds as one initializer list (a kind is its file under dem/kinds/ and
// one line here), each naming itself (SceneKind::name), then the kinds a program registers (register_scene_kind).
// One object of each kind is made, once, to learn the names; a scene's kind is then made by its name alone.
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <vector>

#include "common.hpp"
#include "kerf/error.hpp"

namespace kerf::dem {

namespace {
struct Registered {
  std::string name;
  SceneKindFactory make;
};

/// The registered kinds in order: the library's, named by an object of each made once, then those added.
std::vector<Registered>& registry() {
  static std::vector<Registered> kinds = [] {
    const std::initializer_list<SceneKindFactory> library{
        kinds::make_specimen_kind,       // specimen.cpp
        kinds::make_tension_kind,        // lab_test.cpp
        kinds::make_compression_kind,    // lab_test.cpp
        kinds::make_calibrate_kind,      // calibrate.cpp
        kinds::make_cut_kind,            // cut.cpp
        kinds::make_calibrate_cut_kind,  // calibrate_cut.cpp
        kinds::make_toughness_kind,      // toughness.cpp
    };
    std::vector<Registered> out;
    for (SceneKindFactory make : library) out.push_back({make()->name(), make});
    return out;
  }();
  return kinds;
}
}  // namespace

std::vector<std::string> scene_kind_names() {
  std::vector<std::string> names;
  for (const Registered& kind : registry()) names.push_back(kind.name);
  return names;
}

std::unique_ptr<SceneKind> make_scene_kind(const std::string& name, const std::string& path) {
  for (const Registered& kind : registry())
    if (kind.name == name) return kind.make();
  throw InputError(path, name, describe_choices(name, scene_kind_names()));
}

void register_scene_kind(SceneKindFactory make) {
  std::string name = make()->name();
  for (const Registered& kind : registry())
    if (kind.name == name) throw std::logic_error("register_scene_kind: kind '" + name + "' is registered already");
  registry().push_back({std::move(name), make});
}

}  // namespace kerf::dem
