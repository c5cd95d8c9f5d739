// Weibull joint strengths (BondGeometry::strength_factor, weibull_strength_factor, draw_joint_strengths): every
// law's strength test takes the joint's factor; a specimen's factors follow Weibull's distribution with the size
// effect (Kolmogorov-Smirnov); without a modulus nothing changes; the factors travel with every copy of a specimen
// (with_material, a saved specimen, a checkpoint, a cut's window) and a copy with other Weibull keys is refused.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <vector>

#include "kerf/dem/engine/simulation.hpp"
#include "kerf/dem/laws/flat_joint.hpp"
#include "kerf/dem/laws/material.hpp"
#include "kerf/dem/laws/parallel_bond.hpp"
#include "kerf/dem/laws/softening_flat_joint.hpp"
#include "kerf/dem/procedures/cutting.hpp"
#include "kerf/dem/procedures/specimen.hpp"
#include "kerf/error.hpp"
#include "quick_specimen.hpp"

using namespace kerf::dem;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {

/// The tension load (the normal force of the whole joint, every element at the same opening) at which a joint of
/// each law first reports a break, opened in steps of 1e-4 of the material's strength opening.
template <class P>
double tension_break_force(const P& p, const BondGeometry& geo) {
  const auto n = static_cast<std::size_t>(bond_elements(p));
  std::vector<double> shear(n, 0.0), damage(n, 0.0);
  std::vector<std::uint8_t> bonded(n, 1);
  std::vector<BreakMode> breaks(n, BreakMode::none);
  const double g0 = p.bond.tensile_strength_Pa / geo.normal_stiffness;
  double peak = 0;
  for (int k = 1; k < 100000; ++k) {
    const BondKinematics kin{k * 1e-4 * g0, 0.0, 0.0};
    BondResult r;
    if constexpr (BondLawWithState<P>)
      r = bond_update(p, geo, kin, shear.data(), bonded.data(), breaks.data(), damage.data());
    else
      r = bond_update(p, geo, kin, shear.data(), bonded.data(), breaks.data());
    peak = std::max(peak, r.normal_force_N);
    if (r.n_breaking > 0) return peak;
  }
  return -1;
}

/// A material of the softening joint (the cut's glass kind) with Weibull strengths of modulus m.
Material weibull_material(double m, double reference_half_length_m = 2.5e-6) {
  Material mat;
  SofteningFlatJointParams j;
  j.fracture_energy_J_per_m2 = 1.0;
  j.bond.tensile_strength_Pa = 85e6;
  j.bond.cohesion_Pa = 450e6;
  j.bond.strength_weibull_modulus = m;
  j.bond.strength_reference_half_length_m = reference_half_length_m;
  mat.joint = SofteningFlatJointParams::validated(j);
  return mat;
}

/// A small random specimen of 2.5-3.25 um disks (the steady cut's), its genesis short.
Simulation weibull_specimen(const Material& mat, std::uint64_t seed = 7, SpecimenSpec* spec_out = nullptr) {
  SpecimenSpec spec = testing::quick_random_spec(0.25e-3, 0.12e-3, seed);
  spec.radius_min_m = 2.5e-6;
  spec.radius_max_m = 3.25e-6;
  if (spec_out) *spec_out = spec;
  SpecimenReport report;
  return make_specimen(mat, spec, report);
}

/// Kolmogorov-Smirnov distance between the uniform distribution and the values F(w_k) of every joint's factor
/// under the Weibull law of modulus m, P(w) = 1 - exp(-(R / R_ref) (w Gamma(1 + 1/m))^m) (the inversion of
/// weibull_strength_factor); `n` receives the count.
double ks_distance(const BondStore& b, double m, double reference_half_length_m, std::size_t& n) {
  std::vector<double> u;
  const double gamma = std::tgamma(1 + 1 / m);
  for (std::size_t k = 0; k < b.size(); ++k) {
    const double w = b.joint_geometry(k).strength_factor, r = b.geometry[k].half_length_m;
    u.push_back(1 - std::exp(-(r / reference_half_length_m) * std::pow(w * gamma, m)));
  }
  std::sort(u.begin(), u.end());
  n = u.size();
  const double count = static_cast<double>(n);
  double d = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const double below = static_cast<double>(k);
    d = std::max({d, (below + 1) / count - u[k], u[k] - below / count});
  }
  return d;
}

}  // namespace

