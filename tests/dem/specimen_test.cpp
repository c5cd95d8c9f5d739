// Specimen genesis: hexagonal packing against the closed-form lattice elasticity, random packing quality
// (density, coordination, low locked-in stress), reproducibility from the seed, save/load round trip.
#include "kerf/dem/procedures/specimen.hpp"

#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <vector>

using namespace kerf::dem;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {

SpecimenSpec small_random() {
  SpecimenSpec s;
  s.width_m = s.height_m = 0.3e-3;
  s.growth_steps = 3000;
  s.relax_steps = 1000;
  s.seed = 42;
  return s;
}

// Equal disks of 10 um on a triangular lattice filling a square of this side.
SpecimenSpec hexagonal_spec(double side_m) {
  SpecimenSpec spec;
  spec.packing = Packing::hexagonal;
  spec.width_m = spec.height_m = side_m;
  spec.radius_min_m = spec.radius_max_m = 10e-6;
  return spec;
}

}  // namespace

TEST_CASE("specimen: hexagonal lattice stress under affine strain matches the closed form", "[specimen]") {
  // Triangular lattice of disks (spacing d = 2R) with bond stiffnesses K_n, K_s: lambda = sqrt(3)/4 (K_n - K_s),
  // mu = sqrt(3)/4 (K_n + K_s) per thickness (sum over the 3 bond directions of the cell, area 2 sqrt(3) R^2).
  const SpecimenSpec spec = hexagonal_spec(0.3e-3);
  Material m;
  SpecimenReport report;
  Simulation sim = make_specimen(m, spec, report);
  REQUIRE(report.n_particles > 150);
  CHECK_THAT(report.coordination_number, WithinAbs(2.0 * report.n_bonds / report.n_particles, 1e-12));
  const double exx = 2e-5, eyy = -6e-6, exy = 4e-6;
  // Impose the displacement in one step: positions moved, velocities = displacement / dt so that the
  // incremental shear springs see it too.
  auto& p = sim.particles();
  const double dt = sim.time_step();
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double x = p.x[i], y = p.y[i];
    p.vx[i] = (exx * x + exy * y) / dt;
    p.vy[i] = (exy * x + eyy * y) / dt;
    p.x[i] += p.vx[i] * dt;
    p.y[i] += p.vy[i] * dt;
  }
  sim.evaluate_forces_with_increment();
  const double t = spec.thickness_m, R = 10e-6;
  const double kn = std::get<FlatJointParams>(m.joint).bond.effective_modulus_Pa * t,
               ks = kn / std::get<FlatJointParams>(m.joint).bond.stiffness_ratio;  // K_n = k_n 2R t
  const double lambda = std::sqrt(3.0) / 4 * (kn - ks) / t, mu = std::sqrt(3.0) / 4 * (kn + ks) / t;
  // Stress of the interior disks (six joints each): sigma_p = -(1 / (2 A_p t)) sum f_on_j (x) (x_j - x_i),
  // A_p = 2 sqrt(3) R^2 (each joint shared by two disks).
  const auto& b = sim.bonds();
  std::vector<int> n_joints(sim.particles().size(), 0);
  for (std::size_t k = 0; k < b.size(); ++k)
    ++n_joints[static_cast<std::size_t>(b.i[k])], ++n_joints[static_cast<std::size_t>(b.j[k])];
  std::array<double, 3> s{0, 0, 0};
  int n_interior = 0;
  for (int v : n_joints) n_interior += v == 6;
  REQUIRE(n_interior > 50);
  for (std::size_t k = 0; k < b.size(); ++k) {
    const auto i = static_cast<std::size_t>(b.i[k]), j = static_cast<std::size_t>(b.j[k]);
    const double share = 0.5 * ((n_joints[i] == 6) + (n_joints[j] == 6));
    const double lx = p.x[j] - p.x[i], ly = p.y[j] - p.y[i];
    s[0] -= share * b.out[k][0] * lx, s[1] -= share * b.out[k][1] * ly;
    s[2] -= share * 0.5 * (b.out[k][0] * ly + b.out[k][1] * lx);
  }
  for (double& v : s) v /= n_interior * 2 * std::sqrt(3.0) * R * R * t;
  // Linear in the strain up to the geometric nonlinearity (relative size ~ strain).
  CHECK_THAT(s[0], WithinRel(lambda * (exx + eyy) + 2 * mu * exx, 1e-3));
  CHECK_THAT(s[1], WithinRel(lambda * (exx + eyy) + 2 * mu * eyy, 1e-3));
  CHECK_THAT(s[2], WithinRel(2 * mu * exy, 1e-3));
  // Plane-stress constants of the lattice: nu = (kappa - 1) / (3 kappa + 1) (0.204 for kappa = 3.1).
  const double kappa = std::get<FlatJointParams>(m.joint).bond.stiffness_ratio;
  CHECK_THAT(lambda / (lambda + 2 * mu), WithinRel((kappa - 1) / (3 * kappa + 1), 1e-12));
  // Interior disks are in equilibrium under a homogeneous strain.
  double worst = 0, scale = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    scale = std::max(scale, std::hypot(p.fx[i], p.fy[i]));
    if (p.x[i] > 3 * R && p.x[i] < spec.width_m - 3 * R && p.y[i] > 3 * R && p.y[i] < spec.height_m - 3 * R)
      worst = std::max(worst, std::hypot(p.fx[i], p.fy[i]));
  }
  CHECK(worst < 1e-3 * scale);
}

