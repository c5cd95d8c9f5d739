#pragma once
// One field table per parameter struct: the single description of a struct's parameters as users see them.
//
// Each field names its key (with the unit suffix users type: "tensile_strength_MPa"), the unit and its
// conversion to SI, the valid range (in the key's unit), a one-line description and how to get and set the
// SI value on the struct. The default of a field is the struct's own member initialiser (`S{}`), written
// once. Reading, writing (to JSON), validation and the key reference in the docs all come from the table:
//
//   struct Tool { double rake_rad = -0.26; int segments = 4; };
//   const FieldTable<Tool> kToolFields{
//       number_field("rake_deg", units::kDeg, Range::open(-90.0, 90.0), "rake angle", &Tool::rake_rad),
//       int_field("edge_segments", 1, 64, "segments of the rounded edge", &Tool::segments)};
//   Tool tool = read_fields(reader, kToolFields, Tool{});    // unknown keys still need reader.finish()
//   check_fields(kToolFields, tool);                         // InputError naming the key, not the JSON path
//   Json j = fields_to_json(kToolFields, tool);              // key -> value in the key's unit
//   std::string md = fields_markdown(kToolFields);           // | key | unit | range | default | meaning |
//
// Physics code validates with check_fields (the key alone names the field); the scene layer, which knows the
// JSON path, prefixes it (with_path) so the message names "material.tensile_strength_MPa".
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "kerf/error.hpp"
#include "kerf/json_reader.hpp"
#include "kerf/units.hpp"

