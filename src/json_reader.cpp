#include "kerf/json_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "kerf/error.hpp"

namespace kerf {

bool Range::contains(double x) const {
  if (!std::isfinite(x)) return false;
  if (lo && (lo_open ? !(x > *lo) : !(x >= *lo))) return false;
  if (hi && (hi_open ? !(x < *hi) : !(x <= *hi))) return false;
  return true;
}

std::string Range::describe(std::string_view unit) const {
  const std::string u = unit.empty() ? "" : fmt::format(" {}", unit);
  if (lo && hi) {
    return fmt::format("a value in {}{}, {}{}{}", lo_open ? "(" : "[", format_value(*lo), format_value(*hi),
                       hi_open ? ")" : "]", u);
  }
  if (lo && *lo == 0.0) {
    return fmt::format("a {} value{}", lo_open ? "positive" : "non-negative", unit.empty() ? "" : " in" + u);
  }
  if (lo) return fmt::format("a value {} {}{}", lo_open ? ">" : ">=", format_value(*lo), u);
  if (hi) return fmt::format("a value {} {}{}", hi_open ? "<" : "<=", format_value(*hi), u);
  return fmt::format("a finite number{}", u);
}

double check_number(double value, const std::string& path, const Range& range, std::string_view unit) {
  if (!range.contains(value)) throw InputError(path, format_value(value), range.describe(unit));
  return value;
}

double check_field(double value, const std::string& path, std::string_view field, const Range& range,
                   std::string_view unit) {
  return range.contains(value) ? value : check_number(value, fmt::format("{}.{}", path, field), range, unit);
}

namespace {
std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0u : 1u)});
      diagonal = above;
    }
  }
  return row[b.size()];
}
}  // namespace

std::optional<std::string> nearest_choice(std::string_view word, const std::vector<std::string>& choices) {
  std::optional<std::string> best;
  std::size_t best_distance = std::max<std::size_t>(2, word.size() / 3) + 1;
  for (const auto& choice : choices) {
    const std::size_t d = edit_distance(word, choice);
    if (d < best_distance) {
      best_distance = d;
      best = choice;
    }
  }
  return best;
}

std::string describe_choices(std::string_view word, const std::vector<std::string>& choices) {
  std::string text = "one of ";
  for (std::size_t i = 0; i < choices.size(); ++i) text += fmt::format("{}'{}'", i ? ", " : "", choices[i]);
  if (auto near = nearest_choice(word, choices)) text += fmt::format(" (did you mean '{}'?)", *near);
  return text;
}

std::string json_value_text(const Json& value) {
  // The parser keeps documents shallow (kMaxJsonDepth) and strings are printed, never executed: invalid UTF-8
  // from a --set value is replaced rather than thrown over.
  std::string text =
      value.is_string() ? value.get<std::string>() : value.dump(-1, ' ', false, Json::error_handler_t::replace);
  if (text.size() > 60) text = text.substr(0, 57) + "...";
  return text;
}

ObjectReader::ObjectReader(const Json& object, std::string path) : object_(object), path_(std::move(path)) {
  if (!object_.is_object()) {
    throw InputError(path_.empty() ? "(document)" : path_, json_value_text(object_), "a JSON object");
  }
}

std::string ObjectReader::key_path(std::string_view key) const {
  return path_.empty() ? std::string(key) : fmt::format("{}.{}", path_, key);
}

bool ObjectReader::has(std::string_view key) const {
  return object_.contains(key);
}

bool ObjectReader::knows(std::string_view key) const {
  return std::find(known_.begin(), known_.end(), key) != known_.end();
}

void ObjectReader::mark_known(std::string_view key) {
  if (!knows(key)) known_.emplace_back(key);
}

const Json* ObjectReader::find(std::string_view key) {
  mark_known(key);
  auto it = object_.find(key);
  return it == object_.end() ? nullptr : &*it;
}

