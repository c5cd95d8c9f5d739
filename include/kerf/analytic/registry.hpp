#pragma once
// The registry of analytic models: one line per model, in analytic/registry.cpp. A scene names the models it
// needs by these names; only those are built and run; an unknown name is an error listing the valid ones.
// Each line carries the enum value its name constructs, so a scene maps a name to its model by the name and
// the order of the lines changes nothing. This header is a leaf (it includes no other analytic header, and names
// the scene's types by declaration only): the scenes include it; registry.cpp, which sees every model to list it,
// is the one file that includes the models.
//
//   for (const auto& m : kerf::analytic_models()) fmt::print("{}.{}: {}\n", m.kind, m.name, m.summary);
//   auto names = kerf::analytic_model_names("force");   // {"auto", "merchant", "liu_li", "oxley", ...}
//   auto rule = kerf::registered_model<kerf::ShearAngleSource>("shear_angle", "lee_shaffer");
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "kerf/json_reader.hpp"

namespace kerf {

class AnalyticCase;           // kinds/evaluate.hpp
class MaterialCache;          // kinds/scene.hpp
struct OrthogonalForceModel;  // kinds/force_model.hpp
struct ModelParams;           // kinds/model_params.hpp

/// Builds the scene kind a force line names from a document (evaluate.hpp's parse_scene calls it).
using SceneBuilder = std::unique_ptr<AnalyticCase> (*)(const Json& document, MaterialCache* cache);

struct AnalyticModelInfo {
  std::string_view kind;         ///< the scene key under `models` ("force", "flow_stress", ...)
  std::string_view name;         ///< the value a scene uses
  std::string_view summary;      ///< what it is, with its source
  std::string_view needs;        ///< what the scene and material must provide
  int id = -1;                   ///< the value of the kind's enum this name constructs; -1: none (handled by name)
  SceneBuilder build = nullptr;  ///< force lines: the scene kind that runs this model (parse_scene)
  /// force lines of the orthogonal kind: the model that kind runs (nullptr: a scene kind of its own)
  const OrthogonalForceModel* orthogonal = nullptr;
  /// The parameter block its model owns (its keys join the orthogonal scene's `models` section, its objects the
  /// objects under `models`); nullptr: none. A block several lines share is carried by one of them or by each.
  const ModelParams* params = nullptr;
};

const std::vector<AnalyticModelInfo>& analytic_models();
/// Adds a line to the registry (a model or scene kind that lives outside registry.cpp: a test's toy, a
/// plug-in). Call it before the registry is read by other threads (a static initialiser); returns true so that
/// `static const bool registered = kerf::register_analytic_model({...});` registers at start-up. A kind and name
/// already registered is a std::logic_error.
bool register_analytic_model(const AnalyticModelInfo& line);
/// The names registered under one kind, in registry order: the one list of them (the scene's field tables and
/// error messages read it). Built at the first call; a line registered later makes a new list, the old one staying
/// valid for those who hold it (a field table built before the registration keeps the names it had).
std::span<const std::string_view> analytic_model_names(std::string_view kind);
/// The names of the force lines that carry a model of the orthogonal kind (their `orthogonal` member), in registry
/// order: the values of the orthogonal scene's models.force (`trepanning`, a scene kind of its own, is not one).
std::span<const std::string_view> orthogonal_force_names();

/// The parameter blocks the registry's lines carry, each once, in the order of the first line that carries it: the
/// orthogonal scene composes its `models` section of them (kinds/scene.cpp), built at its first read.
std::vector<const ModelParams*> analytic_model_params();

/// The line of `kind` and `name` in `registry`; nullptr when none.
const AnalyticModelInfo* registered_line(const std::vector<AnalyticModelInfo>& registry, std::string_view kind,
                                         std::string_view name);

/// The enum value registered for `kind` and `name` in `registry` (a line's own id, never its position);
/// nullopt when no line has that kind and name, or the line has no enum value.
std::optional<int> registered_id(const std::vector<AnalyticModelInfo>& registry, std::string_view kind,
                                 std::string_view name);

/// The model of `kind` that `name` constructs. Names are checked against the registry when a scene is read, so
/// an unregistered name here is a programming error (std::logic_error).
template <class Enum>
Enum registered_model(std::string_view kind, std::string_view name,
                      const std::vector<AnalyticModelInfo>& registry = analytic_models()) {
  const std::optional<int> id = registered_id(registry, kind, name);
  if (!id)
    throw std::logic_error("analytic registry: no model '" + std::string(name) + "' of kind " + std::string(kind));
  return static_cast<Enum>(*id);
}

}  // namespace kerf
