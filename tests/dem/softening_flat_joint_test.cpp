// The softening flat joint (kerf/dem/laws/softening_flat_joint.hpp): one joint opened to failure takes the
// closed-form work, unloading follows the damaged secant, the strength envelope before softening is the flat
// joint's, the key is validated; through the engine: zero fracture energy is the flat joint to the bit, a bond
// pulled apart breaks at the softening opening, and a damaged state round-trips through a checkpoint.
#include "kerf/dem/laws/softening_flat_joint.hpp"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

#include "../../dem/laws/softening_flat_joint_simd.hpp"
#include "kerf/dem/engine/simulation.hpp"
#include "kerf/dem/laws/material.hpp"
#include "kerf/dem/procedures/lab_test.hpp"
#include "kerf/dem/procedures/specimen.hpp"
#include "kerf/error.hpp"
#include "quick_specimen.hpp"

using namespace kerf::dem;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {

SofteningFlatJointParams softening(double fracture_energy_J_per_m2, int n_elements = 2) {
  SofteningFlatJointParams p;
  p.fracture_energy_J_per_m2 = fracture_energy_J_per_m2;
  p.n_elements = n_elements;
  return SofteningFlatJointParams::validated(p);
}

/// Joints of a glass whose elements fail in tension more than in shear (as the calibrated glasses: c about 5
/// sigma_c), unlike Yang et al. 2018's Table 1 (c = 113 MPa against sigma_c = 200 MPa), whose random specimens break in
/// shear before any element reaches its tensile strength.
SofteningFlatJointParams glass(double fracture_energy_J_per_m2) {
  SofteningFlatJointParams p = softening(fracture_energy_J_per_m2);
  p.bond.tensile_strength_Pa = 85e6;
  p.bond.cohesion_Pa = 450e6;
  return SofteningFlatJointParams::validated(p);
}

/// One joint between two disks of radius 10 um, its element states, driven by prescribed motions.
struct Joint {
  SofteningFlatJointParams p;
  BondGeometry geo;
  std::vector<double> shear, damage;
  std::vector<std::uint8_t> bonded;
  std::vector<BreakMode> breaks;

  explicit Joint(const SofteningFlatJointParams& params)
      : p(params),
        geo(bond_geometry(p, 10e-6, 10e-6, 1e-3)),
        shear(static_cast<std::size_t>(p.n_elements), 0.0),
        damage(static_cast<std::size_t>(p.n_elements), 0.0),
        bonded(static_cast<std::size_t>(p.n_elements), 1),
        breaks(static_cast<std::size_t>(p.n_elements), BreakMode::none) {}

  BondResult update(double gap, double rotation = 0, double ds = 0) {
    return softening_flat_joint_update(p, geo, {gap, rotation, ds}, shear, bonded, breaks, damage);
  }
  /// What the engine does after its force loop.
  void apply_breaks() {
    for (std::size_t e = 0; e < breaks.size(); ++e)
      if (breaks[e] != BreakMode::none) bonded[e] = 0, shear[e] = 0, damage[e] = 1;
  }
  double energy(double gap, double rotation = 0) const {
    return bond_energy(p, geo, {gap, rotation, 0}, shear.data(), bonded.data(), damage.data());
  }
  double element_area() const { return 2 * geo.half_length_m / p.n_elements * geo.thickness_m; }
  double joint_area() const { return 2 * geo.half_length_m * geo.thickness_m; }
  double g0() const { return p.bond.tensile_strength_Pa / geo.normal_stiffness; }
};

bool same_bits(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

}  // namespace

TEST_CASE("softening flat joint: opened to failure, a joint takes A (sigma_c^2 / (2 k_n) + G_f)", "[softening]") {
  for (const double gf_J_per_m2 : {0.0, 0.3, 2.0, 10.0}) {
    Joint j(softening(gf_J_per_m2));
    INFO("G_f = " << gf_J_per_m2 << " J/m^2");
    const double g0 = j.g0(), w_c = j.p.softening_opening_m;
    CHECK_THAT(w_c, WithinAbs(2 * gf_J_per_m2 / j.p.bond.tensile_strength_Pa, 1e-30));
    const double gf = g0 + w_c;
    // Pure opening in small steps from rest: the force is piecewise linear in the gap (rising to sigma_c A at
    // g_0, falling to zero at g_f), so the trapezoidal work is exact but for the two steps holding a kink.
    const int n = 20000;
    const double dg = 1.5 * gf / n;
    double work = 0, f_prev = 0, peak = 0, g_break = -1;
    for (int k = 1; k <= n && g_break < 0; ++k) {
      const double g = k * dg;
      const BondResult r = j.update(g);
      work += 0.5 * (f_prev + r.normal_force_N) * dg;
      f_prev = r.normal_force_N;
      peak = std::max(peak, r.normal_force_N);
      if (r.n_breaking > 0) {
        g_break = g;
        CHECK(r.n_breaking == 2);
        CHECK(j.breaks[0] == BreakMode::tension);
        CHECK(j.breaks[1] == BreakMode::tension);
        CHECK_THAT(r.normal_force_N, WithinAbs(gf_J_per_m2 > 0 ? 0.0 : r.normal_force_N, 1e-12));
      } else if (g > g0 && gf_J_per_m2 > 0) {
        // On the softening envelope: sigma_c (g_f - g) / w_c, at the damaged secant (1 - D) k_n g.
        CHECK_THAT(r.normal_force_N, WithinRel(j.p.bond.tensile_strength_Pa * (gf - g) / w_c * j.joint_area(), 1e-9));
        CHECK_THAT(r.normal_force_N, WithinRel((1 - j.damage[0]) * j.geo.normal_stiffness * g * j.joint_area(), 1e-9));
        // The energy books: the work so far less the stored energy is the area between the envelope and the
        // secant back to the origin, (sigma_c g - sigma(g) g_0) / 2 per area.
        // The trapezoid is exact but for the step holding the kink at g_0: an error below the slopes' jump dg^2.
        const double sigma = r.normal_force_N / j.joint_area();
        const double kink = (j.geo.normal_stiffness + j.p.bond.tensile_strength_Pa / w_c) * j.joint_area() * dg * dg;
        CHECK_THAT(work - j.energy(g),
                   WithinAbs(0.5 * (j.p.bond.tensile_strength_Pa * g - sigma * g0) * j.joint_area(), kink));
      }
    }
    REQUIRE(g_break > 0);
    CHECK(g_break >= gf);
    CHECK(g_break < gf + dg * (1 + 1e-9));
    CHECK_THAT(peak, WithinRel(j.p.bond.tensile_strength_Pa * j.joint_area(), 2 * dg / g0));
    // For G_f = 0 the force at the breaking step is still the bonded element's (the flat joint): take the work
    // to the strength, as the flat joint's element then drops its force.
    if (gf_J_per_m2 == 0) work -= 0.5 * (f_prev + j.p.bond.tensile_strength_Pa * j.joint_area()) * (g_break - g0);
    const double closed_form =
        j.joint_area() *
        (j.p.bond.tensile_strength_Pa * j.p.bond.tensile_strength_Pa / (2 * j.geo.normal_stiffness) + gf_J_per_m2);
    CHECK_THAT(work, WithinRel(closed_form, 1e-3));
    j.apply_breaks();
    CHECK(j.energy(2 * gf) == 0);
    CHECK(j.update(2 * gf).normal_force_N == 0);  // broken and open: nothing
  }
}

TEST_CASE("softening flat joint: unloading returns along the damaged secant, compression is undamaged", "[softening]") {
  Joint j(softening(2.0));
  const double g0 = j.g0(), gf = g0 + j.p.softening_opening_m;
  const double kappa = 0.5 * (g0 + gf);  // half-way down the softening branch
  for (int k = 1; k <= 100; ++k) j.update(kappa * k / 100);
  const double d = j.damage[0];
  CHECK(d > 0);
  CHECK(d < 1);
  CHECK(j.damage[1] == d);
  CHECK_THAT(d, WithinRel(1 - g0 * (gf - kappa) / (kappa * j.p.softening_opening_m), 1e-12));
  const double k_damaged = (1 - d) * j.geo.normal_stiffness * j.joint_area();
  const double k_intact = j.geo.normal_stiffness * j.joint_area();
  // Unload to zero, into compression, reload to kappa: the secant, no further damage, no work lost on the cycle.
  double work = 0, f_prev = j.update(kappa).normal_force_N;
  const double e_start = j.energy(kappa);
  std::vector<double> path;
  for (int k = 100; k >= -100; --k) path.push_back(kappa * k / 100);
  for (int k = -99; k <= 100; ++k) path.push_back(kappa * k / 100);
  for (std::size_t s = 1; s < path.size(); ++s) {
    const double g = path[s];
    const BondResult r = j.update(g);
    work += 0.5 * (f_prev + r.normal_force_N) * (g - path[s - 1]);
    f_prev = r.normal_force_N;
    CHECK(r.n_breaking == 0);
    CHECK_THAT(r.normal_force_N, WithinRel((g > 0 ? k_damaged : k_intact) * g, 1e-12));
    if (g == 0) CHECK(r.normal_force_N == 0);
    CHECK(j.damage[0] == d);
    CHECK_THAT(j.energy(g), WithinRel(0.5 * (g > 0 ? k_damaged : k_intact) * g * g, 1e-12));
  }
  CHECK_THAT(work, WithinAbs(0, 1e-9 * e_start));
  // Past the largest opening reached, the envelope again: the damage grows.
  j.update(1.01 * kappa);
  CHECK(j.damage[0] > d);
}

// Long (~85 lines) for a reason: one joint law before softening, a section each: tension, shear, and random joints
// against the flat joint's bits.
TEST_CASE("softening flat joint: before softening starts, the flat joint's strength envelope and numbers",
          "[softening]") {
  SECTION("tension: within sigma_c undamaged; past it, the flat joint breaks and the softening joint softens") {
    Joint j(softening(1.0));
    const double g0 = j.g0();
    j.update(g0 * (1 - 1e-9));
    CHECK(j.damage[0] == 0);
    CHECK(j.breaks[0] == BreakMode::none);
    const BondResult r = j.update(g0 * (1 + 1e-6));
    CHECK(r.n_breaking == 0);
    CHECK(j.damage[0] > 0);
    CHECK(j.damage[0] < 1e-5);
  }
  SECTION("shear: on the Coulomb envelope c - sigma tan(phi), at the flat joint's increment") {
    for (double sigma : {0.0, -100e6, 0.5 * 200e6}) {
      Joint j(softening(1.0));
      const double gap = sigma / j.geo.normal_stiffness;
      const double strength = j.p.bond.cohesion_Pa - sigma * std::tan(j.p.bond.friction_angle_rad);
      const double ds_break = strength / j.geo.shear_stiffness;
      j.update(gap, 0, ds_break * (1 - 1e-9));
      CHECK(j.breaks[0] == BreakMode::none);
      std::fill(j.shear.begin(), j.shear.end(), 0.0);
      j.update(gap, 0, ds_break * (1 + 1e-9));
      CHECK(j.breaks[0] == BreakMode::shear);
      CHECK(j.breaks[1] == BreakMode::shear);
      CHECK(j.damage[0] == 0);
    }
  }
  SECTION(
      "random joints within the tensile strength, bonded or not: the flat joint's bits; the engine's fast "
      "path gives the softening update's bits everywhere") {
    std::mt19937_64 rng(20261129);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    int n_compared = 0, n_fast = 0;
    for (int k = 0; k < 20000; ++k) {
      const int nr = k % 3 == 0 ? 3 : 2;
      SofteningFlatJointParams raw = softening(0.5 + std::abs(unit(rng)), nr);
      raw.bond.effective_modulus_Pa = 107e9 * (1 + 0.5 * unit(rng));
      raw.bond.friction_angle_rad = 0.4 * (1 + unit(rng));
      Joint soft(SofteningFlatJointParams::validated(raw));
      const double R = soft.geo.half_length_m;
      const BondKinematics kin{6e-3 * unit(rng) * R, 4e-3 * unit(rng), 2e-3 * R * unit(rng)};
      for (auto& s : soft.shear) s = 1.5 * unit(rng);
      for (auto& b : soft.bonded) b = unit(rng) > -0.6;
      // The flat joint on the same state.
      std::vector<double> shear = soft.shear;
      std::vector<BreakMode> breaks(soft.breaks.size());
      const FlatJointParams& flat = soft.p;
      const BondResult a = flat_joint_update(flat, soft.geo, kin, shear, soft.bonded, breaks);
      // The fast path and the general update on copies of the state.
      Joint fast = soft;
      const BondResult f = bond_update_fast(fast.p, fast.geo, kin, fast.shear.data(), fast.bonded.data(),
                                            fast.breaks.data(), fast.damage.data());
      const BondResult b = soft.update(kin.gap_m, kin.rotation_rad, kin.shear_increment_m);
      REQUIRE(same_bits(f.normal_force_N, b.normal_force_N));
      REQUIRE(same_bits(f.shear_force_N, b.shear_force_N));
      REQUIRE(same_bits(f.moment_N_m, b.moment_N_m));
      REQUIRE(f.n_breaking == b.n_breaking);
      for (std::size_t e = 0; e < soft.shear.size(); ++e) {
        REQUIRE(same_bits(fast.shear[e], soft.shear[e]));
        REQUIRE(same_bits(fast.damage[e], soft.damage[e]));
        REQUIRE(fast.breaks[e] == soft.breaks[e]);
      }
      n_fast += nr == 2 && soft.bonded[0] && soft.bonded[1] && b.n_breaking == 0;
      // Where no element passed its tensile strength, the flat joint's numbers to the bit.
      bool softened = false;
      for (std::size_t e = 0; e < soft.damage.size(); ++e) softened = softened || soft.damage[e] > 0;
      bool tension_break = false;
      for (auto m : breaks) tension_break = tension_break || m == BreakMode::tension;
      CHECK(softened == tension_break);  // the flat joint breaks in tension exactly where the softening begins
      if (softened) continue;
      ++n_compared;
      REQUIRE(same_bits(a.normal_force_N, b.normal_force_N));
      REQUIRE(same_bits(a.shear_force_N, b.shear_force_N));
      REQUIRE(same_bits(a.moment_N_m, b.moment_N_m));
      REQUIRE(a.n_breaking == b.n_breaking);
      for (std::size_t e = 0; e < shear.size(); ++e) {
        REQUIRE(same_bits(shear[e], soft.shear[e]));
        REQUIRE(breaks[e] == soft.breaks[e]);
      }
    }
    CHECK(n_compared > 5000);
    CHECK(n_compared < 19000);  // the sample also softens joints
    CHECK(n_fast > 1000);
  }
}

TEST_CASE("softening flat joint: a damaged joint in opening, bending and shear keeps a potential", "[softening]") {
  // Damage fixed by a first opening; then a closed loop of gap, rotation and shear inside the largest opening
  // reached (the gap running into compression, so that the elements' closed parts come and go): the work done on
  // the joint over the loop is zero and its energy returns to its start.
  Joint j(softening(3.0));
  const double g0 = j.g0(), gf = g0 + j.p.softening_opening_m, kappa = 0.5 * (g0 + gf);
  j.update(kappa);
  const double d = j.damage[0];
  REQUIRE(d > 0);
  const double R = j.geo.half_length_m;
  const double g_start = kappa - 0.6 * g0, amp_g = 0.5 * g0, amp_t = 0.2 * g0 / R, amp_s = 0.1 * g0;
  BondResult prev = j.update(g_start);  // unloading along the secant
  const double e_start = j.energy(g_start);
  double g = g_start, theta = 0, s = 0, work = 0, e_min = e_start;
  const int n = 20000;
  for (int k = 1; k <= n; ++k) {
    const double phase = 2 * M_PI * k / n;
    const double g_new = g_start - amp_g * (1 - std::cos(phase)), t_new = amp_t * std::sin(phase);
    const double s_new = amp_s * std::sin(2 * phase);
    const BondResult r = j.update(g_new, t_new, s_new - s);
    REQUIRE(r.n_breaking == 0);
    // dW = F_n dg - M dtheta - F_s ds: F_n opens (tension positive), M and F_s act on disk 2 (BondResult).
    work += 0.5 * (prev.normal_force_N + r.normal_force_N) * (g_new - g) -
            0.5 * (prev.moment_N_m + r.moment_N_m) * (t_new - theta) -
            0.5 * (prev.shear_force_N + r.shear_force_N) * (s_new - s);
    g = g_new, theta = t_new, s = s_new;
    prev = r;
    e_min = std::min(e_min, j.energy(g, theta));
    // The energy the work has brought, at every point of the loop.
    REQUIRE_THAT(j.energy(g, theta) - e_start, WithinAbs(work, 2e-3 * e_start));
  }
  CHECK(j.damage[0] == d);
  CHECK(j.damage[1] == d);
  CHECK(e_min < 0.5 * e_start);  // the loop went far from its start
  CHECK_THAT(j.energy(g, theta), WithinRel(e_start, 1e-9));
  CHECK_THAT(work, WithinAbs(0, 1e-4 * e_start));
}

TEST_CASE("softening flat joint: fracture_energy_J_per_m2 is validated and read with the flat joint's keys",
          "[softening]") {
  SofteningFlatJointParams p;
  p.fracture_energy_J_per_m2 = -1;
  try {
    SofteningFlatJointParams::validated(p);
    FAIL("a negative fracture energy accepted");
  } catch (const kerf::InputError& e) {
    CHECK(e.field() == "fracture_energy_J_per_m2");
    CHECK(e.value() == "-1");
  }
  CHECK_THROWS_WITH(kerf::with_path("material", [&] { return SofteningFlatJointParams::validated(p); }),
                    "material.fracture_energy_J_per_m2 = -1: expected a non-negative value in J/m^2");
  const Material m =
      read_material(kerf::Json::parse(R"({"bond_model": "softening_flat_joint", "fracture_energy_J_per_m2": 4,
      "tensile_strength_MPa": 80, "n_elements": 3, "residual_friction_coefficient": 0.3})"),
                    "material");
  REQUIRE(std::holds_alternative<SofteningFlatJointParams>(m.joint));
  const auto& s = std::get<SofteningFlatJointParams>(m.joint);
  CHECK(s.fracture_energy_J_per_m2 == 4);
  CHECK(s.n_elements == 3);
  CHECK(s.residual_friction_coefficient == 0.3);
  CHECK_THAT(s.softening_opening_m, WithinRel(2 * 4 / 80e6, 1e-15));
  CHECK_THAT(s.tan_friction_angle, WithinRel(std::tan(s.bond.friction_angle_rad), 1e-15));
  CHECK_THROWS_WITH(read_material(kerf::Json::parse(R"({"bond_model": "softening_flat_joint",
      "fracture_energy_J_per_m2": -0.5})"),
                                  "material"),
                    Catch::Matchers::StartsWith("material.fracture_energy_J_per_m2 = -0.5"));
  // The flat joint has no fracture energy.
  CHECK_THROWS_WITH(read_material(kerf::Json::parse(R"({"fracture_energy_J_per_m2": 1})"), "material"),
                    Catch::Matchers::StartsWith("material.fracture_energy_J_per_m2 = 1: expected a known key"));
  // Written and read back the same (material_to_json).
  CHECK(same_micro_parameters(read_material(material_to_json(m), "material"), m));
}

