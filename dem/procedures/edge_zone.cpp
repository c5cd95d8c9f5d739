// The edge zone of a windowed cut (issue 54 item 4; CutParams::edge_zone, docs/dem.md "The edge zone"): the tool's
// edge as a sub-grid model. Glass meets a diamond edge through a ductile layer about d_c thick (0.04-0.1 um for
// soda-lime glass), 100-300 times below the disks (docs/physics-glass-edge.md): the disks cannot carry that
// contact, a rigid 20 um disk wedged under the tip carries jams instead (docs/notes/2026-11-29-jams.md). Within the
// zone the analytic side's force on the layer (kerf::edge_force_per_width) acts on the tool while the glass entering
// the zone is intact, its reaction on that glass (Newton's third law); the disks the edge reaches leave the model as
// the layer's chip and powder.
#include <algorithm>
#include <cmath>

#include "kerf/dem/procedures/cutting.hpp"
#include "kerf/error.hpp"

namespace kerf::dem {

namespace {

/// Whether intact joints (a bonded element) tie disk `start` of `sim` to the bulk: to a held disk (the workpiece's
/// held rows, the window's frame) or to a disk more than `bulk_depth_m` below the cut line. A local search, from
/// the disks near the tip: the whole workpiece's (CutWindow::now) costs as much as a sample's 50 steps. Every disk
/// a search visits shares its answer (`known`: 0 unknown, 1 tied, 2 not), so each cluster is searched once.
class LocalTies {
 public:
  LocalTies(const Simulation& sim, double y_cut_m, double bulk_depth_m)
      : p_(sim.particles()), y_bulk_m_(y_cut_m - bulk_depth_m), known_(p_.size(), 0), g_(sim.intact_joint_graph()) {}

  bool tied(std::size_t start) {
    if (known_[start] == 0) {
      std::vector<std::size_t> seen{start};
      known_[start] = 3;  // being searched
      bool bulk = false;
      for (std::size_t head = 0; head < seen.size() && !bulk; ++head) {
        const std::size_t u = seen[head];
        if (p_.group[u] != 0 || p_.y[u] < y_bulk_m_) {
          bulk = true;
          break;
        }
        for (std::size_t k = g_.start[u]; k < g_.start[u + 1]; ++k) {
          const std::size_t v = g_.other[k];
          if (known_[v] == 1) bulk = true;
          if (known_[v] != 0) continue;
          known_[v] = 3;
          seen.push_back(v);
        }
      }
      for (const auto u : seen) known_[u] = bulk ? 1 : 2;
    }
    return known_[start] == 1;
  }

 private:
  const Particles& p_;
  double y_bulk_m_;
  std::vector<std::uint8_t> known_;
  Simulation::JointGraph g_;
};

}  // namespace

EdgeZoneSets edge_zone_sets(const Simulation& sim, std::int32_t first_tool_wall, std::int32_t n_tool_walls,
                            std::array<double, 2> tip_m, double y_cut_m, double reach_m, double bulk_depth_m) {
  const Particles& p = sim.particles();
  LocalTies ties(sim, y_cut_m, bulk_depth_m);
  EdgeZoneSets z;
  std::vector<std::uint8_t> reached(p.size(), 0);
  for (const auto u : tool_contacts_near(sim, first_tool_wall, n_tool_walls, tip_m, reach_m)) {
    if (p.group[u] != 0 || reached[u] || p.y[u] - p.radius[u] >= y_cut_m) continue;
    reached[u] = 1;
    (ties.tied(u) ? z.reached_tied : z.reached_loose).push_back(u);
  }
  for (std::size_t u = 0; u < p.size(); ++u) {
    const double r = p.radius[u];
    if (p.group[u] != 0 || reached[u] || std::abs(p.y[u] - y_cut_m) >= r || p.x[u] - r >= tip_m[0] ||
        std::hypot(p.x[u] - tip_m[0], p.y[u] - tip_m[1]) >= reach_m + r || !ties.tied(u))
      continue;
    z.footprint.push_back(u);
  }
  std::sort(z.reached_tied.begin(), z.reached_tied.end());
  std::sort(z.reached_loose.begin(), z.reached_loose.end());
  return z;
}

bool CutRun::edge_zone_begin_sample() {
  const auto tip = edge();
  // The lateral crack runs ahead of the edge (design 2): the joints across the cut line it has reached break first.
  if (params_.edge_zone.lateral_crack == LateralCrack::ahead_of_edge)
    break_cut_line_ahead(sim_, res_.y_cut_m, tip[0], params_.edge_zone.lateral_crack_length_m);
  const auto sets = [&] {
    return edge_zone_sets(sim_, first_tool_wall_, n_tool_walls_, tip, res_.y_cut_m, params_.edge_zone.radius_m,
                          kEdgeZoneBulkReaches * params_.edge_zone.radius_m);
  };
  EdgeZoneSets z = sets();
  if (!z.reached_tied.empty() || !z.reached_loose.empty()) {
    // What the removed disks held leaves with them (the books); the rebuilt window has other indices.
    take_window(window_->remove_at_edge(sim_, z.reached_tied, z.reached_loose));
    z = sets();
  }
  // A groove's laser-affected layer below the disks' scale (grooves.damage_model edge_zone): where the cut line at
  // the tip lies in it, the edge meets damaged glass, not an intact layer to cut; no force (a bound). The disks it
  // reached have left as its chip all the same (above).
  if (params_.grooves.damage_model == GrooveDamageModel::edge_zone) {
    const auto& box = res_.workpiece_box_m;
    if (in_groove_layer(params_, groove_centres(params_, box[0], box[1]), res_.y_top_m, tip[0], res_.y_cut_m))
      z.footprint.clear();
  }
  // The layer's reaction, shared equally by the footprint's disks: minus the force the layer exerts on the tool.
  std::vector<Simulation::DiskLoad> loads;
  if (!z.footprint.empty()) {
    const double t = sim_.options().thickness_m, n = static_cast<double>(z.footprint.size());
    for (const auto u : z.footprint)
      loads.push_back(
          {u, -params_.edge_zone.cutting_force_N_per_m * t / n, -params_.edge_zone.thrust_force_N_per_m * t / n});
  }
  sim_.set_disk_loads(std::move(loads));
  return !z.footprint.empty();
}

double CutRun::edge_zone_reaction_work_J(const std::vector<std::array<double, 2>>& start_m) const {
  const Particles& p = sim_.particles();
  const auto& loads = sim_.disk_loads();
  if (start_m.size() != loads.size()) throw std::logic_error("edge zone: the loads changed within a sample");
  double work = 0;
  for (std::size_t k = 0; k < loads.size(); ++k)
    work += loads[k].fx_N * (p.x[loads[k].disk] - start_m[k][0]) + loads[k].fy_N * (p.y[loads[k].disk] - start_m[k][1]);
  return work;
}

}  // namespace kerf::dem