TEST_CASE("specimen: random packing is dense, well connected and nearly free of locked-in stress", "[specimen]") {
  Material m;
  SpecimenReport report;
  const SpecimenSpec spec = small_random();
  Simulation sim = make_specimen(m, spec, report);
  CHECK(report.n_particles > 250);
  CHECK(report.packing_fraction > 0.80);
  CHECK(report.packing_fraction < 0.90);
  CHECK(report.coordination_number > 3.5);
  CHECK(report.n_floaters_left <= report.n_particles / 25);
  // Locked-in stress: well below the compaction pressure (joints are installed stress free).
  CHECK(std::abs(report.residual_stress_xx_Pa) < spec.compaction_pressure_Pa);
  CHECK(std::abs(report.residual_stress_yy_Pa) < spec.compaction_pressure_Pa);
  // Isotropy of the fabric: joints along x and along y carry similar counts.
  double nxx = 0, nyy = 0;
  const auto& b = sim.bonds();
  const auto& p = sim.particles();
  for (std::size_t k = 0; k < b.size(); ++k) {
    const auto i = static_cast<std::size_t>(b.i[k]), j = static_cast<std::size_t>(b.j[k]);
    const double dx = p.x[j] - p.x[i], dy = p.y[j] - p.y[i], d2 = dx * dx + dy * dy;
    nxx += dx * dx / d2, nyy += dy * dy / d2;
  }
  CHECK_THAT(nxx / (nxx + nyy), WithinAbs(0.5, 0.05));
  // Same seed, same specimen.
  SpecimenReport again;
  Simulation sim2 = make_specimen(m, spec, again);
  CHECK(sim2.particles().x == sim.particles().x);
  CHECK(again.n_bonds == report.n_bonds);
}

