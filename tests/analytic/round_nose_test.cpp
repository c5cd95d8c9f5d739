#include "kerf/analytic/kinds/round_nose.hpp"

#include <catch2/catch.hpp>
#include <cmath>

#include "kerf/error.hpp"

using Catch::Matchers::WithinRel;

TEST_CASE("Round-nose chip: area, edge length and thicknesses", "[round_nose]") {
  // Shao et al. 2013's turning: f = 0.25 um/rev, R = 0.5 mm.
  const kerf::RoundNoseTurning turn{.feed_m_per_rev = 0.25e-6, .nose_radius_m = 0.5e-3, .depth_of_cut_m = 10e-6};
  const auto chip = kerf::round_nose_chip(turn, nullptr);
  CHECK_THAT(chip.area_m2, WithinRel(2.5e-12, 1e-14));
  CHECK_THAT(chip.engaged_edge_length_m,
             WithinRel(0.5e-3 * (std::acos(1.0 - 0.02) + std::asin(0.25e-6 / 1e-3)), 1e-14));
  // First order in f: t_max ~ f sin(kappa), sin(kappa) = sqrt(2 R a - a^2) / R; the next term is about
  // f / (2 sqrt(2 R a)) = 0.13 % smaller here.
  const double half_chord = std::sqrt(2 * 0.5e-3 * 10e-6 - 1e-10);
  const double small_feed_limit = 0.25e-6 * half_chord / 0.5e-3;
  CHECK_THAT(chip.maximum_thickness_m, WithinRel(small_feed_limit, 2e-3));
  // Exact geometry: the previous pass's arc meets the surface at (c - f, a) from the current centre's foot,
  // at distance R - t_max from the current centre.
  const double R = 0.5e-3, a = 10e-6, f = 0.25e-6, t = chip.maximum_thickness_m;
  CHECK_THAT(std::hypot(half_chord - f, R - a), WithinRel(R - t, 1e-12));
  CHECK(chip.equivalent_thickness_m < chip.maximum_thickness_m);
  CHECK_THAT(chip.equivalent_thickness_m * chip.engaged_edge_length_m, WithinRel(chip.area_m2, 1e-14));
}

TEST_CASE("Round-nose chip thickness grows with depth of cut and feed", "[round_nose]") {
  double previous = 0.0;
  for (double depth_um : {0.5, 2.0, 10.0, 50.0, 300.0}) {
    const auto chip = kerf::round_nose_chip({0.25e-6, 0.5e-3, depth_um * 1e-6}, nullptr);
    CHECK(chip.maximum_thickness_m > previous);
    previous = chip.maximum_thickness_m;
  }
}

TEST_CASE("Depth below the feed's reach fires a guard and keeps t_max <= a_p", "[round_nose][guards]") {
  kerf::Guards guards;
  const auto chip = kerf::round_nose_chip({50e-6, 0.5e-3, 0.1e-6}, &guards);
  CHECK(guards.has(kerf::Guard::turning_depth_below_feed));
  CHECK(chip.maximum_thickness_m <= 0.1e-6);
}

TEST_CASE("Round-nose geometry is validated", "[round_nose]") {
  CHECK_THROWS_AS(kerf::RoundNoseTurning({0.25e-6, 0.5e-3, 0.6e-3}).validate("cut.turning"), kerf::InputError);
  CHECK_THROWS_AS(kerf::RoundNoseTurning({0.0, 0.5e-3, 10e-6}).validate("cut.turning"), kerf::InputError);
}
