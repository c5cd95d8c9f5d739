// The parallel bond driven through prescribed motions (closed forms of the 2D strip: F = k_n A g,
// M = -k_n I theta, incremental shear; breaks on the periphery stress), against the flat joint where their
// elastic responses coincide, and through the engine (a bond pulled apart, then the pair as a linear contact;
// energy conserved without damping).
#include "kerf/dem/laws/parallel_bond.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "kerf/dem/engine/simulation.hpp"
#include "kerf/dem/laws/flat_joint.hpp"
#include "kerf/error.hpp"

using namespace kerf::dem;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {

struct Bond {
  ParallelBondParams p;
  BondGeometry geo;
  double shear = 0;
  std::uint8_t bonded = 1;
  BreakMode mode = BreakMode::none;

  explicit Bond(const ParallelBondParams& raw = {})
      : p(ParallelBondParams::validated(raw)), geo(bond_geometry(p, 10e-6, 10e-6, 1e-3)) {}
  BondResult update(double gap, double rotation, double ds) {
    return bond_update(p, geo, {gap, rotation, ds}, &shear, &bonded, &mode);
  }
  double area() const { return 2 * geo.half_length_m * geo.thickness_m; }
  double inertia() const { return geo.thickness_m * std::pow(2 * geo.half_length_m, 3) / 12; }
};

Material parallel_bond_glass(double damping) {
  Material m;
  m.joint = ParallelBondParams{};
  m.local_damping = damping;
  return m;
}

}  // namespace

TEST_CASE("parallel bond: force, moment and shear are the strip's closed forms", "[parallel_bond]") {
  Bond b;
  const double kn = b.geo.normal_stiffness, ks = b.geo.shear_stiffness;
  CHECK_THAT(kn, WithinRel(107e9 / 20e-6, 1e-14));
  CHECK_THAT(ks, WithinRel(kn / 3.1, 1e-14));
  auto r = b.update(2e-9, 0, 0);
  CHECK_THAT(r.normal_force_N, WithinRel(kn * b.area() * 2e-9, 1e-14));
  CHECK(r.moment_N_m == 0);
  r = b.update(0, 1e-6, 0);
  CHECK_THAT(r.moment_N_m, WithinRel(-kn * b.inertia() * 1e-6, 1e-14));
  // Shear is incremental: two increments add, a reversal takes it back.
  b.update(0, 0, 1e-10);
  r = b.update(0, 0, 1e-10);
  CHECK_THAT(r.shear_force_N, WithinRel(-2 * ks * b.area() * 1e-10, 1e-12));
  r = b.update(0, 0, -2e-10);
  CHECK_THAT(r.shear_force_N, WithinAbs(0, 1e-18));
  CHECK(b.mode == BreakMode::none);
}

TEST_CASE("parallel bond: elastic response equals the intact flat joint's", "[parallel_bond]") {
  // Both are the same linear strip while intact (a flat joint sums its elements' springs): equal resultants
  // on random motions within rounding. What differs is strength and what is left after a break.
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  ParallelBondParams pp;
  pp.bond.tensile_strength_Pa = pp.bond.cohesion_Pa = 1e30;  // elastic
  FlatJointParams fp;
  fp.bond.tensile_strength_Pa = fp.bond.cohesion_Pa = 1e30;
  fp = FlatJointParams::validated(fp);
  for (int k = 0; k < 200; ++k) {
    Bond b(pp);
    const BondGeometry fgeo = bond_geometry(fp, 10e-6, 10e-6, 1e-3);
    double fshear[2] = {0, 0};
    const std::uint8_t fbonded[2] = {1, 1};
    BreakMode fbreaks[2];
    const BondKinematics kin{1e-8 * u(rng), 1e-3 * u(rng), 1e-8 * u(rng)};
    const BondResult a = b.update(kin.gap_m, kin.rotation_rad, kin.shear_increment_m);
    const BondResult f = bond_update(fp, fgeo, kin, fshear, fbonded, fbreaks);
    CHECK_THAT(a.normal_force_N, WithinRel(f.normal_force_N, 1e-12));
    CHECK_THAT(a.shear_force_N, WithinRel(f.shear_force_N, 1e-12));
    CHECK_THAT(a.moment_N_m, WithinAbs(f.moment_N_m, 1e-12 * std::abs(f.moment_N_m) + 1e-30));
  }
}

