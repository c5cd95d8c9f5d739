// What the DEM engine reports of its state: the forces on held groups, kinetic and stored elastic energy, touching
// pairs, the coordination number, a disk's contacts, the average stress.
#include <algorithm>
#include <cmath>

#include "kerf/dem/engine/simulation.hpp"
#include "simulation_internal.hpp"

namespace kerf::dem {

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
    e += 0.5 *
         ((p_.vx[u] * p_.vx[u] + p_.vy[u] * p_.vy[u]) / p_.inv_mass[u] + p_.omega[u] * p_.omega[u] / p_.inv_inertia[u]);
  return e;
}

double Simulation::stored_elastic_energy() const {
  return joint_and_contact_energy() + wall_contact_energy();
}

double Simulation::joint_and_contact_energy() const {
  double e = 0;
  const auto stride = static_cast<std::size_t>(b_.stride);
  std::visit(
      [&](const auto& law) {
        for (std::size_t b = 0; b < b_.size(); ++b) {
          if (!b_.active[b]) continue;
          const auto i = static_cast<std::size_t>(b_.i[b]), j = static_cast<std::size_t>(b_.j[b]);
          const double d = std::hypot(p_.x[j] - p_.x[i], p_.y[j] - p_.y[i]);
          const BondKinematics kin{d - b_.ref_distance_m[b], p_.theta[j] - p_.theta[i] - b_.ref_rotation_rad[b], 0};
          using Law = std::decay_t<decltype(law)>;
          if constexpr (BondLawWithState<Law>)
            e += bond_energy(law, b_.joint_geometry(b), kin, b_.shear_force_N.data() + b * stride,
                             b_.bonded.data() + b * stride,
                             b_.element_state.data() + b * stride * static_cast<std::size_t>(bond_state_size<Law>()));
          else
            e += bond_energy(law, b_.joint_geometry(b), kin, b_.shear_force_N.data() + b * stride,
                             b_.bonded.data() + b * stride);
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

std::vector<std::pair<std::size_t, double>> Simulation::wall_overlaps() const {
  std::vector<std::pair<std::size_t, double>> touching;
  for (std::size_t k = 0; k < wall_contacts_.size(); ++k) {
    const Wall& w = walls_[static_cast<std::size_t>(wall_contacts_[k][0])];
    const auto u = static_cast<std::size_t>(wall_contacts_[k][1]);
    if (!w.enabled) continue;
    // As wall_loop: the disk against a wall of zero radius.
    const auto q = closest_on_segment(w, p_.x[u], p_.y[u]);
    const double overlap = p_.radius[u] - std::hypot(p_.x[u] - q[0], p_.y[u] - q[1]);
    if (overlap > 0) touching.emplace_back(k, overlap);
  }
  return touching;
}

double Simulation::wall_contact_energy() const {
  double e = 0;
  const double t = opt_.thickness_m;
  std::visit(
      [&](const auto& law) {
        // With the material's law: the wall's own friction does not change the stored energy.
        for (const auto& [k, overlap] : wall_overlaps())
          e += contact_energy(law, p_.radius[static_cast<std::size_t>(wall_contacts_[k][1])], 0.0, t, overlap,
                              wall_shear_[k]);
      },
      material_.contact);
  return e;
}

std::vector<Simulation::WallContactLoad> Simulation::wall_contact_loads() const {
  std::vector<WallContactLoad> loads;
  const double t = opt_.thickness_m;
  std::visit(
      [&](const auto& law) {
        for (const auto& [k, overlap] : wall_overlaps()) {
          const auto u = static_cast<std::size_t>(wall_contacts_[k][1]);
          double shear = wall_shear_[k];  // a copy: no shear increment, the state untouched
          loads.push_back({wall_contacts_[k][0], wall_contacts_[k][1],
                           contact_update(law, p_.radius[u], 0.0, t, overlap, 0.0, shear).normal_force_N});
        }
      },
      material_.contact);
  return loads;
}

Simulation::JointGraph Simulation::intact_joint_graph() const {
  JointGraph g;
  g.start.assign(p_.size() + 1, 0);
  for (std::size_t b = 0; b < b_.size(); ++b)
    if (b_.active[b] && b_.n_bonded_elements(b) > 0)
      ++g.start[static_cast<std::size_t>(b_.i[b]) + 1], ++g.start[static_cast<std::size_t>(b_.j[b]) + 1];
  for (std::size_t u = 0; u < p_.size(); ++u) g.start[u + 1] += g.start[u];
  g.other.resize(g.start.back());
  std::vector<std::size_t> fill(g.start.begin(), g.start.end() - 1);
  for (std::size_t b = 0; b < b_.size(); ++b)
    if (b_.active[b] && b_.n_bonded_elements(b) > 0) {
      g.other[fill[static_cast<std::size_t>(b_.i[b])]++] = static_cast<std::size_t>(b_.j[b]);
      g.other[fill[static_cast<std::size_t>(b_.j[b])]++] = static_cast<std::size_t>(b_.i[b]);
    }
  return g;
}

std::vector<std::uint8_t> Simulation::tied_to_held(std::span<const std::uint8_t> excluded) const {
  const auto out = [&](std::size_t u) { return u < excluded.size() && excluded[u] != 0; };
  const JointGraph g = intact_joint_graph();
  // Breadth-first from every held disk.
  std::vector<std::uint8_t> tied(p_.size(), 0);
  std::vector<std::size_t> queue;
  for (std::size_t u = 0; u < p_.size(); ++u)
    if (p_.group[u] != 0 && !out(u)) tied[u] = 1, queue.push_back(u);
  for (std::size_t head = 0; head < queue.size(); ++head)
    for (std::size_t k = g.start[queue[head]]; k < g.start[queue[head] + 1]; ++k) {
      const auto v = g.other[k];
      if (!tied[v] && !out(v)) tied[v] = 1, queue.push_back(v);
    }
  return tied;
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

Simulation::DiskStresses Simulation::disk_stresses() const {
  const std::size_t n = p_.size();
  DiskStresses out{std::vector<std::array<double, 3>>(n, {0, 0, 0}), std::vector<double>(n, 0.0)};
  // f (x) arm, symmetrised, on disk u (its volume divides at the end).
  const auto add = [&](std::size_t u, double fx, double fy, double ax, double ay) {
    auto& s = out.stress_Pa[u];
    s[0] += fx * ax, s[1] += fy * ay, s[2] += 0.5 * (fx * ay + fy * ax);
    out.force_sum_N[u] += std::hypot(fx, fy);
  };
  // A disk pair: o is the force on j; i gets -o at r_i along the centre line, j gets o at -r_j along it.
  const auto pair = [&](const std::array<double, 4>& o, std::size_t i, std::size_t j) {
    if (o[0] == 0 && o[1] == 0) return;
    const double lx = p_.x[j] - p_.x[i], ly = p_.y[j] - p_.y[i], l = std::hypot(lx, ly);
    if (!(l > 0)) return;
    const double nx = lx / l, ny = ly / l;
    add(i, -o[0], -o[1], p_.radius[i] * nx, p_.radius[i] * ny);
    add(j, o[0], o[1], -p_.radius[j] * nx, -p_.radius[j] * ny);
  };
  for (std::size_t b = 0; b < b_.size(); ++b)
    if (b_.active[b]) pair(b_.out[b], static_cast<std::size_t>(b_.i[b]), static_cast<std::size_t>(b_.j[b]));
  for (std::size_t k = 0; k < pairs_.size(); ++k)
    pair(pair_out_[k], static_cast<std::size_t>(pairs_[k].i), static_cast<std::size_t>(pairs_[k].j));
  for (std::size_t k = 0; k < wall_contacts_.size(); ++k) {
    const auto& o = wall_out_[k];
    if (o[0] == 0 && o[1] == 0) continue;
    const auto u = static_cast<std::size_t>(wall_contacts_[k][1]);
    const auto q = closest_on_segment(walls_[static_cast<std::size_t>(wall_contacts_[k][0])], p_.x[u], p_.y[u]);
    add(u, o[0], o[1], q[0] - p_.x[u], q[1] - p_.y[u]);
  }
  for (std::size_t u = 0; u < n; ++u) {
    const double v = M_PI * p_.radius[u] * p_.radius[u] * opt_.thickness_m;
    for (double& c : out.stress_Pa[u]) c /= v;
  }
  return out;
}

std::array<double, 2> Simulation::joint_force(std::size_t b) const {
  const auto i = static_cast<std::size_t>(b_.i[b]), j = static_cast<std::size_t>(b_.j[b]);
  const double lx = p_.x[j] - p_.x[i], ly = p_.y[j] - p_.y[i], l = std::hypot(lx, ly);
  if (!(l > 0)) return {0, 0};
  const double nx = lx / l, ny = ly / l;
  const auto& o = b_.out[b];  // the force on j: along -n when the joint pulls (tension)
  return {-(o[0] * nx + o[1] * ny), o[1] * nx - o[0] * ny};
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
