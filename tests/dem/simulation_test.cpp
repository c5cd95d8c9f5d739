// Engine invariants: Newton's third law, objectivity, energy balance without damping, time-step
// stability, determinism across thread counts, a single joint pulled to failure through the engine.
#include "kerf/dem/engine/simulation.hpp"

#include <omp.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "kerf/error.hpp"

using namespace kerf::dem;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {

Material glass(double damping = 0.0) {
  Material m;
  m.local_damping = damping;
  return m;
}

/// Two disks of 10 um 20 um apart, jointed, initialised.
Simulation jointed_pair() {
  Simulation sim(glass(), {});
  sim.add_particle(0, 0, 10e-6);
  sim.add_particle(20e-6, 0, 10e-6);
  sim.install_bond(0, 1);
  sim.initialise();
  return sim;
}

/// A small jointed cluster: a perturbed triangular lattice of nx x ny disks with radii 8-10 um.
Simulation cluster(const Material& m, int nx, int ny, unsigned seed) {
  SimulationOptions options;
  options.min_parallel_items = 0;  // threads even for small systems, so that thread-count effects would show
  Simulation sim(m, options);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> jitter(-0.3e-6, 0.3e-6), radius(8e-6, 10e-6);
  const double a = 20e-6;
  for (int r = 0; r < ny; ++r)
    for (int c = 0; c < nx; ++c)
      sim.add_particle((c + 0.5 * (r % 2)) * a + jitter(rng), r * a * std::sqrt(3.0) / 2 + jitter(rng), radius(rng));
  sim.install_bonds_within_gap(3e-6);
  return sim;
}

void randomise_velocities(Simulation& sim, unsigned seed, double v, double w) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  auto& p = sim.particles();
  for (std::size_t i = 0; i < p.size(); ++i) p.vx[i] = v * u(rng), p.vy[i] = v * u(rng), p.omega[i] = w * u(rng);
}

}  // namespace

TEST_CASE("engine: contact forces sum to zero and conserve angular momentum", "[simulation]") {
  Simulation sim = cluster(glass(), 8, 8, 1);
  REQUIRE(sim.bonds().size() > 100);
  sim.initialise();
  randomise_velocities(sim, 2, 0.5, 2e4);
  sim.run(200);  // deform: joints, some unjointed overlaps
  auto& p = sim.particles();
  double fx = 0, fy = 0, mz = 0, fmax = 0;
  sim.evaluate_forces();
  for (std::size_t i = 0; i < p.size(); ++i) {
    fx += p.fx[i], fy += p.fy[i];
    mz += p.x[i] * p.fy[i] - p.y[i] * p.fx[i] + p.torque[i];
    fmax = std::max(fmax, std::hypot(p.fx[i], p.fy[i]));
  }
  REQUIRE(fmax > 0);
  CHECK(std::abs(fx) < 1e-12 * fmax * static_cast<double>(p.size()));
  CHECK(std::abs(fy) < 1e-12 * fmax * static_cast<double>(p.size()));
  CHECK(std::abs(mz) < 1e-12 * fmax * 200e-6 * static_cast<double>(p.size()));
}

TEST_CASE("engine: a rigid-body rotation produces no force and keeps a preload's magnitude", "[simulation]") {
  Simulation sim = jointed_pair();
  auto& p = sim.particles();
  p.group[0] = p.group[1] = 1;  // kinematics prescribed by the test
  sim.invalidate_neighbours();
  const double dt = sim.time_step();
  // Preload: stretch by 1 nm and shear by 0.5 nm (through the velocity of disk 1 over one evaluation).
  p.x[1] += 1e-9;
  p.vy[1] = 0.5e-9 / dt;
  sim.evaluate_forces_with_increment();
  p.vy[1] = 0;
  const double f0 = std::hypot(p.fx[1], p.fy[1]);
  REQUIRE(f0 > 0);
  const double x1 = p.x[1];
  // Rotate the pair rigidly about the origin by 90 degrees in 1000 exact increments, spinning the disks too.
  const int n = 1000;
  const double omega = (M_PI / 2) / (n * dt);
  for (int k = 1; k <= n; ++k) {
    const double a = k * (M_PI / 2) / n;
    p.x[1] = x1 * std::cos(a), p.y[1] = x1 * std::sin(a);
    p.theta[0] = p.theta[1] = a;
    for (int i : {0, 1}) p.vx[i] = -omega * p.y[i], p.vy[i] = omega * p.x[i], p.omega[i] = omega;
    sim.evaluate_forces_with_increment();
    CHECK_THAT(std::hypot(p.fx[1], p.fy[1]), WithinRel(f0, 1e-9));
  }
  // The stretched pair now lies along y: the normal force is along y, the shear preload along -x.
  CHECK(p.fy[1] < 0);
  CHECK(std::abs(p.fx[1]) > 0);
  CHECK(sim.cracks().empty());
}