const Json& ObjectReader::get(std::string_view key) {
  const Json* value = find(key);
  if (!value) {
    // A key of the object that nothing has read yet and is near this one ("tools" for "tool") is its misspelling.
    std::vector<std::string> unread;
    for (const auto& [name, ignored] : object_.items())
      if (!knows(name)) unread.push_back(name);
    std::string expected = "a value for this required key";
    if (auto near = nearest_choice(key, unread))
      expected += fmt::format(" (the scene has '{}': did you mean '{}'?)", *near, key);
    throw InputError(key_path(key), "(missing)", expected);
  }
  return *value;
}

namespace {
/// What a text where a number belongs gets told: "0.2um" is a number with a unit, which the key's name carries.
std::string not_a_number(const Json& value, const Range& range, std::string_view unit) {
  std::string expected = range.describe(unit);
  if (!value.is_string()) return expected;
  const std::string text = value.get<std::string>();
  char* end = nullptr;
  const double number = std::strtod(text.c_str(), &end);
  if (end == text.c_str() || !std::isfinite(number)) return expected + " (a number)";
  std::string_view rest(end);
  while (!rest.empty() && rest.front() == ' ') rest.remove_prefix(1);
  return expected + fmt::format(" ('{}' is not a number; the unit is in the key name{}: write {})", text,
                                unit.empty() || unit.front() == '(' ? "" : fmt::format(", {}", unit),
                                text.substr(0, static_cast<std::size_t>(end - text.c_str())));
}

/// The number at `key` of `reader`, checked against `range`; the key's path is built only for a message.
double as_number(const Json& value, const ObjectReader& reader, std::string_view key, const Range& range,
                 std::string_view unit) {
  if (!value.is_number())
    throw InputError(reader.key_path(key), json_value_text(value), not_a_number(value, range, unit));
  const double number = value.get<double>();
  return range.contains(number) ? number : check_number(number, reader.key_path(key), range, unit);
}
}  // namespace

double ObjectReader::get_number(std::string_view key, const Range& range, std::string_view unit) {
  return as_number(get(key), *this, key, range, unit);
}

std::optional<double> ObjectReader::get_optional_number(std::string_view key, const Range& range,
                                                        std::string_view unit) {
  const Json* value = find(key);
  if (!value || value->is_null()) return std::nullopt;
  return as_number(*value, *this, key, range, unit);
}

double ObjectReader::get_number_or(std::string_view key, double fallback, const Range& range, std::string_view unit) {
  return get_optional_number(key, range, unit).value_or(fallback);
}

namespace {
double checked_si(double given, double (*to_si)(double), const ObjectReader& reader, std::string_view key,
                  std::string_view unit) {
  const double si = to_si(given);
  if (std::isfinite(si) && (given == 0.0 || std::isnormal(si))) return si;
  throw InputError(reader.key_path(key), format_value(given),
                   fmt::format("a value in {} that stays a finite, non-zero number in SI units (it becomes {})", unit,
                               format_value(si)));
}
}  // namespace

double ObjectReader::get_si(std::string_view key, const Range& range, std::string_view unit, double (*to_si)(double)) {
  return checked_si(get_number(key, range, unit), to_si, *this, key, unit);
}

double ObjectReader::get_si_or(std::string_view key, double fallback, const Range& range, std::string_view unit,
                               double (*to_si)(double)) {
  const auto value = get_optional_number(key, range, unit);
  return value ? checked_si(*value, to_si, *this, key, unit) : to_si(fallback);
}

std::optional<double> ObjectReader::get_optional_si(std::string_view key, const Range& range, std::string_view unit,
                                                    double (*to_si)(double)) {
  const auto value = get_optional_number(key, range, unit);
  if (!value) return std::nullopt;
  return checked_si(*value, to_si, *this, key, unit);
}

int ObjectReader::get_int_or(std::string_view key, int fallback, int lo, int hi) {
  const Json* value = find(key);
  if (!value) return fallback;
  const std::string expected = fmt::format("an integer in [{}, {}]", lo, hi);
  if (!value->is_number_integer()) throw InputError(key_path(key), json_value_text(*value), expected);
  const auto n = value->get<long long>();
  if (n < lo || n > hi) throw InputError(key_path(key), json_value_text(*value), expected);
  return static_cast<int>(n);
}

