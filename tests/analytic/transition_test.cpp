#include "kerf/analytic/forces/transition.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <utility>

#include "kerf/analytic/forces/glass_edge.hpp"
#include "kerf/analytic/forces/transition_model.hpp"
#include "kerf/analytic/kinds/predict.hpp"
#include "kerf/analytic/kinds/scene.hpp"
#include "kerf/error.hpp"
#include "kerf/units.hpp"

using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {
constexpr double kRake = -15.0, kMu = 0.3;

kerf::Json glass_scene(double depth_um, const std::string& force = "transition", double edge_radius_um = 0.0) {
  return {{"material", "soda_lime_glass"},
          {"tool", {{"rake_deg", kRake}, {"edge_radius_um", edge_radius_um}}},
          {"cut",
           {{"uncut_chip_thickness_um", depth_um},
            {"width_mm", 1.0},
            {"speed_m_per_min", 60.0},
            {"friction_coefficient", kMu}}},
          {"models", {{"force", force}}}};
}
kerf::Prediction predict_doc(const kerf::Json& doc) {
  return kerf::predict(kerf::parse_analytic_scene(doc));
}
double critical_depth_um() {
  return kerf::parse_analytic_scene(glass_scene(1.0)).critical_depth_m.value() * 1e6;
}
}  // namespace

TEST_CASE("Fracture part: zeta K_c (sqrt(h) - sqrt(l)), thrust along the rake face's friction", "[transition]") {
  const kerf::TransitionParams t{.layer_factor = 1.0, .fracture_coefficient = 0.8};
  const double rake = kerf::units::deg_to_rad(-15.0), beta = std::atan(0.3), l = 36e-9;
  CHECK(kerf::fracture_force_per_width(t, 0.75e6, l, l, rake, beta).cutting_N_per_m == 0.0);
  CHECK(kerf::fracture_force_per_width(t, 0.75e6, 0.5 * l, l, rake, beta).cutting_N_per_m == 0.0);
  const auto f = kerf::fracture_force_per_width(t, 0.75e6, 1e-4, l, rake, beta);
  CHECK_THAT(f.cutting_N_per_m, WithinRel(0.8 * 0.75e6 * (std::sqrt(1e-4) - std::sqrt(l)), 1e-14));
  CHECK_THAT(f.thrust_N_per_m / f.cutting_N_per_m, WithinRel(std::tan(beta - rake), 1e-14));
  kerf::TransitionParams none = t;
  none.fracture = kerf::FractureModel::none;
  CHECK(kerf::fracture_force_per_width(none, 0.75e6, 1e-4, l, rake, beta).cutting_N_per_m == 0.0);
  CHECK_THROWS_AS(kerf::fracture_force_per_width(t, 0.75e6, -1e-9, l, rake, beta), kerf::InputError);
  // A rake above the friction angle: the thrust turns negative, as in Merchant's circle; beyond 90 deg, refused.
  CHECK(kerf::fracture_force_per_width(t, 0.75e6, 1e-4, l, 0.3, 0.1).thrust_N_per_m < 0.0);
  CHECK_THROWS_AS(kerf::fracture_force_per_width(t, 0.75e6, 1e-4, l, -1.2, 0.5), kerf::InputError);
}

TEST_CASE("Transition model: the ductile model below the layer, continuous at it", "[transition]") {
  const double dc_um = critical_depth_um();
  for (double r_um : {0.0, 0.02}) {
    // Below l = d_c: the ductile model itself (merchant for a sharp edge, liu_li with one), to the bit.
    const auto below = predict_doc(glass_scene(0.5 * dc_um, "transition", r_um));
    const auto ductile = predict_doc(glass_scene(0.5 * dc_um, r_um > 0.0 ? "liu_li" : "merchant", r_um));
    CHECK(below.cutting_force_N == ductile.cutting_force_N);
    CHECK(below.thrust_force_N == ductile.thrust_force_N);
    CHECK(kerf::transition_details(below)->fracture.cutting_N_per_m == 0.0);
    // Through l: relative jump < 1e-9.
    const auto just_below = predict_doc(glass_scene(dc_um * (1.0 - 1e-12), "transition", r_um));
    const auto just_above = predict_doc(glass_scene(dc_um * (1.0 + 1e-12), "transition", r_um));
    CHECK_THAT(just_above.cutting_force_N, WithinRel(just_below.cutting_force_N, 1e-9));
    CHECK_THAT(just_above.thrust_force_N, WithinRel(just_below.thrust_force_N, 1e-9));
  }
}