TEST_CASE("engine: energy is conserved without damping", "[simulation]") {
  // Velocity Verlet conserves energy up to an O(dt^2) oscillation: check the error is small and that it
  // shrinks 16-fold when dt shrinks 4-fold.
  const auto energy_error = [](double dt_fraction, double& e0) {
    Simulation sim = cluster(glass(0.0), 6, 6, 3);
    sim.initialise();
    const double dt = sim.time_step() * dt_fraction;
    sim.set_time_step(dt);
    randomise_velocities(sim, 4, 0.05, 1e3);
    e0 = sim.kinetic_energy() + sim.stored_elastic_energy();
    double worst = 0;
    const auto steps = static_cast<int>(std::lround(100 / dt_fraction));
    for (int k = 0; k < 20; ++k) {
      sim.run(steps);
      worst = std::max(worst, std::abs(sim.kinetic_energy() + sim.stored_elastic_energy() - e0) / e0);
    }
    REQUIRE(sim.cracks().empty());  // elastic: nothing may break at these speeds
    return worst;
  };
  double e0 = 0;
  const double coarse = energy_error(1.0, e0), fine = energy_error(0.25, e0);
  CHECK(coarse < 0.05);
  CHECK(fine < 5e-3);
  CHECK(coarse / fine > 10);
  // Damping dissipates: the same start with alpha = 0.7 loses most of its energy.
  Simulation damped = cluster(glass(0.7), 6, 6, 3);
  damped.initialise();
  randomise_velocities(damped, 4, 0.05, 1e3);
  damped.run(2000);
  CHECK(damped.kinetic_energy() + damped.stored_elastic_energy() < 0.2 * e0);
}

TEST_CASE("engine: the automatic time step is stable and a too large one is caught", "[simulation]") {
  Simulation ok = cluster(glass(0.0), 6, 6, 5);
  ok.initialise();
  const double dt = ok.time_step();
  // dt scales with R sqrt(rho / E*): about 0.3-0.4 ns per um of radius for glass (physics-dem.md section 1).
  CHECK(dt > 0.05e-9 * 8);
  CHECK(dt < 0.4e-9 * 8);
  randomise_velocities(ok, 6, 0.05, 1e3);
  CHECK_NOTHROW(ok.run(3000));

  Simulation bad = cluster(glass(0.0), 6, 6, 5);
  bad.set_time_step(5 * dt);
  bad.initialise();
  randomise_velocities(bad, 6, 0.05, 1e3);
  CHECK_THROWS_AS(bad.run(3000), kerf::ModelError);
}

TEST_CASE("engine: bit-identical results for 1 and 2 threads", "[simulation]") {
  const auto run_with = [](int threads) {
    omp_set_num_threads(threads);
    Simulation sim = cluster(glass(0.2), 10, 10, 7);
    sim.initialise();
    randomise_velocities(sim, 8, 20.0, 2e6);  // violent enough to break joints
    sim.run(500);
    omp_set_num_threads(1);
    return sim;
  };
  Simulation a = run_with(1), b = run_with(2);
  REQUIRE(!a.cracks().empty());
  CHECK(a.cracks().size() == b.cracks().size());
  CHECK(a.particles().x == b.particles().x);
  CHECK(a.particles().y == b.particles().y);
  CHECK(a.particles().omega == b.particles().omega);
  CHECK(a.bonds().shear_force_N == b.bonds().shear_force_N);
}

