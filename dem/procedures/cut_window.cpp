// The active window of a steady-state cut (kerf/dem/procedures/cut_window.hpp).
#include "kerf/dem/procedures/cut_window.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "../engine/serial.hpp"
#include "kerf/dem/procedures/specimen.hpp"
#include "kerf/error.hpp"

namespace kerf::dem {

namespace {
constexpr std::string_view kWindowMagic = "KERFWIN3";  // 2: the absorbing layer in the box; 3: the held rows' layer
}  // namespace

void add_held_rows_layer(const Particles& p, const HeldRows& held, double thickness_m, double peak_rate_per_s,
                         std::vector<double>& rates_per_s) {
  for (std::size_t u = 0; u < p.size(); ++u)
    if (p.group[u] == 0)
      rates_per_s[u] =
          std::max(rates_per_s[u], sponge_rate_per_s(held.distance_m(p.x[u], p.y[u]), thickness_m, peak_rate_per_s));
}

CutWindow::CutWindow(Simulation workpiece, const CutWindowBox& box, double y_top_m, double y_cut_m)
    : full_(std::move(workpiece)), box_(box), y_top_m_(y_top_m), y_cut_m_(y_cut_m) {
  const auto& p = full_.particles();
  if (p.size() == 0) throw ModelError("dem", "a windowed cut of an empty workpiece");
  x0_ = p.x;
  removed_.assign(p.size(), 0);
  x_built_m_ = std::numeric_limits<double>::infinity();
  full_.cracks().clear();  // the cut's cracks only
  index_reservoir();
}

void CutWindow::index_reservoir() {
  const auto& p = full_.particles();
  const auto [r_min, r_max] = std::minmax_element(p.radius.begin(), p.radius.end());
  r_max_m_ = *r_max;
  // Held frame: two largest diameters, the reach of any joint or contact of a disk inside the box.
  frame_m_ = 4 * *r_max;
  skin_m_ = full_.options().skin_m > 0 ? full_.options().skin_m : 0.3 * *r_min;  // as Simulation::initialise
  local_of_.assign(p.size(), -1);
  for (std::size_t u = 0; u < global_of_.size(); ++u)
    local_of_[static_cast<std::size_t>(global_of_[u])] = static_cast<std::int32_t>(u);
  by_x0_.resize(p.size());
  std::iota(by_x0_.begin(), by_x0_.end(), 0);
  std::sort(by_x0_.begin(), by_x0_.end(), [&](std::int32_t a, std::int32_t b) {
    return x0_[static_cast<std::size_t>(a)] != x0_[static_cast<std::size_t>(b)]
               ? x0_[static_cast<std::size_t>(a)] < x0_[static_cast<std::size_t>(b)]
               : a < b;
  });
  // Joints per disk (CSR), each joint under both its disks.
  const auto& b = full_.bonds();
  bond_start_.assign(p.size() + 1, 0);
  for (std::size_t k = 0; k < b.size(); ++k)
    ++bond_start_[static_cast<std::size_t>(b.i[k]) + 1], ++bond_start_[static_cast<std::size_t>(b.j[k]) + 1];
  for (std::size_t u = 0; u < p.size(); ++u) bond_start_[u + 1] += bond_start_[u];
  bond_list_.resize(static_cast<std::size_t>(bond_start_.back()));
  std::vector<std::int32_t> fill(bond_start_.begin(), bond_start_.end() - 1);
  for (std::size_t k = 0; k < b.size(); ++k) {
    bond_list_[static_cast<std::size_t>(fill[static_cast<std::size_t>(b.i[k])]++)] = static_cast<std::int32_t>(k);
    bond_list_[static_cast<std::size_t>(fill[static_cast<std::size_t>(b.j[k])]++)] = static_cast<std::int32_t>(k);
  }
}

void CutWindow::sync(const Simulation& current) {
  const Particles& c = current.particles();
  Particles& q = full_.particles();
  if (c.size() != global_of_.size() || current.bonds().size() != bond_global_of_.size())
    throw ModelError("dem", "windowed cut: the running simulation is not the window's");
  for (std::size_t u = 0; u < c.size(); ++u) {
    const auto g = static_cast<std::size_t>(global_of_[u]);
    q.x[g] = c.x[u], q.y[g] = c.y[u], q.theta[g] = c.theta[u];
    q.vx[g] = c.vx[u], q.vy[g] = c.vy[u], q.omega[g] = c.omega[u];
    max_displacement_m_ = std::max(max_displacement_m_, std::abs(c.x[u] - x0_[g]));
  }
  const BondStore& cb = current.bonds();
  BondStore& fb = full_.bonds();
  for (std::size_t k = 0; k < cb.size(); ++k) {
    const auto g = static_cast<std::size_t>(bond_global_of_[k]);
    fb.active[g] = cb.active[k];
    fb.copy_elements(g, cb, k);
  }
  // The window's cracks not moved yet (sync may run more than once on one window).
  const auto& events = current.cracks();
  for (std::size_t k = cracks_synced_; k < events.size(); ++k) {
    CrackEvent e = events[k];
    e.bond = bond_global_of_[static_cast<std::size_t>(e.bond)];
    full_.cracks().push_back(e);
  }
  cracks_synced_ = events.size();
  ContactSprings s = current.contact_springs();
  for (auto& pair : s.pairs)
    pair = {global_of_[static_cast<std::size_t>(pair.i)], global_of_[static_cast<std::size_t>(pair.j)]};
  for (auto& w : s.wall_contacts) w[1] = global_of_[static_cast<std::size_t>(w[1])];
  springs_ = std::move(s);  // still sorted: the window's disks are in the workpiece's order
  full_.walls() = current.walls();
  full_.set_clock(current.time(), current.step_count());
}

WorkpieceNow workpiece_now(const Simulation& sim) {
  const Particles& p = sim.particles();
  return {p.x, p.y, std::vector<std::uint8_t>(p.size(), 1), sim.tied_to_held()};
}

WorkpieceNow CutWindow::now(const Simulation& current) const {
  const Particles& c = current.particles();
  const Particles& q = full_.particles();
  const BondStore& cb = current.bonds();
  const BondStore& fb = full_.bonds();
  if (c.size() != global_of_.size() || cb.size() != bond_global_of_.size())
    throw ModelError("dem", "windowed cut: the running simulation is not the window's");
  WorkpieceNow w{q.x, q.y, std::vector<std::uint8_t>(q.size()), std::vector<std::uint8_t>(q.size(), 0)};
  for (std::size_t g = 0; g < q.size(); ++g) w.present[g] = !removed_[g];
  for (std::size_t u = 0; u < c.size(); ++u) {
    const auto g = static_cast<std::size_t>(global_of_[u]);
    w.x_m[g] = c.x[u], w.y_m[g] = c.y[u];
  }
  // The joints with a bonded element: the reservoir's, and the running window's where it has them.
  std::vector<std::uint8_t> bonded(fb.size());
  for (std::size_t b = 0; b < fb.size(); ++b) bonded[b] = fb.active[b] && fb.n_bonded_elements(b) > 0;
  for (std::size_t k = 0; k < cb.size(); ++k)
    bonded[static_cast<std::size_t>(bond_global_of_[k])] = cb.active[k] && cb.n_bonded_elements(k) > 0;
  // Breadth-first from every held disk of the workpiece (its group, not the window's frame).
  std::vector<std::size_t> queue;
  for (std::size_t g = 0; g < q.size(); ++g)
    if (q.group[g] != 0 && w.present[g]) w.tied[g] = 1, queue.push_back(g);
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const std::size_t g = queue[head];
    for (auto k = bond_start_[g]; k < bond_start_[g + 1]; ++k) {
      const auto b = static_cast<std::size_t>(bond_list_[static_cast<std::size_t>(k)]);
      if (!bonded[b]) continue;
      const auto other = static_cast<std::size_t>(fb.i[b] == static_cast<std::int32_t>(g) ? fb.j[b] : fb.i[b]);
      if (!w.tied[other] && w.present[other]) w.tied[other] = 1, queue.push_back(other);
    }
  }
  return w;
}

