// Physics functions name their own fields; the scene layer names the scene's keys (kinds/scene_keys.hpp, issue 56
// item 3): the mapping, and the physics' own names where they are called without a scene.
#include "kerf/analytic/kinds/scene_keys.hpp"

#include <catch2/catch.hpp>
#include <cmath>

#include "kerf/analytic/forces/critical_depth.hpp"
#include "kerf/analytic/forces/liu_li.hpp"
#include "kerf/analytic/forces/ploughing.hpp"
#include "kerf/analytic/forces/transition.hpp"

namespace {

constexpr kerf::SceneKeyOf kKeys[] = {{"uncut_chip_thickness_m", "cut.uncut_chip_thickness_um", kerf::units::kUm, "m"},
                                      {"friction_angle_rad", "cut.friction_angle_deg", kerf::units::kDeg, ""},
                                      {"params.ductile_layer_factor", "models.transition.ductile_layer_factor"}};

template <class F>
std::string message_of(F&& f) {
  try {
    f();
  } catch (const kerf::InputError& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace

TEST_CASE("A physics field is named by the scene's key, its value and unit the key's", "[scene_keys][issue56]") {
  const kerf::InputError physics("uncut_chip_thickness_m", "-1e-06", "a positive value in m");
  const kerf::InputError named = kerf::at_scene_key(physics, kKeys);
  CHECK(named.field() == "cut.uncut_chip_thickness_um");
  CHECK(named.value() == "-1");
  CHECK(std::string(named.what()) == "cut.uncut_chip_thickness_um = -1: expected a positive value in um");

  // A value that is no number stays as it was; an expectation without the unit is kept.
  const kerf::InputError missing("friction_angle_rad", "(missing)", "a friction angle");
  CHECK(std::string(kerf::at_scene_key(missing, kKeys).what()) ==
        "cut.friction_angle_deg = (missing): expected a "
        "friction angle");
  // A field the scene did not set is left alone.
  const kerf::InputError other("attack_angle_deg", "-1", "a non-negative value in deg");
  CHECK(kerf::at_scene_key(other, kKeys).field() == "attack_angle_deg");
}

TEST_CASE("Physics functions throw on their own field names, the scene layer on its keys", "[scene_keys][issue56]") {
  const kerf::LiuLiParams liu_li{};
  CHECK(message_of([&] { kerf::liu_li_force_per_width(liu_li, 1e9, -1e-6, nullptr); }) ==
        "uncut_chip_thickness_m = -1e-06: expected a positive value in m");
  CHECK(message_of([&] {
          kerf::naming_scene_keys(kKeys, [&] { return kerf::liu_li_force_per_width(liu_li, 1e9, -1e-6, nullptr); });
        }) == "cut.uncut_chip_thickness_um = -1: expected a positive value in um");

  kerf::TransitionParams transition;
  transition.layer_factor = 0.0;
  CHECK(message_of([&] {
          kerf::fracture_force_per_width(transition, 0.75e6, 1e-4, 1e-8, 0.0, 0.3);
        }).starts_with("params.ductile_layer_factor = 0:"));
  CHECK(message_of([&] {
          kerf::naming_scene_keys(
              kKeys, [&] { return kerf::fracture_force_per_width(transition, 0.75e6, 1e-4, 1e-8, 0.0, 0.3); });
        }).starts_with("models.transition.ductile_layer_factor = 0:"));

  CHECK(message_of([] {
          kerf::edge_ploughing_force_per_width({.edge_radius_m = -1e-6}, 1e9, 1e-7, nullptr);
        }).starts_with("edge_radius_m = -1e-06:"));
  CHECK(message_of([] { kerf::classify_regime(-1e-9, 36e-9); }).starts_with("depth_m = -1e-09:"));
}
