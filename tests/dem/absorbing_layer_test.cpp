// The absorbing layer of a windowed cut (Simulation::set_absorbing_rates, CutWindowBox::absorbing_m): a free
// disk's velocity decays as exp(-gamma t), a prescribed one keeps its own; no layer is the engine as before,
// to the bit; along a bonded chain held at its far end, an undamped wave packet keeps its energy (reflected by
// the held end) and a layer before that end takes it out (a sponge absorbs waves shorter than itself; longer
// ones, and a pulse's net momentum, it reflects in part); the window ramps the rate from the box's edges as
// documented; a windowed cut with a layer differs from one without; its keys are validated. The layer along
// the workpiece's held rows (cut.held_absorbing_depths): ramped from the held left side and bottom, with every
// disk active and in a window (the larger of the two rates), applied, its key validated against the workpiece.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "kerf/dem/engine/simulation.hpp"
#include "kerf/dem/procedures/cut_window.hpp"
#include "kerf/dem/procedures/cutting.hpp"
#include "quick_specimen.hpp"

using namespace kerf::dem;
using Catch::Matchers::WithinRel;

namespace {
Material undamped_elastic() {
  Material m;
  m.local_damping = 0;
  auto& j = std::get<FlatJointParams>(m.joint);
  j.bond.tensile_strength_Pa = j.bond.cohesion_Pa = 1e15;  // elastic: never breaks
  return m;
}

/// A chain of n bonded disks along x, disk n - 1 held (the rigid frame).
Simulation chain(int n) {
  Simulation sim(undamped_elastic(), {});
  for (int k = 0; k < n; ++k) sim.add_particle(20e-6 * k, 0, 10e-6);
  for (int k = 0; k + 1 < n; ++k) sim.install_bond(k, k + 1);
  sim.particles().group[static_cast<std::size_t>(n - 1)] = 1;
  sim.initialise();
  return sim;
}

double energy(const Simulation& sim) {
  return sim.kinetic_energy() + sim.stored_elastic_energy();
}

/// The inner lines of a cut workpiece's held rows, from the specimen itself (Yang et al. 2018, Section 4: centres
/// within two largest radii of the left side or the bottom).
HeldRows held_rows_of_specimen(const Simulation& specimen) {
  const auto& p = specimen.particles();
  double x_min = 1e300, y_min = 1e300, r_max = 0;
  for (std::size_t u = 0; u < p.size(); ++u) {
    x_min = std::min(x_min, p.x[u] - p.radius[u]);
    y_min = std::min(y_min, p.y[u] - p.radius[u]);
    r_max = std::max(r_max, p.radius[u]);
  }
  return {x_min + 2 * r_max, y_min + 2 * r_max};
}

CutParams windowed_with_layer(double layer_depths) {
  CutParams p = kerf::dem::testing::windowed(3, 2, 2, 2);
  p.cut.length_m = 0.15e-3;
  p.window.absorbing_depths = layer_depths;
  return p;
}
}  // namespace

TEST_CASE("absorbing layer: a free disk's velocity and spin decay as exp(-gamma t), a prescribed disk's do not",
          "[absorbing_layer]") {
  Simulation sim(undamped_elastic(), {});
  sim.add_particle(0, 0, 10e-6);
  sim.add_particle(1e-3, 0, 10e-6);  // far apart: no contact
  auto& p = sim.particles();
  p.group[1] = 1;
  const double gamma = 3e6, dt = 1e-9;
  sim.set_absorbing_rates({gamma, gamma});
  sim.initialise();
  sim.set_time_step(dt);
  p.vx[0] = 2.0, p.vy[0] = -1.0, p.omega[0] = 5e3, p.vx[1] = 0.5;
  const int n = 2000;
  for (int k = 0; k < n; ++k) sim.step();
  const double decay = std::exp(-gamma * n * dt);
  CHECK_THAT(p.vx[0], WithinRel(2.0 * decay, 1e-12));
  CHECK_THAT(p.vy[0], WithinRel(-1.0 * decay, 1e-12));
  CHECK_THAT(p.omega[0], WithinRel(5e3 * decay, 1e-12));
  // The distance travelled: the sum of the decaying velocities times dt, a geometric series.
  const double f = std::exp(-gamma * dt);
  CHECK_THAT(p.x[0], WithinRel(dt * 2.0 * (1 - std::pow(f, n)) / (1 - f), 1e-9));
  CHECK(p.vx[1] == 0.5);  // prescribed: its velocity is the loading's
  // A disk added after the rates were set has none.
  sim.add_particle(-1e-3, 0, 10e-6);
  CHECK(sim.absorbing_rates().back() == 0);
  sim.particles().vx[2] = 1.0;
  sim.step();  // the decay factors follow the new disk
  CHECK(sim.particles().vx[2] == 1.0);
  CHECK_THROWS(sim.set_absorbing_rates({1.0}));
  CHECK_THROWS(sim.set_absorbing_rates({1.0, -1.0, 0.0}));
}