TEST_CASE("Transition model: finite and monotone from 10 nm to 0.2 mm, no fracture part as K_c grows",
          "[transition][extremes]") {
  double previous = 0.0;
  for (double h_um = 0.01; h_um <= 200.0; h_um *= 1.5) {
    const auto p = predict_doc(glass_scene(h_um));
    CHECK(std::isfinite(p.cutting_force_N));
    CHECK(std::isfinite(p.thrust_force_N));
    CHECK(p.cutting_force_N > previous);
    previous = p.cutting_force_N;
  }
  // A tougher glass (K_c x10: d_c x100 = 3.6 um) cut at 1 um: no fracture part, the ductile model alone.
  kerf::Json tough = glass_scene(1.0);
  tough["material"] = kerf::Json{
      {"name", "tough"},
      {"elastic", {{"youngs_modulus_GPa", 71}, {"poissons_ratio", 0.23}}},
      {"brittle", {{"hardness_GPa", 5.5}, {"fracture_toughness_MPa_sqrt_m", 7.5}, {"constraint_factor", 1.7}}}};
  const auto p = predict_doc(tough);
  CHECK(kerf::transition_details(p)->fracture.cutting_N_per_m == 0.0);
  tough["models"]["force"] = "merchant";
  CHECK(predict_doc(tough).cutting_force_N == p.cutting_force_N);
  // The layer alone (fracture none) above l: the force stops growing with the depth.
  kerf::Json edge_only = glass_scene(10.0);
  edge_only["models"]["fracture"] = "none";
  kerf::Json deeper = edge_only;
  deeper["cut"]["uncut_chip_thickness_um"] = 100.0;
  CHECK(predict_doc(edge_only).cutting_force_N == predict_doc(deeper).cutting_force_N);
}

TEST_CASE("Transition model: a metal without toughness is refused, naming the group", "[transition][errors]") {
  kerf::Json doc = glass_scene(1.0);
  doc["material"] = "aisi_1045";
  try {
    predict_doc(doc);
    FAIL("no error");
  } catch (const kerf::InputError& e) {
    CHECK(e.field() == "material.brittle");
  }
}

TEST_CASE("Transition parameters are checked through their field table, as the scene reads them",
          "[transition][errors]") {
  // validate() and the scene's models.transition share transition_fields(): the same range, the same expectation.
  const auto message = [](const auto& body) -> std::string {
    try {
      body();
    } catch (const kerf::InputError& e) {
      return e.what();
    }
    return "(no error)";
  };
  for (const auto& [key, value] : {std::pair{"ductile_layer_factor", 0.0}, std::pair{"fracture_coefficient", -1.0}}) {
    kerf::TransitionParams t;
    (std::string(key) == "ductile_layer_factor" ? t.layer_factor : t.fracture_coefficient) = value;
    const std::string own = message([&] { t.validate("params"); });
    kerf::Json doc = glass_scene(1.0);
    doc["models"]["transition"] = {{key, value}};
    const std::string scene = message([&] { kerf::parse_analytic_scene(doc); });
    CHECK(own.starts_with("params." + std::string(key) + " = "));
    CHECK(scene.starts_with("models.transition." + std::string(key) + " = "));
    CHECK(own.substr(own.find(" = ")) == scene.substr(scene.find(" = ")));
  }
  CHECK(message([] { kerf::TransitionParams{.layer_factor = 0.0}.validate("params"); }) ==
        "params.ductile_layer_factor = 0: expected a positive value in (times d_c)");
  CHECK_NOTHROW(kerf::TransitionParams{}.validate("params"));
}

TEST_CASE("Edge force on the ductile layer: Merchant's closed form for a sharp edge", "[transition][glass_edge]") {
  const kerf::EdgeTool tool{
      .rake_rad = kerf::units::deg_to_rad(kRake), .edge_radius_m = 0.0, .friction_coefficient = kMu};
  const kerf::EdgeForce f = kerf::edge_force_per_width(kerf::Json("soda_lime_glass"), tool);
  // Y = H / C = 5.5 GPa / 1.7, k = Y / sqrt(3); phi = pi/4 - (beta - alpha)/2 (Merchant's minimum energy).
  const double k = 5.5e9 / 1.7 / std::sqrt(3.0), a = tool.rake_rad, b = std::atan(kMu);
  const double phi = M_PI / 4.0 - (b - a) / 2.0, l = f.critical_depth_m;
  const double cutting = k * l * std::cos(b - a) / (std::sin(phi) * std::cos(phi + b - a));
  CHECK_THAT(f.ductile_layer_m, WithinRel(l, 1e-15));
  CHECK_THAT(f.force.cutting_N_per_m, WithinRel(cutting, 1e-9));
  CHECK_THAT(f.force.thrust_N_per_m, WithinRel(cutting * std::tan(b - a), 1e-9));
  CHECK_THAT(f.flow_stress_Pa, WithinRel(5.5e9 / 1.7, 1e-15));
  // The same number as the transition model's edge part of a deep cut; the layer scales it linearly.
  const auto deep = predict_doc(glass_scene(100.0));
  CHECK_THAT(kerf::transition_details(deep)->layer.cutting_N_per_m, WithinRel(f.force.cutting_N_per_m, 1e-12));
  kerf::EdgeTool thicker = tool;
  thicker.layer_factor = 3.0;
  CHECK_THAT(kerf::edge_force_per_width(kerf::Json("soda_lime_glass"), thicker).force.cutting_N_per_m,
             WithinRel(3.0 * f.force.cutting_N_per_m, 1e-9));
  // A rounded edge (r >> l) stays finite and pushes down harder than a sharp one.
  kerf::EdgeTool honed = tool;
  honed.edge_radius_m = 20e-6;
  const auto rounded = kerf::edge_force_per_width(kerf::Json("soda_lime_glass"), honed);
  CHECK(std::isfinite(rounded.force.cutting_N_per_m));
  CHECK(rounded.force.thrust_N_per_m > f.force.thrust_N_per_m);
}
