#include "kerf/analytic/forces/critical_depth.hpp"

#include <catch2/catch.hpp>

#include "kerf/error.hpp"

using Catch::Matchers::WithinRel;

namespace {
double critical_depth_nm_of(const std::string& name) {
  const auto material = kerf::load_material(kerf::Json(name), "material");
  return kerf::critical_depth_m(kerf::brittle_properties(material, "material")) * 1e9;
}
std::string field_of_missing(const kerf::Json& inline_material) {
  try {
    kerf::brittle_properties(kerf::load_material(inline_material, "material"), "material");
  } catch (const kerf::InputError& e) {
    return e.field();
  }
  return "(no error)";
}
}  // namespace

TEST_CASE("Bifano critical depth d_c = 0.15 (E/H)(K_c/H)^2", "[critical_depth]") {
  // Closed form: E = 100 GPa, H = 10 GPa, K_c = 1 MPa m^0.5 -> 0.15 * 10 * (1e-4)^2 m = 15 nm.
  CHECK_THAT(kerf::critical_depth_m({100e9, 10e9, 1e6}), WithinRel(15e-9, 1e-14));
  // Scaling: d_c ~ E K_c^2 / H^3.
  CHECK_THAT(kerf::critical_depth_m({100e9, 20e9, 1e6}), WithinRel(15e-9 / 8.0, 1e-14));
  CHECK_THAT(kerf::critical_depth_m({100e9, 10e9, 2e6}), WithinRel(60e-9, 1e-14));
}

TEST_CASE("Critical depths of the bundled brittle materials are tens of nanometres", "[critical_depth]") {
  // Material files: soda-lime E 71, H 5.5, K_c 0.75; K9 E 82, H 7.2, K_c 0.85; p-SiC E 410, H 24, K_c 3.5.
  CHECK_THAT(critical_depth_nm_of("soda_lime_glass"),
             WithinRel(0.15 * (71 / 5.5) * (0.75e-3 / 5.5) * (0.75e-3 / 5.5) * 1e9, 1e-12));
  CHECK_THAT(critical_depth_nm_of("soda_lime_glass"), WithinRel(36.0, 0.01));
  CHECK_THAT(critical_depth_nm_of("k9_glass"), WithinRel(23.8, 0.01));
  CHECK_THAT(critical_depth_nm_of("psic"), WithinRel(54.5, 0.01));
}

TEST_CASE("Regime: ductile below d_c, transition up to 3 d_c, brittle beyond", "[critical_depth]") {
  const double dc = 36e-9;
  CHECK(kerf::classify_regime(0.0, dc) == kerf::CuttingRegime::ductile);
  CHECK(kerf::classify_regime(20e-9, dc) == kerf::CuttingRegime::ductile);
  CHECK(kerf::classify_regime(36e-9, dc) == kerf::CuttingRegime::transition);
  CHECK(kerf::classify_regime(100e-9, dc) == kerf::CuttingRegime::transition);
  CHECK(kerf::classify_regime(108e-9, dc) == kerf::CuttingRegime::brittle);
  // Yang et al. 2018 cuts soda-lime glass 0.1 mm deep: deep in the brittle regime.
  CHECK(kerf::classify_regime(0.1e-3, dc) == kerf::CuttingRegime::brittle);
  // No band: a sharp switch at d_c.
  CHECK(kerf::classify_regime(36e-9, dc, {.brittle_factor = 1.0}) == kerf::CuttingRegime::brittle);
  CHECK(kerf::cutting_regime_name(kerf::CuttingRegime::transition) == "transition");
  CHECK_THROWS_AS(kerf::classify_regime(-1e-9, dc), kerf::InputError);
  CHECK_THROWS_AS(kerf::classify_regime(1e-9, dc, {.brittle_factor = 0.5}), kerf::InputError);
}

TEST_CASE("Missing material data is named by group and key", "[critical_depth][errors]") {
  const kerf::Json no_brittle = {{"name", "x"}, {"elastic", {{"youngs_modulus_GPa", 70}}}};
  CHECK(field_of_missing(no_brittle) == "material.brittle");
  const kerf::Json no_toughness = {
      {"name", "x"}, {"elastic", {{"youngs_modulus_GPa", 70}}}, {"brittle", {{"hardness_GPa", 5.5}}}};
  CHECK(field_of_missing(no_toughness) == "material.brittle.fracture_toughness_MPa_sqrt_m");
  const kerf::Json no_elastic = {{"name", "x"},
                                 {"brittle", {{"hardness_GPa", 5.5}, {"fracture_toughness_MPa_sqrt_m", 0.7}}}};
  CHECK(field_of_missing(no_elastic) == "material.elastic");
  const kerf::Json zero_hardness = {{"name", "x"},
                                    {"elastic", {{"youngs_modulus_GPa", 70}}},
                                    {"brittle", {{"hardness_GPa", 0}, {"fracture_toughness_MPa_sqrt_m", 0.7}}}};
  CHECK(field_of_missing(zero_hardness) == "material.brittle.hardness_GPa");
}
