#pragma once
// models.force = auto as a unit of the orthogonal kind (kinds/force_model.hpp): it predicts nothing itself but chooses,
// for the scene as read, the cheapest valid built-in model (kinds/scene.cpp asks it once the scene is read). Its
// registry line: analytic/registry.cpp.
//
//   std::string reason;
//   std::string_view name = kerf::auto_force_model.choose(scene, &reason);   // "merchant", "liu_li" or "oxley"
#include "kerf/analytic/kinds/force_model.hpp"

namespace kerf {

extern const OrthogonalForceModel auto_force_model;

}  // namespace kerf