TEST_CASE("joint strengths: the factor is Weibull's inversion, 1 without a modulus, finite at the extremes",
          "[joint_strengths]") {
  BondStiffnessStrength b;
  CHECK(weibull_strength_factor(b, 3e-6, 0.3) == 1.0);  // m = 0: the material's strengths
  b.strength_weibull_modulus = 6;
  b.strength_reference_half_length_m = 2.5e-6;
  // U = 1/e: -ln U = 1, so w = (R_ref / R)^(1/m) / Gamma(1 + 1/m).
  CHECK_THAT(weibull_strength_factor(b, 2.5e-6, std::exp(-1.0)), WithinRel(1 / std::tgamma(1 + 1.0 / 6), 1e-14));
  CHECK_THAT(weibull_strength_factor(b, 5e-6, std::exp(-1.0)),
             WithinRel(std::pow(0.5, 1.0 / 6) / std::tgamma(1 + 1.0 / 6), 1e-14));
  // Larger joints are weaker at the same draw (the size effect), a larger draw -ln U stronger.
  CHECK(weibull_strength_factor(b, 5e-6, 0.3) < weibull_strength_factor(b, 2.5e-6, 0.3));
  CHECK(weibull_strength_factor(b, 2.5e-6, 0.1) > weibull_strength_factor(b, 2.5e-6, 0.3));
  // The mean over U by quadrature (the midpoint rule on a fine grid): (R_ref / R)^(1/m).
  const int n = 400000;
  double mean = 0;
  for (int k = 0; k < n; ++k) mean += weibull_strength_factor(b, 4e-6, (k + 0.5) / n) / n;
  CHECK_THAT(mean, WithinRel(std::pow(2.5 / 4.0, 1.0 / 6), 1e-4));
  // Extremes of the key's range and of the draw: finite, never NaN.
  for (const double m : {1e-3, 0.5, 100.0})
    for (const double u : {0x1.0p-54, 0.5, 1 - 0x1.0p-54}) {
      b.strength_weibull_modulus = m;
      const double w = weibull_strength_factor(b, 3e-6, u);
      CHECK(std::isfinite(w));
      CHECK(w >= 0);
    }
}

TEST_CASE("joint strengths: every law breaks a joint in tension at its own strength w sigma_c", "[joint_strengths]") {
  const double r = 3e-6, t = 1e-3;
  for (const double w : {1.0, 0.37, 2.6}) {
    INFO("w = " << w);
    FlatJointParams fj = FlatJointParams::validated(FlatJointParams{});
    BondGeometry g = bond_geometry(fj, r, r, t);
    g.strength_factor = w;
    const double area = 2 * g.half_length_m * t;
    CHECK_THAT(tension_break_force(fj, g), WithinRel(w * fj.bond.tensile_strength_Pa * area, 2e-4 / w));
    ParallelBondParams pb = ParallelBondParams::validated(ParallelBondParams{});
    BondGeometry gp = bond_geometry(pb, r, r, t);
    gp.strength_factor = w;
    CHECK_THAT(tension_break_force(pb, gp), WithinRel(w * pb.bond.tensile_strength_Pa * area, 2e-4 / w));
    // The softening joint: its peak at w sigma_c, and, with G_f the material's, its softening opening 2 G_f /
    // (w sigma_c): the damage is D(g) of the header with g_0 w and w_c / w.
    SofteningFlatJointParams sj;
    sj.fracture_energy_J_per_m2 = 2.0;
    sj = SofteningFlatJointParams::validated(sj);
    BondGeometry gs = bond_geometry(sj, r, r, t);
    gs.strength_factor = w;
    const double g0 = w * sj.bond.tensile_strength_Pa / gs.normal_stiffness, wc = sj.softening_opening_m / w;
    CHECK(softening_damage(sj, gs, 0.999 * g0) == 0);
    CHECK_THAT(softening_damage(sj, gs, g0 + 0.5 * wc), WithinRel(1 - g0 * 0.5 * wc / ((g0 + 0.5 * wc) * wc), 1e-12));
    CHECK(softening_damage(sj, gs, g0 + wc) == 1);
    CHECK_THAT(tension_break_force(SofteningFlatJointParams::validated(SofteningFlatJointParams{}), gs),
               WithinRel(w * sj.bond.tensile_strength_Pa * area, 2e-4 / w));
  }
}

TEST_CASE("joint strengths: a specimen's factors follow Weibull's law with the joint's size (Kolmogorov-Smirnov)",
          "[joint_strengths]") {
  for (const auto& [m, r_ref] : {std::pair{6.0, 2.5e-6}, std::pair{3.0, 4e-6}}) {
    INFO("m = " << m << ", R_ref = " << r_ref);
    const Simulation sim = weibull_specimen(weibull_material(m, r_ref));
    std::size_t n = 0;
    const double d = ks_distance(sim.bonds(), m, r_ref, n);
    REQUIRE(n > 800);
    const double critical = 1.63 / std::sqrt(static_cast<double>(n));  // 1 % level
    CHECK(d < critical);
    // The test has power: the same factors against a modulus 30 % off, or without the joint's size, fail it.
    std::size_t n2 = 0;
    CHECK(ks_distance(sim.bonds(), 1.3 * m, r_ref, n2) > critical);
    CHECK(ks_distance(sim.bonds(), m, 2 * r_ref, n2) > critical);
  }
}