namespace {
/// A small random specimen (a few hundred disks) and its tension test with `joint`, to the end.
struct TensionRun {
  LabTestResult result;
  Simulation final_state{Material{}, SimulationOptions{}};
};
TensionRun tension(const Simulation& specimen, const BondLaw& joint) {
  Material m = specimen.material();
  m.joint = joint;
  LoadingSpec load;
  load.test = LabTest::tension;
  load.speed_m_per_s = 0.1;
  load.quasi_static_check = false;
  TensionRun run;
  run.result = run_lab_test(with_material(specimen, m), load, {}, &run.final_state);
  return run;
}
}  // namespace

TEST_CASE("softening flat joint: with zero fracture energy, a tension test is the flat joint's to the bit",
          "[softening]") {
  SpecimenReport report;
  const Simulation specimen =
      make_specimen(Material{}, kerf::dem::testing::quick_random_spec(0.2e-3, 0.4e-3, 5), report);
  REQUIRE(report.n_particles > 200);
  const TensionRun flat = tension(specimen, static_cast<const FlatJointParams&>(glass(0.0)));
  const TensionRun soft = tension(specimen, glass(0.0));
  const auto& a = flat.final_state;
  const auto& b = soft.final_state;
  REQUIRE(!a.cracks().empty());
  CHECK(a.step_count() == b.step_count());
  CHECK(a.particles().x == b.particles().x);
  CHECK(a.particles().y == b.particles().y);
  CHECK(a.particles().theta == b.particles().theta);
  CHECK(a.particles().fx == b.particles().fx);
  CHECK(a.particles().fy == b.particles().fy);
  CHECK(a.particles().torque == b.particles().torque);
  CHECK(a.bonds().bonded == b.bonds().bonded);
  CHECK(a.bonds().shear_force_N == b.bonds().shear_force_N);
  REQUIRE(a.cracks().size() == b.cracks().size());
  for (std::size_t k = 0; k < a.cracks().size(); ++k) {
    CHECK(a.cracks()[k].time_s == b.cracks()[k].time_s);
    CHECK(a.cracks()[k].bond == b.cracks()[k].bond);
    CHECK(a.cracks()[k].element == b.cracks()[k].element);
    CHECK(a.cracks()[k].mode == b.cracks()[k].mode);
  }
  CHECK(flat.result.peak_stress_Pa == soft.result.peak_stress_Pa);
  CHECK(a.stored_elastic_energy() == b.stored_elastic_energy());
  // Every broken element of the softening joint is wholly damaged, every other undamaged.
  for (std::size_t k = 0; k < b.bonds().element_state.size(); ++k)
    CHECK(b.bonds().element_state[k] == (b.bonds().bonded[k] ? 0.0 : 1.0));
  int n_tension = 0;
  for (const CrackEvent& c : a.cracks()) n_tension += c.mode == BreakMode::tension;
  CHECK(n_tension > 0);  // the softening law's own branch decided those (and found them the flat joint's)
  // A fracture energy changes the test (the same specimen): a higher peak, reached later.
  const TensionRun softer = tension(specimen, glass(5.0));
  CHECK(softer.result.peak_stress_Pa > flat.result.peak_stress_Pa);
  CHECK(softer.result.strain_at_peak > flat.result.strain_at_peak);
}

