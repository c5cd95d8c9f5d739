#pragma once
// Errors that kerf reports to its users.
//
// Two kinds, as in deal.II: internal invariants are asserts; user-facing problems are exceptions that
// name the field (its dotted JSON path or CLI option), the offending value and what was expected.
//
//   throw kerf::InputError("tool.rake_deg", "95", "a value in (-90, 90) deg");
//   // what(): "tool.rake_deg = 95: expected a value in (-90, 90) deg"
#include <stdexcept>
#include <string>

namespace kerf {

/// Exit status of the command-line programs for usage and input errors.
inline constexpr int kExitInputError = 2;
/// Exit status when a model cannot produce an answer for valid input (e.g. a solver fails).
inline constexpr int kExitModelError = 3;

/// Bad input: names the field, the value and what was expected. The CLIs exit with status 2.
class InputError : public std::runtime_error {
 public:
  InputError(std::string field, std::string value, std::string expected);

  const std::string& field() const noexcept { return field_; }
  const std::string& value() const noexcept { return value_; }
  const std::string& expected() const noexcept { return expected_; }

 private:
  std::string field_, value_, expected_;
};

/// A model failed for input it accepted (no bracket, no convergence): says which model and why.
class ModelError : public std::runtime_error {
 public:
  ModelError(const std::string& model, const std::string& reason);
};

/// Formats a number for an error message with enough digits to be recognised ("0.1", "1e-09").
std::string format_value(double value);

}  // namespace kerf