TEST_CASE("engine: a team that changes size every 16 steps gives the one-thread results to the bit", "[simulation]") {
  // The governor (kerf/dem/engine/team_governor.hpp) set to switch at every probe, every other window of 16 steps:
  // the steps alternate between 2 threads and 1, joints breaking on both.
  const int before = omp_get_max_threads();
  omp_set_num_threads(1);
  Simulation a = cluster(glass(0.2), 10, 10, 7);
  a.initialise();
  randomise_velocities(a, 8, 20.0, 2e6);
  a.run(800);
  omp_set_num_threads(2);
  Simulation b = cluster(glass(0.2), 10, 10, 7);
  b.set_team_governor(TeamGovernor({1e-12, 1, 0.0}));
  b.initialise();
  randomise_velocities(b, 8, 20.0, 2e6);
  b.run(800);
  omp_set_num_threads(before);
  REQUIRE(!a.cracks().empty());
  CHECK(b.team_governor().switches() >= 10);
  CHECK(a.cracks().size() == b.cracks().size());
  CHECK(a.particles().x == b.particles().x);
  CHECK(a.particles().y == b.particles().y);
  CHECK(a.particles().omega == b.particles().omega);
  CHECK(a.bonds().shear_force_N == b.bonds().shear_force_N);
}

TEST_CASE("engine: a single joint pulled apart breaks at 2 R t sigma_c", "[simulation]") {
  Simulation sim(glass(0.0), {});
  sim.add_particle(0, 0, 10e-6);
  sim.add_particle(20e-6, 0, 10e-6);
  sim.install_bond(0, 1);
  auto& p = sim.particles();
  p.group[0] = 1;
  p.group[1] = 2;
  p.vx[1] = 0.01;  // m/s
  sim.initialise();
  double peak = 0;
  while (sim.cracks().empty() && sim.step_count() < 100000) {
    sim.step();
    peak = std::max(peak, p.fx[1] * -1);
  }
  REQUIRE(sim.cracks().size() == 2);
  CHECK(sim.cracks()[0].mode == BreakMode::tension);
  const double expected = 2 * 10e-6 * 1e-3 * 200e6;
  CHECK_THAT(peak, WithinRel(expected, 1e-3));
  // The crack lies across the joint (orientation along y) at the contact point.
  CHECK_THAT(std::abs(std::sin(sim.cracks()[0].orientation_rad)), WithinRel(1.0, 1e-9));
  CHECK_THAT(sim.cracks()[0].x_m, WithinRel(10e-6 + 0.5 * (p.x[1] - 20e-6), 1e-3));
  // Once the surfaces are apart the pair is an unjointed (linear) contact: nothing pulls back.
  sim.run(100);
  CHECK(sim.group_force(2)[0] == 0);
}

TEST_CASE("engine: prescribed disks keep their velocity and their raw force under local damping", "[simulation]") {
  // Two disks, both prescribed, pulled apart at a constant speed with strong damping: the kicks must leave
  // their velocities exactly as set and their forces undamped (the reaction a test or a tool reads). A free
  // disk bonded to the moving one does get damped forces (the blend chooses per disk).
  Simulation sim(glass(0.7), {});
  sim.add_particle(0, 0, 10e-6);
  sim.add_particle(20e-6, 0, 10e-6);
  sim.add_particle(40e-6, 0, 10e-6);
  sim.install_bond(0, 1);
  sim.install_bond(1, 2);
  auto& p = sim.particles();
  p.group[0] = 1;
  p.group[1] = 2;
  p.vx[1] = 1e-3;  // m/s
  sim.initialise();
  const auto& b = sim.bonds();
  const double kn_area = b.geometry[0].normal_stiffness * 2 * b.geometry[0].half_length_m * b.geometry[0].thickness_m;
  int n_damped = 0;
  for (int s = 0; s < 200; ++s) {
    sim.step();
    REQUIRE(p.vx[0] == 0.0);
    REQUIRE(p.vx[1] == 1e-3);
    REQUIRE(p.vy[1] == 0.0);
    // Disk 0 feels only joint 0-1: the raw joint force, tension positive pulls it towards disk 1.
    const double gap = p.x[1] - p.x[0] - 20e-6;
    CHECK_THAT(p.fx[0], WithinRel(kn_area * gap, 1e-9));
    // The free disk's force is the damped one: (1 - alpha sign(F v)) times the raw sum, 0.3x or 1.7x it.
    const double raw_on_free = -kn_area * (p.x[2] - p.x[1] - 20e-6);
    if (raw_on_free != 0 && std::abs(p.fx[2] - raw_on_free) > 1e-9 * std::abs(raw_on_free)) ++n_damped;
  }
  CHECK(p.x[1] > 20e-6 + 199 * 1e-3 * sim.time_step());
  CHECK(n_damped > 100);
}

