#pragma once
// The registry of analytic models: one line per model, in analytic/registry.cpp. A scene names the models it
// needs by these names; only those are built and run; an unknown name is an error listing the valid ones.
//
//   for (const auto& m : kerf::analytic_models()) fmt::print("{}.{}: {}\n", m.kind, m.name, m.summary);
//   auto names = kerf::analytic_model_names("force");   // {"auto", "merchant", "liu_li", "oxley"}
#include <string>
#include <string_view>
#include <vector>

namespace kerf {

struct AnalyticModelInfo {
  std::string_view kind;     ///< the scene key under `models` ("force", "flow_stress", ...)
  std::string_view name;     ///< the value a scene uses
  std::string_view summary;  ///< what it is, with its source
  std::string_view needs;    ///< what the scene and material must provide
};

const std::vector<AnalyticModelInfo>& analytic_models();
/// The names registered under one kind, in registry order (built once).
const std::vector<std::string>& analytic_model_names(std::string_view kind);

}  // namespace kerf
