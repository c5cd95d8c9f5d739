#pragma once
// Field-table pieces the analytic scene and its models' units share (kinds/scene.cpp, forces/*_model.cpp): a number
// reached through a member of a member, a choice mapped to an enum by name, and a choice among the registry's lines
// of one kind (each line's enum value, so the order of the lines changes nothing).
//
//   constexpr char kClosure[] = "friction_closure";
//   auto field = kerf::model_choice<ChipTermParams, FrictionClosure, kClosure>(
//       "beta_k along the edge", [](auto& s) -> auto& { return s.liu_li.closure; });
#include <cstddef>
#include <optional>
#include <span>
#include <string_view>

#include "kerf/analytic/registry.hpp"
#include "kerf/field_table.hpp"

namespace kerf {

/// A number field whose SI value is reached through `at` (a member of a member): `[](auto& s) -> auto& {...}`.
template <class S, class At>
NumberField<S> number_at(std::string_view key, FieldUnit unit, Range range, std::string_view doc, At at,
                         bool required = false) {
  return {key,      unit, range, doc, [at](const S& s) { return at(s); }, [at](S& s, double v) { at(s) = v; },
          required, {},   {}};
}

/// A choice whose names map to an enum through `parse` (nullopt: a name the field handles by itself), the enum
/// reached through `at`: the registry's names, the quadrature rules. The order of the names changes nothing.
template <class S, class E, class At>
ChoiceField<S> mapped_choice(std::string_view key, std::span<const std::string_view> names, std::string_view doc, At at,
                             std::optional<E> (*parse)(std::string_view)) {
  return {key, names, doc,
          [=](const S& s) {
            for (std::size_t k = 0; k < names.size(); ++k)
              if (parse(names[k]) == at(s)) return static_cast<int>(k);
            return 0;
          },
          [=](S& s, int k) { at(s) = *parse(names[static_cast<std::size_t>(k)]); }};
}

/// The enum value the registry line of `Kind` and `name` constructs.
template <class E, const char* Kind>
std::optional<E> registered_as(std::string_view name) {
  const auto id = registered_id(analytic_models(), Kind, name);
  return id ? std::optional<E>(static_cast<E>(*id)) : std::nullopt;
}

/// The key `Kind` (a kind of the registry: "friction_closure") as a choice among its lines, the enum reached
/// through `at`.
template <class S, class E, const char* Kind, class At>
ChoiceField<S> model_choice(std::string_view doc, At at) {
  return mapped_choice<S, E>(Kind, analytic_model_names(Kind), doc, at, &registered_as<E, Kind>);
}

}  // namespace kerf