void CutWindow::remove_loose_fragments() {
  // The removed disks are out of the workpiece: no path runs through them, and a crushed grain stays counted as one.
  const auto tied = full_.tied_to_held(removed_);
  const Particles& q = full_.particles();
  for (std::size_t g = 0; g < q.size(); ++g)
    if (!tied[g] && !removed_[g] && q.y[g] > y_cut_m_) removed_[g] = 1;
}

// Long (~150 lines) for a reason: its stages (candidates, roles, disks, joints, springs, absorbing layers, kept
// forces) share global_of_ and local_of_, whose order is the new window's disk order and so fixes its results.
Simulation CutWindow::build(const Simulation* current, double x_edge_m) {
  if (current) sync(*current);
  if (remove_loose_) remove_loose_fragments();
  Particles& q = full_.particles();
  const double x0 = x_edge_m - box_.ahead_m, x1 = x_edge_m + box_.behind_m;
  const double y0 = y_cut_m_ - box_.below_m, y1 = y_top_m_ + box_.above_m, f = frame_m_;

  // Candidates: the disks whose uncut x lies within reach of the box and its frame (a disk written back
  // may have moved by up to max_displacement_m_ since), and the window's own disks (a chip may be anywhere).
  std::vector<std::int32_t> candidates(global_of_);
  const double lo = x0 - f - max_displacement_m_, hi = x1 + f + max_displacement_m_;
  auto first = std::lower_bound(by_x0_.begin(), by_x0_.end(), lo,
                                [&](std::int32_t g, double x) { return x0_[static_cast<std::size_t>(g)] < x; });
  for (auto it = first; it != by_x0_.end() && x0_[static_cast<std::size_t>(*it)] <= hi; ++it) candidates.push_back(*it);
  std::sort(candidates.begin(), candidates.end());
  candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());

  // The forces a step leaves are those of its damped second half kick, which the next step's first half kick
  // uses: the free disks keep them (re-evaluated forces would be undamped; a disk new to the window gets those).
  struct KeptForce {
    std::int32_t global;
    double fx, fy, torque;
  };
  std::vector<KeptForce> kept;
  if (current) {
    const Particles& c = current->particles();
    for (std::size_t u = 0; u < c.size(); ++u)
      if (c.group[u] == 0) kept.push_back({global_of_[u], c.fx[u], c.fy[u], c.torque[u]});
  }
  // Each candidate's role in the new window: free, held (frame) or out; a free disk of the running window
  // that leaves the box more than a largest radius above the cut line is chip or debris (the tool passed
  // there): removed.
  enum Role : std::uint8_t { kOut, kFree, kHeld };
  std::vector<Role> role(candidates.size(), kOut);
  for (std::size_t k = 0; k < candidates.size(); ++k) {
    const auto g = static_cast<std::size_t>(candidates[k]);
    if (removed_[g]) continue;
    const double x = q.x[g], y = q.y[g];
    const bool boundary = q.group[g] != 0;  // the workpiece's held left side and bottom
    const bool in_box = x >= x0 && x <= x1 && y >= y0 && y <= y1;
    const bool was_free =
        current && local_of_[g] >= 0 && current->particles().group[static_cast<std::size_t>(local_of_[g])] == 0;
    if (was_free && !in_box && y > y_cut_m_ + r_max_m_) {
      removed_[g] = 1;
      continue;
    }
    if (!boundary && in_box)
      role[k] = kFree;
    else if (x >= x0 - f && x <= x1 + f && y >= y0 - f && y <= y1 + f)
      role[k] = kHeld;
  }
  for (auto g : global_of_) local_of_[static_cast<std::size_t>(g)] = -1;
  global_of_.clear();
  bond_global_of_.clear();
  std::vector<std::uint8_t> held;
  for (std::size_t k = 0; k < candidates.size(); ++k) {
    const auto gi = candidates[k];
    const auto g = static_cast<std::size_t>(gi);
    if (removed_[g]) continue;
    const bool is_free = role[k] == kFree;
    if (!is_free) q.vx[g] = q.vy[g] = q.omega[g] = 0;  // at rest from now on (until a window frees it)
    if (role[k] == kOut) continue;
    local_of_[g] = static_cast<std::int32_t>(global_of_.size());
    global_of_.push_back(gi);
    held.push_back(is_free ? 0 : 1);
  }
  if (global_of_.empty()) throw ModelError("dem", "windowed cut: no disk inside the window");

  SimulationOptions options = full_.options();
  options.skip_held_pairs = true;
  options.skin_m = skin_m_;
  Simulation sim(full_.material(), options);
  sim.types() = full_.types();
  for (std::size_t u = 0; u < global_of_.size(); ++u) {
    const auto g = static_cast<std::size_t>(global_of_[u]);
    sim.add_particle(q.x[g], q.y[g], q.radius[g], q.type[g]);
    Particles& p = sim.particles();
    p.theta[u] = q.theta[g], p.vx[u] = q.vx[g], p.vy[u] = q.vy[g], p.omega[u] = q.omega[g];
    p.group[u] = held[u];
  }
  for (const Wall& w : full_.walls()) sim.add_wall(w);
  // The joints of the free disks (a joint between two held disks moves nothing), in the workpiece's order.
  const BondStore& fb = full_.bonds();
  for (std::size_t u = 0; u < global_of_.size(); ++u) {
    if (held[u]) continue;
    const auto g = static_cast<std::size_t>(global_of_[u]);
    for (auto k = bond_start_[g]; k < bond_start_[g + 1]; ++k) {
      const auto b = static_cast<std::size_t>(bond_list_[static_cast<std::size_t>(k)]);
      const auto other = static_cast<std::size_t>(fb.i[b] == static_cast<std::int32_t>(g) ? fb.j[b] : fb.i[b]);
      if (fb.active[b] && local_of_[other] >= 0) bond_global_of_.push_back(static_cast<std::int32_t>(b));
    }
  }
  std::sort(bond_global_of_.begin(), bond_global_of_.end());
  bond_global_of_.erase(std::unique(bond_global_of_.begin(), bond_global_of_.end()), bond_global_of_.end());
  for (const auto bg : bond_global_of_) {
    const auto b = static_cast<std::size_t>(bg);
    const auto k = static_cast<std::size_t>(sim.install_bond(local_of_[static_cast<std::size_t>(fb.i[b])],
                                                             local_of_[static_cast<std::size_t>(fb.j[b])],
                                                             fb.ref_distance_m[b], fb.ref_rotation_rad[b]));
    sim.bonds().copy_elements(k, fb, b);
  }
  // The shear springs of the contacts between disks both in the window (sorted again by window index:
  // the same order, the window's disks being in the workpiece's order).
  ContactSprings s;
  for (std::size_t k = 0; k < springs_.pairs.size(); ++k) {
    const auto li = local_of_[static_cast<std::size_t>(springs_.pairs[k].i)];
    const auto lj = local_of_[static_cast<std::size_t>(springs_.pairs[k].j)];
    if (li >= 0 && lj >= 0) s.pairs.push_back({li, lj}), s.pair_shear_N.push_back(springs_.pair_shear_N[k]);
  }
  for (std::size_t k = 0; k < springs_.wall_contacts.size(); ++k) {
    const auto lu = local_of_[static_cast<std::size_t>(springs_.wall_contacts[k][1])];
    if (lu >= 0)
      s.wall_contacts.push_back({springs_.wall_contacts[k][0], lu}), s.wall_shear_N.push_back(springs_.wall_shear_N[k]);
  }
  sim.set_contact_springs(std::move(s));
  sim.set_time_step(full_.time_step());
  sim.set_clock(full_.time(), full_.step_count());
  // The team governor goes on with what it measured (a window is rebuilt more often than it measures).
  sim.set_adaptive_team(full_.adaptive_team());
  if (current) sim.set_team_governor(current->team_governor());
  if (box_.absorbing_m > 0 || box_.held_absorbing_m > 0) {
    // The absorbing layers: a quadratic ramp from 0 at their inner side to the full rate at the box's edge
    // (and at the workpiece's held rows).
    std::vector<double> rates(global_of_.size(), 0.0);
    const Particles& p = sim.particles();
    for (std::size_t u = 0; u < rates.size(); ++u) {
      if (p.group[u] != 0) continue;
      const double d = std::min({p.x[u] - x0, x1 - p.x[u], p.y[u] - y0});
      rates[u] = sponge_rate_per_s(d, box_.absorbing_m, box_.absorbing_rate_per_s);
    }
    if (box_.held_absorbing_m > 0)
      add_held_rows_layer(p, box_.held_rows, box_.held_absorbing_m, box_.held_absorbing_rate_per_s, rates);
    sim.set_absorbing_rates(std::move(rates));
  }
  sim.initialise();
  Particles& p = sim.particles();
  for (const KeptForce& k : kept) {
    const auto u = local_of_[static_cast<std::size_t>(k.global)];
    if (u >= 0 && p.group[static_cast<std::size_t>(u)] == 0)
      p.fx[static_cast<std::size_t>(u)] = k.fx, p.fy[static_cast<std::size_t>(u)] = k.fy,
      p.torque[static_cast<std::size_t>(u)] = k.torque;
  }
  cracks_synced_ = 0;
  x_built_m_ = x_edge_m;
  ++rebuilds_;
  largest_window_ = std::max(largest_window_, global_of_.size());
  return sim;
}