TEST_CASE("engine: a run restored from its saved state equals the uninterrupted run", "[simulation]") {
  Simulation sim = cluster(glass(0.2), 10, 10, 9);
  sim.initialise();
  randomise_velocities(sim, 10, 20.0, 2e6);  // joints break, contacts form and the lists are rebuilt
  sim.run(250);
  const std::string saved = sim.serialize();
  sim.run(250);
  Simulation resumed = Simulation::deserialize(saved);
  CHECK(resumed.step_count() == 250);
  resumed.run(250);
  REQUIRE(!sim.cracks().empty());
  CHECK(resumed.cracks().size() == sim.cracks().size());
  CHECK(resumed.particles().x == sim.particles().x);
  CHECK(resumed.particles().omega == sim.particles().omega);
  CHECK(resumed.bonds().shear_force_N == sim.bonds().shear_force_N);
  CHECK(resumed.time() == sim.time());
  CHECK_THROWS_AS(Simulation::deserialize(saved.substr(0, saved.size() / 2)), kerf::ModelError);
}

TEST_CASE("engine: a wall's own friction coefficient limits the shear of its contacts", "[simulation]") {
  // A held disk pressed 0.1 um into a wall that slides past it: once sliding, the wall feels a tangential
  // force of mu times the normal one, with mu the wall's own coefficient, or the material's when it has none.
  const auto slide = [](double wall_mu) {
    Simulation sim(glass(0.0), {});
    sim.add_particle(0, 0, 10e-6);
    sim.particles().group[0] = 1;
    Wall w{-50e-6, -9.9e-6, 50e-6, -9.9e-6, 0.1, 0};
    w.friction_coefficient = wall_mu;
    sim.add_wall(w);
    sim.initialise();
    // Sliding starts after mu kappa* overlap of travel: 0.42 um at mu = 1.5; the run slides several times that.
    sim.run(20000);
    const Wall& after = sim.walls()[0];
    REQUIRE(after.fy < 0);  // the disk pushes the wall down
    return std::abs(after.fx) / std::abs(after.fy);
  };
  CHECK(slide(0.0) == 0.0);
  CHECK_THAT(slide(0.2), WithinRel(0.2, 1e-9));
  CHECK_THAT(slide(-1.0), WithinRel(std::get<LinearContactParams>(Material{}.contact).friction_coefficient, 1e-9));
  CHECK_THAT(slide(1.5), WithinRel(1.5, 1e-9));
}

TEST_CASE("simulation: a wall contact's load is k_n times its overlap, and ties to the held disks follow bonded joints",
          "[simulation]") {
  // The diagnostics a cut's crushing grains use (CutRun::crush_grains): a disk 0.2 um into a wall feels the linear
  // law's k_n overlap (L = R for a wall), a disk clear of it none; a chain held at one end is tied along its
  // bonded joints, and a joint with every element broken cuts the chain there.
  Simulation sim(Material{}, {});
  const double r = 10e-6, overlap = 0.2e-6;
  sim.add_particle(0, r - overlap, r);   // on the wall y = 0
  sim.add_particle(2 * r, r + 1e-6, r);  // clear of it
  sim.add_particle(4 * r, r + 1e-6, r);
  sim.add_wall(Wall{-1e-3, 0, 1e-3, 0});
  sim.install_bond(0, 1);
  sim.install_bond(1, 2);
  sim.particles().group[0] = 1;
  sim.initialise();
  const auto loads = sim.wall_contact_loads();
  REQUIRE(loads.size() == 1);
  CHECK(loads[0].disk == 0);
  const auto& law = std::get<LinearContactParams>(sim.material().contact);
  CHECK_THAT(loads[0].normal_force_N,
             WithinRel(linear_normal_stiffness(law, r, 0, sim.options().thickness_m) * overlap, 1e-9));
  CHECK(sim.tied_to_held() == std::vector<std::uint8_t>{1, 1, 1});
  auto& b = sim.bonds();
  for (int e = 0; e < b.stride; ++e) b.bonded[static_cast<std::size_t>(b.stride + e)] = 0;  // joint 1-2 broken
  CHECK(sim.tied_to_held() == std::vector<std::uint8_t>{1, 1, 0});
  sim.particles().group[0] = 0;
  CHECK(sim.tied_to_held() == std::vector<std::uint8_t>{0, 0, 0});
}

