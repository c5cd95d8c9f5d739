// The DEM engine's step, its hot path: the force loops (joints, unjointed contacts, walls) and the gather, breaks
// applied after the loops, velocity-Verlet with Cundall local damping, the absorbing layer's decay, instability
// detection. The engine's other rooms: simulation_setup.cpp (particles, joints, walls, the time step),
// simulation_neighbours.cpp (contact and incidence lists), simulation_state.cpp (the state's bytes),
// simulation_diagnostics.cpp (energies, stresses, counts). Every loop of a step and what it inlines is in this one
// file, as before the split: a function moved to another file could no longer inline into the step.
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
#include <type_traits>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "../laws/flat_joint_simd.hpp"
#include "../laws/softening_flat_joint_simd.hpp"
#include "kerf/error.hpp"
#include "simulation_internal.hpp"

namespace kerf::dem {

namespace {

/// A law's update as its loop calls it: the law's own (bond_update), unless the law has a hand-vectorised path
/// of its own in an internal header (the flat joint's, flat_joint_simd.hpp), which overloads this.
template <class Law>
inline BondResult bond_update_fast(const Law& law, const BondGeometry& geo, const BondKinematics& kin, double* shear,
                                   const std::uint8_t* bonded, BreakMode* breaks) {
  return bond_update(law, geo, kin, shear, bonded, breaks);
}
/// The same for a law with a state per element (BondLawWithState; the softening flat joint's overload:
/// softening_flat_joint_simd.hpp).
template <class Law>
inline BondResult bond_update_fast(const Law& law, const BondGeometry& geo, const BondKinematics& kin, double* shear,
                                   const std::uint8_t* bonded, BreakMode* breaks, double* state) {
  return bond_update(law, geo, kin, shear, bonded, breaks, state);
}

/// Square root of each lane, correctly rounded as std::sqrt (one sqrtpd instead of two sqrtsd on x86-64).
inline v2d lane_sqrt(v2d v) {
#if defined(__SSE2__)
  return _mm_sqrt_pd(v);
#else
  return v2d{std::sqrt(v[0]), std::sqrt(v[1])};
#endif
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

}  // namespace

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

// Long (~90 lines) for a reason: the hot loop; its two passes over a block share the block and the disks'
// pointers, and what it inlines was measured as it stands (docs/performance.md).
template <class Law, bool kViscous, bool kFactors, class... State>
void Simulation::bond_loop(const Law& law, ForceCounts& counts, State*... state) {
  constexpr auto kState = static_cast<std::size_t>(bond_state_size<Law>());  // the law's doubles per element
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
      // Without strength factors the factor is the constant 1, which the compiler folds away (x * 1.0 is x).
      const BondGeometry geo{b_.geometry[b], kFactors ? b_.strength_factor[b] : 1.0};
      BondResult r = bond_update_fast(law, geo, kin, b_.shear_force_N.data() + e0, b_.bonded.data() + e0,
                                      b_.pending.data() + e0, (state + e0 * kState)...);
      n_breaking += r.n_breaking;
      if constexpr (kViscous) {
        // Dashpots beside the bond's springs (not part of its strength test): on disk 2, -c_n v_n n - c_s v_s s.
        const auto i = static_cast<std::size_t>(b_.i[b]), j = static_cast<std::size_t>(b_.j[b]);
        const double dvx = vx[j] - vx[i], dvy = vy[j] - vy[i];
        const double vn = dvx * nx + dvy * ny, vs = dvx * sx + dvy * sy - a2 * om[j] - a1 * om[i];
        const TimeStepStiffness k = bond_time_step_stiffness(law, geo);
        r.normal_force_N += dashpot_coefficient(i, static_cast<std::int64_t>(j), k.normal) * vn;  // tension positive
        r.shear_force_N -= dashpot_coefficient(i, static_cast<std::int64_t>(j), k.shear) * vs;
      }
      // Force on disk 2: -F_n n + F_s s (tension positive pulls disk 2 back towards disk 1).
      out = {-r.normal_force_N * nx + r.shear_force_N * sx, -r.normal_force_N * ny + r.shear_force_N * sy,
             -a1 * r.shear_force_N - r.moment_N_m, -a2 * r.shear_force_N + r.moment_N_m};
      // The law says when a bond carries no force any more and hands its pair over to the unbonded contact.
      if (bond_retires(law, geo, kin, r, block.surface_gap[q], b_.bonded.data() + e0)) {
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
      r.normal_force_N -= dashpot_coefficient(i, static_cast<std::int64_t>(j), ks.normal) * vn;
      r.shear_force_N -= dashpot_coefficient(i, static_cast<std::int64_t>(j), ks.shear) * vs;
    }
    // Force on disk 2: +F_n n (compression pushes it away) + F_s s.
    pair_out_[k] = {r.normal_force_N * nx + r.shear_force_N * sx, r.normal_force_N * ny + r.shear_force_N * sy,
                    -a1 * r.shear_force_N, -a2 * r.shear_force_N};
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
      r.normal_force_N -= dashpot_coefficient(u, -1, ks.normal) * vn;
      r.shear_force_N -= dashpot_coefficient(u, -1, ks.shear) * vs;
    }
    wall_out_[k] = {r.normal_force_N * nx + r.shear_force_N * sx, r.normal_force_N * ny + r.shear_force_N * sy,
                    -a * r.shear_force_N};
  }
}