TEST_CASE(
    "softening flat joint: through the engine, a bond pulled apart breaks at g_0 + w_c after taking its "
    "work",
    "[softening]") {
  Material m;
  m.joint = softening(4.0);
  Simulation sim(m, {});
  sim.add_particle(0, 0, 10e-6);
  sim.add_particle(20e-6, 0, 10e-6);
  sim.install_bond(0, 1);
  auto& p = sim.particles();
  p.group[0] = 1;
  p.group[1] = 2;
  const double v = 0.01;
  p.vx[1] = v;  // pulled apart at a prescribed speed: the force is the law's at each gap
  sim.initialise();
  REQUIRE(sim.bonds().state_size == 1);
  REQUIRE(sim.bonds().element_state.size() == 2);
  const auto& joint = std::get<SofteningFlatJointParams>(m.joint);
  const BondGeometry geo = bond_geometry(joint, 10e-6, 10e-6, 1e-3);
  const double g0 = joint.bond.tensile_strength_Pa / geo.normal_stiffness, gf = g0 + joint.softening_opening_m;
  const double area = 2 * geo.half_length_m * geo.thickness_m;
  double work = 0, f_prev = 0, peak = 0;
  while (sim.cracks().empty() && sim.step_count() < 1000000) {
    sim.step();
    const double f = -sim.group_force(2)[0];  // the joint pulls disk 2 back
    work += 0.5 * (f + f_prev) * v * sim.time_step();
    f_prev = f;
    peak = std::max(peak, f);
  }
  REQUIRE(sim.cracks().size() == 2);
  CHECK(sim.cracks()[0].mode == BreakMode::tension);
  const double gap = p.x[1] - p.x[0] - 20e-6;
  CHECK(gap >= gf);
  CHECK(gap < gf + 2 * v * sim.time_step());
  CHECK_THAT(peak, WithinRel(joint.bond.tensile_strength_Pa * area, 1e-3));
  CHECK_THAT(work, WithinRel(area * (joint.bond.tensile_strength_Pa * joint.bond.tensile_strength_Pa /
                                         (2 * geo.normal_stiffness) +
                                     joint.fracture_energy_J_per_m2),
                             2e-3));
  CHECK(sim.bonds().element_state == std::vector<double>{1.0, 1.0});
}