Simulation CutWindow::crush(const Simulation& current, const std::vector<std::size_t>& grains,
                            const std::vector<std::size_t>& tied_disks) {
  for (const auto u : grains) removed_[static_cast<std::size_t>(global_of_[u])] = 2;
  for (const auto u : tied_disks) removed_[static_cast<std::size_t>(global_of_[u])] = 3;
  return build(&current, x_built_m_);
}

Simulation CutWindow::remove_at_edge(const Simulation& current, const std::vector<std::size_t>& tied,
                                     const std::vector<std::size_t>& loose) {
  for (const auto u : tied) removed_[static_cast<std::size_t>(global_of_[u])] = 4;
  for (const auto u : loose) removed_[static_cast<std::size_t>(global_of_[u])] = 5;
  return build(&current, x_built_m_);
}

Simulation CutWindow::machined_workpiece() const {
  std::vector<std::uint8_t> keep(removed_.size());
  for (std::size_t g = 0; g < keep.size(); ++g) keep[g] = !removed_[g];
  Simulation out = copy_disks_and_joints(full_, full_.material(), true, keep);
  for (const Wall& w : full_.walls()) out.add_wall(w);
  out.cracks() = full_.cracks();  // by place (their joint numbers are the whole workpiece's)
  return out;
}

ChipAccount CutWindow::chips() const {
  ChipAccount a;
  const Particles& q = full_.particles();
  for (std::size_t g = 0; g < removed_.size(); ++g)
    if (removed_[g]) {
      ++a.particles, a.mass_kg += 1 / q.inv_mass[g];
      if (removed_[g] == 2) ++a.crushed_grains, a.crushed_mass_kg += 1 / q.inv_mass[g];
      if (removed_[g] == 3) ++a.crushed_tied_disks, a.crushed_tied_mass_kg += 1 / q.inv_mass[g];
      if (removed_[g] == 4) ++a.edge_tied_disks, a.edge_tied_mass_kg += 1 / q.inv_mass[g];
      if (removed_[g] == 5) ++a.edge_loose_disks, a.edge_loose_mass_kg += 1 / q.inv_mass[g];
    }
  const BondStore& b = full_.bonds();
  for (const auto& e : full_.cracks()) {
    const auto k = static_cast<std::size_t>(e.bond);
    if (removed_[static_cast<std::size_t>(b.i[k])] || removed_[static_cast<std::size_t>(b.j[k])]) ++a.cracks;
  }
  return a;
}