namespace kerf {

/// A unit as users type it, with its conversion to and from SI (functions, not a factor: deg -> rad is
/// deg * pi / 180, which is not deg * (pi / 180) to the bit).
struct FieldUnit {
  std::string_view symbol;  ///< "GPa", "deg", "" (dimensionless or already SI without a suffix)
  double (*to_si)(double);
  double (*from_si)(double);
};

namespace units {
inline constexpr double identity(double v) {
  return v;
}
inline constexpr FieldUnit kNone{"", identity, identity};
inline constexpr FieldUnit kSi(std::string_view symbol) {
  return {symbol, identity, identity};
}
inline constexpr FieldUnit kGPa{"GPa", gpa_to_pa, pa_to_gpa};
inline constexpr FieldUnit kMPa{"MPa", mpa_to_pa, pa_to_mpa};
inline constexpr FieldUnit kDeg{"deg", deg_to_rad, rad_to_deg};
inline constexpr FieldUnit kMm{"mm", mm_to_m, m_to_mm};
inline constexpr FieldUnit kUm{"um", um_to_m, m_to_um};
inline constexpr FieldUnit kNPerMm{"N/mm", n_per_mm_to_n_per_m, n_per_m_to_n_per_mm};  ///< force per unit width
inline constexpr FieldUnit kPercent{"%", percent_to_fraction, fraction_to_percent};
inline constexpr FieldUnit kMPaSqrtM{"MPa sqrt(m)", mpa_to_pa, pa_to_mpa};  ///< a fracture toughness K_IC
}  // namespace units

/// A real parameter, stored in SI on the struct.
template <class S>
struct NumberField {
  std::string_view key;
  FieldUnit unit;
  Range range;  ///< in the key's unit
  std::string_view doc;
  std::function<double(const S&)> get;  ///< SI
  std::function<void(S&, double)> set;  ///< SI
  bool required = false;                ///< a key without a default: read_fields throws when it is absent
  /// A key that may hold no value (an optional number, a default that depends on other keys): `has` tells
  /// whether the struct holds one (empty: always), `absent` is what the key reference says when it does not.
  std::function<bool(const S&)> has;
  std::string_view absent;
};

/// An integer parameter in [lo, hi].
template <class S>
struct IntField {
  std::string_view key;
  int lo, hi;
  std::string_view doc;
  std::function<int(const S&)> get;
  std::function<void(S&, int)> set;
};

/// A yes/no parameter.
template <class S>
struct BoolField {
  std::string_view key;
  std::string_view doc;
  std::function<bool(const S&)> get;
  std::function<void(S&, bool)> set;
};

/// A choice among named values, parsed once into its enum (the index into `names` is the enum's value).
template <class S>
struct ChoiceField {
  std::string_view key;
  std::span<const std::string_view> names;
  std::string_view doc;
  std::function<int(const S&)> get;
  std::function<void(S&, int)> set;
};

/// A text (a name, a file, a source). `check` returns the expectation when the text is not acceptable, else
/// an empty string (no check when empty).
template <class S>
struct TextField {
  std::string_view key;
  std::string_view doc;
  std::function<std::string(const S&)> get;
  std::function<void(S&, const std::string&)> set;
  std::function<std::string(const std::string&)> check;
};

/// An ordered list of names out of `names` (JSON: an array of names, or one name), kept in the order given.
template <class S>
struct NameListField {
  std::string_view key;
  std::span<const std::string_view> names;
  std::string_view doc;
  std::function<std::vector<std::string>(const S&)> get;
  std::function<void(S&, const std::vector<std::string>&)> set;
};

/// A set of names out of a list (JSON: an array of names), stored as flags (bit k: names[k] chosen).
template <class S>
struct FlagsField {
  std::string_view key;
  std::span<const std::string_view> names;
  std::string_view doc;
  std::function<unsigned(const S&)> get;
  std::function<void(S&, unsigned)> set;
};

template <class S>
using Field = std::variant<NumberField<S>, IntField<S>, BoolField<S>, ChoiceField<S>, TextField<S>, FlagsField<S>,
                           NameListField<S>>;

template <class S>
using FieldTable = std::vector<Field<S>>;

/// A number stored in SI in `member`.
template <class S>
NumberField<S> number_field(std::string_view key, FieldUnit unit, Range range, std::string_view doc,
                            double S::*member) {
  return {
      key,   unit, range, doc, [member](const S& s) { return s.*member; }, [member](S& s, double v) { s.*member = v; },
      false, {},   {}};
}
/// A number the user may leave out (no default): `absent` is what the key reference says then ("none").
template <class S>
NumberField<S> optional_number_field(std::string_view key, FieldUnit unit, Range range, std::string_view doc,
                                     std::optional<double> S::*member, std::string_view absent = "none") {
  return {key,
          unit,
          range,
          doc,
          [member](const S& s) { return (s.*member).value_or(0.0); },
          [member](S& s, double v) { s.*member = v; },
          false,
          [member](const S& s) { return (s.*member).has_value(); },
          absent};
}
/// A number the user must give (no default).
template <class S>
NumberField<S> required_number_field(std::string_view key, FieldUnit unit, Range range, std::string_view doc,
                                     double S::*member) {
  NumberField<S> f = number_field(key, unit, range, doc, member);
  f.required = true;
  return f;
}
template <class S>
IntField<S> int_field(std::string_view key, int lo, int hi, std::string_view doc, int S::*member) {
  return {key, lo, hi, doc, [member](const S& s) { return s.*member; }, [member](S& s, int v) { s.*member = v; }};
}
template <class S>
BoolField<S> bool_field(std::string_view key, std::string_view doc, bool S::*member) {
  return {key, doc, [member](const S& s) { return s.*member; }, [member](S& s, bool v) { s.*member = v; }};
}

template <class S>
TextField<S> text_field(std::string_view key, std::string_view doc, std::string S::*member,
                        std::function<std::string(const std::string&)> check = {}) {
  return {key, doc, [member](const S& s) { return s.*member; }, [member](S& s, const std::string& v) { s.*member = v; },
          std::move(check)};
}

/// The names of an enum's values, in the enum's order (value k is names[k]), and the parse of a name.
template <class E>
struct EnumNames {
  std::span<const std::string_view> names;
  /// The enum value called `text`; InputError on `path` listing the valid names otherwise.
  E parse(const std::string& text, const std::string& path) const {
    for (std::size_t k = 0; k < names.size(); ++k)
      if (names[k] == text) return static_cast<E>(k);
    throw InputError(path, text, describe_choices(text, std::vector<std::string>(names.begin(), names.end())));
  }
  std::string name(E value) const { return std::string(names[static_cast<std::size_t>(value)]); }
};

template <class S, class E>
ChoiceField<S> choice_field(std::string_view key, const EnumNames<E>& names, std::string_view doc, E S::*member) {
  return {key, names.names, doc, [member](const S& s) { return static_cast<int>(s.*member); },
          [member](S& s, int v) { s.*member = static_cast<E>(v); }};
}

namespace detail {
/// The fields of B as fields of S, through `part(s)`, B's part of an S (a member or a base), for both constness.
template <class S, class B, class Part>
FieldTable<S> fields_through(const FieldTable<B>& table, Part part, const FieldTable<S>& own, const char* who) {
  // Each field is built in its place and filled there, none moved (GCC 12 flags moving a just-built field's
  // std::function members as "may be used uninitialized", a false positive); reserved so none moves later.
  FieldTable<S> out;
  out.reserve(table.size() + own.size());
  for (const auto& field : table) {
    std::visit(
        [&](const auto& f) {
          using F = std::decay_t<decltype(f)>;
          if constexpr (std::is_same_v<F, NumberField<B>>) {
            auto& g = std::get<NumberField<S>>(out.emplace_back(std::in_place_type<NumberField<S>>));
            g.key = f.key, g.unit = f.unit, g.range = f.range, g.doc = f.doc, g.required = f.required,
            g.absent = f.absent;
            if (f.has) g.has = [has = f.has, part](const S& s) { return has(part(s)); };
            g.get = [get = f.get, part](const S& s) { return get(part(s)); };
            g.set = [set = f.set, part](S& s, double v) { set(part(s), v); };
          } else if constexpr (std::is_same_v<F, IntField<B>>) {
            auto& g = std::get<IntField<S>>(out.emplace_back(std::in_place_type<IntField<S>>));
            g.key = f.key, g.lo = f.lo, g.hi = f.hi, g.doc = f.doc;
            g.get = [get = f.get, part](const S& s) { return get(part(s)); };
            g.set = [set = f.set, part](S& s, int v) { set(part(s), v); };
          } else if constexpr (std::is_same_v<F, BoolField<B>>) {
            auto& g = std::get<BoolField<S>>(out.emplace_back(std::in_place_type<BoolField<S>>));
            g.key = f.key, g.doc = f.doc;
            g.get = [get = f.get, part](const S& s) { return get(part(s)); };
            g.set = [set = f.set, part](S& s, bool v) { set(part(s), v); };
          } else if constexpr (std::is_same_v<F, ChoiceField<B>>) {
            auto& g = std::get<ChoiceField<S>>(out.emplace_back(std::in_place_type<ChoiceField<S>>));
            g.key = f.key, g.names = f.names, g.doc = f.doc;
            g.get = [get = f.get, part](const S& s) { return get(part(s)); };
            g.set = [set = f.set, part](S& s, int v) { set(part(s), v); };
          } else {
            throw std::logic_error(std::string(who) + ": number, integer, flag and choice fields only (" +
                                   std::string(f.key) + ")");
          }
        },
        field);
  }
  for (const auto& field : own) out.push_back(field);
  return out;
}
}  // namespace detail

/// The fields of a member struct (`member` of S, of type B, with its own table) as fields of S: one table
/// written once and embedded in each struct that holds it (the bond laws' BondStiffnessStrength, an analytic
/// model's parameters in its scene). Number, integer, flag and choice fields; then `own`, the fields S holds itself.
template <class S, class B>
FieldTable<S> embedded_fields(const FieldTable<B>& table, B S::*member, const FieldTable<S>& own = {}) {
  return detail::fields_through(
      table, [member](auto& s) -> auto& { return s.*member; }, own, "embedded_fields");
}

/// The fields of B as fields of S through `part`, B's part of an S reached by a function of either constness
/// (`[](auto& s) -> auto& {...}`): a part S holds without naming its type (an analytic model's parameter block in
/// its scene, kerf/analytic/kinds/model_params.hpp). Number, integer, flag and choice fields; then `own`.
template <class S, class B, class Part>
FieldTable<S> fields_of_part(const FieldTable<B>& table, Part part, const FieldTable<S>& own = {}) {
  return detail::fields_through(table, part, own, "fields_of_part");
}

/// The fields of a base struct B of S (a parameter struct that extends another: the softening flat joint is a
/// flat joint with a fracture energy) as fields of S, then `own`: the base's table written once.
template <class S, class B>
requires std::is_base_of_v<B, S> FieldTable<S> inherited_fields(const FieldTable<B>& table,
                                                                const FieldTable<S>& own = {}) {
  return detail::fields_through(
      table, [](auto& s) -> auto& {
        if constexpr (std::is_const_v<std::remove_reference_t<decltype(s)>>)
          return static_cast<const B&>(s);
        else
          return static_cast<B&>(s);
      },
      own, "inherited_fields");
}

/// Whether read_fields refuses a number that its conversion to SI takes to 0, a subnormal or infinity, naming
/// the key (ObjectReader::get_si): the analytic scenes ask for it; the DEM's tables read the plain conversion
/// (their own checks judge the value then).
enum class SiCheck { off, on };

/// Reads every field present in the reader's object into `s` (absent fields keep their value, the default
/// when `s` is S{}); values are range-checked in the key's unit; errors name the dotted path. The reader's
/// finish() (unknown keys) is the caller's: a scene object may hold several tables.
template <class S>
void read_fields_into(ObjectReader& reader, const FieldTable<S>& table, S& s, SiCheck si_check = SiCheck::off) {
  for (const auto& field : table) {
    std::visit(
        [&](const auto& f) {
          using F = std::decay_t<decltype(f)>;
          const std::string key(f.key);
          if constexpr (std::is_same_v<F, NumberField<S>>) {
            if (si_check == SiCheck::on) {
              if (f.required)
                f.set(s, reader.get_si(key, f.range, f.unit.symbol, f.unit.to_si));
              else if (const auto v = reader.get_optional_si(key, f.range, f.unit.symbol, f.unit.to_si))
                f.set(s, *v);
            } else {
              if (f.required)
                f.set(s, f.unit.to_si(reader.get_number(key, f.range, f.unit.symbol)));
              else if (const auto v = reader.get_optional_number(key, f.range, f.unit.symbol))
                f.set(s, f.unit.to_si(*v));
            }
          } else if constexpr (std::is_same_v<F, IntField<S>>) {
            f.set(s, reader.get_int_or(key, f.get(s), f.lo, f.hi));
          } else if constexpr (std::is_same_v<F, BoolField<S>>) {
            f.set(s, reader.get_bool_or(key, f.get(s)));
          } else if constexpr (std::is_same_v<F, ChoiceField<S>>) {
            if (!reader.has(key)) return;  // s keeps its choice (as ObjectReader::get_choice_or, no copy of the names)
            const Json& value = reader.get(key);
            const std::string text = value.is_string() ? value.get<std::string>() : json_value_text(value);
            const auto it = value.is_string() ? std::find(f.names.begin(), f.names.end(), text) : f.names.end();
            if (it == f.names.end())
              throw InputError(reader.key_path(key), text,
                               describe_choices(text, std::vector<std::string>(f.names.begin(), f.names.end())));
            f.set(s, static_cast<int>(it - f.names.begin()));
          } else if constexpr (std::is_same_v<F, TextField<S>>) {
            const std::string text = reader.get_string_or(key, f.get(s));
            if (f.check)
              if (const std::string expected = f.check(text); !expected.empty())
                throw InputError(reader.key_path(key), text, expected);
            f.set(s, text);
          } else if constexpr (std::is_same_v<F, NameListField<S>>) {
            const Json* value = reader.find(key);
            if (!value) return;
            const std::vector<std::string> names(f.names.begin(), f.names.end());
            if (!value->is_string() && !value->is_array())
              throw InputError(reader.key_path(key), json_value_text(*value), "a list of names");
            std::vector<std::string> list;
            for (const auto& item : value->is_string() ? Json::array({*value}) : *value) {
              const std::string name = item.is_string() ? item.get<std::string>() : json_value_text(item);
              if (!item.is_string() || std::find(names.begin(), names.end(), name) == names.end())
                throw InputError(reader.key_path(key), name, describe_choices(name, names));
              list.push_back(name);
            }
            f.set(s, list);
          } else {
            const Json* list = reader.find(key);
            if (!list) return;
            const std::vector<std::string> names(f.names.begin(), f.names.end());
            if (!list->is_array()) throw InputError(reader.key_path(key), json_value_text(*list), "a list of names");
            unsigned flags = 0;
            for (const auto& item : *list) {
              const std::string name = item.is_string() ? item.get<std::string>() : json_value_text(item);
              const auto it = std::find(names.begin(), names.end(), name);
              if (it == names.end()) throw InputError(reader.key_path(key), name, describe_choices(name, names));
              flags |= 1u << (it - names.begin());
            }
            f.set(s, flags);
          }
        },
        field);
  }
}

/// read_fields_into a copy of `s`.
template <class S>
S read_fields(ObjectReader& reader, const FieldTable<S>& table, S s, SiCheck si_check = SiCheck::off) {
  read_fields_into(reader, table, s, si_check);
  return s;
}

/// Checks every field of `s` against its range; InputError names the key (no path: see with_path).
template <class S>
void check_fields(const FieldTable<S>& table, const S& s) {
  for (const auto& field : table) {
    std::visit(
        [&](const auto& f) {
          using F = std::decay_t<decltype(f)>;
          if constexpr (std::is_same_v<F, NumberField<S>>) {
            if (f.has && !f.has(s)) return;
            const double v = f.unit.from_si(f.get(s));
            if (!f.range.contains(v))
              throw InputError(std::string(f.key), format_value(v), f.range.describe(f.unit.symbol));
          } else if constexpr (std::is_same_v<F, IntField<S>>) {
            const int v = f.get(s);
            if (v < f.lo || v > f.hi)
              throw InputError(std::string(f.key), std::to_string(v),
                               fmt::format("an integer in [{}, {}]", f.lo, f.hi));
          } else if constexpr (std::is_same_v<F, ChoiceField<S>>) {
            const int v = f.get(s);
            if (v < 0 || static_cast<std::size_t>(v) >= f.names.size())
              throw InputError(std::string(f.key), std::to_string(v), "a valid choice");
          } else if constexpr (std::is_same_v<F, TextField<S>>) {
            if (f.check)
              if (const std::string expected = f.check(f.get(s)); !expected.empty())
                throw InputError(std::string(f.key), f.get(s), expected);
          }
        },
        field);
  }
}

/// Every field as key -> value in the key's unit (what read_fields reads back to the same struct).
template <class S>
Json fields_to_json(const FieldTable<S>& table, const S& s) {
  Json j = Json::object();
  for (const auto& field : table) {
    std::visit(
        [&](const auto& f) {
          using F = std::decay_t<decltype(f)>;
          const std::string key(f.key);
          if constexpr (std::is_same_v<F, NumberField<S>>) {
            if (!f.has || f.has(s)) j[key] = f.unit.from_si(f.get(s));
          } else if constexpr (std::is_same_v<F, ChoiceField<S>>) {
            j[key] = std::string(f.names[static_cast<std::size_t>(f.get(s))]);
          } else if constexpr (std::is_same_v<F, FlagsField<S>>) {
            Json list = Json::array();
            for (std::size_t k = 0; k < f.names.size(); ++k)
              if (f.get(s) >> k & 1u) list.push_back(std::string(f.names[k]));
            j[key] = list;
          } else {
            j[key] = f.get(s);
          }
        },
        field);
  }
  return j;
}

/// Each key of `table`, and of `more` (keys read beside it: objects of the same section), once: std::logic_error
/// naming `section` and the key otherwise (a table composed of parts, e.g. the analytic models' parameter blocks,
/// where two parts declaring one key would read one value into both).
template <class S>
void check_unique_keys(const FieldTable<S>& table, std::string_view section,
                       std::span<const std::string_view> more = {}) {
  std::vector<std::string_view> keys;
  for (const auto& field : table)
    keys.push_back(std::visit([](const auto& f) { return std::string_view(f.key); }, field));
  keys.insert(keys.end(), more.begin(), more.end());
  std::sort(keys.begin(), keys.end());
  if (const auto twice = std::adjacent_find(keys.begin(), keys.end()); twice != keys.end())
    throw std::logic_error(std::string(section) + ": the key '" + std::string(*twice) + "' is declared twice");
}

/// The key reference of a table as a Markdown table: key, unit, valid range, default (of `defaults`), meaning;
/// without the header, rows to append to another table.
template <class S>
std::string fields_markdown(const FieldTable<S>& table, const S& defaults = S{}, bool with_header = true) {
  std::string md = with_header ? "| key | unit | valid | default | meaning |\n|---|---|---|---|---|\n" : "";
  for (const auto& field : table) {
    std::visit(
        [&](const auto& f) {
          using F = std::decay_t<decltype(f)>;
          std::string unit = "-", valid, value;
          if constexpr (std::is_same_v<F, NumberField<S>>) {
            if (!f.unit.symbol.empty()) unit = std::string(f.unit.symbol);
            valid = f.range.describe("");
            value = f.required                  ? "required"
                    : f.has && !f.has(defaults) ? std::string(f.absent)
                                                : format_value(f.unit.from_si(f.get(defaults)));
          } else if constexpr (std::is_same_v<F, IntField<S>>) {
            valid = fmt::format("an integer in [{}, {}]", f.lo, f.hi);
            value = std::to_string(f.get(defaults));
          } else if constexpr (std::is_same_v<F, BoolField<S>>) {
            valid = "true or false";
            value = f.get(defaults) ? "true" : "false";
          } else if constexpr (std::is_same_v<F, ChoiceField<S>>) {
            for (std::size_t k = 0; k < f.names.size(); ++k) valid += fmt::format("{}`{}`", k ? ", " : "", f.names[k]);
            value = fmt::format("`{}`", f.names[static_cast<std::size_t>(f.get(defaults))]);
          } else if constexpr (std::is_same_v<F, TextField<S>>) {
            valid = f.check ? std::string(f.check("")) : "text";
            if (valid.empty()) valid = "text";
            value = f.get(defaults).empty() ? "empty" : fmt::format("`{}`", f.get(defaults));
          } else if constexpr (std::is_same_v<F, NameListField<S>>) {
            valid = "a list of ";
            for (std::size_t k = 0; k < f.names.size(); ++k) valid += fmt::format("{}`{}`", k ? ", " : "", f.names[k]);
            for (const auto& name : f.get(defaults)) value += fmt::format("{}`{}`", value.empty() ? "" : ", ", name);
            if (value.empty()) value = "none";
          } else {
            valid = "a list of ";
            for (std::size_t k = 0; k < f.names.size(); ++k) {
              valid += fmt::format("{}`{}`", k ? ", " : "", f.names[k]);
              if (f.get(defaults) >> k & 1u) value += fmt::format("{}`{}`", value.empty() ? "" : ", ", f.names[k]);
            }
            if (value.empty()) value = "none";
          }
          md += fmt::format("| `{}` | {} | {} | {} | {} |\n", f.key, unit, valid, value, f.doc);
        },
        field);
  }
  return md;
}

/// Runs `body`; an InputError it throws is rethrown with `path.` before its field (the scene layer's map
/// from a physics check to the JSON key).
template <class Body>
decltype(auto) with_path(const std::string& path, Body&& body) {
  try {
    return std::forward<Body>(body)();
  } catch (const InputError& e) {
    if (path.empty()) throw;
    throw e.with_prefix(path);
  }
}

}  // namespace kerf
