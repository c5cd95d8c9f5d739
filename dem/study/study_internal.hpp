#pragma once
// What the study's files (dem/study/) share, internal to the library.
#include <string>

#include "kerf/dem/study/study.hpp"

namespace kerf::dem {

/// A condition's value in a CSV cell, a label or an override: a string as it is, anything else as JSON.
std::string value_text(const Json& value);

}  // namespace kerf::dem
