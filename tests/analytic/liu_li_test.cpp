#include "kerf/analytic/forces/liu_li.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "kerf/analytic/forces/shear_angle.hpp"
#include "kerf/error.hpp"
#include "kerf/units.hpp"

using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;
using kerf::FrictionClosure;
using kerf::LiuLiParams;
using kerf::units::deg_to_rad;

namespace {
constexpr double kShearStress = 1e9;  // Pa; the forces are linear in it

LiuLiParams params(FrictionClosure closure, double rake_deg = 0.0, double radius_um = 1.0, double beta_deg = 20.0) {
  LiuLiParams p;
  p.rake_rad = deg_to_rad(rake_deg);
  p.edge_radius_m = radius_um * 1e-6;
  p.friction_angle_rad = deg_to_rad(beta_deg);
  p.closure = closure;
  // The chip ratio of the matching shear-angle model at the nominal rake.
  const double phi = kerf::shear_angle(
      closure == FrictionClosure::lee_shaffer ? kerf::ShearAngleModel::lee_shaffer : kerf::ShearAngleModel::merchant,
      p.rake_rad, p.friction_angle_rad);
  p.chip_ratio = kerf::chip_ratio_from_shear_angle(phi, p.rake_rad);
  p.quadrature.relative_tolerance = 1e-12;
  return p;
}
}  // namespace

TEST_CASE("Merchant closure: the edge cutting force equals its closed form", "[liu_li]") {
  for (double rake_deg : {-30.0, 0.0, 10.0}) {
    for (double t0_um : {0.2, 1.0, 3.0}) {
      auto p = params(FrictionClosure::merchant, rake_deg);
      const auto r = kerf::liu_li_force_per_width(p, kShearStress, t0_um * 1e-6, nullptr);
      const double g_top = r.upper_limit_rad, g_low = r.lower_limit_rad, rc = p.chip_ratio;
      // physics-analytic.md §2: F_c / (k_s r) = (2 / r_c) [(g_top - g_L) + r_c (cos g_top - cos g_L)]
      const double closed =
          kShearStress * p.edge_radius_m * (2.0 / rc) * ((g_top - g_low) + rc * (std::cos(g_top) - std::cos(g_low)));
      CHECK_THAT(r.edge.cutting_N_per_m, WithinRel(closed, 1e-10));
    }
  }
}

TEST_CASE("Merchant closure matches the Merchant shear angle at the nominal rake", "[liu_li]") {
  // With the chip ratio of the MEP shear angle, the closure gives back the friction angle at g = a.
  const auto p = params(FrictionClosure::merchant, 5.0, 1.0, 25.0);
  const double phi = kerf::local_shear_angle(p.chip_ratio, p.rake_rad);
  CHECK_THAT(kerf::local_friction_angle(p.closure, p.friction_angle_rad, p.rake_rad, phi),
             WithinAbs(p.friction_angle_rad, 1e-12));
}

TEST_CASE("Liu-Li forces are continuous where the chip leaves the edge", "[liu_li]") {
  for (auto closure : {FrictionClosure::constant, FrictionClosure::merchant, FrictionClosure::lee_shaffer}) {
    for (double rake_deg : {-20.0, 0.0, 15.0}) {
      const auto p = params(closure, rake_deg);
      const double boundary = p.edge_radius_m * (1.0 + std::sin(p.rake_rad));
      const auto below = kerf::liu_li_force_per_width(p, kShearStress, boundary * (1.0 - 1e-9), nullptr);
      const auto above = kerf::liu_li_force_per_width(p, kShearStress, boundary * (1.0 + 1e-9), nullptr);
      CHECK(below.chip_on_edge_only);
      CHECK_FALSE(above.chip_on_edge_only);
      CHECK_THAT(above.total.cutting_N_per_m, WithinRel(below.total.cutting_N_per_m, 1e-6));
      CHECK_THAT(above.total.thrust_N_per_m, WithinRel(below.total.thrust_N_per_m, 1e-6));
    }
  }
}

TEST_CASE("Liu-Li reduces to the sharp-tool force as r -> 0", "[liu_li]") {
  for (auto closure : {FrictionClosure::constant, FrictionClosure::merchant, FrictionClosure::lee_shaffer}) {
    const double t0 = 2e-6;
    auto p = params(closure, -5.0, 0.0);
    const double phi = kerf::local_shear_angle(p.chip_ratio, p.rake_rad);
    const double beta = kerf::local_friction_angle(closure, p.friction_angle_rad, p.rake_rad, phi);
    const auto sharp = kerf::sharp_tool_force_per_width(kShearStress, t0, phi, beta, p.rake_rad);
    const auto zero = kerf::liu_li_force_per_width(p, kShearStress, t0, nullptr);
    CHECK(zero.total.cutting_N_per_m == sharp.cutting_N_per_m);
    p.edge_radius_m = 1e-12;
    const auto tiny = kerf::liu_li_force_per_width(p, kShearStress, t0, nullptr);
    CHECK_THAT(tiny.total.cutting_N_per_m, WithinRel(sharp.cutting_N_per_m, 1e-5));
    CHECK_THAT(tiny.total.thrust_N_per_m, WithinRel(sharp.thrust_N_per_m, 1e-5));
  }
}