template <bool kViscous, class Law>
void Simulation::bond_loop_of(const Law& law, ForceCounts& counts) {
  const bool factors = !b_.strength_factor.empty();  // Weibull joint strengths (a loop of their own: see bond_loop)
  if constexpr (BondLawWithState<Law>) {
    if (factors)
      bond_loop<Law, kViscous, true>(law, counts, b_.element_state.data());
    else
      bond_loop<Law, kViscous, false>(law, counts, b_.element_state.data());
  } else {
    if (factors)
      bond_loop<Law, kViscous, true>(law, counts);
    else
      bond_loop<Law, kViscous, false>(law, counts);
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
    std::visit([&](const auto& law) { bond_loop_of<true>(law, counts); }, material_.joint);
    std::visit([&](const auto& law) { pair_loop<std::decay_t<decltype(law)>, true>(law); }, material_.contact);
    std::visit([&](const auto& law) { wall_loop<std::decay_t<decltype(law)>, true>(law); }, material_.contact);
  } else {
    std::visit([&](const auto& law) { bond_loop_of<false>(law, counts); }, material_.joint);
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

void Simulation::break_bond(std::size_t b, BreakMode mode) {
  if (!b_.active[b]) return;
  const auto stride = static_cast<std::size_t>(b_.stride);
  for (std::size_t e = 0; e < stride; ++e)
    if (b_.bonded[b * stride + e]) b_.pending[b * stride + e] = mode;
  need_breaks_ = true;
  apply_breaks();
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
      const ElementPlace place = bond_element_place(law, b_.joint_geometry(b), static_cast<int>(e));
      const double xi = place.centroid_m;
      cracks_.push_back({time_, p_.x[i] + a1 * nx - xi * ny, p_.y[i] + a1 * ny + xi * nx, std::atan2(nx, -ny),
                         place.length_m, b_.pending[k], static_cast<std::int32_t>(b), static_cast<std::int32_t>(e)});
      b_.bonded[k] = 0;
      b_.shear_force_N[k] = 0;              // residual mode: the shear stress of a broken element drops to zero
      if constexpr (BondLawWithState<Law>)  // the law's state of a broken element, as the law says
        bond_element_broken(law, b_.element_state.data() + k * static_cast<std::size_t>(bond_state_size<Law>()));
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
    const bool finite =
        std::isfinite(v2) && std::isfinite(p_.x[u]) && std::isfinite(p_.y[u]) && std::isfinite(p_.omega[u]);
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

void Simulation::set_disk_loads(std::vector<DiskLoad> loads) {
  for (const DiskLoad& l : loads)
    if (l.disk >= p_.size() || !std::isfinite(l.fx_N) || !std::isfinite(l.fy_N))
      throw ModelError("dem", fmt::format("a disk load on disk {} of {} ({}, {} N): a disk that exists, finite forces",
                                          l.disk, p_.size(), l.fx_N, l.fy_N));
  disk_loads_ = std::move(loads);
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
      if (!disk_loads_.empty()) {  // every thread takes the same branch; none when there are no loads
#pragma omp barrier
#pragma omp single
        for (const DiskLoad& l : disk_loads_) p_.fx[l.disk] += l.fx_N, p_.fy[l.disk] += l.fy_N;
      }
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

}  // namespace kerf::dem