TEST_CASE("softening flat joint: a damaged state round-trips through the engine's checkpoint", "[softening]") {
  SpecimenReport report;
  Material m;
  m.joint = glass(3.0);
  const Simulation specimen = make_specimen(m, kerf::dem::testing::quick_random_spec(0.2e-3, 0.4e-3, 6), report);
  LoadingSpec load;
  load.test = LabTest::tension;
  load.speed_m_per_s = 0.1;
  load.quasi_static_check = false;
  LabTestRun run(specimen, load);
  // Advance until some elements are softening (0 < D < 1).
  const auto softening_elements = [](const Simulation& s) {
    int n = 0;
    for (double d : s.bonds().element_state) n += d > 0 && d < 1;
    return n;
  };
  while (softening_elements(run.simulation()) < 5 && run.advance()) {
  }
  REQUIRE(softening_elements(run.simulation()) >= 5);
  const std::string saved = run.serialize();
  LabTestRun resumed = LabTestRun::deserialize(saved);
  CHECK(resumed.simulation().bonds().element_state == run.simulation().bonds().element_state);
  while (run.advance()) {
  }
  while (resumed.advance()) {
  }
  CHECK(resumed.simulation().step_count() == run.simulation().step_count());
  CHECK(resumed.simulation().particles().x == run.simulation().particles().x);
  CHECK(resumed.simulation().bonds().element_state == run.simulation().bonds().element_state);
  CHECK(resumed.simulation().cracks().size() == run.simulation().cracks().size());
  CHECK(resumed.result().peak_stress_Pa == run.result().peak_stress_Pa);
  // The engine state alone too, with its damage.
  const Simulation& s = run.simulation();
  CHECK(Simulation::deserialize(s.serialize()).bonds().element_state == s.bonds().element_state);
}

