// The contact dashpots (Material::viscous_damping_ratio) against the damped linear oscillator's closed forms:
// a bonded disk's free vibration decays with the logarithmic decrement 2 pi beta / sqrt(1 - beta^2) at the
// damped frequency omega sqrt(1 - beta^2), and a disk bouncing off a wall leaves with the restitution
// coefficient exp(-pi beta / sqrt(1 - beta^2)) (a half period of contact).
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <vector>

#include "kerf/dem/engine/simulation.hpp"

using namespace kerf::dem;
using Catch::Matchers::WithinRel;

namespace {
Material damped(double beta) {
  Material m;
  m.local_damping = 0;
  m.viscous_damping_ratio = beta;
  auto& j = std::get<FlatJointParams>(m.joint);
  j.bond.tensile_strength_Pa = j.bond.cohesion_Pa = 1e15;  // elastic: never breaks
  return m;
}
}  // namespace

TEST_CASE("viscous damping: a bonded disk's free vibration decays as the damped oscillator", "[viscous_damping]") {
  for (double beta : {0.02, 0.1, 0.3}) {
    INFO("beta = " << beta);
    Simulation sim(damped(beta), {});
    sim.add_particle(0, 0, 10e-6);
    sim.add_particle(20e-6, 0, 10e-6);
    sim.install_bond(0, 1);
    auto& p = sim.particles();
    p.group[0] = 1;  // held: the oscillator's mass is disk 1's alone
    sim.initialise();
    const auto& g = sim.bonds().geometry[0];
    const double k = g.normal_stiffness * 2 * g.half_length_m * g.thickness_m, m = 1 / p.inv_mass[1];
    const double omega = std::sqrt(k / m), omega_d = omega * std::sqrt(1 - beta * beta);
    sim.set_time_step(2 * std::numbers::pi / omega / 4000);
    p.vx[1] = 1e-3;
    // Successive maxima of the opening: their ratio and spacing.
    std::vector<double> peak_gap, peak_time;
    double prev = 0, prev2 = 0;
    while (peak_gap.size() < 3 && sim.step_count() < 40000) {
      sim.step();
      const double gap = p.x[1] - 20e-6;
      if (prev > prev2 && prev > gap && prev > 0)
        peak_gap.push_back(prev), peak_time.push_back(sim.time() - sim.time_step());
      prev2 = prev, prev = gap;
    }
    REQUIRE(peak_gap.size() == 3);
    const double decrement = std::log(peak_gap[0] / peak_gap[2]) / 2;
    CHECK_THAT(decrement, WithinRel(2 * std::numbers::pi * beta / std::sqrt(1 - beta * beta), 0.01));
    CHECK_THAT((peak_time[2] - peak_time[0]) / 2, WithinRel(2 * std::numbers::pi / omega_d, 0.002));
    CHECK(p.vy[1] == 0);  // a normal oscillation stays normal
  }
}

TEST_CASE("viscous damping: a disk bounces off a wall with the closed-form restitution", "[viscous_damping]") {
  for (double beta : {0.0, 0.05, 0.2}) {
    INFO("beta = " << beta);
    Simulation sim(damped(beta), {});
    sim.add_particle(0, 10.0005e-6, 10e-6);  // 0.5 nm above the wall, falling towards it
    sim.add_wall({-50e-6, 0, 50e-6, 0});
    auto& p = sim.particles();
    p.vy[0] = -0.1;
    sim.initialise();
    const double k = linear_normal_stiffness(LinearContactParams{}, 10e-6, 0, 1e-3), m = 1 / p.inv_mass[0];
    sim.set_time_step(std::numbers::pi * std::sqrt(m / k) / 2000);
    while (!(p.vy[0] > 0 && p.y[0] > 10e-6) && sim.step_count() < 100000) sim.step();
    REQUIRE(p.y[0] > 10e-6);
    const double restitution = p.vy[0] / 0.1;
    CHECK_THAT(restitution, WithinRel(std::exp(-std::numbers::pi * beta / std::sqrt(1 - beta * beta)), 0.01));
  }
}

TEST_CASE("viscous damping: a held disk's dashpot against another held disk does nothing", "[viscous_damping]") {
  // Both ends prescribed: m_eff is infinite and the dashpot has no meaning; no force, no NaN.
  Simulation sim(damped(0.5), {});
  sim.add_particle(0, 0, 10e-6);
  sim.add_particle(19e-6, 0, 10e-6);
  auto& p = sim.particles();
  p.group[0] = 1;
  p.group[1] = 2;
  p.vx[1] = 0.01;
  sim.initialise();
  sim.run(10);
  const double f_spring =
      linear_normal_stiffness(LinearContactParams{}, 10e-6, 10e-6, 1e-3) * (20e-6 - (p.x[1] - p.x[0]));
  CHECK_THAT(sim.group_force(2)[0], WithinRel(f_spring, 1e-9));
}