bool ObjectReader::get_bool_or(std::string_view key, bool fallback) {
  const Json* value = find(key);
  if (!value) return fallback;
  if (!value->is_boolean()) throw InputError(key_path(key), json_value_text(*value), "true or false");
  return value->get<bool>();
}

std::string ObjectReader::get_string(std::string_view key) {
  const Json& value = get(key);
  if (!value.is_string()) throw InputError(key_path(key), json_value_text(value), "a string");
  return value.get<std::string>();
}

std::string ObjectReader::get_string_or(std::string_view key, std::string fallback) {
  return has(key) ? get_string(key) : std::move(fallback);
}

std::string ObjectReader::get_choice(std::string_view key, const std::vector<std::string>& choices) {
  const Json& value = get(key);
  const std::string text = value.is_string() ? value.get<std::string>() : json_value_text(value);
  if (!value.is_string() || std::find(choices.begin(), choices.end(), text) == choices.end()) {
    throw InputError(key_path(key), text, describe_choices(text, choices));
  }
  return text;
}

std::string ObjectReader::get_choice_or(std::string_view key, std::string fallback,
                                        const std::vector<std::string>& choices) {
  return has(key) ? get_choice(key, choices) : std::move(fallback);
}

ObjectReader ObjectReader::get_object(std::string_view key) {
  return ObjectReader(get(key), key_path(key));
}

std::optional<ObjectReader> ObjectReader::find_object(std::string_view key) {
  const Json* value = find(key);
  if (!value) return std::nullopt;
  return ObjectReader(*value, key_path(key));
}

void ObjectReader::ignore(std::string_view key) {
  mark_known(key);
}

void ObjectReader::finish(const std::vector<std::string>& also_valid) const {
  for (const auto& [key, value] : object_.items()) {
    if (knows(key)) continue;
    // The valid keys in sorted order (the order of the suggestion's ties), then also_valid.
    std::vector<std::string> valid = known_;
    std::sort(valid.begin(), valid.end());
    valid.insert(valid.end(), also_valid.begin(), also_valid.end());
    std::string expected = "a known key";
    if (auto near = nearest_choice(key, valid)) expected += fmt::format(" (did you mean '{}'?)", *near);
    throw InputError(key_path(key), json_value_text(value), expected + "; see docs/scenes.md");
  }
}

namespace {

/// Builds a document as nlohmann's own parser does, with two checks it lacks: nesting deeper than
/// kMaxJsonDepth is refused before it is built (a deep value would overflow the stack of every recursive
/// function that later walks it, the printer first), and a number too large for a double names its key.
class CheckedSax : public nlohmann::detail::json_sax_dom_parser<Json> {
  using Base = nlohmann::detail::json_sax_dom_parser<Json>;
  struct Level {
    bool object;
    std::string key;
    std::size_t index;
  };

 public:
  CheckedSax(Json& document, std::string source, bool name_overflow)
      : Base(document, true), source_(std::move(source)), name_overflow_(name_overflow) {}

  bool null() { return value(Base::null()); }
  bool boolean(bool v) { return value(Base::boolean(v)); }
  bool number_integer(number_integer_t v) { return value(Base::number_integer(v)); }
  bool number_unsigned(number_unsigned_t v) { return value(Base::number_unsigned(v)); }
  bool number_float(number_float_t v, const string_t& s) { return value(Base::number_float(v, s)); }
  bool string(string_t& v) { return value(Base::string(v)); }
  bool binary(binary_t& v) { return value(Base::binary(v)); }
  bool start_object(std::size_t n) { return enter(true) && Base::start_object(n); }
  bool key(string_t& k) {
    levels_.back().key = k;
    return Base::key(k);
  }
  bool end_object() { return leave(Base::end_object()); }
  bool start_array(std::size_t n) { return enter(false) && Base::start_array(n); }
  bool end_array() { return leave(Base::end_array()); }

  template <class Exception>
  bool parse_error(std::size_t position, const std::string& last_token, const Exception& ex) {
    if constexpr (std::is_same_v<Exception, nlohmann::detail::out_of_range>) {
      if (name_overflow_ && ex.id == 406) {
        throw InputError(where(), last_token, fmt::format("a finite number (it overflows a double; in {})", source_));
      }
    }
    return Base::parse_error(position, last_token, ex);
  }

