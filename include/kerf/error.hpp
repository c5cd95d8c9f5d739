#pragma once
// Errors that kerf reports to its users.
//
// Two kinds, as in deal.II: internal invariants are asserts; user-facing problems are exceptions that
// name the field (its dotted JSON path or CLI option), the offending value and what was expected.
//
//   throw kerf::InputError("tool.rake_deg", "95", "a value in (-90, 90) deg");
//   // what(): "tool.rake_deg = 95: expected a value in (-90, 90) deg"
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>

namespace kerf {

/// Exit status of the command-line programs for usage and input errors.
inline constexpr int kExitInputError = 2;
/// Exit status when a model cannot produce an answer for valid input (e.g. a solver fails), when a result
/// would not be finite, or when a checkpoint is damaged.
inline constexpr int kExitModelError = 3;
/// Exit status when an output cannot be written (a directory that is not writable, a full disk).
inline constexpr int kExitOutputError = 4;

/// Bad input: names the field, the value and what was expected. The CLIs exit with status 2.
class InputError : public std::runtime_error {
 public:
  InputError(std::string field, std::string value, std::string expected);

  const std::string& field() const noexcept { return field_; }
  const std::string& value() const noexcept { return value_; }
  const std::string& expected() const noexcept { return expected_; }

  /// A fault in a relation between two keys (radius_min_um <= radius_max_um) told from either key: `other` is
  /// the same fault named from the other key, which a program prints instead when the user set that key and
  /// not this one (kerf::blame_the_key_set, json_reader.hpp).
  InputError or_from(InputError other) &&;
  const InputError* other_side() const noexcept { return other_.get(); }
  /// The same error with `prefix.` before its field (and its other side's).
  InputError with_prefix(const std::string& prefix) const;

 private:
  std::string field_, value_, expected_;
  std::shared_ptr<const InputError> other_;
};

/// A model failed for input it accepted (no bracket, no convergence): says which model and why.
class ModelError : public std::runtime_error {
 public:
  ModelError(const std::string& model, const std::string& reason);
};

/// An output that cannot be written: names the path and why. The CLIs exit with status 4.
class OutputError : public std::runtime_error {
 public:
  OutputError(const std::string& path, const std::string& reason);
};

/// The text on one line with its control characters escaped (a newline as \n, ESC as \x1b, a C1 control as
/// \u0085...), so that no message splits, stops short at a NUL or reaches the terminal as an escape sequence.
/// Prints "<program>: error: <what>" (one printable line) on stderr and returns the exit status of the
/// exception being handled: InputError 2, ModelError 3, OutputError 4, anything else 1. Call it in a catch
/// block: both command-line programs end this way.
int report_error(std::string_view program);

/// Every error's what() is printable already.
std::string printable(std::string_view text);

/// Formats a number for an error message with enough digits to be recognised ("0.1", "1e-09").
std::string format_value(double value);

}  // namespace kerf