std::string CutWindow::serialize() const {
  std::string out(kWindowMagic);
  serial::Out io{out};
  io(full_.serialize(), box_, y_top_m_, y_cut_m_, x_built_m_, max_displacement_m_, x0_, removed_, global_of_,
     bond_global_of_, springs_.pairs, springs_.pair_shear_N, springs_.wall_contacts, springs_.wall_shear_N, rebuilds_,
     largest_window_, cracks_synced_);
  return out;
}

CutWindow CutWindow::deserialize(std::string_view bytes) {
  serial::In io = serial::open_tagged(bytes, kWindowMagic, "window state");
  CutWindow w;
  std::string full;
  io(full, w.box_, w.y_top_m_, w.y_cut_m_, w.x_built_m_, w.max_displacement_m_, w.x0_, w.removed_, w.global_of_,
     w.bond_global_of_, w.springs_.pairs, w.springs_.pair_shear_N, w.springs_.wall_contacts, w.springs_.wall_shear_N,
     w.rebuilds_, w.largest_window_, w.cracks_synced_);
  io.expect_end("window state");
  w.full_ = Simulation::deserialize(full);
  const std::size_t n = w.full_.particles().size();
  const auto in_range = [&](const std::vector<std::int32_t>& v, std::size_t limit) {
    return std::all_of(v.begin(), v.end(),
                       [&](std::int32_t k) { return k >= 0 && static_cast<std::size_t>(k) < limit; });
  };
  if (n == 0 || w.x0_.size() != n || w.removed_.size() != n || !in_range(w.global_of_, n) ||
      !in_range(w.bond_global_of_, w.full_.bonds().size()) ||
      !std::all_of(w.full_.cracks().begin(), w.full_.cracks().end(), [&](const CrackEvent& e) {
        return e.bond >= 0 && static_cast<std::size_t>(e.bond) < w.full_.bonds().size();
      }))
    throw ModelError("dem", "corrupt window state");
  w.index_reservoir();
  return w;
}

}  // namespace kerf::dem