TEST_CASE("engine: a disk's stress from its contacts is the closed form, rotates as a tensor, and sums the forces",
          "[simulation][stress]") {
  // Three equal disks in a row, pressed together by their overlaps (unjointed contacts): the middle one carries
  // the contact force F on opposite sides, sigma_nn = -2 F / (pi R t) along the row, 0 across it; an end disk
  // carries F once, half that. The row turned by an angle a: sigma' = Q sigma Q^T. Thickness 2 mm: the stress
  // does not depend on it (F doubles with it).
  const double radius = 10e-6, overlap = 0.2e-6;
  for (const double angle_deg : {0.0, 30.0, 90.0}) {
    const double a = angle_deg * M_PI / 180, c = std::cos(a), s = std::sin(a);
    SimulationOptions options;
    options.thickness_m = 2e-3;
    Simulation sim(glass(), options);
    const double pitch = 2 * radius - overlap;
    for (int k = 0; k < 3; ++k) sim.add_particle(k * pitch * c, k * pitch * s, radius);
    sim.initialise();
    sim.evaluate_forces();
    const auto& p = sim.particles();
    const double force = std::hypot(p.fx[0], p.fy[0]);  // the end disk: one contact
    REQUIRE(force > 0);
    CHECK_THAT(p.fx[0] * c + p.fy[0] * s, WithinRel(-force, 1e-12));  // pushed outwards: compression
    const auto stresses = sim.disk_stresses();
    const double sigma_nn = -2 * force / (M_PI * radius * options.thickness_m);  // the middle disk, along the row
    const double scale = std::abs(sigma_nn);
    const auto& mid = stresses.stress_Pa[1];
    CHECK_THAT(mid[0], WithinAbs(sigma_nn * c * c, 1e-12 * scale));
    CHECK_THAT(mid[1], WithinAbs(sigma_nn * s * s, 1e-12 * scale));
    CHECK_THAT(mid[2], WithinAbs(sigma_nn * c * s, 1e-12 * scale));
    for (int end : {0, 2}) {
      const auto& e = stresses.stress_Pa[static_cast<std::size_t>(end)];
      CHECK_THAT(e[0], WithinAbs(0.5 * sigma_nn * c * c, 1e-12 * scale));
      CHECK_THAT(e[1], WithinAbs(0.5 * sigma_nn * s * s, 1e-12 * scale));
      CHECK_THAT(e[2], WithinAbs(0.5 * sigma_nn * c * s, 1e-12 * scale));
    }
    CHECK_THAT(stresses.force_sum_N[1], WithinRel(2 * force, 1e-12));
    CHECK_THAT(stresses.force_sum_N[0], WithinRel(force, 1e-12));
  }
}

TEST_CASE("engine: a joint's force is tension positive along its centre line, its shear across it",
          "[simulation][stress]") {
  Simulation sim = jointed_pair();
  auto& p = sim.particles();
  const auto& b = sim.bonds();
  const double kn_area = b.geometry[0].normal_stiffness * 2 * b.geometry[0].half_length_m * b.geometry[0].thickness_m;
  for (const double gap : {1e-9, -1e-9}) {
    p.x[1] = 20e-6 + gap;
    sim.evaluate_forces();
    const auto f = sim.joint_force(0);
    CHECK_THAT(f[0], WithinRel(kn_area * gap, 1e-9));  // stretched: tension, positive; pressed: negative
    CHECK_THAT(f[1], WithinAbs(0.0, 1e-12 * kn_area * 1e-9));
    // The disks' stresses: uniaxial along x, tension positive for a stretched joint, equal on both disks.
    const auto st = sim.disk_stresses();
    const double sigma = kn_area * gap * 10e-6 / (M_PI * 10e-6 * 10e-6 * sim.options().thickness_m);
    for (std::size_t i : {0u, 1u}) {
      CHECK_THAT(st.stress_Pa[i][0], WithinRel(sigma, 1e-9));
      CHECK_THAT(st.stress_Pa[i][1], WithinAbs(0.0, 1e-12 * std::abs(sigma)));
    }
  }
}
