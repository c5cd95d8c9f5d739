// The flat-joint law driven through prescribed motions (MercuryDPM style): tension to failure, shear
// failure on the Coulomb envelope, bending with partial damage, load-unload-reload, closed-form stiffness.
#include "kerf/dem/laws/flat_joint.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "../../dem/laws/flat_joint_simd.hpp"
#include "kerf/error.hpp"

using namespace kerf::dem;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {

struct Joint {
  FlatJointParams p;
  BondGeometry geo;
  std::vector<double> shear;
  std::vector<std::uint8_t> bonded;
  std::vector<BreakMode> breaks;

  explicit Joint(FlatJointParams params, double r1 = 10e-6, double r2 = 10e-6, double t = 1e-3)
      : p(FlatJointParams::validated(params)),
        geo(bond_geometry(p, r1, r2, t)),
        shear(static_cast<std::size_t>(p.n_elements), 0.0),
        bonded(static_cast<std::size_t>(p.n_elements), 1),
        breaks(static_cast<std::size_t>(p.n_elements), BreakMode::none) {}

  BondResult update(double gap, double rotation, double ds) {
    return flat_joint_update(p, geo, {gap, rotation, ds}, shear, bonded, breaks);
  }
  void apply_breaks() {
    for (std::size_t e = 0; e < breaks.size(); ++e)
      if (breaks[e] != BreakMode::none) bonded[e] = 0, shear[e] = 0;
  }
  double element_area() const { return 2 * geo.half_length_m / p.n_elements * geo.thickness_m; }
};

bool same_bits(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

/// Runs the general update on `general` and the intact two-element path on `fast` (the same joint and shear
/// state) and requires the same resultants, shear forces and break decisions to the bit; returns the general
/// result.
BondResult require_fast_path_equal(Joint& general, Joint& fast, const BondKinematics& kin) {
  const BondResult a = flat_joint_update(general.p, general.geo, kin, general.shear, general.bonded, general.breaks);
  const BondResult b = flat_joint_update_two_bonded(fast.p, fast.geo, kin, fast.shear.data(), fast.breaks.data());
  REQUIRE(same_bits(a.normal_force_N, b.normal_force_N));
  REQUIRE(same_bits(a.shear_force_N, b.shear_force_N));
  REQUIRE(same_bits(a.moment_N_m, b.moment_N_m));
  REQUIRE(a.n_breaking == b.n_breaking);
  for (std::size_t e = 0; e < 2; ++e) {
    REQUIRE(same_bits(general.shear[e], fast.shear[e]));
    REQUIRE(general.breaks[e] == fast.breaks[e]);
  }
  return a;
}

}  // namespace

TEST_CASE("flat joint: stiffness and bending closed forms", "[flat_joint]") {
  Joint j(FlatJointParams{});
  const double R = j.geo.half_length_m, t = j.geo.thickness_m, kn = j.geo.normal_stiffness;
  CHECK_THAT(kn, WithinRel(107e9 / 20e-6, 1e-14));
  const double g = 1e-9;
  auto r = j.update(g, 0, 0);
  CHECK_THAT(r.normal_force_N, WithinRel(kn * 2 * R * t * g, 1e-12));
  CHECK_THAT(r.moment_N_m, WithinAbs(0, 1e-20));
  // Pure bending: M = -k_n I theta with I = t (2R)^3 / 12, for any number of elements.
  for (int nr : {2, 3, 8}) {
    FlatJointParams p;
    p.n_elements = nr;
    Joint b(p);
    const double theta = 1e-6;
    auto rb = b.update(0, theta, 0);
    CHECK_THAT(rb.normal_force_N, WithinAbs(0, 1e-12));
    CHECK_THAT(rb.moment_N_m, WithinRel(-kn * t * std::pow(2 * R, 3) / 12 * theta, 1e-12));
  }
}

TEST_CASE("flat joint: tension breaks every element at sigma_c A_e", "[flat_joint]") {
  Joint j(FlatJointParams{});
  const double g_break = j.p.bond.tensile_strength_Pa / j.geo.normal_stiffness;
  auto below = j.update(0.999 * g_break, 0, 0);
  CHECK(below.n_breaking == 0);
  auto above = j.update(1.001 * g_break, 0, 0);
  CHECK(above.n_breaking == 2);
  CHECK(j.breaks[0] == BreakMode::tension);
  CHECK(j.breaks[1] == BreakMode::tension);
  CHECK_THAT(above.normal_force_N, WithinRel(1.001 * 2 * j.p.bond.tensile_strength_Pa * j.element_area(), 1e-12));
  j.apply_breaks();
  // Broken and open: no force at all; closed again: compression only.
  auto open = j.update(2 * g_break, 0, 0);
  CHECK(open.normal_force_N == 0);
  CHECK(open.n_breaking == 0);
  auto closed = j.update(-g_break, 0, 0);
  CHECK_THAT(closed.normal_force_N, WithinRel(-2 * j.p.bond.tensile_strength_Pa * j.element_area(), 1e-12));
}

TEST_CASE("flat joint: shear breaks on the Coulomb envelope c - sigma tan(phi)", "[flat_joint]") {
  Joint j(FlatJointParams{});
  const double sigma = -100e6;  // compression
  const double gap = sigma / j.geo.normal_stiffness;
  const double strength = j.p.bond.cohesion_Pa - sigma * std::tan(j.p.bond.friction_angle_rad);
  const double ds_break = strength / j.geo.shear_stiffness;  // tau = k_s * total shear displacement
  const int n = 1000;
  int broke_at = -1;
  for (int k = 1; k <= n && broke_at < 0; ++k) {
    auto r = j.update(gap, 0, 1.5 * ds_break / n);
    if (r.n_breaking > 0) {
      broke_at = k;
      CHECK(j.breaks[0] == BreakMode::shear);
      CHECK(j.breaks[1] == BreakMode::shear);
      // Shear force opposes the displacement of disk 2.
      CHECK_THAT(r.shear_force_N,
                 WithinRel(-k * 1.5 * ds_break / n * j.geo.shear_stiffness * 2 * j.element_area(), 1e-9));
    }
  }
  // It breaks at the first increment that reaches the envelope, not before.
  CHECK(broke_at == static_cast<int>(std::ceil(n / 1.5 - 1e-9)));
  j.apply_breaks();
  // Residual: Coulomb friction mu |F_n| after breakage.
  auto r = j.update(gap, 0, ds_break);
  CHECK_THAT(std::abs(r.shear_force_N),
             WithinRel(j.p.residual_friction_coefficient * std::abs(r.normal_force_N), 1e-12));
}

TEST_CASE("flat joint: bending breaks the opening element only (partial damage)", "[flat_joint]") {
  Joint j(FlatJointParams{});
  // theta > 0 opens the element at xi < 0: g_e = -theta xi_e.
  const double xi0 = flat_joint_element_centroid(j.geo, 2, 0);
  const double theta_break = j.p.bond.tensile_strength_Pa / (j.geo.normal_stiffness * -xi0);
  auto below = j.update(0, 0.99 * theta_break, 0);
  CHECK(below.n_breaking == 0);
  auto above = j.update(0, 1.01 * theta_break, 0);
  REQUIRE(above.n_breaking == 1);
  CHECK(j.breaks[0] == BreakMode::tension);
  CHECK(j.breaks[1] == BreakMode::none);
  const double m_intact = above.moment_N_m;
  j.apply_breaks();
  // The damaged joint is softer in bending: its broken half is open and carries nothing.
  auto after = j.update(0, 1.01 * theta_break, 0);
  CHECK(after.n_breaking == 0);
  CHECK(std::abs(after.moment_N_m) < std::abs(m_intact));
  CHECK(after.normal_force_N < 0);  // only the compressed bonded element pushes
}

TEST_CASE("flat joint: load-unload-reload is elastic while bonded, compression-only once broken", "[flat_joint]") {
  Joint j(FlatJointParams{});
  const double g_break = j.p.bond.tensile_strength_Pa / j.geo.normal_stiffness;
  const double k = j.geo.normal_stiffness * 2 * j.geo.half_length_m * j.geo.thickness_m;
  for (double g : {0.5 * g_break, 0.0, -0.5 * g_break, 0.5 * g_break})
    CHECK_THAT(j.update(g, 0, 0).normal_force_N, WithinRel(k * g, 1e-12));
  CHECK(j.update(0.0, 0, 0).normal_force_N == 0);
  j.update(1.2 * g_break, 0, 0);
  j.apply_breaks();
  // Unload to zero and below, reload into tension: same stiffness in compression, nothing in tension.
  CHECK(j.update(0.5 * g_break, 0, 0).normal_force_N == 0);
  CHECK_THAT(j.update(-0.5 * g_break, 0, 0).normal_force_N, WithinRel(-0.5 * k * g_break, 1e-12));
  CHECK(j.update(0.5 * g_break, 0, 0).normal_force_N == 0);
}

TEST_CASE("flat joint: unbonded elements integrate the closed part of a tilted gap", "[flat_joint]") {
  FlatJointParams p;
  p.n_elements = 3;
  Joint j(p);
  std::fill(j.bonded.begin(), j.bonded.end(), 0);
  const double R = j.geo.half_length_m, kt = j.geo.normal_stiffness * j.geo.thickness_m;
  for (double g : {-2e-9, 0.0, 1e-9}) {
    for (double theta : {-3e-4, 1e-5, 2e-4}) {
      auto r = j.update(g, theta, 0);
      // Midpoint-rule reference with many points.
      const int m = 200000;
      double fn = 0, mom = 0;
      for (int q = 0; q < m; ++q) {
        const double xi = -R + (q + 0.5) * 2 * R / m;
        const double f = kt * std::min(g - theta * xi, 0.0) * 2 * R / m;
        fn += f;
        mom += f * xi;
      }
      CHECK_THAT(r.normal_force_N, WithinAbs(fn, 1e-6 * std::abs(fn) + 1e-12));
      CHECK_THAT(r.moment_N_m, WithinAbs(mom, 1e-6 * std::abs(mom) + 1e-18));
    }
  }
}

TEST_CASE("flat joint: parameters are validated when built", "[flat_joint]") {
  FlatJointParams p;
  p.n_elements = 1;
  try {
    FlatJointParams::validated(p);
    FAIL("n_elements = 1 accepted");
  } catch (const kerf::InputError& e) {
    CHECK(e.field() == "n_elements");  // the law's own key; the scene layer adds the JSON path
    CHECK(e.value() == "1");
  }
  CHECK_THROWS_WITH(kerf::with_path("material", [&] { return FlatJointParams::validated(p); }),
                    "material.n_elements = 1: expected an integer in [2, 16]");
  p = FlatJointParams{};
  p.bond.tensile_strength_Pa = -1e6;
  CHECK_THROWS_AS(FlatJointParams::validated(p), kerf::InputError);
}

TEST_CASE("flat joint: the two-element intact path equals the general update to the bit", "[flat_joint]") {
  // Random joints and motions spanning elastic loading, tension breaks, shear breaks and both signs of every
  // quantity; the engine takes the fast path for intact two-element joints, so any difference in a single bit
  // would change a simulation.
  std::mt19937_64 rng(20261122);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int n_tension = 0, n_shear = 0, n_none = 0;
  for (int k = 0; k < 20000; ++k) {
    FlatJointParams raw;
    raw.bond.effective_modulus_Pa = 107e9 * (1 + 0.5 * unit(rng));
    raw.bond.stiffness_ratio = 3.1 * (1 + 0.5 * unit(rng));
    raw.bond.radius_multiplier = 0.75 + 0.25 * std::abs(unit(rng));
    raw.bond.friction_angle_rad = 0.4 * (1 + unit(rng));
    Joint general(raw, 10e-6 * (1.15 + 0.15 * unit(rng)), 10e-6 * (1.15 + 0.15 * unit(rng)));
    if (k % 3 != 0) general.geo.strength_factor = std::exp(0.5 * unit(rng));  // Weibull strengths: a joint's own
    Joint fast = general;
    const double R = general.geo.half_length_m;
    const double strain = 6e-3 * unit(rng);  // sigma = Ebar* g_s / (R1 + R2): sigma_c = 200 MPa near +4.3e-3
    const BondKinematics kin{strain * R, 4e-3 * unit(rng), 2e-3 * R * unit(rng)};
    for (auto& s : general.shear) s = 1.5 * unit(rng);  // N; c A_e is about 1 N
    fast.shear = general.shear;
    require_fast_path_equal(general, fast, kin);
    for (std::size_t e = 0; e < 2; ++e) {
      n_tension += general.breaks[e] == BreakMode::tension;
      n_shear += general.breaks[e] == BreakMode::shear;
      n_none += general.breaks[e] == BreakMode::none;
    }
  }
  // The sample reaches every branch of the strength test.
  CHECK(n_tension > 2000);
  CHECK(n_shear > 2000);
  CHECK(n_none > 2000);
}

TEST_CASE("flat joint: the intact path decides breaks as the stress test does, ulps from the envelopes",
          "[flat_joint]") {
  // The fast path skips the stresses when an element is far from both envelopes; this scans each envelope in
  // steps of one ulp of the load, across it, for random joints and for strengths that make the shear envelope
  // cancel (c close to sigma_c tan phi) or vanish (c = 0, sigma_c = 0). Every decision and every bit must
  // equal the general update's, which always forms the stresses.
  std::mt19937_64 rng(20261123);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const auto step_ulps = [](double v, int n) {
    for (int s = 0; s < std::abs(n); ++s) v = std::nextafter(v, n > 0 ? INFINITY : -INFINITY);
    return v;
  };
  int scans_crossing = 0, n_scans = 0;
  for (int k = 0; k < 600; ++k) {
    FlatJointParams raw;
    raw.bond.effective_modulus_Pa = 107e9 * (1 + 0.5 * unit(rng));
    raw.bond.friction_angle_rad = 0.4 * (1 + unit(rng));
    raw.bond.tensile_strength_Pa = 200e6 * (1 + 0.9 * unit(rng));
    raw.bond.cohesion_Pa = 113e6 * (1 + 0.9 * unit(rng));
    if (k % 5 == 1)
      raw.bond.cohesion_Pa =
          raw.bond.tensile_strength_Pa * std::tan(raw.bond.friction_angle_rad) * (1 + 1e-9 * unit(rng));
    if (k % 5 == 2) raw.bond.cohesion_Pa = 0;
    if (k % 5 == 3) raw.bond.tensile_strength_Pa = 0;
    Joint general(raw, 10e-6 * (1.15 + 0.15 * unit(rng)), 10e-6 * (1.15 + 0.15 * unit(rng)));
    if (k % 3 == 2) general.geo.strength_factor = 0.3 + 2 * std::abs(unit(rng));  // a joint's own strengths
    const double w = general.geo.strength_factor;
    const double area = general.element_area();
    const double kn_t_le = general.geo.normal_stiffness * general.geo.thickness_m * general.geo.half_length_m;
    const bool tension_scan = k % 2 == 0;
    // Tension: g_s such that sigma = w sigma_c. Shear: sigma somewhere below it, |F_s| on the envelope.
    const double sigma_c = general.p.bond.tensile_strength_Pa * w, cohesion = general.p.bond.cohesion_Pa * w;
    const double sigma = tension_scan ? sigma_c : sigma_c * (0.9 - 2 * std::abs(unit(rng)));
    const double gap0 = sigma * area / kn_t_le;
    const double shear0 =
        std::max(0.0, cohesion - sigma * general.p.tan_friction_angle) * area * (unit(rng) < 0 ? -1 : 1);
    bool seen_break = false, seen_intact = false;
    for (int m = -40; m <= 40; ++m) {
      Joint fast = general;
      const double gap = tension_scan ? step_ulps(gap0, m) : gap0;
      for (auto& s : general.shear) s = tension_scan ? 0.0 : step_ulps(shear0, m);
      fast.shear = general.shear;
      const BondResult a = require_fast_path_equal(general, fast, {gap, 0.0, 0.0});
      (a.n_breaking > 0 ? seen_break : seen_intact) = true;
    }
    ++n_scans;
    scans_crossing += seen_break && seen_intact;
  }
  // The scans do straddle the envelopes: most see both decisions within +-40 ulps.
  CHECK(scans_crossing > n_scans / 2);
}