TEST_CASE("absorbing layer: no layer is the engine as before, to the bit", "[absorbing_layer]") {
  Simulation a = chain(12), b = chain(12);
  b.set_absorbing_rates(std::vector<double>(12, 0.0));  // a layer of zero rates...
  Simulation c = chain(12);
  c.set_absorbing_rates({});  // ...and none
  for (auto* s : {&a, &b, &c}) s->particles().vx[0] = 1e-3;
  for (int k = 0; k < 3000; ++k) a.step(), b.step(), c.step();
  CHECK(a.particles().x == b.particles().x);
  CHECK(a.particles().vx == b.particles().vx);
  CHECK(a.particles().x == c.particles().x);
  CHECK(a.particles().vx == c.particles().vx);
}

TEST_CASE("absorbing layer: a wave along an undamped chain keeps its energy off a held end and is absorbed by a layer",
          "[absorbing_layer]") {
  const int n = 120, layer = 30;
  Simulation bare = chain(n), sponge = chain(n);
  // Wave speed and the peak rate as the cut sets it: 3 a c / L for a attenuation e-folds over L.
  const auto& g = bare.bonds().geometry[0];
  const double k = g.normal_stiffness * 2 * g.half_length_m * g.thickness_m, m = 1 / bare.particles().inv_mass[0];
  const double spacing = 20e-6, c = spacing * std::sqrt(k / m), length = layer * spacing;
  const double gamma_max = 3 * 3.0 * c / length;
  std::vector<double> rates(n, 0.0);
  for (int u = n - 1 - layer; u < n - 1; ++u) {
    const double d = spacing * (n - 1 - u);  // distance to the held end
    rates[static_cast<std::size_t>(u)] = gamma_max * std::pow(1 - d / length, 2);
  }
  sponge.set_absorbing_rates(rates);
  // A wave packet of zero net momentum, one wavelength of 20 spacings (shorter than the layer), near the free end.
  for (auto* s : {&bare, &sponge})
    for (int u = 0; u < 20; ++u)
      s->particles().vx[static_cast<std::size_t>(u + 20)] = 1e-3 * std::sin(0.314159 * (u + 0.5));
  const double e0 = energy(bare);
  REQUIRE(energy(sponge) == e0);
  // Long enough for the pulse to reach the held end and come back to the free end twice.
  const double transit = n * spacing / c;
  const int steps = static_cast<int>(4 * transit / bare.time_step());
  for (int s = 0; s < steps; ++s) bare.step(), sponge.step();
  INFO("energy left: " << energy(bare) / e0 << " without the layer, " << energy(sponge) / e0 << " with it");
  CHECK_THAT(energy(bare), WithinRel(e0, 0.01));  // undamped and elastic: conserved, reflected by the held end
  CHECK(energy(sponge) < 0.02 * e0);              // the layer took it out (3 e-folds each way: about e^-6)
}