TEST_CASE("specimen: the packing is the spec's alone, the joints and the relaxation the material's", "[specimen]") {
  // Why (docs/dem.md, Calibration): a calibration evaluates each candidate material on the packing compacted
  // once; that is the specimen a scene with the same spec and the candidate builds only if the compaction
  // does not depend on the material.
  const SpecimenSpec spec = small_random();
  Material soft, stiff;
  std::get<LinearContactParams>(stiff.contact).effective_modulus_Pa *= 3;
  std::get<FlatJointParams>(stiff.joint).bond.effective_modulus_Pa *= 3;
  stiff.density_kg_per_m3 *= 1.5;
  stiff.local_damping = 0.3;
  const CompactedPacking packing = compact_packing(spec);
  CHECK(packing.disks.bonds().size() == 0);
  SpecimenReport a, b, c;
  const Simulation from_soft = make_specimen(soft, spec, a);
  const Simulation from_stiff = make_specimen(stiff, spec, b);
  const Simulation finished = finish_specimen(packing, stiff, spec, c);
  // The same disks: radii to the bit (set by the compaction alone), positions within the relaxation's motion.
  REQUIRE(from_soft.particles().size() == from_stiff.particles().size());
  CHECK(from_soft.particles().radius == from_stiff.particles().radius);
  CHECK(from_soft.particles().radius == packing.disks.particles().radius);
  double largest_move = 0;
  for (std::size_t k = 0; k < from_soft.particles().size(); ++k)
    largest_move = std::max(largest_move, std::hypot(from_soft.particles().x[k] - from_stiff.particles().x[k],
                                                     from_soft.particles().y[k] - from_stiff.particles().y[k]));
  CHECK(largest_move < 0.05 * spec.radius_min_m);
  CHECK(largest_move > 0);  // the relaxation is the material's
  // make_specimen is the two parts, to the bit.
  CHECK(finished.particles().x == from_stiff.particles().x);
  CHECK(finished.particles().y == from_stiff.particles().y);
  CHECK(finished.bonds().i == from_stiff.bonds().i);
  CHECK(c.genesis_steps == b.genesis_steps);
  CHECK(c.residual_stress_xx_Pa == b.residual_stress_xx_Pa);
  CHECK(a.radius_scale == b.radius_scale);
  // A different reference modulus is a different packing.
  SpecimenSpec harder = spec;
  harder.compaction_modulus_Pa *= 2;
  CHECK(compact_packing(harder).disks.particles().radius != packing.disks.particles().radius);
}

TEST_CASE("specimen: save and load round trip", "[specimen]") {
  Material m;
  SpecimenReport report;
  SpecimenSpec spec = small_random();
  spec.packing = Packing::hexagonal;
  Simulation sim = make_specimen(m, spec, report);
  sim.bonds().bonded[3] = 0;  // a damaged element must survive the round trip
  const auto file = std::filesystem::path(KERF_BINARY_DIR) / "specimen_roundtrip.json";
  save_specimen(file.string(), sim, spec, report);
  SpecimenSpec spec2;
  SpecimenReport report2;
  Simulation loaded = load_specimen(file.string(), m, spec2, report2);
  CHECK(loaded.particles().x == sim.particles().x);
  CHECK(loaded.particles().radius == sim.particles().radius);
  CHECK(loaded.bonds().bonded == sim.bonds().bonded);
  CHECK(loaded.bonds().ref_distance_m == sim.bonds().ref_distance_m);
  CHECK(report2.n_bonds == report.n_bonds);
  CHECK(spec2.packing == Packing::hexagonal);
  std::filesystem::remove(file);
}

namespace {
// The length of segment f inside the box [x0, x1] x [y0, y1] (Liang-Barsky clipping).
double length_inside(const Flaw& f, double x0, double x1, double y0, double y1) {
  double t0 = 0, t1 = 1;
  const double dx = f.x1_m - f.x0_m, dy = f.y1_m - f.y0_m;
  const std::array<double, 4> p{-dx, dx, -dy, dy}, q{f.x0_m - x0, x1 - f.x0_m, f.y0_m - y0, y1 - f.y0_m};
  for (std::size_t k = 0; k < 4; ++k) {
    if (p[k] == 0) {
      if (q[k] < 0) return 0;
      continue;
    }
    const double t = q[k] / p[k];
    if (p[k] < 0)
      t0 = std::max(t0, t);
    else
      t1 = std::min(t1, t);
  }
  return t1 > t0 ? (t1 - t0) * std::hypot(dx, dy) : 0;
}

int broken_joints(const Simulation& sim) {
  int n = 0;
  for (std::size_t k = 0; k < sim.bonds().size(); ++k) n += sim.bonds().n_bonded_elements(k) == 0 ? 1 : 0;
  return n;
}
}  // namespace

