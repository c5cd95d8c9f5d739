// Calibration to one measured cut: the strength factor's material and its update rule.
#include "kerf/dem/procedures/cut_calibration.hpp"

#include <catch2/catch.hpp>
#include <cmath>

#include "kerf/dem/procedures/calibration.hpp"
#include "kerf/error.hpp"

using namespace kerf::dem;
using Catch::Matchers::WithinRel;

TEST_CASE("cut calibration: the strength factor scales both bond strengths and nothing else", "[cut_calibration]") {
  Material m;
  m.name = "glass";
  const Material same = scale_bond_strengths(m, 1.0, "other");
  CHECK(same.name == "glass");
  CHECK(same_micro_parameters(same, m));
  const Material s = scale_bond_strengths(m, 1.5, "glass_x1.5");
  CHECK(s.name == "glass_x1.5");
  CHECK(std::get<FlatJointParams>(s.joint).bond.tensile_strength_Pa ==
        1.5 * std::get<FlatJointParams>(m.joint).bond.tensile_strength_Pa);
  CHECK(std::get<FlatJointParams>(s.joint).bond.cohesion_Pa ==
        1.5 * std::get<FlatJointParams>(m.joint).bond.cohesion_Pa);
  Material back = s;
  std::get<FlatJointParams>(back.joint).bond.tensile_strength_Pa =
      std::get<FlatJointParams>(m.joint).bond.tensile_strength_Pa;
  std::get<FlatJointParams>(back.joint).bond.cohesion_Pa = std::get<FlatJointParams>(m.joint).bond.cohesion_Pa;
  CHECK(same_micro_parameters(back, m));  // moduli, stiffness ratios, friction, damping untouched
  CHECK_THROWS_AS(scale_bond_strengths(m, 0.0, "x"), kerf::ModelError);
  CHECK_THROWS_AS(scale_bond_strengths(m, std::nan(""), "x"), kerf::ModelError);
}

TEST_CASE("cut calibration: the update meets a power law and stays bounded on noise", "[cut_calibration]") {
  // Forces proportional to the strengths: one step lands on the target.
  CHECK_THAT(next_strength_factor({{1.0, 8.45}}, 14.98), WithinRel(14.98 / 8.45, 1e-12));
  CHECK_THAT(next_strength_factor({{2.0, 10.0}}, 5.0), WithinRel(1.0, 1e-12));
  // F = 6 s^0.7: the secant finds the slope and converges in a few evaluations.
  const auto force = [](double s) { return 6.0 * std::pow(s, 0.7); };
  std::vector<CutCalibrationPoint> h{{1.0, force(1.0)}};
  for (int k = 0; k < 6; ++k) {
    const double s = next_strength_factor(h, 15.0);
    h.push_back({s, force(s)});
  }
  CHECK_THAT(h.back().main_force_N, WithinRel(15.0, 1e-9));
  // Scatter that makes the force fall as the strengths rise: the slope is held at 0.5, not followed.
  CHECK_THAT(next_strength_factor({{1.0, 8.0}, {1.5, 7.0}}, 14.0), WithinRel(1.5 * std::pow(2.0, 2.0), 1e-12));
  // A flat secant would ask for a huge step: capped at a factor 4.
  CHECK_THAT(next_strength_factor({{1.0, 8.0}, {1.01, 8.0001}}, 1e6), WithinRel(4.04, 1e-12));
  CHECK_THAT(next_strength_factor({{1.0, 8.0}}, 1e-6), WithinRel(0.25, 1e-12));
  // The points with the same factor as the last are skipped for the slope (here ln(9/4) / ln 2).
  CHECK_THAT(next_strength_factor({{0.5, 4.0}, {1.0, 8.0}, {1.0, 9.0}}, 18.0),
             WithinRel(std::pow(2.0, std::log(2.0) / std::log(9.0 / 4.0)), 1e-12));
  CHECK_THROWS_AS(next_strength_factor({}, 1.0), kerf::ModelError);
  CHECK_THROWS_AS(next_strength_factor({{1.0, 0.0}}, 1.0), kerf::ModelError);
}