TEST_CASE("parallel bond: breaks on its periphery stress", "[parallel_bond]") {
  const ParallelBondParams p;
  SECTION("tension: at F = 2 R t sigma_c") {
    Bond b;
    const double g_break = p.bond.tensile_strength_Pa / b.geo.normal_stiffness;
    b.update(g_break * (1 - 1e-9), 0, 0);
    CHECK(b.mode == BreakMode::none);
    const auto r = b.update(g_break * (1 + 1e-9), 0, 0);
    CHECK(b.mode == BreakMode::tension);
    CHECK(r.n_breaking == 1);
    CHECK_THAT(r.normal_force_N, WithinRel(2 * 10e-6 * 1e-3 * p.bond.tensile_strength_Pa, 1e-8));
  }
  SECTION("bending: at |M| R / I = sigma_c, twice sooner than a two-element flat joint's first element") {
    Bond b;
    const double theta_break = p.bond.tensile_strength_Pa / (b.geo.normal_stiffness * b.geo.half_length_m);
    b.update(0, theta_break * (1 - 1e-9), 0);
    CHECK(b.mode == BreakMode::none);
    b.update(0, -theta_break * (1 + 1e-9), 0);  // either sense
    CHECK(b.mode == BreakMode::tension);
  }
  SECTION("shear: on the Coulomb envelope c - sigma tan(phi), higher under compression") {
    for (double sigma : {0.0, -50e6}) {
      Bond b;
      const double gap = sigma / b.geo.normal_stiffness;
      const double tau_c = p.bond.cohesion_Pa - sigma * std::tan(p.bond.friction_angle_rad);
      const double ds_break = tau_c / b.geo.shear_stiffness;
      b.update(gap, 0, ds_break * (1 - 1e-9));
      CHECK(b.mode == BreakMode::none);
      b.shear = 0;
      b.update(gap, 0, ds_break * (1 + 1e-9));
      CHECK(b.mode == BreakMode::shear);
    }
  }
  SECTION("a broken bond carries nothing") {
    Bond b;
    b.bonded = 0;
    b.shear = 5;
    const auto r = b.update(1e-6, 1e-3, 1e-9);
    CHECK(r.normal_force_N == 0);
    CHECK(r.moment_N_m == 0);
    CHECK(b.shear == 0);
  }
}

TEST_CASE("parallel bond: parameters are validated, errors name the key", "[parallel_bond]") {
  ParallelBondParams p;
  p.bond.radius_multiplier = 0;
  CHECK_THROWS_WITH(ParallelBondParams::validated(p), "radius_multiplier = 0: expected a value in (0, 1]");
  p = {};
  p.bond.friction_angle_rad = 2.0;
  CHECK_THROWS_AS(ParallelBondParams::validated(p), kerf::InputError);
  const Material m = read_material(kerf::Json::parse(R"({"bond_model": "parallel_bond", "tensile_strength_MPa": 90,
      "friction_angle_deg": 30, "friction_coefficient": 0.4})"),
                                   "material");
  REQUIRE(std::holds_alternative<ParallelBondParams>(m.joint));
  CHECK(std::get<ParallelBondParams>(m.joint).bond.tensile_strength_Pa == 90e6);
  CHECK_THAT(std::get<ParallelBondParams>(m.joint).tan_friction_angle, WithinRel(std::tan(M_PI / 6), 1e-15));
  CHECK(std::get<LinearContactParams>(m.contact).friction_coefficient == 0.4);  // the contact's key
  // A flat joint's own key is not a parallel bond's.
  CHECK_THROWS_WITH(read_material(kerf::Json::parse(R"({"bond_model": "parallel_bond", "n_elements": 2})"), "material"),
                    Catch::Matchers::StartsWith("material.n_elements = 2: expected a known key"));
}

