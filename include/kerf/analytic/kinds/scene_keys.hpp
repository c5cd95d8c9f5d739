#pragma once
// Physics functions name their own fields (an argument, or an argument's member, in SI: "uncut_chip_thickness_m",
// "cut.workpiece_temperature_K" of an OxleyCut); the scene layer that called them names the scene's key instead,
// with the value in the key's unit. A force model's unit lists the fields it passes from the scene:
//
//   constexpr kerf::SceneKeyOf kKeys[] = {
//       {"uncut_chip_thickness_m", "cut.uncut_chip_thickness_um", kerf::units::kUm, "m"}};
//   const auto r =
//       kerf::naming_scene_keys(kKeys, [&] { return kerf::liu_li_force_per_width(params, k_s, t0, &guards); });
//   // "cut.uncut_chip_thickness_um = -1: expected a positive value in um"
#include <span>
#include <string_view>

#include "kerf/error.hpp"
#include "kerf/field_table.hpp"

namespace kerf {

/// A physics function's field and the scene key that sets it.
struct SceneKeyOf {
  std::string_view field;         ///< as the physics names it: "uncut_chip_thickness_m"
  std::string_view key;           ///< the scene's key: "cut.uncut_chip_thickness_um"
  FieldUnit unit = units::kNone;  ///< the key's unit: the value is converted from SI to it
  std::string_view si_unit = "";  ///< the field's unit as its expectation ends ("in m"): becomes the key's
};

/// `e` naming the scene key of its field (its value in the key's unit, an expectation that ends in the SI unit
/// ending in the key's); `e` itself when its field is none of `keys`.
InputError at_scene_key(const InputError& e, std::span<const SceneKeyOf> keys);

/// f(), an InputError it throws named by the scene key of its field (at_scene_key).
template <class F>
decltype(auto) naming_scene_keys(std::span<const SceneKeyOf> keys, F&& f) {
  try {
    return f();
  } catch (const InputError& e) {
    throw at_scene_key(e, keys);
  }
}

}  // namespace kerf