TEST_CASE("joint strengths: without a modulus every factor is 1, and the draw leaves the packing alone",
          "[joint_strengths]") {
  const Simulation plain = weibull_specimen(weibull_material(0));
  CHECK(plain.bonds().strength_factor.empty());  // every factor 1: the joint loop reads none
  // The reference half-length alone changes nothing while m = 0: the same specimen to the bit.
  const Simulation other = weibull_specimen(weibull_material(0, 9e-6));
  CHECK(other.particles().x == plain.particles().x);
  CHECK(other.particles().y == plain.particles().y);
  // The draws are a stream of their own: the compacted packing (before the joints) does not depend on them.
  SpecimenSpec spec = testing::quick_random_spec(0.25e-3, 0.12e-3, 7);
  spec.radius_min_m = 2.5e-6;
  spec.radius_max_m = 3.25e-6;
  const CompactedPacking packing = compact_packing(spec);
  SpecimenReport r1, r2;
  const Simulation a = finish_specimen(packing, weibull_material(0), spec, r1);
  const Simulation b = finish_specimen(packing, weibull_material(6), spec, r2);
  REQUIRE(a.bonds().size() == b.bonds().size());
  CHECK(a.bonds().i == b.bonds().i);
  CHECK(a.bonds().j == b.bonds().j);
}

TEST_CASE("joint strengths: the factors travel with the specimen's copies, and other Weibull keys are refused",
          "[joint_strengths]") {
  const Material mat = weibull_material(6);
  SpecimenSpec spec;
  const Simulation sim = weibull_specimen(mat, 11, &spec);
  const auto factors = [](const Simulation& s) {
    std::vector<double> f;
    for (std::size_t k = 0; k < s.bonds().size(); ++k) f.push_back(s.bonds().joint_geometry(k).strength_factor);
    return f;
  };
  const std::vector<double> drawn = factors(sim);
  REQUIRE(std::any_of(drawn.begin(), drawn.end(), [](double w) { return w != 1.0; }));
  SECTION("with_material: another strength, the same factors") {
    Material stronger = mat;
    std::get<SofteningFlatJointParams>(stronger.joint).bond.tensile_strength_Pa *= 2;
    CHECK(factors(with_material(sim, stronger)) == drawn);
    Material other_m = weibull_material(8);
    CHECK_THROWS_WITH(with_material(sim, other_m),
                      Catch::Contains("material.strength_weibull_modulus = 8") && Catch::Contains("the specimen's 6"));
    CHECK_THROWS_WITH(with_material(sim, weibull_material(6, 3e-6)),
                      Catch::Contains("material.strength_reference_half_length_um = 3"));
  }
  SECTION("a checkpoint") {
    CHECK(factors(Simulation::deserialize(sim.serialize())) == drawn);
  }
  SECTION("a saved specimen") {
    const auto path = std::filesystem::temp_directory_path() / "kerf_joint_strengths_specimen.json";
    SpecimenReport report;
    save_specimen(path.string(), sim, spec, report);
    SpecimenSpec spec2;
    SpecimenReport report2;
    CHECK(factors(load_specimen(path.string(), mat, spec2, report2)) == drawn);
    CHECK_THROWS_WITH(load_specimen(path.string(), weibull_material(0), spec2, report2),
                      Catch::Contains("material.strength_weibull_modulus = 0"));
    std::filesystem::remove(path);
  }
}

TEST_CASE("joint strengths: a window covering the whole workpiece cuts Weibull glass as the full cut, to the bit",
          "[joint_strengths]") {
  // The window's disks and joints are copies of the full specimen's: with their factors, the same cut (the window
  // tests' workpiece and cut, its joints of Table 1 with Weibull strengths).
  Material mat;
  std::get<FlatJointParams>(mat.joint).bond.strength_weibull_modulus = 5;
  std::get<FlatJointParams>(mat.joint).bond.strength_reference_half_length_m = 10e-6;
  SpecimenSpec spec = testing::quick_random_spec(0.4e-3, 0.25e-3, 3);
  spec.radius_min_m = 10e-6;
  spec.radius_max_m = 13e-6;
  SpecimenReport report;
  const Simulation specimen = make_specimen(mat, spec, report);
  CutParams full = testing::windowed(100, 100, 100, 100);
  full.window.enabled = false;
  CutRun a(specimen, full), b(specimen, testing::windowed(100, 100, 100, 100));
  bool more = true;
  while (more) {
    more = a.advance();
    REQUIRE(b.advance() == more);
    REQUIRE(a.simulation().particles().x == b.simulation().particles().x);
    REQUIRE(a.result().samples.back().main_force_N == b.result().samples.back().main_force_N);
  }
  CHECK(b.result().window.rebuilds > 5);
  CHECK(a.result().cracks.tensile + a.result().cracks.shear > 0);  // the joints did break: their strengths acted
}