TEST_CASE("parallel bond: through the engine, a bond pulled apart breaks once and leaves a linear contact",
          "[parallel_bond]") {
  Simulation sim(parallel_bond_glass(0.0), {});
  sim.add_particle(0, 0, 10e-6);
  sim.add_particle(20e-6, 0, 10e-6);
  sim.install_bond(0, 1);
  auto& p = sim.particles();
  p.group[0] = 1;
  p.group[1] = 2;
  p.vx[1] = 0.01;  // m/s, pulled apart
  sim.initialise();
  CHECK(sim.bonds().stride == 1);
  double peak = 0;
  while (sim.cracks().empty() && sim.step_count() < 100000) {
    sim.step();
    peak = std::max(peak, -p.fx[1]);
  }
  REQUIRE(sim.cracks().size() == 1);  // one element: one crack
  CHECK(sim.cracks()[0].mode == BreakMode::tension);
  CHECK_THAT(sim.cracks()[0].length_m, WithinRel(20e-6, 1e-12));
  CHECK_THAT(peak, WithinRel(2 * 10e-6 * 1e-3 * 200e6, 1e-3));
  CHECK(sim.bonds().active[0] == 0);  // removed with its break
  sim.run(10);
  CHECK(sim.group_force(2)[0] == 0);  // apart: nothing pulls back
  // Pushed back together, the pair is the linear contact alone: compression only, k_n of the contact.
  p.vx[1] = -0.05;
  sim.run(2000);
  const double overlap = 20e-6 - (p.x[1] - p.x[0]);
  REQUIRE(overlap > 0);
  const double kn = linear_normal_stiffness(LinearContactParams{}, 10e-6, 10e-6, 1e-3);
  CHECK_THAT(p.fx[1], WithinRel(kn * overlap, 1e-6));
}

TEST_CASE("parallel bond: energy is conserved without damping, bond and contact in parallel", "[parallel_bond]") {
  // A bonded cluster, compressed so that the linear contacts act beside the bonds: velocity Verlet keeps the
  // kinetic plus strain energy (both laws' energies) to O(dt^2). The contacts are frictionless here: a
  // contact that slides dissipates, as it should (with mu = 0.577 the same run loses about 20 %).
  const auto energy_error = [](double dt_fraction) {
    Material m = parallel_bond_glass(0.0);
    m.contact = with_friction(LinearContactParams{}, 0.0);
    Simulation sim(m, {});
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> jitter(-2e-9, 2e-9), u(-1, 1);
    const double a = 19.995e-6;  // closer than the 20 um diameters: every bonded pair also overlaps
    for (int r = 0; r < 6; ++r)
      for (int c = 0; c < 6; ++c)
        sim.add_particle((c + 0.5 * (r % 2)) * a + jitter(rng), r * a * std::sqrt(3.0) / 2 + jitter(rng), 10e-6);
    sim.install_bonds_within_gap(1e-6);
    sim.initialise();
    sim.set_time_step(sim.time_step() * dt_fraction);
    auto& p = sim.particles();
    for (std::size_t i = 0; i < p.size(); ++i)
      p.vx[i] = 0.02 * u(rng), p.vy[i] = 0.02 * u(rng), p.omega[i] = 200 * u(rng);
    const double e0 = sim.kinetic_energy() + sim.stored_elastic_energy();
    double worst = 0;
    const auto steps = static_cast<int>(std::lround(100 / dt_fraction));
    for (int k = 0; k < 20; ++k) {
      sim.run(steps);
      worst = std::max(worst, std::abs(sim.kinetic_energy() + sim.stored_elastic_energy() - e0) / e0);
    }
    REQUIRE(sim.cracks().empty());
    REQUIRE(sim.n_touching_pairs() > 30);  // the contacts beside the bonds are really there
    return worst;
  };
  const double coarse = energy_error(1.0), fine = energy_error(0.25);
  CHECK(coarse < 0.05);
  CHECK(fine < 5e-3);
  CHECK(coarse / fine > 10);
}
