// Orthogonal cutting (seed 000, Section 4; physics-dem.md section 4).
// The workpiece and the run (CutRun: its loop, energy books, edge observations); the parameters are cut_params.cpp's,
// the groove and tool geometry cut_geometry.cpp's, the statistics and forces.csv cut_results.cpp's, the state as bytes
// cut_state.cpp's.
#include "kerf/dem/procedures/cutting.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "cut_internal.hpp"
#include "kerf/dem/procedures/specimen.hpp"
#include "kerf/error.hpp"
#include "kerf/units.hpp"

namespace kerf::dem {

namespace {
struct Bounds {
  double x_min = 1e300, x_max = -1e300, y_min = 1e300, y_max = -1e300, r_min = 1e300, r_max = 0;
};
Bounds bounds_of(const Particles& p) {
  Bounds b;
  for (std::size_t i = 0; i < p.size(); ++i) {
    b.x_min = std::min(b.x_min, p.x[i] - p.radius[i]);
    b.x_max = std::max(b.x_max, p.x[i] + p.radius[i]);
    b.y_min = std::min(b.y_min, p.y[i] - p.radius[i]);
    b.y_max = std::max(b.y_max, p.y[i] + p.radius[i]);
    b.r_min = std::min(b.r_min, p.radius[i]);
    b.r_max = std::max(b.r_max, p.radius[i]);
  }
  return b;
}

/// The tool may advance at most this fraction of the smallest disk radius per time step: a contact then
/// builds up over 100 steps or more, and no disk can pass through a tool face between two steps.
constexpr double kMaxToolAdvancePerRadius = 0.01;

/// The cut must be one the disks resolve and the workpiece holds: deeper than the smallest disk radius
/// (a shallower tool passes over the disks' tops and measures nothing); neither the tool nor a groove
/// reaching the held bottom rows (a groove that deep would cut the workpiece into loose columns); and
/// short enough that the tool's leading edge (it starts half a largest radius right of the workpiece)
/// stays off the held left disks (centres within 2 largest radii of the left side, as the bottom rows).
void check_cut_fits_workpiece(const CutParams& p, const Bounds& b) {
  const double held_top_depth_m = b.y_max - b.y_min - 2 * b.r_max;
  const auto above_held_rows = [&](const char* key, double depth_m, const char* what) {
    require(depth_m < held_top_depth_m, key, units::m_to_mm(depth_m),
            std::string(what) + " above the held bottom row (workpiece height " +
                format_value(units::m_to_mm(b.y_max - b.y_min)) + " mm)");
  };
  above_held_rows("cut.depth_of_cut_mm", p.cut.depth_of_cut_m, "a depth of cut");
  if (p.grooves.shape != GrooveShape::none) above_held_rows("grooves.depth_mm", p.grooves.depth_m, "a groove depth");
  require(p.cut.depth_of_cut_m >= b.r_min, "cut.depth_of_cut_mm", units::m_to_mm(p.cut.depth_of_cut_m),
          "a depth of cut of at least the smallest disk radius (" + format_value(units::m_to_um(b.r_min)) +
              " um): a shallower tool passes over the disks' tops; use smaller disks (specimen.radius_min_um, "
              "specimen.radius_max_um)");
  // The layer along the held rows (held_absorbing_depths) must stay below the cut line and off the tool's path.
  const double layer_m = window_box_m(p).held_absorbing_m;
  if (layer_m > 0)
    require(layer_m < held_top_depth_m - p.cut.depth_of_cut_m, "cut.held_absorbing_depths", p.cut.held_absorbing_depths,
            "a layer below the cut line: thinner than " +
                format_value((held_top_depth_m - p.cut.depth_of_cut_m) / p.cut.depth_of_cut_m) + " depths of cut (" +
                format_value(units::m_to_mm(held_top_depth_m - p.cut.depth_of_cut_m)) +
                " mm, the distance from the held bottom rows to the cut line)");
  const double width = b.x_max - b.x_min, max_travel = width - 2.5 * b.r_max - layer_m;
  require(p.cut.length_m <= max_travel, "cut.length_mm", units::m_to_mm(p.cut.length_m),
          "a travel of at most " + format_value(units::m_to_mm(max_travel)) +
              " mm: further on, the tool would reach the held left disks" +
              (layer_m > 0 ? " (or their absorbing layer)" : "") + " of the " + format_value(units::m_to_mm(width)) +
              " mm long workpiece");
}

/// The held rows of the workpiece cut from a specimen of bounds `b` (make_workpiece).
HeldRows held_rows_of(const Bounds& b) {
  return {b.x_min + 2 * b.r_max, b.y_min + 2 * b.r_max};
}

/// A groove pattern that removes no disk is not a grooved workpiece: either no groove lies on the surface
/// (the pitch) or none is wide enough to hold a disk's centre (the width).
void check_grooves_remove_disks(const CutParams& p, const Bounds& b, std::size_t n_removed) {
  if (p.grooves.shape == GrooveShape::none || n_removed > 0) return;
  require(!groove_centres(p, b.x_min, b.x_max).empty(), "grooves.pitch_mm", units::m_to_mm(p.grooves.pitch_m),
          "a pitch that puts at least one groove on the " + format_value(units::m_to_mm(b.x_max - b.x_min)) +
              " mm long workpiece");
  throw InputError("grooves.width_mm", format_value(units::m_to_mm(p.grooves.width_m)),
                   "a groove wide enough to remove disks (no disk centre lies inside any groove; disk radii " +
                       format_value(units::m_to_um(b.r_min)) + "-" + format_value(units::m_to_um(b.r_max)) + " um)");
}

/// The tool speed against the time step: fast enough to finish within kMaxRunSteps, slow enough to
/// advance at most kMaxToolAdvancePerRadius of the smallest radius per step.
void check_tool_speed(const CutParams& p, double time_step_s, double time_step_safety, double r_min_m) {
  const double fastest = kMaxToolAdvancePerRadius * r_min_m / time_step_s;
  const double slowest = p.cut.length_m / (kMaxRunSteps * time_step_s);
  const std::string step = format_value(time_step_s * 1e9) + " ns";
  require(p.cut.speed_m_per_s <= fastest, "cut.speed_m_per_s", p.cut.speed_m_per_s,
          "a speed of at most " + format_value(fastest) + " m/s: the tool may advance at most " +
              format_value(100 * kMaxToolAdvancePerRadius) + " % of the smallest disk radius (" +
              format_value(units::m_to_um(r_min_m)) + " um) per time step (" + step + ")");
  refuse_small_time_step_safety(p.cut.length_m / (p.cut.speed_m_per_s * time_step_s), time_step_s, time_step_safety);
  require(p.cut.speed_m_per_s >= slowest, "cut.speed_m_per_s", p.cut.speed_m_per_s,
          "a speed of at least " + format_value(slowest) + " m/s: slower, the travel of " +
              format_value(units::m_to_mm(p.cut.length_m)) + " mm takes more than " + format_value(kMaxRunSteps) +
              " time steps of " + step + " (the seed's 4.23 mm/s is scaled up in every DEM cut; docs/dem.md)");
}
}  // namespace

Simulation make_workpiece(const Simulation& specimen, const CutParams& params, std::size_t& n_removed) {
  const auto& p = specimen.particles();
  const Bounds b = bounds_of(p);
  const HeldRows held = held_rows_of(b);
  const auto centres = groove_centres(params, b.x_min, b.x_max);
  // Grooves: the paper deletes the disks inside each groove (seed 000 Section 4); a disk goes when its
  // centre lies inside the outline.
  std::vector<std::uint8_t> keep(p.size());
  for (std::size_t k = 0; k < p.size(); ++k) keep[k] = !inside_any_groove(params, centres, b.y_max, p.x[k], p.y[k]);
  Simulation sim = copy_disks_and_joints(specimen, specimen.material(), true, keep);
  n_removed = p.size() - sim.particles().size();
  // Seed 000 Section 4: the particles on the left side and the bottom are fixed (zero prescribed
  // velocity, group 1); the top is free. "On the side" = centre within 2 R_max of the edge, as the grips.
  auto& q = sim.particles();
  for (std::size_t k = 0; k < q.size(); ++k) {
    q.group[k] = 0;  // whatever the specimen held (a test's grips)
    if (q.x[k] < held.x_m || q.y[k] < held.y_m) {
      q.group[k] = 1;
      q.vx[k] = q.vy[k] = q.omega[k] = 0;
    }
  }
  return sim;
}

std::vector<std::size_t> tool_contacts_near(const Simulation& sim, std::int32_t first_tool_wall,
                                            std::int32_t n_tool_walls, std::array<double, 2> tip_m, double reach_m) {
  const Particles& p = sim.particles();
  std::vector<std::size_t> near;
  for (const auto& c : sim.wall_contact_loads()) {
    if (c.wall < first_tool_wall || c.wall >= first_tool_wall + n_tool_walls) continue;
    const Wall& w = sim.walls()[static_cast<std::size_t>(c.wall)];
    const auto u = static_cast<std::size_t>(c.disk);
    const double ex = w.x1 - w.x0, ey = w.y1 - w.y0, len2 = ex * ex + ey * ey;
    const double s = len2 > 0 ? std::clamp(((p.x[u] - w.x0) * ex + (p.y[u] - w.y0) * ey) / len2, 0.0, 1.0) : 0.0;
    if (std::hypot(w.x0 + s * ex - tip_m[0], w.y0 + s * ey - tip_m[1]) <= reach_m) near.push_back(u);
  }
  return near;
}

EdgeMeets edge_meets(const Simulation& sim, std::int32_t first_tool_wall, std::int32_t n_tool_walls,
                     std::array<double, 2> tip_m, const std::vector<std::uint8_t>& tied) {
  bool loose = false;
  for (const auto u : tool_contacts_near(sim, first_tool_wall, n_tool_walls, tip_m, kEdgeZoneM)) {
    if (tied[u]) return EdgeMeets::tied;
    loose = true;
  }
  return loose ? EdgeMeets::loose : EdgeMeets::nothing;
}

void add_tied_profile(const WorkpieceNow& now, std::array<double, 2> tip_m, double y_cut_m, TiedProfile& into) {
  for (std::size_t g = 0; g < now.present.size(); ++g) {
    if (!now.present[g]) continue;
    const double depth = y_cut_m - now.y_m[g];
    if (!(depth >= kTiedBandDepthM.front() && depth < kTiedBandDepthM.back())) continue;
    const double dx = now.x_m[g] - tip_m[0];  // the tool moves in -x: ahead is dx < 0
    const double along = std::abs(dx);
    if (!(along >= kTiedStretchM[0] && along < kTiedStretchM[1])) continue;
    const std::size_t side = dx < 0 ? 0 : 1;
    std::size_t band = 0;
    while (depth >= kTiedBandDepthM[band + 1]) ++band;
    ++into.disks[side][band];
    into.tied[side][band] += now.tied[g];
  }
}

CutWindowBox window_box_m(const CutParams& p) {
  const double d = p.cut.depth_of_cut_m;
  CutWindowBox box{p.window.ahead_depths * d, p.window.behind_depths * d, p.window.below_depths * d,
                   p.window.above_depths * d, p.window.shift_depths * d};
  if (p.window.absorbing_depths > 0) box.absorbing_m = p.window.absorbing_depths * d;
  box.held_absorbing_m = p.cut.held_absorbing_depths * d;
  return box;
}

CutRun::CutRun(const Simulation& specimen, const CutParams& params)
    : sim_(specimen.material(), specimen.options()), params_(params) {
  validate_cut_params(params_);
  const Bounds b0 = bounds_of(specimen.particles());
  check_cut_fits_workpiece(params_, b0);
  sim_ = make_workpiece(specimen, params_, res_.n_removed_by_grooves);
  check_grooves_remove_disks(params_, b0, res_.n_removed_by_grooves);
  res_.y_top_m = b0.y_max;
  res_.workpiece_box_m = {b0.x_min, b0.x_max, b0.y_min, b0.y_max};
  res_.groove_damage_joints = apply_groove_damage(sim_, params_, res_.workpiece_box_m);
  res_.y_cut_m = b0.y_max - params_.cut.depth_of_cut_m;
  if (params_.edge_zone.lateral_crack == LateralCrack::whole_cut_line)
    res_.cut_line_joints_broken = separate_cut_line(sim_, res_.y_cut_m);
  res_.width_m = sim_.options().thickness_m;
  // The tool starts with the part that meets the workpiece first (its left-most point between the cut
  // line and the top surface: the rake face at the surface for a negative rake) half a largest radius
  // right of the workpiece, so the travel is not spent in the air. It moves in -x.
  auto outline = tool_outline(params_, 0, res_.y_cut_m);
  const double shift = b0.x_max + 0.5 * b0.r_max - leading_x_in_band(outline, res_.y_cut_m, res_.y_top_m);
  for (auto& q : outline) q[0] += shift;
  first_tool_wall_ = static_cast<std::int32_t>(sim_.walls().size());
  for (std::size_t k = 0; k < outline.size(); ++k) {
    const auto& a = outline[k];
    const auto& e = outline[(k + 1) % outline.size()];
    Wall face{a[0], a[1], e[0], e[1], -params_.cut.speed_m_per_s, 0};
    face.friction_coefficient = params_.tool.friction_coefficient;
    sim_.add_wall(face);
  }
  n_tool_walls_ = static_cast<std::int32_t>(outline.size());
  sim_.invalidate_neighbours();
  sim_.initialise();
  check_tool_speed(params_, sim_.time_step(), sim_.options().time_step_safety, b0.r_min);
  if (params_.edge_zone.enabled) {
    if (params_.edge_zone.radius_m == 0) params_.edge_zone.radius_m = 2 * b0.r_max;  // stored with the parameters
    require(params_.edge_zone.cutting_force_N_per_m >= 0, "edge_zone.cutting_force_N_per_mm",
            units::n_per_m_to_n_per_mm(params_.edge_zone.cutting_force_N_per_m),
            "the layer's force per unit width, given or computed from the material by the cut kind, >= 0");
  }
  sim_.cracks().clear();  // only the cut's cracks count
  t0_ = sim_.time();
  res_.n_particles = sim_.particles().size();
  res_.time_step_s = sim_.time_step();
  res_.samples.push_back({0, 0, 0, 0});
  // A sponge layer's peak rate for its thickness L: the amplitude decays at gamma / 2 in time, gamma / (2 c)
  // in space; through the quadratic ramp and back, exp(-gamma_max L / (3 c)) = exp(-attenuation).
  const auto peak_rate_per_s = [&](double thickness_m) {
    return 3 * params_.window.absorbing_attenuation * p_wave_speed_m_per_s(sim_.material()) / thickness_m;
  };
  const HeldRows held = held_rows_of(b0);
  CutWindowBox box = window_box_m(params_);
  const double held_layer_m = box.held_absorbing_m;
  if (params_.window.enabled) {
    // The workpiece becomes the window's reservoir; its time step (of the whole workpiece) is every window's.
    if (box.absorbing_m > 0) box.absorbing_rate_per_s = peak_rate_per_s(box.absorbing_m);
    if (held_layer_m > 0) {
      box.held_absorbing_rate_per_s = peak_rate_per_s(held_layer_m);
      box.held_rows = held;
    }
    const double x_edge = edge()[0];
    window_.emplace(std::move(sim_), box, res_.y_top_m, res_.y_cut_m);
    window_->set_remove_loose_fragments(params_.window.remove_loose_fragments);
    sim_ = window_->build(nullptr, x_edge);
  } else if (held_layer_m > 0) {
    // Every disk active: the layer along the held rows is set once (no disk joins or leaves the cut).
    std::vector<double> rates(sim_.particles().size(), 0.0);
    add_held_rows_layer(sim_.particles(), held, held_layer_m, peak_rate_per_s(held_layer_m), rates);
    sim_.set_absorbing_rates(std::move(rates));
  }
}

std::array<double, 2> CutRun::edge() const {
  return tool_edge(sim_, first_tool_wall_, n_tool_walls_);
}

std::array<double, 2> tool_edge(const Simulation& sim, std::int32_t first_tool_wall, std::int32_t n_tool_walls) {
  const auto& walls = sim.walls();
  double y_low = std::numeric_limits<double>::infinity(), x_edge = y_low;
  for (std::int32_t w = 0; w < n_tool_walls; ++w) {
    const Wall& face = walls[static_cast<std::size_t>(first_tool_wall + w)];
    for (const auto& [x, y] : {std::pair{face.x0, face.y0}, std::pair{face.x1, face.y1}}) {
      if (y < y_low - 1e-12)
        y_low = y, x_edge = x;
      else if (y < y_low + 1e-12)
        x_edge = std::min(x_edge, x);
    }
  }
  return {x_edge, y_low};
}

std::size_t CutRun::n_cracks() const {
  // A window's cracks are moved to its reservoir when it is rebuilt.
  return window_ ? window_->cracks().size() + sim_.cracks().size() : sim_.cracks().size();
}

namespace {
/// The books between two moments (CutEnergy's balance).
CutEnergy cut_energy_between(const CutEnergyBooks& from, const CutEnergyBooks& to) {
  CutEnergy e;
  e.tool_work_J = to.tool_work_J - from.tool_work_J;
  e.left_kinetic_J = to.left_kinetic_J - from.left_kinetic_J;
  e.left_strain_J = to.left_strain_J - from.left_strain_J;
  e.stored_change_J = (to.kinetic_J + to.strain_J) - (from.kinetic_J + from.strain_J);
  e.dissipated_J = e.tool_work_J - e.left_kinetic_J - e.left_strain_J - e.stored_change_J;
  return e;
}
}  // namespace

CutEnergyBooks CutRun::books_now() const {
  CutEnergyBooks b = books_;
  b.kinetic_J = sim_.kinetic_energy();
  b.strain_J = sim_.stored_elastic_energy();
  return b;
}

void CutRun::crush_grains() {
  // The disks a tool face presses with more than their splitting load F = pi sigma r t, sigma the loose grains'
  // (CutParams::ActiveWindow::grain_strength_Pa) or the tied disks' (tied_grain_strength_Pa); 0 is never.
  const double loose_Pa = params_.window.grain_strength_Pa, tied_Pa = params_.window.tied_grain_strength_Pa;
  const double weakest_Pa = loose_Pa > 0 && tied_Pa > 0 ? std::min(loose_Pa, tied_Pa) : std::max(loose_Pa, tied_Pa);
  const auto& p = sim_.particles();
  const double t = sim_.options().thickness_m;
  const auto splitting_load_N = [&](std::size_t u, double strength_Pa) {
    return std::numbers::pi * strength_Pa * p.radius[u] * t;
  };
  std::vector<std::pair<std::size_t, double>> pressed;  // disk, its largest tool load
  for (const auto& c : sim_.wall_contact_loads()) {
    const auto u = static_cast<std::size_t>(c.disk);
    if (c.wall >= first_tool_wall_ && c.wall < first_tool_wall_ + n_tool_walls_ && p.group[u] == 0 &&
        c.normal_force_N > splitting_load_N(u, weakest_Pa))
      pressed.emplace_back(u, c.normal_force_N);
  }
  if (pressed.empty()) return;
  // Each against its own strength: a loose fragment's disk as a grain, a disk tied to the workpiece as one.
  const auto tied = sim_.tied_to_held();
  std::vector<std::size_t> grains, tied_disks;
  for (const auto& [u, load_N] : pressed) {
    const double strength_Pa = tied[u] ? tied_Pa : loose_Pa;
    if (strength_Pa > 0 && load_N > splitting_load_N(u, strength_Pa)) (tied[u] ? tied_disks : grains).push_back(u);
  }
  if (grains.empty() && tied_disks.empty()) return;
  for (auto* list : {&grains, &tied_disks}) {
    std::sort(list->begin(), list->end());
    list->erase(std::unique(list->begin(), list->end()), list->end());
  }
  take_window(window_->crush(sim_, grains, tied_disks));  // what the crushed disks held leaves with them
}

void CutRun::take_window(Simulation next) {
  // What the disks leaving the integration take with them (less what joining disks bring): the books. `next` was
  // built from sim_ without changing it.
  const CutEnergyBooks before = books_now();
  sim_ = std::move(next);
  const CutEnergyBooks after = books_now();
  books_.left_kinetic_J += before.kinetic_J - after.kinetic_J;
  books_.left_strain_J += before.strain_J - after.strain_J;
}

bool CutRun::advance() {
  if (finished_) return false;
  const auto start = std::chrono::steady_clock::now();
  if (window_) {
    const double x_edge = edge()[0];
    if (window_->due(x_edge)) take_window(window_->build(&sim_, x_edge));
  }
  // The edge zone: the layer's force on the tool while the edge meets intact glass, its reaction on that glass.
  const bool zone_on = params_.edge_zone.enabled && edge_zone_begin_sample();
  const double t = sim_.options().thickness_m;
  const double zone_fx = zone_on ? params_.edge_zone.cutting_force_N_per_m * t : 0.0;
  const double zone_fy = zone_on ? params_.edge_zone.thrust_force_N_per_m * t : 0.0;
  std::vector<std::array<double, 2>> loaded_at;
  for (const auto& l : sim_.disk_loads()) loaded_at.push_back({sim_.particles().x[l.disk], sim_.particles().y[l.disk]});
  res_.particle_steps += static_cast<double>(sim_.particles().size()) * params_.cut.sample_every_steps;
  double fx = 0, fy = 0;
  const auto& walls = sim_.walls();
  for (int s = 0; s < params_.cut.sample_every_steps; ++s) {
    sim_.step();
    for (std::int32_t w = 0; w < n_tool_walls_; ++w) {
      fx += walls[static_cast<std::size_t>(first_tool_wall_ + w)].fx;
      fy += walls[static_cast<std::size_t>(first_tool_wall_ + w)].fy;
    }
    if (zone_on) fx += zone_fx, fy += zone_fy;
  }
  const double reaction_work_J = zone_on ? edge_zone_reaction_work_J(loaded_at) : 0.0;
  if (window_ && (params_.window.grain_strength_Pa > 0 || params_.window.tied_grain_strength_Pa > 0)) crush_grains();
  const auto f = tool_force_components(fx / params_.cut.sample_every_steps, fy / params_.cut.sample_every_steps);
  const double elapsed = sim_.time() - t0_, travel = params_.cut.speed_m_per_s * elapsed;
  res_.samples.push_back({travel, elapsed, f[0], f[1]});
  const bool steady = travel >= params_.cut.entry_fraction * params_.cut.length_m;  // past the entry
  // What the edge meets: once per kEdgeObserveTravelM of travel over the steady part (it changes nothing).
  if (edge_kept_ && steady) {
    const auto step = static_cast<std::int64_t>(std::floor(travel / kEdgeObserveTravelM));
    if (step > edge_last_step_) {
      edge_last_step_ = step;
      observe_edge();
    }
  }
  // The tool moves at -speed in x; the disks push it with fx each step: it does fx speed dt of work on them.
  books_.tool_work_J += fx * params_.cut.speed_m_per_s * sim_.time_step();
  if (params_.edge_zone.enabled && steady) {
    CutEdgeZoneRecord& z = res_.edge_zone;
    ++z.samples;
    z.intact_samples += zone_on;
    if (steady_booked_) {  // the books' steady part starts after its first sample
      z.tool_work_J += zone_fx * params_.cut.sample_every_steps * params_.cut.speed_m_per_s * sim_.time_step();
      z.reaction_work_J += reaction_work_J;
    }
  }
  if (books_kept_ && !steady_booked_ && steady) {
    books_steady_start_ = books_now();
    steady_booked_ = true;
  }
  res_.steps = sim_.step_count();
  res_.wall_time_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (travel >= params_.cut.length_m) finish();
  return !finished_;
}

std::vector<std::uint8_t> CutRun::tied_of(const WorkpieceNow& now) const {
  std::vector<std::uint8_t> tied(sim_.particles().size());
  for (std::size_t u = 0; u < tied.size(); ++u)
    tied[u] = now.tied[window_ ? static_cast<std::size_t>(window_->workpiece_index(u)) : u];
  return tied;
}

void CutRun::observe_edge() {
  const auto tip = edge();
  const WorkpieceNow now = window_ ? window_->now(sim_) : workpiece_now(sim_);
  const std::vector<std::uint8_t> tied = tied_of(now);
  CutEdgeRecord& e = res_.edge;
  ++e.observations;
  switch (edge_meets(sim_, first_tool_wall_, n_tool_walls_, tip, tied)) {
    case EdgeMeets::tied:
      ++e.touches_tied;
      break;
    case EdgeMeets::loose:
      ++e.touches_loose;
      break;
    case EdgeMeets::nothing:
      break;
  }
  add_tied_profile(now, tip, res_.y_cut_m, e.profile);
}

void CutRun::finish() {
  finished_ = true;
  const double steady_from_m = params_.cut.entry_fraction * params_.cut.length_m;
  steady_statistics(res_, steady_from_m);
  res_.travel_windows = travel_window_means(res_.samples, params_.cut.length_m, params_.cut.window_m);
  const double x_edge = edge()[0];
  // It was (final travel - steady start) further right when the steady part began.
  res_.steady_machined_x_m = {x_edge, x_edge + res_.samples.back().travel_m - steady_from_m};
  if (window_) {
    window_->sync(sim_);
    res_.window = {window_->rebuilds(), window_->largest_window(), window_->chips()};
  }
  res_.cracks = count_cut_cracks(cracks(), res_.y_cut_m, res_.steady_machined_x_m);
  res_.energy_booked = books_kept_ && steady_booked_;
  res_.edge_recorded = edge_kept_;
  if (res_.energy_booked) res_.energy = cut_energy_between(books_steady_start_, books_now());
}

}  // namespace kerf::dem
