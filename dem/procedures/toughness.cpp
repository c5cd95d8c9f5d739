// The fracture-toughness test: SENB in three-point bending (kerf/dem/procedures/toughness.hpp; issue 37).
#include "kerf/dem/procedures/toughness.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>

#include "kerf/dem/procedures/specimen.hpp"
#include "kerf/error.hpp"
#include "kerf/units.hpp"

namespace kerf::dem {

namespace {
/// Each roller is an arc of this many wall segments spanning kRollerArcRad either side of its contact point.
constexpr int kRollerSegments = 8;
constexpr double kRollerArcRad = 40 * std::numbers::pi / 180;
/// The notch leaves at least this many largest-disk diameters of ligament.
constexpr double kMinLigamentDiameters = 4;
}  // namespace

const FieldTable<ToughnessSpec>& toughness_fields() {
  using T = ToughnessSpec;
  static const FieldTable<ToughnessSpec> table{
      number_field(
          "notch_depth_mm", units::kMm, Range::positive(),
          "depth a of the notch (a slot one disk wide: the disks within R_max of the notch line removed) from the "
          "beam's tension face at "
          "mid-span; a / W in [0.1, 0.8] with W = specimen.height_mm",
          &T::notch_depth_m),
      number_field("roller_radius_mm", units::kMm, Range::positive(),
                   "radius of the three rigid rollers (walls; below W / 2); the span is S = 4 W (ASTM E399)",
                   &T::roller_radius_m),
      number_field("speed_m_per_s", units::kSi("m/s"), Range{0.0, 10.0, true, false},
                   "speed of the load roller (the supports stand still)", &T::speed_m_per_s),
      number_field(
          "stop_fraction_of_peak", units::kNone, Range::open(0.0, 1.0),
          "stop once the load has stayed below this fraction of the peak over peak_window_um (the ligament broken "
          "through)",
          &T::stop_fraction),
      number_field("max_deflection_um", units::kUm, Range::positive(), "stop anyway at this load-point deflection",
                   &T::max_deflection_m),
      number_field("peak_window_um", units::kUm, Range::positive(),
                   "K_IC from the peak of the load averaged over this much deflection (centred moving average; the "
                   "load on a rigid roller rings in an undamped glass)",
                   &T::peak_window_m),
      number_field("youngs_modulus_GPa", units::kGPa, Range::positive(),
                   "E' of the 2D model for the check K_IC^2 / E' against G_c: the glass's calibrated in-plane E "
                   "(Yang et al. 2018, Table 2 for the shipped glasses)",
                   &T::youngs_modulus_Pa),
      int_field("sample_every_steps", 1, 1000000, "steps per curve sample", &T::sample_every_steps),
      bool_field("quasi_static_check", "rerun at half the speed and report the change of the peak load",
                 &T::quasi_static_check)};
  return table;
}

void check_toughness_spec(const ToughnessSpec& spec, const SpecimenSpec& specimen, const ToughnessKeys& keys) {
  with_path(keys.section, [&] { check_fields(toughness_fields(), spec); });
  const double w = specimen.height_m, a = spec.notch_depth_m;
  const double mm = units::m_to_mm(1.0);
  const std::string notch = keys.section + ".notch_depth_mm";
  if (a >= w)
    throw InputError(notch, format_value(a * mm),
                     "a notch shorter than the beam's depth " + keys.depth + " = " + format_value(w * mm) + " mm");
  if (a < 0.1 * w || a > 0.8 * w)
    throw InputError(notch, format_value(a * mm),
                     "a / W in [0.1, 0.8] with W = " + keys.depth + " = " + format_value(w * mm) + " mm");
  if (w - a < kMinLigamentDiameters * 2 * specimen.radius_max_m)
    throw InputError(notch, format_value(a * mm),
                     "a ligament W - a of at least " + format_value(kMinLigamentDiameters) +
                         " disk diameters (2 specimen.radius_max_um)");
  const double span = kSenbSpanOverDepth * w;
  if (span <= a)  // cannot happen while a < W; kept as the relation the test rests on
    throw InputError(keys.depth, format_value(w * mm), "a span 4 W longer than the notch");
  const double length = span + 2 * kSenbOverhangOverDepth * w;
  if (specimen.width_m < length * (1 - 1e-9))
    throw InputError(keys.length, format_value(specimen.width_m * mm),
                     "a beam at least " + format_value(length * mm) + " mm long: the span S = 4 W = " +
                         format_value(span * mm) + " mm (ASTM E399) and 0.1 W beyond each support");
  if (spec.roller_radius_m >= 0.5 * w)
    throw InputError(keys.section + ".roller_radius_mm", format_value(spec.roller_radius_m * mm),
                     "a roller radius below W / 2 = " + format_value(0.5 * w * mm) + " mm");
}

double senb_geometry_factor(double x) {
  // Srawley 1976, Eq. 2 (S = 4W); ASTM E399 A3.5.3.
  const double poly = 1.99 - x * (1 - x) * (2.15 - 3.93 * x + 2.7 * x * x);
  return 3 * std::sqrt(x) * poly / (2 * (1 + 2 * x) * std::pow(1 - x, 1.5));
}

double senb_stress_intensity(double load_N, double span_m, double thickness_m, double depth_m, double notch_m) {
  return load_N * span_m / (thickness_m * std::pow(depth_m, 1.5)) * senb_geometry_factor(notch_m / depth_m);
}

// Long (~90 lines) for a reason: the beam's set-up in order (the notch, the rollers, the crack's neighbourhood),
// each stage on the specimen the one before left.
ToughnessRun::ToughnessRun(const Simulation& specimen, const ToughnessSpec& spec) : sim_(specimen), spec_(spec) {
  const auto& p0 = specimen.particles();
  const std::size_t n0 = p0.size();
  double x_min = 1e300, x_max = -1e300, y_min = 1e300, y_max = -1e300, r_max = 0;
  for (std::size_t i = 0; i < n0; ++i) {
    x_min = std::min(x_min, p0.x[i] - p0.radius[i]), x_max = std::max(x_max, p0.x[i] + p0.radius[i]);
    y_min = std::min(y_min, p0.y[i] - p0.radius[i]), y_max = std::max(y_max, p0.y[i] + p0.radius[i]);
    r_max = std::max(r_max, p0.radius[i]);
  }
  const double w = y_max - y_min, xc = 0.5 * (x_min + x_max), a = spec.notch_depth_m;
  res_.depth_m = w;
  res_.length_m = x_max - x_min;
  res_.span_m = kSenbSpanOverDepth * w;
  res_.thickness_m = sim_.options().thickness_m;
  res_.notch_m = a;
  res_.notch_x_m = xc;
  if (res_.length_m < res_.span_m + 2 * r_max)
    throw ModelError("dem", "toughness test: the beam is shorter than its span 4 W");
  // The notch: a slot one disk wide, from the tension face to y_min + a: the disks whose centres lie within
  // R_max of x = xc below y_min + a are removed (no joint crosses the line there: two kept disks either side
  // are at least 2 R_max apart). Not retired joints: a genesis locks overlaps into its stress-free joints
  // (floaters enlarged), and unjointing them hands that overlap to the contact law at once, a burst of
  // kinetic energy that breaks joints at the notch before any load (docs/dem.md, "Fracture toughness").
  const double y_notch_top = y_min + a;
  std::vector<std::uint8_t> keep(n0, 1);
  for (std::size_t i = 0; i < n0; ++i)
    if (std::abs(p0.x[i] - xc) < r_max && p0.y[i] < y_notch_top) keep[i] = 0, ++res_.n_notch_disks;
  sim_ = copy_disks_and_joints(specimen, specimen.material(), /*source_types=*/true, keep);
  sim_.set_adaptive_team(specimen.adaptive_team());
  const auto& p = sim_.particles();
  const std::size_t n = p.size();
  // A joint that still crosses the notch's line (a pair farther apart than 2 R_max: none within the usual
  // installation gap) is retired.
  auto& b = sim_.bonds();
  for (std::size_t k = 0; k < b.size(); ++k) {
    if (!b.active[k]) continue;
    const auto i = static_cast<std::size_t>(b.i[k]), j = static_cast<std::size_t>(b.j[k]);
    if ((p.x[i] - xc) * (p.x[j] - xc) >= 0) continue;
    const double s = (xc - p.x[i]) / (p.x[j] - p.x[i]);
    if (p.y[i] + s * (p.y[j] - p.y[i]) >= y_notch_top) continue;
    b.active[k] = 0;
    for (int e = 0; e < b.stride; ++e)
      b.bonded[k * static_cast<std::size_t>(b.stride) + static_cast<std::size_t>(e)] = 0;
    ++res_.n_notch_joints_retired;
  }
  // The rollers: arcs touching the nearest disk (load roller above mid-span, supports below at +- S/2).
  const double r = spec.roller_radius_m, v = spec.speed_m_per_s;
  const auto add_roller = [&](double cx, bool above, std::vector<int>& walls) {
    double cy = above ? -1e300 : 1e300;
    for (std::size_t i = 0; i < n; ++i) {
      const double dx = p.x[i] - cx, reach = r + p.radius[i];
      if (std::abs(dx) >= reach) continue;
      const double h = std::sqrt(reach * reach - dx * dx);
      cy = above ? std::max(cy, p.y[i] + h) : std::min(cy, p.y[i] - h);
    }
    const double mid = above ? -0.5 * std::numbers::pi : 0.5 * std::numbers::pi;  // towards the beam
    for (int s = 0; s < kRollerSegments; ++s) {
      const double t0 = mid - kRollerArcRad + 2 * kRollerArcRad * s / kRollerSegments;
      const double t1 = mid - kRollerArcRad + 2 * kRollerArcRad * (s + 1) / kRollerSegments;
      walls.push_back(sim_.add_wall({cx + r * std::cos(t0), cy + r * std::sin(t0), cx + r * std::cos(t1),
                                     cy + r * std::sin(t1), 0, above ? -v : 0.0}));
    }
  };
  add_roller(xc, true, load_walls_);
  add_roller(xc - 0.5 * res_.span_m, false, support_walls_);
  add_roller(xc + 0.5 * res_.span_m, false, support_walls_);
  sim_.invalidate_neighbours();
  sim_.initialise();
  res_.n_particles = n;
  // Broken through once a crack within W/2 of the notch's line lies within 0.1 W or two disk diameters
  // (whichever is more) of the loaded face: the crack has crossed the ligament up to the compressed zone
  // under the load roller, where it stops (W = 1 mm: 63 um below the face, 2.4 diameters).
  through_y_m_ = y_max - std::max(0.1 * w, 4 * r_max);
  crack_band_m_ = 0.5 * w;
  res_.time_step_s = sim_.time_step();
  const double slowest = spec.quasi_static_check ? 0.5 * v : v;
  const double steps = spec.max_deflection_m / (slowest * res_.time_step_s);
  refuse_small_time_step_safety(steps, res_.time_step_s, sim_.options().time_step_safety);
  if (steps > kMaxRunSteps)
    throw InputError("toughness.speed_m_per_s", format_value(v),
                     "a speed at which max_deflection_um " + format_value(units::m_to_um(spec.max_deflection_m)) +
                         " takes at most " + format_value(kMaxRunSteps) + " time steps of " +
                         format_value(res_.time_step_s * 1e9) + " ns" +
                         (spec.quasi_static_check ? " at the quasi-static check's half speed" : ""));
  counted_ = sim_.cracks().size();
  t0_ = sim_.time();
  res_.curve.push_back({0, 0, 0, 0, 0, sim_.stored_elastic_energy(), sim_.kinetic_energy(), 0, 0});
}

double ToughnessRun::roller_force(const std::vector<int>& walls) const {
  double f = 0;
  for (int w : walls) f += sim_.walls()[static_cast<std::size_t>(w)].fy;
  return f;
}

bool ToughnessRun::advance() {
  if (finished_) return false;
  const auto start = std::chrono::steady_clock::now();
  const double v = spec_.speed_m_per_s, dt = sim_.time_step();
  // The load roller's work, step by step (trapezoidal in time; its speed is constant).
  // The sample's load is its mean over the sample's steps (the load on a rigid roller rings from step to step
  // in an undamped glass; the mean is the impulse over the time, the same the work integral sees).
  double work = res_.external_work_J, load_sum = 0, support_sum = 0;
  for (int s = 0; s < spec_.sample_every_steps; ++s) {
    sim_.step();
    const double load = roller_force(load_walls_);  // the disks push the load roller up
    work += 0.5 * (load_prev_ + load) * v * dt;
    load_prev_ = load;
    load_sum += load;
    support_sum -= roller_force(support_walls_);
  }
  res_.external_work_J = work;
  for (std::size_t k = counted_ + static_cast<std::size_t>(n_cracks_); k < sim_.cracks().size(); ++k) {
    const CrackEvent& e = sim_.cracks()[k];
    if (std::abs(e.x_m - res_.notch_x_m) < crack_band_m_) res_.crack_tip_y_m = std::max(res_.crack_tip_y_m, e.y_m);
  }
  n_cracks_ = static_cast<int>(sim_.cracks().size() - counted_);
  const double elapsed = sim_.time() - t0_, deflection = v * elapsed, load = load_sum / spec_.sample_every_steps;
  res_.curve.push_back({elapsed, deflection, load, support_sum / spec_.sample_every_steps, work,
                        sim_.stored_elastic_energy(), sim_.kinetic_energy(), n_cracks_, 0});
  if (load > res_.raw_peak_load_N) res_.raw_peak_load_N = load;
  if (res_.through_sample < 0 && res_.crack_tip_y_m >= through_y_m_)
    res_.through_sample = static_cast<int>(res_.curve.size()) - 1;
  // Broken through: the load below the stop fraction over a whole peak window (a ringing load touches zero
  // for a moment after a break, and a hexagonal lattice's ligament stood after three).
  if (n_cracks_ > 0 && load < spec_.stop_fraction * res_.raw_peak_load_N) {
    if (low_since_m_ < 0) low_since_m_ = deflection;
  } else {
    low_since_m_ = -1;
  }
  if (low_since_m_ >= 0 && deflection - low_since_m_ >= spec_.peak_window_m) {
    res_.stop_reason = "load fell below the stop fraction of the peak";
    finished_ = true;
  } else if (deflection >= spec_.max_deflection_m) {
    res_.stop_reason = "maximum deflection reached before the load fell";
    finished_ = true;
  }
  res_.steps = sim_.step_count();
  res_.wall_time_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (finished_) finish();
  return !finished_;
}

void ToughnessRun::finish() {
  ToughnessResult& r = res_;
  // The load averaged over peak_window_um of deflection about each sample (the samples within half the
  // window either side; equal spacing in deflection), and its peak.
  auto& c = r.curve;
  const double half = 0.5 * spec_.peak_window_m;
  std::size_t lo = 0, hi = 0;
  double sum = 0;
  for (std::size_t k = 0; k < c.size(); ++k) {
    while (hi < c.size() && c[hi].deflection_m <= c[k].deflection_m + half) sum += c[hi++].load_N;
    while (c[lo].deflection_m < c[k].deflection_m - half) sum -= c[lo++].load_N;
    c[k].smoothed_load_N = sum / static_cast<double>(hi - lo);
    if (c[k].smoothed_load_N > r.peak_load_N)
      r.peak_load_N = c[k].smoothed_load_N, r.deflection_at_peak_m = c[k].deflection_m;
  }
  r.fracture_toughness_Pa_sqrt_m = senb_stress_intensity(r.peak_load_N, r.span_m, r.thickness_m, r.depth_m, r.notch_m);
  r.raw_peak_toughness_Pa_sqrt_m =
      senb_stress_intensity(r.raw_peak_load_N, r.span_m, r.thickness_m, r.depth_m, r.notch_m);
  const double ligament_area = r.thickness_m * (r.depth_m - r.notch_m);
  // The energy stored and moving at the end, less what the specimen held at the start (the genesis's
  // residual stresses): the rest of the load roller's work was dissipated (joints broken, friction).
  // At the sample the crack broke through the ligament (the end when it did not): later work goes into the
  // hinge the broken halves make under the load roller (friction, contacts), not into the crack.
  const ToughnessSample &start = r.curve.front(), &end = r.through_sample >= 0
                                                             ? r.curve[static_cast<std::size_t>(r.through_sample)]
                                                             : r.curve.back();
  const double kept =
      end.stored_elastic_energy_J - start.stored_elastic_energy_J + end.kinetic_energy_J - start.kinetic_energy_J;
  r.fracture_energy_J_per_m2 = (end.external_work_J - kept) / ligament_area;
  r.work_of_fracture_J_per_m2 = end.external_work_J / ligament_area;
  r.irwin_energy_J_per_m2 = r.fracture_toughness_Pa_sqrt_m * r.fracture_toughness_Pa_sqrt_m / spec_.youngs_modulus_Pa;
}

ToughnessResult run_toughness_test(const Simulation& specimen, const ToughnessSpec& spec,
                                   const std::function<void(const Simulation&, const ToughnessSample&)>& on_sample,
                                   Simulation* final_state) {
  ToughnessRun run(specimen, spec);
  bool more = true;
  while (more) {
    more = run.advance();
    if (on_sample) on_sample(run.simulation(), run.result().curve.back());
  }
  if (final_state) *final_state = run.simulation();
  return run.result();
}

}  // namespace kerf::dem
