// The DEM engine's neighbour lists: the unjointed pairs and disk-wall contacts within the skin (their shear springs
// carried over), and each disk's incidence list, whose order fixes the order of the force sums. Rebuilt by the step
// (simulation.cpp) when a disk or wall has moved half the skin.
#include <algorithm>

#include "kerf/dem/engine/simulation.hpp"
#include "kerf/error.hpp"
#include "simulation_internal.hpp"

namespace kerf::dem {

// Long (~90 lines) for a reason: the pairs and wall contacts are rebuilt, then the incidence lists from both in
// the order that fixes the force sums; one function keeps that order in one place.
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
  for (std::size_t k = 0; k < pairs_.size(); ++k)
    put(pairs_[k].i, encode(k, kPair, 0)), put(pairs_[k].j, encode(k, kPair, 1));
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
    if (pair_shear_[k] != 0) s.pairs.push_back(pairs_[k]), s.pair_shear_N.push_back(pair_shear_[k]);
  for (std::size_t k = 0; k < wall_contacts_.size(); ++k)
    if (wall_shear_[k] != 0) s.wall_contacts.push_back(wall_contacts_[k]), s.wall_shear_N.push_back(wall_shear_[k]);
  return s;
}

void Simulation::set_contact_springs(ContactSprings springs) {
  const auto n = static_cast<std::int32_t>(p_.size()), nw = static_cast<std::int32_t>(walls_.size());
  const auto valid = [&](std::int32_t u, std::int32_t limit) { return u >= 0 && u < limit; };
  if (springs.pairs.size() != springs.pair_shear_N.size() ||
      springs.wall_contacts.size() != springs.wall_shear_N.size() ||
      !std::is_sorted(springs.pairs.begin(), springs.pairs.end()) ||
      !std::is_sorted(springs.wall_contacts.begin(), springs.wall_contacts.end()))
    throw ModelError("dem", "contact springs: lists of different lengths or not sorted");
  for (const auto& c : springs.pairs)
    if (!valid(c.i, n) || !valid(c.j, n) || c.i >= c.j) throw ModelError("dem", "contact springs: a pair out of range");
  for (const auto& c : springs.wall_contacts)
    if (!valid(c[0], nw) || !valid(c[1], n)) throw ModelError("dem", "contact springs: a wall contact out of range");
  pairs_ = std::move(springs.pairs);
  pair_shear_ = std::move(springs.pair_shear_N);
  wall_contacts_ = std::move(springs.wall_contacts);
  wall_shear_ = std::move(springs.wall_shear_N);
  need_rebuild_ = true;
}

}  // namespace kerf::dem