 private:
  bool value(bool ok) {
    if (!levels_.empty() && !levels_.back().object) ++levels_.back().index;
    return ok;
  }
  bool enter(bool object) {
    if (levels_.size() >= kMaxJsonDepth) {
      throw InputError(source_, fmt::format("(arrays and objects nested deeper than {} at {})", kMaxJsonDepth, where()),
                       fmt::format("JSON nested at most {} levels deep", kMaxJsonDepth));
    }
    levels_.push_back({object, "", 0});
    return true;
  }
  bool leave(bool ok) {
    levels_.pop_back();
    return value(ok);
  }
  /// The dotted path of the value being read: "tool.rake_deg", "conditions[2].feed".
  std::string where() const {
    std::string path;
    for (const auto& level : levels_) {
      if (level.object) path += (path.empty() ? "" : ".") + level.key;
      if (!level.object) path += fmt::format("[{}]", level.index);
    }
    return path.empty() ? "(document)" : path;
  }

  std::string source_;
  bool name_overflow_;
  std::vector<Level> levels_;
};

}  // namespace

Json parse_json_text(std::string_view text, const std::string& source) {
  Json document;
  CheckedSax sax(document, source, /*name_overflow=*/true);
  try {
    Json::sax_parse(text, &sax, nlohmann::detail::input_format_t::json, /*strict=*/true, /*ignore_comments=*/true);
  } catch (const Json::parse_error& e) {
    throw InputError(source, "(malformed JSON)", fmt::format("valid JSON ({})", e.what()));
  }
  return document;
}

Json parse_override_value(const std::string& text) {
  Json value;
  CheckedSax sax(value, "--set", /*name_overflow=*/false);
  try {
    Json::sax_parse(text, &sax, nlohmann::detail::input_format_t::json, /*strict=*/true);
  } catch (const Json::exception&) {
    return Json(text);  // not JSON (or a number beyond a double): the text itself, checked by its reader
  }
  return value;
}

void apply_override(Json& document, const std::string& assignment, const std::string& option_name) {
  const auto eq = assignment.find('=');
  apply_override(document, assignment,
                 parse_override_value(eq == std::string::npos ? std::string() : assignment.substr(eq + 1)),
                 option_name);
}

void apply_override(Json& document, const std::string& assignment, Json value, const std::string& option_name) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0) {
    throw InputError(option_name, assignment, "key.path=value, e.g. tool.rake_deg=-5");
  }
  const std::string path = assignment.substr(0, eq);
  Json* node = &document;
  std::size_t start = 0;
  while (true) {
    const auto dot = path.find('.', start);
    const std::string key = path.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
    if (key.empty()) throw InputError(option_name, assignment, "a dotted key path without empty parts");
    if (!node->is_object()) {
      throw InputError(option_name, assignment,
                       fmt::format("a path through objects ('{}' is not an object)", path.substr(0, start - 1)));
    }
    node = &(*node)[key];
    if (dot == std::string::npos) break;
    if (node->is_null()) *node = Json::object();
    start = dot + 1;
  }
  *node = std::move(value);
}

void blame_the_key_set(const InputError& e, const std::vector<std::string>& assignments) {
  const auto set = [&](const std::string& field) {
    return std::any_of(assignments.begin(), assignments.end(),
                       [&](const std::string& a) { return a.substr(0, a.find('=')) == field; });
  };
  if (e.other_side() && set(e.other_side()->field()) && !set(e.field())) throw *e.other_side();
  throw e;
}

Json read_json_file(const std::string& file_path) {
  std::error_code ignored;
  if (std::filesystem::is_directory(file_path, ignored))
    throw InputError("file", file_path, "a JSON file, not a directory");
  std::ifstream in(file_path);
  if (!in) throw InputError("file", file_path, "a readable JSON file");
  std::stringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) throw InputError("file", file_path, "a readable JSON file");
  return parse_json_text(buffer.str(), file_path);
}

}  // namespace kerf