TEST_CASE("absorbing layer: the window ramps the rate from its ahead, behind and lower edges", "[absorbing_layer]") {
  Simulation work = kerf::dem::testing::quick_workpiece_specimen(0.8e-3, 0.3e-3, 5);
  work.initialise();
  double y_top = 0;
  for (std::size_t u = 0; u < work.particles().size(); ++u)
    y_top = std::max(y_top, work.particles().y[u] + work.particles().radius[u]);
  const double depth = 0.05e-3, y_cut = y_top - depth, x_edge = 0.5e-3;
  CutWindowBox box{3 * depth, 2 * depth, 2 * depth, 2 * depth, 0.2 * depth};
  box.absorbing_m = depth;
  box.absorbing_rate_per_s = 1e8;
  CutWindow window(std::move(work), box, y_top, y_cut);
  const Simulation sim = window.build(nullptr, x_edge);
  const auto& p = sim.particles();
  const auto& rates = sim.absorbing_rates();
  REQUIRE(rates.size() == p.size());
  const double x0 = x_edge - box.ahead_m, x1 = x_edge + box.behind_m, y0 = y_cut - box.below_m;
  int in_layer = 0, inside = 0;
  for (std::size_t u = 0; u < p.size(); ++u) {
    if (p.group[u] != 0) {
      CHECK(rates[u] == 0);  // held: at rest anyway
      continue;
    }
    const double d = std::min({p.x[u] - x0, x1 - p.x[u], p.y[u] - y0});
    REQUIRE(d >= 0);  // a free disk is inside the box
    const double expected = d < box.absorbing_m ? 1e8 * std::pow(1 - d / box.absorbing_m, 2) : 0.0;
    CHECK_THAT(rates[u], WithinRel(expected, 1e-12));
    (d < box.absorbing_m ? in_layer : inside) += 1;
  }
  CHECK(in_layer > 20);
  CHECK(inside > 20);
}

TEST_CASE("absorbing layer: a windowed cut with a layer differs from one without (it is applied)",
          "[absorbing_layer]") {
  // (Restored halfway, a cut with a layer goes on to the bit: cut_window_test.cpp.)
  const Simulation specimen = kerf::dem::testing::quick_workpiece_specimen(0.6e-3, 0.25e-3, 7);
  CutRun with(specimen, windowed_with_layer(1)), without(specimen, windowed_with_layer(0));
  REQUIRE(!with.simulation().absorbing_rates().empty());
  REQUIRE(without.simulation().absorbing_rates().empty());
  while (with.advance()) {
  }
  while (without.advance()) {
  }
  CHECK(without.result().main_force_N != with.result().main_force_N);
}

TEST_CASE("absorbing layer: its keys are validated with their dotted names", "[absorbing_layer]") {
  CutParams p = windowed_with_layer(2);  // as thick as the window behind and below the tool
  CHECK_THROWS_WITH(validate_cut_params(p), Catch::Contains("active_window.absorbing_depths = 2"));
  p = windowed_with_layer(1.5);
  CHECK_NOTHROW(validate_cut_params(p));
  p.window.absorbing_attenuation = 0;
  CHECK_THROWS_WITH(validate_cut_params(p), Catch::Contains("active_window.absorbing_attenuation = 0"));
  p = windowed_with_layer(-1);
  CHECK_THROWS_WITH(validate_cut_params(p), Catch::Contains("active_window.absorbing_depths = -1"));
}

TEST_CASE("absorbing layer along the held rows: every disk active, ramped from the held left side and bottom",
          "[absorbing_layer]") {
  const Simulation specimen = kerf::dem::testing::quick_workpiece_specimen(0.6e-3, 0.25e-3, 7);
  CutParams p = windowed_with_layer(0);
  p.window.enabled = false;
  {
    const CutRun none(specimen, p);
    CHECK(none.simulation().absorbing_rates().empty());  // no layer: the engine as before
  }
  p.cut.held_absorbing_depths = 1;
  const CutRun run(specimen, p);
  const auto& q = run.simulation().particles();
  const auto& rates = run.simulation().absorbing_rates();
  REQUIRE(rates.size() == q.size());
  const HeldRows held = held_rows_of_specimen(specimen);
  const double layer = p.cut.depth_of_cut_m;
  // The peak rate as the window's layer has it: 3 a c / L.
  const double peak = 3 * p.window.absorbing_attenuation * p_wave_speed_m_per_s(run.simulation().material()) / layer;
  int in_left = 0, in_bottom = 0, inside = 0;
  for (std::size_t u = 0; u < q.size(); ++u) {
    const double dx = q.x[u] - held.x_m, dy = q.y[u] - held.y_m;
    if (dx < 0 || dy < 0) {
      CHECK(q.group[u] != 0);  // the held rows themselves
      CHECK(rates[u] == 0);
      continue;
    }
    REQUIRE(q.group[u] == 0);
    const double d = std::min(dx, dy);
    const double expected = d < layer ? peak * std::pow(1 - d / layer, 2) : 0.0;
    CHECK_THAT(rates[u], WithinRel(expected, 1e-12));
    if (d >= layer)
      ++inside;
    else
      (dx < dy ? in_left : in_bottom) += 1;
  }
  CHECK(in_left > 10);
  CHECK(in_bottom > 20);
  CHECK(inside > 100);
}