TEST_CASE("softening flat joint: its damage round-trips through a specimen file as element_damage", "[softening]") {
  SpecimenReport report;
  Material m;
  m.joint = glass(3.0);
  const SpecimenSpec spec = kerf::dem::testing::quick_random_spec(0.2e-3, 0.4e-3, 6);
  Simulation sim = make_specimen(m, spec, report);
  // The engine keeps the law's state by the law's declaration: one double per element, named by the law.
  REQUIRE(sim.bonds().state_size == 1);
  REQUIRE(sim.bonds().state_names.size() == 1);
  CHECK(sim.bonds().state_names[0] == "damage");
  REQUIRE(sim.bonds().element_state.size() == sim.bonds().bonded.size());
  for (std::size_t k = 0; k < sim.bonds().element_state.size(); ++k)
    sim.bonds().element_state[k] = 0.125 * static_cast<double>(k % 7);
  const auto file = std::filesystem::path(KERF_BINARY_DIR) / "softening_specimen_roundtrip.json";
  save_specimen(file.string(), sim, spec, report);
  std::ifstream in(file);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  CHECK(text.find("\"element_damage\"") != std::string::npos);
  SpecimenSpec spec2;
  SpecimenReport report2;
  const Simulation loaded = load_specimen(file.string(), m, spec2, report2);
  // The file holds the active joints, in order.
  std::vector<double> saved;
  const auto n = static_cast<std::size_t>(sim.bonds().stride);
  for (std::size_t b = 0; b < sim.bonds().size(); ++b)
    if (sim.bonds().active[b])
      saved.insert(saved.end(), sim.bonds().element_state.begin() + static_cast<std::ptrdiff_t>(b * n),
                   sim.bonds().element_state.begin() + static_cast<std::ptrdiff_t>((b + 1) * n));
  CHECK(loaded.bonds().element_state == saved);
  std::filesystem::remove(file);
}