TEST_CASE("specimen: seeded flaws cross the lattice's joints as Buffon's needle says", "[specimen]") {
  // A line of length L thrown at random on a triangular lattice of spacing 2R crosses on average
  // L n_b (2R) (2 / pi) joints, n_b = sqrt(3) / (2 R^2) joints per unit area: 2 sqrt(3) L / (pi R).
  const SpecimenSpec spec = hexagonal_spec(1.5e-3);
  Material m;
  m.flaw_length_m = 100e-6;
  m.flaw_density_per_m2 = 20e6;  // about 50 flaws: few cross one another
  SpecimenReport report;
  const Simulation intact = make_specimen(Material{}, spec, report);
  REQUIRE(broken_joints(intact) == 0);
  Simulation sim = make_specimen(m, spec, report);
  const auto& p = sim.particles();
  const auto [x0, x1] = std::minmax_element(p.x.begin(), p.x.end());
  const auto [y0, y1] = std::minmax_element(p.y.begin(), p.y.end());
  Simulation again = make_specimen(Material{}, spec, report);
  const std::vector<Flaw> flaws = seed_flaws(again, m, spec.seed);  // the same draw as the genesis's
  double inside_m = 0;
  for (const Flaw& f : flaws) inside_m += length_inside(f, *x0, *x1, *y0, *y1);
  const double expected = 2 * std::sqrt(3.0) * inside_m / (std::numbers::pi * 10e-6);
  INFO("flaws " << flaws.size() << ", expected " << expected << " broken joints");
  REQUIRE(flaws.size() > 30);
  CHECK_THAT(static_cast<double>(broken_joints(sim)), WithinRel(expected, 0.05));
  CHECK(broken_joints(again) == broken_joints(sim));
  // Each packing its own flaws: another seed, another draw.
  Simulation other = make_specimen(Material{}, spec, report);
  const std::vector<Flaw> others = seed_flaws(other, m, spec.seed + 1);
  CHECK(others.front().x0_m != flaws.front().x0_m);
  // Their density is the material's: the expected count over the widened box.
  const double area = (*x1 - *x0 + m.flaw_length_m) * (*y1 - *y0 + m.flaw_length_m);
  CHECK(std::abs(static_cast<double>(flaws.size()) - m.flaw_density_per_m2 * area) <= 1.0);
}

namespace {
// small_random() with radii 7.5-10 um and, when `fine`, a band of 2.5-3.3 um disks across it, 60 um high.
SpecimenSpec banded(bool fine) {
  SpecimenSpec s = small_random();
  if (!fine) return s;
  s.fine_radius_min_m = 2.5e-6, s.fine_radius_max_m = 3.3e-6;
  s.fine_x_min_m = 0, s.fine_x_max_m = s.width_m, s.fine_y_min_m = 0.12e-3, s.fine_y_max_m = 0.18e-3;
  return s;
}

// The Love stress xx of a specimen under an affine strain exx applied in one step (every joint and contact).
double affine_stress_xx(Simulation& sim, const SpecimenSpec& spec, double exx) {
  auto& p = sim.particles();
  const double dt = sim.time_step();
  for (std::size_t i = 0; i < p.size(); ++i) {
    p.vx[i] = exx * p.x[i] / dt, p.vy[i] = 0;
    p.x[i] += p.vx[i] * dt;
  }
  sim.evaluate_forces_with_increment();
  return sim.average_stress(spec.width_m * spec.height_m)[0];
}
}  // namespace

