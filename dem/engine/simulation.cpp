// The DEM engine: neighbour lists, the force loop (joints, unjointed contacts, walls), breaks applied after
// the loop, velocity-Verlet with Cundall local damping, stable time step and instability detection.
#include "kerf/dem/engine/simulation.hpp"

#include <fmt/format.h>
#include <omp.h>

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstring>
#include <exception>
#include <limits>
#include <numbers>
#include <type_traits>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "../laws/flat_joint_simd.hpp"
#include "kerf/error.hpp"
#include "serial.hpp"

namespace kerf::dem {

namespace {

/// A law's update as its loop calls it: the law's own (bond_update), unless the law has a hand-vectorised path
/// of its own in an internal header (the flat joint's, flat_joint_simd.hpp), which overloads this.
template <class Law>
inline BondResult bond_update_fast(const Law& law, const BondGeometry& geo, const BondKinematics& kin, double* shear,
                                   const std::uint8_t* bonded, BreakMode* breaks) {
  return bond_update(law, geo, kin, shear, bonded, breaks);
}

/// Square root of each lane, correctly rounded as std::sqrt (one sqrtpd instead of two sqrtsd on x86-64).
inline v2d lane_sqrt(v2d v) {
#if defined(__SSE2__)
  return _mm_sqrt_pd(v);
#else
  return v2d{std::sqrt(v[0]), std::sqrt(v[1])};
#endif
}

enum Kind : std::uint32_t { kBond = 0, kPair = 1, kWall = 2 };

constexpr std::uint32_t encode(std::size_t index, Kind kind, std::uint32_t role) {
  return static_cast<std::uint32_t>(index) << 3 | kind << 1 | role;
}

/// Cundall's local damping of one force component (physics-dem.md section 1): F (1 - alpha sign(F v)).
/// Written as one product with a factor chosen without branches (the sign of F v is unpredictable, a branch
/// mispredicts about half the time); the factors are exactly 1 - alpha, 1 + alpha and 1.
inline double damp(double force, double velocity, double alpha) {
  const double fv = force * velocity;
  const double sign = static_cast<double>(fv > 0) - static_cast<double>(fv < 0);
  return force * (1 - alpha * sign);
}

/// `a` where `take_a`, else `b`, as a bitwise blend: the same bits as the ternary, but GCC turns a ternary
/// between a new value and the old one into a conditional store, which keeps a loop from vectorising.
inline double blend(bool take_a, double a, double b) {
  const std::uint64_t mask = -static_cast<std::uint64_t>(take_a);
  return std::bit_cast<double>((std::bit_cast<std::uint64_t>(a) & mask) | (std::bit_cast<std::uint64_t>(b) & ~mask));
}

/// The first half kick of the free disks (group 0) with the (damped) forces of the last evaluation and the
/// drift of all disks: this thread's share of a schedule(static) loop over the disks (orphaned worksharing).
/// The arrays are distinct (restrict parameters) and a free disk is chosen by a bitwise blend, not a branch,
/// so the loop vectorises: the same arithmetic on each disk, the same bits.
void kick_and_drift_disks(std::int64_t n, double dt, const std::uint8_t* __restrict group,
                          const double* __restrict inv_m, const double* __restrict inv_i, const double* __restrict fx,
                          const double* __restrict fy, const double* __restrict tq, double* __restrict vx,
                          double* __restrict vy, double* __restrict om, double* __restrict x, double* __restrict y,
                          double* __restrict th) {
  const double half = 0.5 * dt;
#pragma omp for schedule(static) nowait
  for (std::int64_t ii = 0; ii < n; ++ii) {
    const auto u = static_cast<std::size_t>(ii);
    const bool free_disk = group[u] == 0;
    const double vxu = blend(free_disk, vx[u] + half * fx[u] * inv_m[u], vx[u]);
    const double vyu = blend(free_disk, vy[u] + half * fy[u] * inv_m[u], vy[u]);
    const double omu = blend(free_disk, om[u] + half * tq[u] * inv_i[u], om[u]);
    vx[u] = vxu, vy[u] = vyu, om[u] = omu;
    x[u] += dt * vxu;
    y[u] += dt * vyu;
    th[u] += dt * omu;
  }
}

/// Cundall's damping of the new forces against the predicted end-of-step velocity, then the second half kick,
/// for the free disks; a prescribed disk (group > 0) keeps its raw forces (the reaction) and its velocity.
/// This thread's share of a schedule(static) loop over the disks; vectorised as kick_and_drift_disks.
void damped_kick_disks(std::int64_t n, double dt, double alpha, const std::uint8_t* __restrict group,
                       const double* __restrict inv_m, const double* __restrict inv_i, double* __restrict fx,
                       double* __restrict fy, double* __restrict tq, double* __restrict vx, double* __restrict vy,
                       double* __restrict om) {
  const double half = 0.5 * dt;
#pragma omp for schedule(static) nowait
  for (std::int64_t ii = 0; ii < n; ++ii) {
    const auto u = static_cast<std::size_t>(ii);
    const bool free_disk = group[u] == 0;
    const double fxu = damp(fx[u], vx[u] + half * fx[u] * inv_m[u], alpha);
    const double fyu = damp(fy[u], vy[u] + half * fy[u] * inv_m[u], alpha);
    const double tqu = damp(tq[u], om[u] + half * tq[u] * inv_i[u], alpha);
    vx[u] = blend(free_disk, vx[u] + half * fxu * inv_m[u], vx[u]);
    vy[u] = blend(free_disk, vy[u] + half * fyu * inv_m[u], vy[u]);
    om[u] = blend(free_disk, om[u] + half * tqu * inv_i[u], om[u]);
    fx[u] = blend(free_disk, fxu, fx[u]);
    fy[u] = blend(free_disk, fyu, fy[u]);
    tq[u] = blend(free_disk, tqu, tq[u]);
  }
}

/// The disk arrays the contact loops read (positions, velocities, spins, rotations, radii).
// The loops name the pointers one by one, not with a structured binding: clang 14 cannot use a structured
// binding inside an OpenMP region (a C++20 capture it lacks), and the sanitizer and fuzzing builds are clang's.
struct DiskArrays {
  const double *x, *y, *vx, *vy, *om, *th, *rad;
};
inline DiskArrays disk_arrays(const Particles& p) {
  return {p.x.data(), p.y.data(), p.vx.data(), p.vy.data(), p.omega.data(), p.theta.data(), p.radius.data()};
}

/// Closest point of segment (x0, y0)-(x1, y1) to (px, py).
inline std::array<double, 2> closest_on_segment(const Wall& w, double px, double py) {
  const double ex = w.x1 - w.x0, ey = w.y1 - w.y0;
  const double len2 = ex * ex + ey * ey;
  const double s = len2 > 0 ? std::clamp(((px - w.x0) * ex + (py - w.y0) * ey) / len2, 0.0, 1.0) : 0.0;
  return {w.x0 + s * ex, w.y0 + s * ey};
}

}  // namespace

int BondStore::n_bonded_elements(std::size_t b) const {
  int n = 0;
  for (int e = 0; e < stride; ++e) n += bonded[b * static_cast<std::size_t>(stride) + e];
  return n;
}

Simulation::Simulation(const Material& material, const SimulationOptions& options)
    : material_(material), opt_(options), types_{ParticleType{material.density_kg_per_m3}} {
  if (!(options.thickness_m > 0)) throw InputError("specimen.thickness_mm", format_value(options.thickness_m * 1e3), "a positive value in mm");
  if (!(options.time_step_safety > 0 && options.time_step_safety <= 1))
    throw InputError("engine.time_step_safety", format_value(options.time_step_safety), "a value in (0, 1]");
  b_.stride = std::visit([](const auto& law) { return bond_elements(law); }, material.joint);
  speed_limit_ = options.speed_limit_m_per_s > 0 ? options.speed_limit_m_per_s : p_wave_speed_m_per_s(material);
}

double p_wave_speed_m_per_s(const Material& material) {
  const double contact_modulus_pa = std::visit([](const auto& law) { return law.effective_modulus_pa; }, material.contact);
  return std::sqrt(contact_modulus_pa / material.density_kg_per_m3);
}

void refuse_small_time_step_safety(double steps, double time_step_s, double safety) {
  const double default_safety = SimulationOptions{}.time_step_safety;
  // dt is proportional to the safety: at the default the run would take steps * safety / default steps.
  if (!(steps > kMaxRunSteps) || safety >= default_safety || !(steps * safety / default_safety <= kMaxRunSteps)) return;
  throw InputError("engine.time_step_safety", format_value(safety),
                   fmt::format("at least {}: smaller, the run takes {:.3g} time steps of {} ns, more than {}",
                               format_value(safety * steps / kMaxRunSteps), steps, format_value(time_step_s * 1e9),
                               format_value(kMaxRunSteps)));
}

void Simulation::set_time_step_safety(double f) {
  if (!(f > 0 && f <= 1)) throw InputError("engine.time_step_safety", format_value(f), "a value in (0, 1]");
  opt_.time_step_safety = f;
  if (initialised_) refresh_time_step();
}

double Simulation::mass_of(double radius_m, std::uint8_t type) const {
  return types_.at(type).density_kg_per_m3 * std::numbers::pi * radius_m * radius_m * opt_.thickness_m;
}

int Simulation::add_particle(double x_m, double y_m, double radius_m, std::uint8_t type) {
  const double m = mass_of(radius_m, type);
  p_.x.push_back(x_m);
  p_.y.push_back(y_m);
  for (auto* v : {&p_.vx, &p_.vy, &p_.theta, &p_.omega, &p_.fx, &p_.fy, &p_.torque}) v->push_back(0.0);
  p_.radius.push_back(radius_m);
  p_.inv_mass.push_back(1.0 / m);
  p_.inv_inertia.push_back(2.0 / (m * radius_m * radius_m));  // disk: I = m r^2 / 2
  p_.type.push_back(type);
  p_.group.push_back(0);
  if (!absorbing_rate_.empty()) absorbing_rate_.push_back(0.0);
  // Added to a running simulation: the next step's drift measures its move from where it starts (the neighbour
  // lists are rebuilt after that drift).
  if (initialised_) x_ref_.push_back(x_m), y_ref_.push_back(y_m);
  need_rebuild_ = true;
  return static_cast<int>(p_.size() - 1);
}

void Simulation::set_absorbing_rates(std::vector<double> rates_per_s) {
  if (!rates_per_s.empty() && rates_per_s.size() != p_.size())
    throw std::logic_error("Simulation::set_absorbing_rates: one rate per disk");
  for (double r : rates_per_s)
    if (!(r >= 0 && std::isfinite(r))) throw std::logic_error("Simulation::set_absorbing_rates: a rate not finite and >= 0");
  absorbing_rate_ = std::move(rates_per_s);
  absorbing_decay_.clear();
  absorbing_dt_ = 0;
}

void Simulation::absorb_disks() {
  const auto n = static_cast<std::int64_t>(p_.size());
  const std::uint8_t* __restrict group = p_.group.data();
  const double* __restrict decay = absorbing_decay_.data();
  double* __restrict vx = p_.vx.data();
  double* __restrict vy = p_.vy.data();
  double* __restrict om = p_.omega.data();
  // The same static partition as the kick before it: each thread decays the disks it has just kicked.
#pragma omp for schedule(static) nowait
  for (std::int64_t ii = 0; ii < n; ++ii) {
    const auto u = static_cast<std::size_t>(ii);
    const double f = blend(group[u] == 0, decay[u], 1.0);  // a prescribed disk keeps its velocity
    vx[u] *= f, vy[u] *= f, om[u] *= f;
  }
}

void Simulation::set_radius(std::size_t i, double radius_m) {
  const double m = mass_of(radius_m, p_.type[i]);
  p_.radius[i] = radius_m;
  p_.inv_mass[i] = 1.0 / m;
  p_.inv_inertia[i] = 2.0 / (m * radius_m * radius_m);
}

int Simulation::add_wall(const Wall& wall) {
  walls_.push_back(wall);
  need_rebuild_ = true;
  return static_cast<int>(walls_.size() - 1);
}

int Simulation::install_bond(int i, int j) {
  if (i > j) std::swap(i, j);
  const auto ui = static_cast<std::size_t>(i), uj = static_cast<std::size_t>(j);
  return install_bond(i, j, std::hypot(p_.x[uj] - p_.x[ui], p_.y[uj] - p_.y[ui]), p_.theta[uj] - p_.theta[ui]);
}

int Simulation::install_bond(int i, int j, double ref_distance_m, double ref_rotation_rad) {
  const auto ui = static_cast<std::size_t>(i), uj = static_cast<std::size_t>(j);
  b_.i.push_back(i);
  b_.j.push_back(j);
  b_.ref_distance_m.push_back(ref_distance_m);
  b_.ref_rotation_rad.push_back(ref_rotation_rad);
  b_.geometry.push_back(std::visit(
      [&](const auto& law) { return bond_geometry(law, p_.radius[ui], p_.radius[uj], opt_.thickness_m); }, material_.joint));
  b_.active.push_back(1);
  for (int e = 0; e < b_.stride; ++e) {
    b_.shear_force_n.push_back(0.0);
    b_.bonded.push_back(1);
    b_.pending.push_back(BreakMode::none);
  }
  b_.out.push_back({0, 0, 0, 0});
  need_rebuild_ = true;
  return static_cast<int>(b_.size() - 1);
}

int Simulation::install_bonds_within_gap(double gap_m) {
  std::vector<CandidatePair> candidates;
  find_candidate_pairs(p_.x, p_.y, p_.radius, gap_m, candidates);
  std::vector<CandidatePair> existing;
  for (std::size_t b = 0; b < b_.size(); ++b)
    if (b_.active[b]) existing.push_back({b_.i[b], b_.j[b]});
  std::sort(existing.begin(), existing.end());
  int n = 0;
  for (const auto& c : candidates) {
    if (std::binary_search(existing.begin(), existing.end(), c)) continue;
    install_bond(c.i, c.j);
    ++n;
  }
  return n;
}

double Simulation::stable_time_step() const {
  const std::size_t n = p_.size();
  std::vector<double> kt(n, 0.0), kr(n, 0.0);
  const double t = opt_.thickness_m;
  // A contact's stiffness on disk u: the larger eigenvalue of k_n n n + k_s s s, and the rotational k_b + k_s r^2.
  const auto add = [&](std::size_t u, const TimeStepStiffness& k) {
    kt[u] += std::max(k.normal, k.shear);
    kr[u] += k.bending + k.shear * p_.radius[u] * p_.radius[u];
  };
  std::visit(
      [&](const auto& law) {
        for (std::size_t b = 0; b < b_.size(); ++b) {
          if (!b_.active[b]) continue;
          const TimeStepStiffness k = bond_time_step_stiffness(law, b_.geometry[b]);
          for (auto u : {b_.i[b], b_.j[b]}) add(static_cast<std::size_t>(u), k);
        }
      },
      material_.joint);
  return std::visit(
      [&](const auto& law) {
        for (const auto& c : pairs_) {
          const TimeStepStiffness k = contact_time_step_stiffness(law, p_.radius[c.i], p_.radius[c.j], t);
          add(static_cast<std::size_t>(c.i), k);
          add(static_cast<std::size_t>(c.j), k);
        }
        for (const auto& wc : wall_contacts_) {
          const auto u = static_cast<std::size_t>(wc[1]);
          add(u, contact_time_step_stiffness(law, p_.radius[u], 0.0, t));
        }
        double dt = std::numeric_limits<double>::infinity();
        for (std::size_t u = 0; u < n; ++u) {
          // Floor: four contacts with an equal disk, so that contacts formed later (fracture, genesis) stay
          // stable. With f_safety <= 0.8 the step keeps a margin of about sqrt(2) / 0.8 on the Gershgorin bound
          // of the largest eigenfrequency, sqrt(2 sum k / m).
          const TimeStepStiffness self = contact_time_step_stiffness(law, p_.radius[u], p_.radius[u], t);
          const double ktu = std::max(kt[u], 4 * std::max(self.normal, self.shear));
          const double kru = std::max(kr[u], 4 * self.shear * p_.radius[u] * p_.radius[u]);
          dt = std::min({dt, std::sqrt(1.0 / (p_.inv_mass[u] * ktu)), std::sqrt(1.0 / (p_.inv_inertia[u] * kru))});
        }
        dt *= opt_.time_step_safety;
        // A density or stiffness so extreme that the masses or the step leave the doubles (1e308 kg/m^3:
        // dt = inf; 1e-300: the masses underflow) cannot be integrated: say which inputs, before any step.
        if (!(std::isfinite(dt) && dt > 0))
          throw ModelError("dem", fmt::format("the stable time step is {:.4g} s, not a positive finite number: the "
                                              "masses or stiffnesses are beyond double precision "
                                              "(material.density_kg_per_m3 = {:.6g}, specimen.thickness_mm = {:.6g})",
                                              dt, material_.density_kg_per_m3, 1e3 * t));
        return dt;
      },
      material_.contact);
}

void Simulation::initialise() {
  if (p_.size() == 0) throw ModelError("dem", "no particles to simulate");
  skin_ = opt_.skin_m > 0 ? opt_.skin_m : 0.3 * *std::min_element(p_.radius.begin(), p_.radius.end());
  rebuild_neighbours();
  if (!dt_fixed_) dt_ = stable_time_step();
  evaluate_forces();
  initialised_ = true;
}

void Simulation::rebuild_neighbours() {
  const std::size_t n = p_.size();
  x_ref_ = p_.x;
  y_ref_ = p_.y;
  wall_ref_.clear();
  for (const auto& w : walls_) wall_ref_.insert(wall_ref_.end(), {w.x0, w.y0});

  // Active bonds per particle, so that jointed pairs are left out of the unjointed contacts.
  std::vector<std::int32_t> bstart(n + 1, 0), partners;
  for (std::size_t b = 0; b < b_.size(); ++b)
    if (b_.active[b]) ++bstart[static_cast<std::size_t>(b_.i[b]) + 1];
  for (std::size_t u = 0; u < n; ++u) bstart[u + 1] += bstart[u];
  partners.resize(static_cast<std::size_t>(bstart[n]));
  {
    std::vector<std::int32_t> fill(bstart.begin(), bstart.end() - 1);
    for (std::size_t b = 0; b < b_.size(); ++b)
      if (b_.active[b]) partners[static_cast<std::size_t>(fill[static_cast<std::size_t>(b_.i[b])]++)] = b_.j[b];
  }
  std::vector<CandidatePair> found;
  find_candidate_pairs(p_.x, p_.y, p_.radius, skin_, found);
  // A bond law that replaces the unbonded contact of its pair keeps bonded pairs out of the contacts.
  const bool bonded_pairs_touch = std::visit([](const auto& law) { return bond_keeps_contact(law); }, material_.joint);
  // Keep the shear state of the pairs that persist (both lists are sorted by (i, j)).
  std::vector<CandidatePair> pairs;
  std::vector<double> shear;
  pairs.reserve(found.size());
  shear.reserve(found.size());
  std::size_t old = 0;
  for (const auto& c : found) {
    const auto first = partners.begin() + bstart[static_cast<std::size_t>(c.i)];
    const auto last = partners.begin() + bstart[static_cast<std::size_t>(c.i) + 1];
    if (!bonded_pairs_touch && std::find(first, last, c.j) != last) continue;
    if (opt_.skip_held_pairs && p_.group[static_cast<std::size_t>(c.i)] && p_.group[static_cast<std::size_t>(c.j)])
      continue;
    while (old < pairs_.size() && pairs_[old] < c) ++old;
    pairs.push_back(c);
    shear.push_back(old < pairs_.size() && pairs_[old] == c ? pair_shear_[old] : 0.0);
  }
  pairs_ = std::move(pairs);
  pair_shear_ = std::move(shear);
  pair_out_.assign(pairs_.size(), {0, 0, 0, 0});

  // Disk-wall candidates, sorted by (wall, particle), shear state carried over.
  std::vector<std::array<std::int32_t, 2>> wc;
  std::vector<double> wshear;
  std::size_t wold = 0;
  for (std::size_t w = 0; w < walls_.size(); ++w) {
    if (!walls_[w].enabled) continue;
    for (std::size_t u = 0; u < n; ++u) {
      const auto q = closest_on_segment(walls_[w], p_.x[u], p_.y[u]);
      const double reach = p_.radius[u] + skin_;
      const double dx = p_.x[u] - q[0], dy = p_.y[u] - q[1];
      if (dx * dx + dy * dy >= reach * reach) continue;
      const std::array<std::int32_t, 2> key{static_cast<std::int32_t>(w), static_cast<std::int32_t>(u)};
      while (wold < wall_contacts_.size() && wall_contacts_[wold] < key) ++wold;
      wc.push_back(key);
      wshear.push_back(wold < wall_contacts_.size() && wall_contacts_[wold] == key ? wall_shear_[wold] : 0.0);
    }
  }
  wall_contacts_ = std::move(wc);
  wall_shear_ = std::move(wshear);
  wall_out_.assign(wall_contacts_.size(), {0, 0, 0});

  // Incidence lists: the order of the entries fixes the summation order, hence bit-identical results.
  incidence_start_.assign(n + 1, 0);
  const auto count = [&](std::int32_t u) { ++incidence_start_[static_cast<std::size_t>(u) + 1]; };
  for (std::size_t b = 0; b < b_.size(); ++b)
    if (b_.active[b]) count(b_.i[b]), count(b_.j[b]);
  for (const auto& c : pairs_) count(c.i), count(c.j);
  for (const auto& c : wall_contacts_) count(c[1]);
  for (std::size_t u = 0; u < n; ++u) incidence_start_[u + 1] += incidence_start_[u];
  incidence_.resize(static_cast<std::size_t>(incidence_start_[n]));
  std::vector<std::int32_t> fill(incidence_start_.begin(), incidence_start_.end() - 1);
  const auto put = [&](std::int32_t u, std::uint32_t entry) {
    incidence_[static_cast<std::size_t>(fill[static_cast<std::size_t>(u)]++)] = entry;
  };
  // Each particle's entries: its joints, then its pairs, then its walls; where each kind begins is kept so
  // that the gather runs one loop per kind (no branch on the kind, which mispredicted at every change).
  for (std::size_t b = 0; b < b_.size(); ++b)
    if (b_.active[b]) put(b_.i[b], encode(b, kBond, 0)), put(b_.j[b], encode(b, kBond, 1));
  incidence_pair_begin_ = fill;
  for (std::size_t k = 0; k < pairs_.size(); ++k) put(pairs_[k].i, encode(k, kPair, 0)), put(pairs_[k].j, encode(k, kPair, 1));
  incidence_wall_begin_ = fill;
  for (std::size_t k = 0; k < wall_contacts_.size(); ++k) put(wall_contacts_[k][1], encode(k, kWall, 0));

  fixed_.clear();
  for (std::size_t u = 0; u < n; ++u)
    if (p_.group[u]) fixed_.push_back(static_cast<std::int32_t>(u));
  need_rebuild_ = false;
}

ContactSprings Simulation::contact_springs() const {
  ContactSprings s;
  for (std::size_t k = 0; k < pairs_.size(); ++k)
    if (pair_shear_[k] != 0) s.pairs.push_back(pairs_[k]), s.pair_shear_n.push_back(pair_shear_[k]);
  for (std::size_t k = 0; k < wall_contacts_.size(); ++k)
    if (wall_shear_[k] != 0) s.wall_contacts.push_back(wall_contacts_[k]), s.wall_shear_n.push_back(wall_shear_[k]);
  return s;
}

void Simulation::set_contact_springs(ContactSprings springs) {
  const auto n = static_cast<std::int32_t>(p_.size()), nw = static_cast<std::int32_t>(walls_.size());
  const auto valid = [&](std::int32_t u, std::int32_t limit) { return u >= 0 && u < limit; };
  if (springs.pairs.size() != springs.pair_shear_n.size() || springs.wall_contacts.size() != springs.wall_shear_n.size() ||
      !std::is_sorted(springs.pairs.begin(), springs.pairs.end()) ||
      !std::is_sorted(springs.wall_contacts.begin(), springs.wall_contacts.end()))
    throw ModelError("dem", "contact springs: lists of different lengths or not sorted");
  for (const auto& c : springs.pairs)
    if (!valid(c.i, n) || !valid(c.j, n) || c.i >= c.j) throw ModelError("dem", "contact springs: a pair out of range");
  for (const auto& c : springs.wall_contacts)
    if (!valid(c[0], nw) || !valid(c[1], n)) throw ModelError("dem", "contact springs: a wall contact out of range");
  pairs_ = std::move(springs.pairs);
  pair_shear_ = std::move(springs.pair_shear_n);
  wall_contacts_ = std::move(springs.wall_contacts);
  wall_shear_ = std::move(springs.wall_shear_n);
  need_rebuild_ = true;
}

void Simulation::evaluate_forces() {
  const double dt = dt_;
  dt_ = 0;  // no motion: no shear increments (apply_breaks does not read the step)
  evaluate_forces_with_increment();
  dt_ = dt;
}

void Simulation::evaluate_forces_with_increment() {
  if (need_rebuild_) rebuild_neighbours();
  compute_forces();
  apply_breaks();
}

int Simulation::team_threads() {
  const int max_threads = omp_get_max_threads();
  return adaptive_team_ ? governor_.team(max_threads) : max_threads;
}

void Simulation::compute_forces() {
  ForceCounts counts;
  const int team = team_threads();
#pragma omp parallel if (parallel_here()) num_threads(team)
  force_loops(counts);
  finish_forces(counts);
}

void Simulation::finish_forces(const ForceCounts& counts) {
  if (counts.n_retired > 0) need_rebuild_ = true;
  if (counts.n_breaking > 0) need_breaks_ = true;
}

double Simulation::dashpot_coefficient(std::size_t i, std::int64_t j, double stiffness) const {
  const double inv_i = p_.group[i] ? 0.0 : p_.inv_mass[i];
  const double inv_j = j < 0 || p_.group[static_cast<std::size_t>(j)] ? 0.0 : p_.inv_mass[static_cast<std::size_t>(j)];
  const double inv = inv_i + inv_j;
  return inv > 0 ? 2 * material_.viscous_damping_ratio * std::sqrt(stiffness / inv) : 0.0;
}

template <class Law, bool kViscous>
void Simulation::bond_loop(const Law& law, ForceCounts& counts) {
  const double dt = dt_;
  const int stride = b_.stride;
  const auto nb = static_cast<std::int64_t>(b_.size());
  int n_breaking = 0, n_retired = 0;
  const DiskArrays disks = disk_arrays(p_);
  [[maybe_unused]] const double *x = disks.x, *y = disks.y, *vx = disks.vx, *vy = disks.vy, *om = disks.om,
                                *th = disks.th, *rad = disks.rad;

  // Joints in blocks, each in two passes: first the kinematics of every joint of the block (independent from
  // joint to joint, so the square roots and divisions of several joints are in flight at once instead of one
  // joint's chain of them at a time), then the flat-joint law and the forces. The same operations on the
  // same values as one pass: the same bits. The first pass also takes the retired joints (a few per cent of
  // a cut; the second skips them): no branch there, and a retired joint's numbers are never read.
  constexpr std::int64_t kBlock = 64;
  const std::int64_t n_blocks = (nb + kBlock - 1) / kBlock;
#pragma omp for schedule(static) nowait
  for (std::int64_t blk = 0; blk < n_blocks; ++blk) {
    const std::int64_t first = blk * kBlock, count = std::min(kBlock, nb - first);
    struct {
      double nx[kBlock], ny[kBlock], a1[kBlock], a2[kBlock], surface_gap[kBlock], gap[kBlock], rotation[kBlock],
          shear_increment[kBlock];
    } block;
    // Two joints per iteration, one in each lane (lane by lane the same IEEE operations as one joint at a time,
    // so the same bits): one square root and two divisions for two joints. An odd block's last iteration
    // repeats its joint in the second lane, whose slot past the block's count is never read.
    for (std::int64_t q = 0; q < count; q += 2) {
      const auto b0 = static_cast<std::size_t>(first + q), b1 = q + 1 < count ? b0 + 1 : b0;
      const auto i0 = static_cast<std::size_t>(b_.i[b0]), j0 = static_cast<std::size_t>(b_.j[b0]);
      const auto i1 = static_cast<std::size_t>(b_.i[b1]), j1 = static_cast<std::size_t>(b_.j[b1]);
      const auto lanes = [&](const double* v, std::size_t u0, std::size_t u1) { return v2d{v[u0], v[u1]}; };
      const v2d dx = lanes(x, j0, j1) - lanes(x, i0, i1), dy = lanes(y, j0, j1) - lanes(y, i0, i1);
      const v2d d = lane_sqrt(dx * dx + dy * dy);
      const v2d nx = dx / d, ny = dy / d, sx = -ny, sy = nx;
      const v2d ri = lanes(rad, i0, i1), rj = lanes(rad, j0, j1);
      const v2d surface_gap = d - ri - rj;
      const v2d a1 = ri + 0.5 * surface_gap, a2 = rj + 0.5 * surface_gap;  // centre to interface
      // Relative velocity of surface 2 w.r.t. surface 1 at the interface centre, along s (rotation included).
      const v2d vs = (lanes(vx, j0, j1) - lanes(vx, i0, i1)) * sx + (lanes(vy, j0, j1) - lanes(vy, i0, i1)) * sy -
                     a2 * lanes(om, j0, j1) - a1 * lanes(om, i0, i1);
      const v2d gap = d - lanes(b_.ref_distance_m.data(), b0, b1);
      const v2d rotation = lanes(th, j0, j1) - lanes(th, i0, i1) - lanes(b_.ref_rotation_rad.data(), b0, b1);
      const v2d shear_increment = vs * dt;
      const auto store = [q](double* slots, const v2d& v) { std::memcpy(slots + q, &v, sizeof v); };
      store(block.nx, nx), store(block.ny, ny), store(block.a1, a1), store(block.a2, a2);
      store(block.surface_gap, surface_gap), store(block.gap, gap), store(block.rotation, rotation);
      store(block.shear_increment, shear_increment);
    }
    for (std::int64_t q = 0; q < count; ++q) {
      const auto b = static_cast<std::size_t>(first + q);
      auto& out = b_.out[b];
      if (!b_.active[b]) {
        out = {0, 0, 0, 0};
        continue;
      }
      const double nx = block.nx[q], ny = block.ny[q], sx = -ny, sy = nx, a1 = block.a1[q], a2 = block.a2[q];
      const std::size_t e0 = b * static_cast<std::size_t>(stride);
      const BondKinematics kin{block.gap[q], block.rotation[q], block.shear_increment[q]};
      BondResult r = bond_update_fast(law, b_.geometry[b], kin, b_.shear_force_n.data() + e0, b_.bonded.data() + e0,
                                      b_.pending.data() + e0);
      n_breaking += r.n_breaking;
      if constexpr (kViscous) {
        // Dashpots beside the bond's springs (not part of its strength test): on disk 2, -c_n v_n n - c_s v_s s.
        const auto i = static_cast<std::size_t>(b_.i[b]), j = static_cast<std::size_t>(b_.j[b]);
        const double dvx = vx[j] - vx[i], dvy = vy[j] - vy[i];
        const double vn = dvx * nx + dvy * ny, vs = dvx * sx + dvy * sy - a2 * om[j] - a1 * om[i];
        const TimeStepStiffness k = bond_time_step_stiffness(law, b_.geometry[b]);
        r.normal_force_n += dashpot_coefficient(i, static_cast<std::int64_t>(j), k.normal) * vn;  // tension positive
        r.shear_force_n -= dashpot_coefficient(i, static_cast<std::int64_t>(j), k.shear) * vs;
      }
      // Force on disk 2: -F_n n + F_s s (tension positive pulls disk 2 back towards disk 1).
      out = {-r.normal_force_n * nx + r.shear_force_n * sx, -r.normal_force_n * ny + r.shear_force_n * sy,
             -a1 * r.shear_force_n - r.moment_nm, -a2 * r.shear_force_n + r.moment_nm};
      // The law says when a bond carries no force any more and hands its pair over to the unbonded contact.
      if (bond_retires(law, b_.geometry[b], kin, r, block.surface_gap[q], b_.bonded.data() + e0)) {
        b_.active[b] = 0;
        out = {0, 0, 0, 0};
        ++n_retired;
      }
    }
  }

  if (n_breaking > 0 || n_retired > 0) {  // complete for the caller after the wall loop's barrier
#pragma omp atomic
    counts.n_breaking += n_breaking;
#pragma omp atomic
    counts.n_retired += n_retired;
  }
}

template <class Law, bool kViscous>
void Simulation::pair_loop(const Law& law) {
  const double dt = dt_, t = opt_.thickness_m;
  const DiskArrays disks = disk_arrays(p_);
  [[maybe_unused]] const double *x = disks.x, *y = disks.y, *vx = disks.vx, *vy = disks.vy, *om = disks.om,
                                *th = disks.th, *rad = disks.rad;

  const auto np = static_cast<std::int64_t>(pairs_.size());
#pragma omp for schedule(static) nowait
  for (std::int64_t kk = 0; kk < np; ++kk) {
    const auto k = static_cast<std::size_t>(kk);
    const auto i = static_cast<std::size_t>(pairs_[k].i), j = static_cast<std::size_t>(pairs_[k].j);
    const double dx = x[j] - x[i], dy = y[j] - y[i];
    const double d2 = dx * dx + dy * dy, reach = rad[i] + rad[j];
    if (d2 >= reach * reach) {
      pair_shear_[k] = 0;
      pair_out_[k] = {0, 0, 0, 0};
      continue;
    }
    const double d = std::sqrt(d2);
    const double nx = dx / d, ny = dy / d, sx = -ny, sy = nx;
    const double overlap = reach - d;
    const double a1 = rad[i] - 0.5 * overlap, a2 = rad[j] - 0.5 * overlap;
    const double vs = (vx[j] - vx[i]) * sx + (vy[j] - vy[i]) * sy - a2 * om[j] - a1 * om[i];
    ContactResult r = contact_update(law, rad[i], rad[j], t, overlap, vs * dt, pair_shear_[k]);
    if constexpr (kViscous) {  // dashpots: on disk 2, -c_n v_n n - c_s v_s s (compression positive)
      const TimeStepStiffness ks = contact_time_step_stiffness(law, rad[i], rad[j], t);
      const double vn = (vx[j] - vx[i]) * nx + (vy[j] - vy[i]) * ny;
      r.normal_force_n -= dashpot_coefficient(i, static_cast<std::int64_t>(j), ks.normal) * vn;
      r.shear_force_n -= dashpot_coefficient(i, static_cast<std::int64_t>(j), ks.shear) * vs;
    }
    // Force on disk 2: +F_n n (compression pushes it away) + F_s s.
    pair_out_[k] = {r.normal_force_n * nx + r.shear_force_n * sx, r.normal_force_n * ny + r.shear_force_n * sy,
                    -a1 * r.shear_force_n, -a2 * r.shear_force_n};
  }
}

template <class Law, bool kViscous>
void Simulation::wall_loop(const Law& law) {
  const double dt = dt_, t = opt_.thickness_m;
  const DiskArrays disks = disk_arrays(p_);
  [[maybe_unused]] const double *x = disks.x, *y = disks.y, *vx = disks.vx, *vy = disks.vy, *om = disks.om,
                                *th = disks.th, *rad = disks.rad;

  const auto nw = static_cast<std::int64_t>(wall_contacts_.size());
#pragma omp for schedule(static)
  for (std::int64_t kk = 0; kk < nw; ++kk) {
    const auto k = static_cast<std::size_t>(kk);
    const Wall& w = walls_[static_cast<std::size_t>(wall_contacts_[k][0])];
    const auto u = static_cast<std::size_t>(wall_contacts_[k][1]);
    const auto q = closest_on_segment(w, x[u], y[u]);
    const double dx = x[u] - q[0], dy = y[u] - q[1];
    const double d2 = dx * dx + dy * dy;
    if (!w.enabled || d2 >= rad[u] * rad[u] || d2 == 0) {
      wall_shear_[k] = 0;
      wall_out_[k] = {0, 0, 0};
      continue;
    }
    const double d = std::sqrt(d2);
    const double nx = dx / d, ny = dy / d, sx = -ny, sy = nx;  // n from the wall to the disk
    const double overlap = rad[u] - d, a = rad[u] - 0.5 * overlap;
    const double vs = (vx[u] - w.vx) * sx + (vy[u] - w.vy) * sy - a * om[u];
    const Law wall_law = w.friction_coefficient >= 0 ? with_friction(law, w.friction_coefficient) : law;
    ContactResult r = contact_update(wall_law, rad[u], 0.0, t, overlap, vs * dt, wall_shear_[k]);
    if constexpr (kViscous) {  // dashpots against the (infinitely heavy) wall
      const TimeStepStiffness ks = contact_time_step_stiffness(wall_law, rad[u], 0.0, t);
      const double vn = (vx[u] - w.vx) * nx + (vy[u] - w.vy) * ny;
      r.normal_force_n -= dashpot_coefficient(u, -1, ks.normal) * vn;
      r.shear_force_n -= dashpot_coefficient(u, -1, ks.shear) * vs;
    }
    wall_out_[k] = {r.normal_force_n * nx + r.shear_force_n * sx, r.normal_force_n * ny + r.shear_force_n * sy,
                    -a * r.shear_force_n};
  }
}

// Called by every thread of a team (or by one thread outside any): orphaned worksharing loops, each contact
// writing its own slot, then each particle summing its slots in a fixed order, so results are bit-identical
// for any number of threads. The counts are complete after the wall loop's barrier; the gather ends without
// one (the region's end, or the caller's own schedule(static) loop over the particles, follows). Each loop
// is chosen once per call by the law it runs (std::visit), and the law's update inlines into it.
void Simulation::force_loops(ForceCounts& counts) {
  // The joint, pair and wall loops write disjoint slots: no barrier between them.
  if (material_.viscous_damping_ratio > 0) {
    std::visit([&](const auto& law) { bond_loop<std::decay_t<decltype(law)>, true>(law, counts); }, material_.joint);
    std::visit([&](const auto& law) { pair_loop<std::decay_t<decltype(law)>, true>(law); }, material_.contact);
    std::visit([&](const auto& law) { wall_loop<std::decay_t<decltype(law)>, true>(law); }, material_.contact);
  } else {
    std::visit([&](const auto& law) { bond_loop<std::decay_t<decltype(law)>, false>(law, counts); }, material_.joint);
    std::visit([&](const auto& law) { pair_loop<std::decay_t<decltype(law)>, false>(law); }, material_.contact);
    std::visit([&](const auto& law) { wall_loop<std::decay_t<decltype(law)>, false>(law); }, material_.contact);
  }  // the wall loop ends with a barrier

#pragma omp single nowait
  {
    for (auto& w : walls_) w.fx = w.fy = 0;
    for (std::size_t k = 0; k < wall_contacts_.size(); ++k) {
      auto& w = walls_[static_cast<std::size_t>(wall_contacts_[k][0])];
      w.fx -= wall_out_[k][0];
      w.fy -= wall_out_[k][1];
    }
  }

  // Gather: each particle sums its own entries in a fixed order (deterministic for any thread count). No
  // barrier after it: a later schedule(static) loop over the particles gives each thread the same ones.
  const auto n = static_cast<std::int64_t>(p_.size());
#pragma omp for schedule(static) nowait
  for (std::int64_t ii = 0; ii < n; ++ii) {
    const auto u = static_cast<std::size_t>(ii);
    double fx = 0, fy = 0, tq = 0;
    const auto add = [&](const std::array<double, 4>& o, std::uint32_t entry) {
      // Disk 1 (role 0) gets minus the force on disk 2, and its own moment: sign and index without a
      // branch (roles alternate unpredictably); adding -f is the same to the bit as subtracting f.
      const std::uint32_t role = entry & 1u;
      const double sign = role == 0 ? -1.0 : 1.0;
      fx += sign * o[0], fy += sign * o[1], tq += o[2 + role];
    };
    const std::int32_t pairs_begin = incidence_pair_begin_[u], walls_begin = incidence_wall_begin_[u];
    for (std::int32_t k = incidence_start_[u]; k < pairs_begin; ++k) {
      const std::uint32_t entry = incidence_[static_cast<std::size_t>(k)];
      add(b_.out[entry >> 3], entry);
    }
    for (std::int32_t k = pairs_begin; k < walls_begin; ++k) {
      const std::uint32_t entry = incidence_[static_cast<std::size_t>(k)];
      add(pair_out_[entry >> 3], entry);
    }
    for (std::int32_t k = walls_begin; k < incidence_start_[u + 1]; ++k) {
      const auto& o = wall_out_[incidence_[static_cast<std::size_t>(k)] >> 3];
      fx += o[0], fy += o[1], tq += o[2];
    }
    p_.fx[u] = fx;
    p_.fy[u] = fy;
    p_.torque[u] = tq;
  }
}

void Simulation::apply_breaks() {
  if (!need_breaks_) return;
  need_breaks_ = false;
  std::visit([&](const auto& law) { apply_breaks_of(law); }, material_.joint);
}

template <class Law>
void Simulation::apply_breaks_of(const Law& law) {
  const auto stride = static_cast<std::size_t>(b_.stride);
  for (std::size_t b = 0; b < b_.size(); ++b) {
    if (!b_.active[b]) continue;
    for (std::size_t e = 0; e < stride; ++e) {
      const std::size_t k = b * stride + e;
      if (b_.pending[k] == BreakMode::none) continue;
      const auto i = static_cast<std::size_t>(b_.i[b]), j = static_cast<std::size_t>(b_.j[b]);
      const double dx = p_.x[j] - p_.x[i], dy = p_.y[j] - p_.y[i];
      const double d = std::hypot(dx, dy);
      const double nx = dx / d, ny = dy / d;
      const double a1 = p_.radius[i] + 0.5 * (d - p_.radius[i] - p_.radius[j]);
      const auto& g = b_.geometry[b];
      const ElementPlace place = bond_element_place(law, g, static_cast<int>(e));
      const double xi = place.centroid_m;
      cracks_.push_back({time_, p_.x[i] + a1 * nx - xi * ny, p_.y[i] + a1 * ny + xi * nx, std::atan2(nx, -ny),
                         place.length_m, b_.pending[k], static_cast<std::int32_t>(b), static_cast<std::int32_t>(e)});
      b_.bonded[k] = 0;
      b_.shear_force_n[k] = 0;  // residual mode: the shear stress of a broken element drops to zero
      b_.pending[k] = BreakMode::none;
      if (bond_retires_on_break(law)) {  // the whole bond goes with its first break
        b_.active[b] = 0;
        need_rebuild_ = true;
        break;
      }
    }
  }
}

void Simulation::check_stability() const {
  const auto n = static_cast<std::int64_t>(p_.size());
  double worst = 0;
  std::int64_t worst_i = -1;
  for (std::int64_t ii = 0; ii < n; ++ii) {
    const auto u = static_cast<std::size_t>(ii);
    const double v2 = p_.vx[u] * p_.vx[u] + p_.vy[u] * p_.vy[u];
    const bool finite = std::isfinite(v2) && std::isfinite(p_.x[u]) && std::isfinite(p_.y[u]) && std::isfinite(p_.omega[u]);
    if (!finite || v2 > worst) {
      worst = finite ? v2 : std::numeric_limits<double>::infinity();
      worst_i = ii;
      if (!finite) break;
    }
  }
  if (worst_i >= 0 && !(std::sqrt(worst) <= speed_limit_)) {
    const auto u = static_cast<std::size_t>(worst_i);
    throw ModelError("dem", fmt::format("unstable run stopped at step {} (t = {:.6g} s, dt = {:.4g} s): particle {} at "
                                        "({:.6g}, {:.6g}) m has speed {:.4g} m/s, above the limit {:.4g} m/s (p-wave "
                                        "speed); lower engine.time_step_safety or the loading speed",
                                        steps_, time_, dt_, worst_i, p_.x[u], p_.y[u], std::sqrt(worst), speed_limit_));
  }
}

double Simulation::half_kick_and_drift(double dt) {
  const auto n = static_cast<std::int64_t>(p_.size());
  kick_and_drift_disks(n, dt, p_.group.data(), p_.inv_mass.data(), p_.inv_inertia.data(), p_.fx.data(), p_.fy.data(),
                       p_.torque.data(), p_.vx.data(), p_.vy.data(), p_.omega.data(), p_.x.data(), p_.y.data(),
                       p_.theta.data());
  // The largest move in a loop of its own (a maximum of doubles does not vectorise): the same partition as
  // the loop above, so each thread reads the positions it has just written.
  double max_move2 = 0;
#pragma omp for schedule(static) nowait
  for (std::int64_t ii = 0; ii < n; ++ii) {
    const auto u = static_cast<std::size_t>(ii);
    const double mx = p_.x[u] - x_ref_[u], my = p_.y[u] - y_ref_[u];
    max_move2 = std::max(max_move2, mx * mx + my * my);
  }
  return max_move2;
}

void Simulation::damped_half_kick(double dt) {
  damped_kick_disks(static_cast<std::int64_t>(p_.size()), dt, material_.local_damping, p_.group.data(),
                    p_.inv_mass.data(), p_.inv_inertia.data(), p_.fx.data(), p_.fy.data(), p_.torque.data(),
                    p_.vx.data(), p_.vy.data(), p_.omega.data());
}

void Simulation::step() {
  if (!initialised_) initialise();
  const double dt = dt_;
  double max_move2 = 0, wall_move = 0;
  bool must_rebuild = false;
  ForceCounts counts;
  std::exception_ptr failure;
  // One team for the whole step (not one per loop): the serial pieces run in `single` blocks and the
  // threads meet at barriers only where a loop reads what another thread wrote: after the drift, (when the
  // neighbour lists are rebuilt), after the contact loops, and at the end. Its size: team_threads().
  const int team = team_threads();
  const bool absorb = !absorbing_rate_.empty();
  if (absorb && (absorbing_dt_ != dt || absorbing_decay_.size() != absorbing_rate_.size())) {  // this step's factors
    absorbing_decay_.resize(absorbing_rate_.size());
    for (std::size_t u = 0; u < absorbing_rate_.size(); ++u) absorbing_decay_[u] = std::exp(-absorbing_rate_[u] * dt);
    absorbing_dt_ = dt;
  }
#pragma omp parallel if (parallel_here()) num_threads(team)
  {
#pragma omp single nowait
    {
      for (std::size_t w = 0; w < walls_.size(); ++w) {
        auto& wl = walls_[w];
        wl.x0 += dt * wl.vx, wl.x1 += dt * wl.vx, wl.y0 += dt * wl.vy, wl.y1 += dt * wl.vy;
        if (2 * w + 1 < wall_ref_.size())
          wall_move = std::max(wall_move, std::hypot(wl.x0 - wall_ref_[2 * w], wl.y0 - wall_ref_[2 * w + 1]));
      }
      time_ += dt;
      must_rebuild = need_rebuild_ || wall_ref_.size() != 2 * walls_.size();
    }
    const double my_max_move2 = half_kick_and_drift(dt);
#pragma omp critical(kerf_dem_max_move)
    max_move2 = std::max(max_move2, my_max_move2);  // a maximum: the same for any order
#pragma omp barrier
    // Every thread takes the same decision from the same shared values (none changes before the single).
    const double max_move = std::sqrt(max_move2);
    if (must_rebuild || 2 * max_move > skin_ || max_move + wall_move > skin_) {
      // No exception may leave a parallel region (std::terminate): the rebuild's (a non-finite position) is
      // kept, every thread sees it after the single's barrier and skips the rest, and it is thrown below.
#pragma omp single
      try {
        rebuild_neighbours();
      } catch (...) {
        failure = std::current_exception();
      }
    }
    if (!failure) {
      force_loops(counts);
#pragma omp single nowait
      {
        finish_forces(counts);
        apply_breaks();  // joints only: the kick below does not read them
      }
      damped_half_kick(dt);  // no barrier after it: the region's end is one
      if (absorb) absorb_disks();
    }
  }
  if (failure) {
    try {
      std::rethrow_exception(failure);
    } catch (const ModelError& e) {  // with the inputs that led there
      std::string reason = e.what();
      if (reason.rfind("model 'dem': ", 0) == 0) reason.erase(0, std::string_view("model 'dem': ").size());
      throw ModelError("dem", fmt::format("{} (step {}, dt = {:.4g} s, material.density_kg_per_m3 = {:.6g}, "
                                          "specimen.thickness_mm = {:.6g})",
                                          reason, steps_, dt_, material_.density_kg_per_m3, 1e3 * opt_.thickness_m));
    }
  }
  ++steps_;
  if (opt_.check_every > 0 && steps_ % opt_.check_every == 0) check_stability();
  // The governor's clock, every 16 steps (a window is about 0.25 s: thousands of steps).
  if (adaptive_team_ && steps_ % 16 == 0)
    governor_.observe(16, std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count());
}

void Simulation::run(std::int64_t n_steps) {
  for (std::int64_t s = 0; s < n_steps; ++s) step();
}

namespace {
template <class... V>
std::size_t bytes_of(const V&... v) {
  return (... + (v.capacity() * sizeof(typename V::value_type)));
}
}  // namespace

std::size_t Simulation::memory_bytes() const {
  return bytes_of(p_.x, p_.y, p_.vx, p_.vy, p_.theta, p_.omega, p_.fx, p_.fy, p_.torque, p_.radius, p_.inv_mass,
                  p_.inv_inertia, p_.type, p_.group) +
         bytes_of(b_.i, b_.j, b_.ref_distance_m, b_.ref_rotation_rad, b_.geometry, b_.active, b_.shear_force_n,
                  b_.bonded, b_.pending, b_.out) +
         bytes_of(pairs_, pair_shear_, pair_out_, wall_contacts_, wall_shear_, wall_out_, incidence_start_, incidence_,
                  incidence_pair_begin_, incidence_wall_begin_, x_ref_, y_ref_, wall_ref_, fixed_, cracks_);
}

namespace {

constexpr std::string_view kStateMagic = "KERFDEM7";  // 2: Wall::friction_coefficient; 3: the laws as variants;
                                                      // 4: the viscous damping ratio; 5: skip_held_pairs;
                                                      // 6: the absorbing rates; 7: the laws by name
constexpr std::string_view kStateMagicRawLaws = "KERFDEM6";  // still read: the laws as raw variants of 4a34e1f

}  // namespace

template <class Self, class Io>
void Simulation::state_fields(Self& sim, Io& io) {
  auto& p = sim.p_;
  auto& b = sim.b_;
  io(sim.types_);
  for (auto* v : {&p.x, &p.y, &p.vx, &p.vy, &p.theta, &p.omega, &p.fx, &p.fy, &p.torque, &p.radius, &p.inv_mass,
                  &p.inv_inertia})
    io(*v);
  io(p.type, p.group);
  io(b.stride, b.i, b.j, b.ref_distance_m, b.ref_rotation_rad, b.geometry, b.active, b.shear_force_n, b.bonded,
     b.pending, b.out);
  io(sim.walls_, sim.cracks_, sim.pairs_, sim.pair_shear_, sim.pair_out_, sim.wall_contacts_, sim.wall_shear_,
     sim.wall_out_, sim.incidence_start_, sim.incidence_, sim.incidence_pair_begin_,
     sim.incidence_wall_begin_, sim.x_ref_, sim.y_ref_, sim.wall_ref_, sim.fixed_, sim.absorbing_rate_);
  io(sim.need_rebuild_, sim.need_breaks_, sim.initialised_, sim.dt_fixed_);
  io(sim.dt_, sim.time_, sim.skin_, sim.speed_limit_, sim.steps_);
}

std::string Simulation::serialize() const {
  std::string out(kStateMagic);
  serial::Out io{out};
  io(material_.density_kg_per_m3, material_.contact, material_.joint, material_.local_damping,
     material_.viscous_damping_ratio, material_.name, opt_);
  state_fields(*this, io);
  return out;
}

Simulation Simulation::deserialize(std::string_view bytes) {
  std::size_t version = 0;
  serial::In io = serial::open_tagged(bytes, {kStateMagic, kStateMagicRawLaws}, "engine state", &version);
  io.raw_laws = version == 1;
  Material m;
  SimulationOptions opt;
  io(m.density_kg_per_m3, m.contact, m.joint, m.local_damping, m.viscous_damping_ratio, m.name, opt);
  Simulation sim(m, opt);
  state_fields(sim, io);
  io.expect_end("engine state");
  return sim;
}

std::array<double, 2> Simulation::group_force(std::uint8_t g) const {
  double fx = 0, fy = 0;
  for (auto k : fixed_) {
    const auto u = static_cast<std::size_t>(k);
    if (p_.group[u] != g) continue;
    fx += p_.fx[u];
    fy += p_.fy[u];
  }
  return {fx, fy};
}

double Simulation::kinetic_energy() const {
  double e = 0;
  for (std::size_t u = 0; u < p_.size(); ++u)
    e += 0.5 * ((p_.vx[u] * p_.vx[u] + p_.vy[u] * p_.vy[u]) / p_.inv_mass[u] + p_.omega[u] * p_.omega[u] / p_.inv_inertia[u]);
  return e;
}

double Simulation::strain_energy() const {
  double e = 0;
  const auto stride = static_cast<std::size_t>(b_.stride);
  std::visit(
      [&](const auto& law) {
        for (std::size_t b = 0; b < b_.size(); ++b) {
          if (!b_.active[b]) continue;
          const auto i = static_cast<std::size_t>(b_.i[b]), j = static_cast<std::size_t>(b_.j[b]);
          const double d = std::hypot(p_.x[j] - p_.x[i], p_.y[j] - p_.y[i]);
          const BondKinematics kin{d - b_.ref_distance_m[b], p_.theta[j] - p_.theta[i] - b_.ref_rotation_rad[b], 0};
          e += bond_energy(law, b_.geometry[b], kin, b_.shear_force_n.data() + b * stride, b_.bonded.data() + b * stride);
        }
      },
      material_.joint);
  const double t = opt_.thickness_m;
  std::visit(
      [&](const auto& law) {
        for (std::size_t k = 0; k < pairs_.size(); ++k) {
          const auto i = static_cast<std::size_t>(pairs_[k].i), j = static_cast<std::size_t>(pairs_[k].j);
          const double overlap = p_.radius[i] + p_.radius[j] - std::hypot(p_.x[j] - p_.x[i], p_.y[j] - p_.y[i]);
          e += contact_energy(law, p_.radius[i], p_.radius[j], t, overlap, pair_shear_[k]);
        }
      },
      material_.contact);
  return e;
}

int Simulation::n_touching_pairs() const {
  int n = 0;
  for (const auto& c : pairs_) {
    const auto i = static_cast<std::size_t>(c.i), j = static_cast<std::size_t>(c.j);
    if (std::hypot(p_.x[j] - p_.x[i], p_.y[j] - p_.y[i]) < p_.radius[i] + p_.radius[j]) ++n;
  }
  return n;
}

double Simulation::coordination_number() const {
  std::size_t n_bonds = 0;
  for (auto a : b_.active) n_bonds += a;
  std::size_t n_touching = static_cast<std::size_t>(n_touching_pairs());
  if (std::visit([](const auto& law) { return bond_keeps_contact(law); }, material_.joint)) {
    // A bonded pair that also touches is one contact, not two.
    std::vector<CandidatePair> bonded;
    for (std::size_t b = 0; b < b_.size(); ++b)
      if (b_.active[b]) bonded.push_back({std::min(b_.i[b], b_.j[b]), std::max(b_.i[b], b_.j[b])});
    std::sort(bonded.begin(), bonded.end());
    for (const auto& c : pairs_) {
      const auto i = static_cast<std::size_t>(c.i), j = static_cast<std::size_t>(c.j);
      if (std::hypot(p_.x[j] - p_.x[i], p_.y[j] - p_.y[i]) < p_.radius[i] + p_.radius[j] &&
          std::binary_search(bonded.begin(), bonded.end(), c))
        --n_touching;
    }
  }
  return p_.size() ? 2.0 * static_cast<double>(n_bonds + n_touching) / static_cast<double>(p_.size()) : 0.0;
}

int Simulation::n_contacts_of(std::size_t u) const {
  int n = 0;
  for (std::int32_t k = incidence_start_[u]; k < incidence_start_[u + 1]; ++k) {
    const std::uint32_t entry = incidence_[static_cast<std::size_t>(k)];
    const std::size_t idx = entry >> 3;
    const std::uint32_t kind = (entry >> 1) & 3u;
    if (kind == kBond) {
      n += b_.active[idx];
    } else if (kind == kPair) {
      const auto i = static_cast<std::size_t>(pairs_[idx].i), j = static_cast<std::size_t>(pairs_[idx].j);
      n += std::hypot(p_.x[j] - p_.x[i], p_.y[j] - p_.y[i]) < p_.radius[i] + p_.radius[j];
    } else {
      n += wall_out_[idx][0] != 0 || wall_out_[idx][1] != 0;
    }
  }
  return n;
}

std::array<double, 3> Simulation::average_stress(double area_m2) const {
  // sigma = (1/V) sum over particles and their contacts of f_on_p (x) (x_c - x_p); for a disk pair this is
  // -(1/V) f_on_j (x) (x_j - x_i), independent of where the contact point lies.
  double sxx = 0, syy = 0, sxy = 0;
  const auto add = [&](const std::array<double, 4>& o, std::size_t i, std::size_t j) {
    const double lx = p_.x[j] - p_.x[i], ly = p_.y[j] - p_.y[i];
    sxx -= o[0] * lx, syy -= o[1] * ly, sxy -= 0.5 * (o[0] * ly + o[1] * lx);
  };
  for (std::size_t b = 0; b < b_.size(); ++b)
    if (b_.active[b]) add(b_.out[b], static_cast<std::size_t>(b_.i[b]), static_cast<std::size_t>(b_.j[b]));
  for (std::size_t k = 0; k < pairs_.size(); ++k)
    add(pair_out_[k], static_cast<std::size_t>(pairs_[k].i), static_cast<std::size_t>(pairs_[k].j));
  for (std::size_t k = 0; k < wall_contacts_.size(); ++k) {
    const auto u = static_cast<std::size_t>(wall_contacts_[k][1]);
    const auto q = closest_on_segment(walls_[static_cast<std::size_t>(wall_contacts_[k][0])], p_.x[u], p_.y[u]);
    const double lx = q[0] - p_.x[u], ly = q[1] - p_.y[u];  // to the contact (approximately the wall point)
    const auto& o = wall_out_[k];
    sxx += o[0] * lx, syy += o[1] * ly, sxy += 0.5 * (o[0] * ly + o[1] * lx);
  }
  const double v = area_m2 * opt_.thickness_m;
  return {sxx / v, syy / v, sxy / v};
}

}  // namespace kerf::dem
