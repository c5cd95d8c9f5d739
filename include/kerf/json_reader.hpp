#pragma once
// Reading validated parameters from JSON, with errors that name the dotted path of the field.
//
// An ObjectReader wraps one JSON object. Each get_* call names a key, marks it as read and checks the
// value; finish() rejects the keys nobody read, suggesting the nearest valid key:
//
//   kerf::ObjectReader tool(scene_json.at("tool"), "tool");
//   double rake_deg = tool.get_number("rake_deg", kerf::Range::open(-90.0, 90.0), "deg");
//   tool.finish();  // "tool.rake_dg = 5: expected a known key (did you mean 'rake_deg'?); ..."
#include <cmath>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "kerf/error.hpp"

namespace kerf {

using Json = nlohmann::json;

/// An interval check for a number; closed or open at each end, either end may be absent.
struct Range {
  std::optional<double> lo, hi;
  bool lo_open = false, hi_open = false;

  static Range any() { return {}; }
  static Range positive() { return {0.0, std::nullopt, true, false}; }
  static Range non_negative() { return {0.0, std::nullopt, false, false}; }
  static Range open(double lo, double hi) { return {lo, hi, true, true}; }
  static Range closed(double lo, double hi) { return {lo, hi, false, false}; }
  static Range at_least(double lo) { return {lo, std::nullopt, false, false}; }
  static Range above(double lo) { return {lo, std::nullopt, true, false}; }

  bool contains(double x) const;
  /// "a value in (-90, 90) deg", "a positive value in um", "a finite number".
  std::string describe(std::string_view unit) const;
};

/// Checks a finite number against a range; throws InputError naming `path` otherwise.
double check_number(double value, const std::string& path, const Range& range, std::string_view unit);
/// check_number for the field `field` of the object at `path` (path "material.johnson_cook", field "A_MPa"): the
/// field's path is built only for a message (validation that runs at every point of a sweep).
double check_field(double value, const std::string& path, std::string_view field, const Range& range,
                   std::string_view unit);

/// Returns the choice closest to `word` (edit distance) if it is close enough to be a likely typo.
std::optional<std::string> nearest_choice(std::string_view word, const std::vector<std::string>& choices);

/// "one of 'a', 'b', 'c'" plus " (did you mean 'b'?)" when there is a near miss.
std::string describe_choices(std::string_view word, const std::vector<std::string>& choices);

/// Reads the keys of one JSON object and rejects the ones it was not asked for.
class ObjectReader {
 public:
  /// `path` is the dotted path of the object itself ("" for the root).
  ObjectReader(const Json& object, std::string path);

  const std::string& path() const { return path_; }
  std::string key_path(std::string_view key) const;
  bool has(std::string_view key) const;

  /// The raw value (marks the key as read); throws if missing.
  const Json& get(std::string_view key);
  /// The raw value if present (marks the key as read).
  const Json* find(std::string_view key);

  double get_number(std::string_view key, const Range& range, std::string_view unit);
  std::optional<double> get_optional_number(std::string_view key, const Range& range, std::string_view unit);
  double get_number_or(std::string_view key, double fallback, const Range& range, std::string_view unit);
  /// A number in the user's unit converted to SI with `to_si` (units::mm_to_m...): a non-zero value that the
  /// conversion takes to 0, a subnormal or infinity (1e-322 mm, 1e308 MPa) is an InputError naming the key.
  double get_si(std::string_view key, const Range& range, std::string_view unit, double (*to_si)(double));
  double get_si_or(std::string_view key, double fallback, const Range& range, std::string_view unit,
                   double (*to_si)(double));
  /// get_si of a key that may be absent (or null): nullopt then.
  std::optional<double> get_optional_si(std::string_view key, const Range& range, std::string_view unit,
                                        double (*to_si)(double));
  int get_int_or(std::string_view key, int fallback, int lo, int hi);
  bool get_bool_or(std::string_view key, bool fallback);
  std::string get_string(std::string_view key);
  std::string get_string_or(std::string_view key, std::string fallback);
  /// A string that must be one of `choices`; the error lists them and suggests the near miss.
  std::string get_choice(std::string_view key, const std::vector<std::string>& choices);
  std::string get_choice_or(std::string_view key, std::string fallback, const std::vector<std::string>& choices);
  /// A sub-object reader (the key must hold an object).
  ObjectReader get_object(std::string_view key);
  std::optional<ObjectReader> find_object(std::string_view key);

  /// Marks a key as known without reading it (e.g. documentation fields like "description").
  void ignore(std::string_view key);
  /// Throws InputError for the first key that was never read, listing the keys that are valid here.
  void finish(const std::vector<std::string>& also_valid = {}) const;

 private:
  bool knows(std::string_view key) const;
  void mark_known(std::string_view key);

  const Json& object_;
  std::string path_;
  std::vector<std::string> known_;  ///< every key asked for, present or not (a few: a list is cheaper than a set)
};

/// Parses the text of a --set value: JSON if it parses (numbers, true, "quoted", [..]), else a string.
Json parse_override_value(const std::string& text);

/// Applies `path=value` (dotted path) to a JSON document, creating intermediate objects. Throws
/// InputError when the text has no '=' or the path crosses a non-object value.
void apply_override(Json& document, const std::string& assignment, const std::string& option_name = "--set");
/// apply_override with the value already parsed (`value` is parse_override_value of the text after '='; the
/// assignment's text is only for messages): a sweep parses each axis value once, not once per point.
void apply_override(Json& document, const std::string& assignment, Json value, const std::string& option_name);

/// Throws `e`, or the same fault told from its other key (InputError::or_from) when the assignments
/// ("key.path=value", as for apply_override) set that key and not `e`'s: the key the user changed is the one named.
[[noreturn]] void blame_the_key_set(const InputError& e, const std::vector<std::string>& assignments);

/// The deepest nesting of arrays and objects a document may have (the bundled scenes use 4).
inline constexpr std::size_t kMaxJsonDepth = 64;

/// Parses JSON text (comments allowed). Malformed JSON is an InputError naming `source`, line and column;
/// so is nesting deeper than kMaxJsonDepth; a number beyond a double is an InputError naming its key.
Json parse_json_text(std::string_view text, const std::string& source);

/// Reads a JSON file through parse_json_text; a missing file or a directory is an InputError.
Json read_json_file(const std::string& file_path);

/// A short text of a JSON value for error messages (strings unquoted, long values elided).
std::string json_value_text(const Json& value);

/// A number for an output document, or null when it is not finite (a standard error a signal is too short
/// for): JSON has no NaN or infinity.
inline Json finite_or_null(double value) {
  return std::isfinite(value) ? Json(value) : Json();
}

}  // namespace kerf