TEST_CASE("Liu-Li cutting force rises with uncut chip thickness", "[liu_li]") {
  for (auto closure : {FrictionClosure::constant, FrictionClosure::merchant, FrictionClosure::lee_shaffer}) {
    const auto p = params(closure, -10.0, 2.0);
    double previous = -1.0;
    for (double t0_um = 0.01; t0_um < 20.0; t0_um *= 1.3) {
      const auto r = kerf::liu_li_force_per_width(p, kShearStress, t0_um * 1e-6, nullptr);
      CHECK(r.total.cutting_N_per_m >= previous);
      previous = r.total.cutting_N_per_m;
    }
  }
}

TEST_CASE("Constant closure: the pole is found and the integral starts above it", "[liu_li]") {
  // physics-analytic.md §2: r_c = 0.5, beta = 30 deg puts the pole near -45.5 deg.
  LiuLiParams p;
  p.edge_radius_m = 1e-6;
  p.chip_ratio = 0.5;
  p.friction_angle_rad = deg_to_rad(30.0);
  p.closure = FrictionClosure::constant;
  p.lower_limit = kerf::LowerLimitRule::pole;
  kerf::Guards guards;
  const auto r = kerf::liu_li_force_per_width(p, kShearStress, 0.9e-6, &guards);
  REQUIRE(r.pole_rad.has_value());
  CHECK_THAT(kerf::units::rad_to_deg(*r.pole_rad), WithinAbs(-45.5, 0.5));
  CHECK_THAT(r.lower_limit_rad, WithinAbs(*r.pole_rad + p.lower_limit_margin_rad, 1e-12));
  CHECK(guards.has(kerf::Guard::lower_limit_above_pole));
  CHECK(std::isfinite(r.total.thrust_N_per_m));
  // The ploughed layer is what lies below the lower limit.
  CHECK_THAT(r.ploughed_thickness_m, WithinRel(1e-6 * (1.0 + std::sin(r.lower_limit_rad)), 1e-12));
}

TEST_CASE("The stagnation rule starts at -(pi/4 + beta/2)", "[liu_li]") {
  const auto p = params(FrictionClosure::merchant, 0.0, 1.0, 20.0);
  const auto r = kerf::liu_li_force_per_width(p, kShearStress, 1.5e-6, nullptr);
  CHECK_THAT(r.lower_limit_rad, WithinAbs(-(std::numbers::pi / 4 + deg_to_rad(10.0)), 1e-15));
}

TEST_CASE("A cut entirely below the lower limit has no chip and zero modelled force", "[liu_li][guards]") {
  const auto p = params(FrictionClosure::merchant, 0.0, 10.0, 20.0);
  kerf::Guards guards;
  const auto r = kerf::liu_li_force_per_width(p, kShearStress, 1e-9, &guards);  // 1 nm on a 10 um edge
  CHECK(guards.has(kerf::Guard::no_chip_on_edge));
  CHECK(r.total.cutting_N_per_m == 0.0);
  CHECK(r.ploughed_thickness_m == 1e-9);
}

TEST_CASE("Quadrature rules agree on the Liu-Li integral", "[liu_li][quadrature]") {
  auto p = params(FrictionClosure::constant, -10.0, 2.0, 25.0);
  const auto reference = kerf::liu_li_force_per_width(p, kShearStress, 1.2e-6, nullptr);
  for (auto rule : {kerf::QuadratureRule::tanh_sinh, kerf::QuadratureRule::gsl_qag}) {
    p.quadrature.rule = rule;
    const auto r = kerf::liu_li_force_per_width(p, kShearStress, 1.2e-6, nullptr);
    CHECK_THAT(r.total.cutting_N_per_m, WithinRel(reference.total.cutting_N_per_m, 1e-8));
    CHECK_THAT(r.total.thrust_N_per_m, WithinRel(reference.total.thrust_N_per_m, 1e-8));
  }
}

TEST_CASE("Liu-Li never returns NaN over the extreme parameter space", "[liu_li][extremes]") {
  int finite = 0, refused = 0;
  for (auto closure : {FrictionClosure::constant, FrictionClosure::merchant, FrictionClosure::lee_shaffer}) {
    for (double rake_deg : {-60.0, -30.0, 0.0, 30.0}) {
      for (double radius_um : {0.0, 0.01, 1.0, 100.0}) {
        for (double t0_um : {1e-3, 0.1, 10.0, 1000.0}) {
          for (double beta_deg : {0.0, 20.0, 40.0}) {
            auto p = params(closure, rake_deg, radius_um, beta_deg);
            p.quadrature.relative_tolerance = 1e-8;
            if (!(p.chip_ratio > 0.0)) {
              ++refused;  // the shear-angle model gives no chip at this friction and rake
              continue;
            }
            try {
              const auto r = kerf::liu_li_force_per_width(p, kShearStress, t0_um * 1e-6, nullptr);
              CHECK(std::isfinite(r.total.cutting_N_per_m));
              CHECK(std::isfinite(r.total.thrust_N_per_m));
              CHECK(std::isfinite(r.ploughed_thickness_m));
              ++finite;
            } catch (const kerf::InputError&) {
              ++refused;
            }
          }
        }
      }
    }
  }
  CHECK(finite > 400);
  INFO("refused " << refused);
}