TEST_CASE("specimen: a fine region holds finer disks, packed and jointed as the rest, as stiff", "[specimen]") {
  Material m;
  // Off, the region's box is ignored: the packing of the spec without it, to the bit.
  SpecimenSpec box_only = banded(true);
  box_only.fine_radius_min_m = box_only.fine_radius_max_m = 0;
  const CompactedPacking plain = compact_packing(banded(false));
  CHECK(compact_packing(box_only).disks.particles().x == plain.disks.particles().x);

  const SpecimenSpec spec = banded(true);
  SpecimenReport report;
  Simulation sim = make_specimen(m, spec, report);
  const auto& p = sim.particles();
  // The fine disks: the packing fraction of the box's area with their nominal radii, each within its range at
  // the common scale (floaters at most 6 % larger), most centres in the box and few coarse ones.
  const double a = spec.fine_radius_min_m, b = spec.fine_radius_max_m;
  const double band_area = spec.width_m * (spec.fine_y_max_m - spec.fine_y_min_m);
  const double n_expected = spec.packing_fraction * band_area / (std::numbers::pi * (a * a + a * b + b * b) / 3);
  int n_fine = 0, fine_inside = 0, coarse_inside = 0;
  for (std::size_t k = 0; k < p.size(); ++k) {
    const bool fine = p.radius[k] < spec.radius_min_m * report.radius_scale;
    const bool inside = p.y[k] > spec.fine_y_min_m && p.y[k] < spec.fine_y_max_m;
    if (fine) {
      CHECK(p.radius[k] >= a * report.radius_scale * (1 - 1e-12));
      CHECK(p.radius[k] <= b * report.radius_scale * 1.0616);
    }
    n_fine += fine, fine_inside += fine && inside, coarse_inside += !fine && inside;
  }
  CHECK(std::abs(n_fine - n_expected) <= 1);
  CHECK(fine_inside > 0.8 * n_fine);
  CHECK(coarse_inside < 0.05 * n_fine);
  // Jointed as densely as the uniform specimen, fine and coarse joined across the region's sides.
  SpecimenReport uniform_report;
  Simulation uniform = make_specimen(m, banded(false), uniform_report);
  CHECK(report.coordination_number > 0.9 * uniform_report.coordination_number);
  CHECK(report.packing_fraction > uniform_report.packing_fraction - 0.03);
  int across = 0;
  std::vector<int> joints_of(p.size(), 0);
  for (std::size_t k = 0; k < sim.bonds().size(); ++k) {
    const auto i = static_cast<std::size_t>(sim.bonds().i[k]), j = static_cast<std::size_t>(sim.bonds().j[k]);
    ++joints_of[i], ++joints_of[j];
    across += (p.radius[i] < spec.radius_min_m * report.radius_scale) !=
              (p.radius[j] < spec.radius_min_m * report.radius_scale);
  }
  CHECK(across > 2 * spec.width_m / (2 * spec.radius_max_m));  // both sides, more than one joint per coarse disk
  // Few rattlers (disks held by fewer than two joints: fine disks squeezed into the coarse disks' pores, mostly).
  const auto rattlers = std::count_if(joints_of.begin(), joints_of.end(), [](int n) { return n < 2; });
  CHECK(static_cast<double>(rattlers) < 0.02 * static_cast<double>(p.size()));
  // The flat joint's stiffness per unit area does not depend on the disks' size: under one affine strain the
  // banded specimen's stress is the uniform one's within the packings' scatter (a joint stiffness growing with
  // R^2 instead of R would soften the band threefold: -20 %).
  const double exx = 1e-5;
  CHECK_THAT(affine_stress_xx(sim, spec, exx), WithinRel(affine_stress_xx(uniform, banded(false), exx), 0.05));
}

TEST_CASE("specimen: a fine region is refused where it cannot be packed, naming the key", "[specimen]") {
  const auto refused_key = [](const SpecimenSpec& s) {
    try {
      check_specimen_spec(s);
    } catch (const kerf::InputError& e) {
      return e.field();
    }
    return std::string("accepted");
  };
  CHECK(refused_key(banded(true)) == "accepted");
  SpecimenSpec s = banded(true);
  s.packing = Packing::hexagonal;
  CHECK(refused_key(s) == "fine_radius_max_um");
  s = banded(true), s.fine_radius_max_m = 8e-6;  // coarser than the coarse disks' smallest
  CHECK(refused_key(s) == "fine_radius_max_um");
  s = banded(true), s.fine_radius_min_m = 0;
  CHECK(refused_key(s) == "fine_radius_min_um");
  s = banded(true), s.fine_radius_min_m = 4e-6;  // above fine_radius_max
  CHECK(refused_key(s) == "fine_radius_min_um");
  s = banded(true), s.fine_x_max_m = 2 * s.width_m;
  CHECK(refused_key(s) == "fine_x_max_mm");
  s = banded(true), s.fine_y_max_m = s.fine_y_min_m + 10e-6;  // thinner than four fine diameters
  CHECK(refused_key(s) == "fine_y_max_mm");
  s = banded(true), s.fine_y_min_m = 5e-6;  // a sliver below it where no coarse disk's centre fits
  CHECK(refused_key(s) == "fine_y_min_mm");
  s = banded(true), s.fine_x_max_m = s.width_m - 5e-6;
  CHECK(refused_key(s) == "fine_x_max_mm");
  s = banded(true), s.fine_radius_min_m = s.fine_radius_max_m = 1e-8;  // billions of disks
  CHECK(refused_key(s) == "fine_radius_min_um");
}
