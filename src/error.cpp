#include "kerf/error.hpp"

#include <fmt/format.h>

namespace kerf {

InputError::InputError(std::string field, std::string value, std::string expected)
    : std::runtime_error(fmt::format("{} = {}: expected {}", field, value, expected)),
      field_(std::move(field)),
      value_(std::move(value)),
      expected_(std::move(expected)) {}

ModelError::ModelError(const std::string& model, const std::string& reason)
    : std::runtime_error(fmt::format("model '{}': {}", model, reason)) {}

std::string format_value(double value) { return fmt::format("{:.6g}", value); }

}  // namespace kerf