TEST_CASE("absorbing layer along the held rows: in a window, the larger of its rate and the window layer's",
          "[absorbing_layer]") {
  const Simulation specimen = kerf::dem::testing::quick_workpiece_specimen(0.6e-3, 0.25e-3, 7);
  CutParams p = kerf::dem::testing::windowed(3, 2, 4, 2);  // down to the bottom rows
  p.cut.length_m = 0.15e-3;
  p.window.absorbing_depths = 1;  // as thick as the held rows' layer, which starts two radii higher
  p.cut.held_absorbing_depths = 1;
  const CutRun run(specimen, p);
  const CutRun window_layer_only = [&] {
    CutParams q = p;
    q.cut.held_absorbing_depths = 0;
    return CutRun(specimen, q);
  }();
  const auto& q = run.simulation().particles();
  const auto& rates = run.simulation().absorbing_rates();
  const auto& box_rates = window_layer_only.simulation().absorbing_rates();
  REQUIRE(rates.size() == q.size());
  REQUIRE(box_rates.size() == q.size());  // the same window: the held rows' layer adds no disk
  const HeldRows held = held_rows_of_specimen(specimen);
  const double layer = p.cut.depth_of_cut_m;
  const double peak = 3 * p.window.absorbing_attenuation * p_wave_speed_m_per_s(run.simulation().material()) / layer;
  int raised = 0;
  for (std::size_t u = 0; u < q.size(); ++u) {
    if (q.group[u] != 0) {
      CHECK(rates[u] == 0);
      continue;
    }
    const double d = held.distance_m(q.x[u], q.y[u]);
    const double own = d < layer ? peak * std::pow(1 - d / layer, 2) : 0.0;
    CHECK_THAT(rates[u], WithinRel(std::max(own, box_rates[u]), 1e-12));
    raised += rates[u] > box_rates[u];
  }
  // Over the bottom rows the held rows' layer is the higher (the window, 0.25 mm long at the start, holds
  // about two rows of ten such disks).
  CHECK(raised >= 5);
}

TEST_CASE("absorbing layer along the held rows: applied, with every disk active", "[absorbing_layer]") {
  const Simulation specimen = kerf::dem::testing::quick_workpiece_specimen(0.4e-3, 0.2e-3, 5);
  CutParams p = windowed_with_layer(0);
  p.window.enabled = false;
  p.cut.length_m = 0.1e-3;
  CutRun without(specimen, p);
  p.cut.held_absorbing_depths = 1;
  CutRun with(specimen, p);
  while (with.advance()) {
  }
  while (without.advance()) {
  }
  CHECK(without.result().main_force_N != with.result().main_force_N);
  CHECK(std::isfinite(with.result().main_force_N));
}

TEST_CASE("absorbing layer along the held rows: its key is validated against the workpiece", "[absorbing_layer]") {
  const Simulation specimen = kerf::dem::testing::quick_workpiece_specimen(0.6e-3, 0.25e-3, 7);
  CutParams p = windowed_with_layer(0);
  p.cut.held_absorbing_depths = -1;
  CHECK_THROWS_WITH(validate_cut_params(p), Catch::Contains("cut.held_absorbing_depths = -1"));
  // From the held bottom rows (about 26 um up) to the cut line (0.05 mm under the 0.25 mm top): about 0.17 mm,
  // 3.5 depths of cut; a layer that thick would reach the cut line.
  p.cut.held_absorbing_depths = 3.6;
  CHECK_THROWS_WITH(CutRun(specimen, p),
                    Catch::Contains("cut.held_absorbing_depths = 3.6") && Catch::Contains("below the cut line"));
  // The tool must stop before the left side's layer: 0.6 mm less 2.5 largest radii and the layer.
  p.cut.held_absorbing_depths = 2;
  p.cut.length_m = 0.5e-3;
  CHECK_THROWS_WITH(CutRun(specimen, p), Catch::Contains("cut.length_mm = 0.5") && Catch::Contains("absorbing layer"));
  p.cut.length_m = 0.45e-3;
  CHECK_NOTHROW(CutRun(specimen, p));
}
