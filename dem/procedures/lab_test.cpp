// Tension and compression tests (Yang et al. 2018, Section 3; physics-dem.md section 3).
#include "kerf/dem/procedures/lab_test.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <type_traits>

#include "../engine/serial.hpp"
#include "kerf/error.hpp"
#include "kerf/units.hpp"

namespace kerf::dem {

const EnumNames<LabTest>& lab_test_names() {
  static constexpr std::string_view names[] = {"tension", "compression"};
  static const EnumNames<LabTest> table{names};
  return table;
}

const FieldTable<LoadingSpec>& loading_fields() {
  using L = LoadingSpec;
  static const FieldTable<LoadingSpec> table{
      number_field("speed_m_per_s", units::kSi("m/s"), Range{0.0, 10.0, true, false}, "speed of each platen (grip)",
                   &L::speed_m_per_s),
      number_field("stop_fraction_of_peak", units::kNone, Range::open(0.0, 1.0),
                   "stop once the stress has fallen below this fraction of the peak", &L::stop_fraction),
      number_field("max_strain", units::kNone, Range{0.0, 0.5, true, false},
                   "stop anyway at this axial strain (default: 0.005 in tension)", &L::max_strain),
      int_field("sample_every_steps", 1, 1000000, "steps per curve sample", &L::sample_every_steps),
      bool_field("quasi_static_check", "rerun at half the speed and report the change of the peak",
                 &L::quasi_static_check)};
  return table;
}

LoadingSpec read_loading_spec(ObjectReader& r, LabTest test) {
  LoadingSpec s;
  s.test = test;
  if (test == LabTest::tension) s.max_strain = 0.005;
  return read_fields(r, loading_fields(), s);
}

void secant_properties(LabTestResult& res, double fraction) {
  const double target = fraction * res.peak_stress_Pa;
  res.youngs_modulus_Pa = res.poissons_ratio = 0;
  for (std::size_t k = 1; k < res.curve.size(); ++k) {
    const auto &a = res.curve[k - 1], &b = res.curve[k];
    if (b.stress_Pa < target) continue;
    const double w = b.stress_Pa > a.stress_Pa ? (target - a.stress_Pa) / (b.stress_Pa - a.stress_Pa) : 1.0;
    const double strain = a.axial_strain + w * (b.axial_strain - a.axial_strain);
    const double lateral = a.lateral_strain + w * (b.lateral_strain - a.lateral_strain);
    res.youngs_modulus_Pa = strain > 0 ? target / strain : 0;
    // Axial strain is positive in the loading sense: true axial strain is -strain in compression.
    const double true_axial = res.test == LabTest::compression ? -strain : strain;
    res.poissons_ratio = strain > 0 ? -lateral / true_axial : 0;
    return;
  }
}

LabTestRun::LabTestRun(const Simulation& specimen, const LoadingSpec& spec) : sim_(specimen), spec_(spec) {
  auto& p = sim_.particles();
  const std::size_t n = p.size();
  double x_min = 1e300, x_max = -1e300, y_min = 1e300, y_max = -1e300, r_max = 0;
  for (std::size_t i = 0; i < n; ++i) {
    x_min = std::min(x_min, p.x[i] - p.radius[i]);
    x_max = std::max(x_max, p.x[i] + p.radius[i]);
    y_min = std::min(y_min, p.y[i] - p.radius[i]);
    y_max = std::max(y_max, p.y[i] + p.radius[i]);
    r_max = std::max(r_max, p.radius[i]);
  }
  const double width = x_max - x_min, v = spec.speed_m_per_s;
  double length = y_max - y_min;
  if (spec.test == LabTest::tension) {
    // Grips: the row of disks whose centres lie within 2 R_max of the top or the bottom.
    double y_top = 0, y_bottom = 0;
    int n_top = 0, n_bottom = 0;
    for (std::size_t i = 0; i < n; ++i) {
      if (p.y[i] < y_min + 2 * r_max)
        p.group[i] = 1, y_bottom += p.y[i], ++n_bottom;
      else if (p.y[i] > y_max - 2 * r_max)
        p.group[i] = 2, y_top += p.y[i], ++n_top;
      if (p.group[i]) p.vx[i] = p.omega[i] = 0, p.vy[i] = p.group[i] == 1 ? -v : v;
    }
    if (n_top == 0 || n_bottom == 0) throw ModelError("dem", "tension test: no grip particles found");
    length = y_top / n_top - y_bottom / n_bottom;
  } else {
    sim_.add_wall({x_min - width, y_min, x_max + width, y_min, 0, v});
    sim_.add_wall({x_max + width, y_max, x_min - width, y_max, 0, -v});
  }
  // Side disks for the lateral strain: the outermost disks in the middle half of the height.
  for (std::size_t i = 0; i < n; ++i) {
    if (p.group[i] || std::abs(p.y[i] - 0.5 * (y_min + y_max)) > 0.25 * (y_max - y_min)) continue;
    if (p.x[i] - p.radius[i] < x_min + 0.5 * r_max) left_.push_back(static_cast<std::int64_t>(i));
    if (p.x[i] + p.radius[i] > x_max - 0.5 * r_max) right_.push_back(static_cast<std::int64_t>(i));
  }
  side0_ = side_distance();
  sim_.invalidate_neighbours();
  sim_.initialise();
  res_.test = spec.test;
  res_.width_m = width;
  res_.height_m = length;
  res_.speed_m_per_s = v;
  res_.n_particles = n;
  res_.time_step_s = sim_.time_step();
  // Stable at the extremes: the job's slowest run (the quasi-static check reruns at half the speed) must
  // reach max_strain within kMaxRunSteps (strain = 2 v t / length).
  const double slowest = spec.quasi_static_check ? 0.5 * v : v;
  const double min_speed = spec.max_strain * length / (2 * kMaxRunSteps * res_.time_step_s);
  refuse_small_time_step_safety(spec.max_strain * length / (2 * slowest * res_.time_step_s), res_.time_step_s,
                                sim_.options().time_step_safety);
  if (slowest < min_speed)
    throw InputError("loading.speed_m_per_s", format_value(v),
                     "a speed of at least " + format_value(spec.quasi_static_check ? 2 * min_speed : min_speed) +
                         " m/s: slower, loading to max_strain " + format_value(spec.max_strain) + " takes more than " +
                         format_value(kMaxRunSteps) + " time steps of " + format_value(res_.time_step_s * 1e9) + " ns" +
                         (spec.quasi_static_check ? " at the quasi-static check's half speed" : ""));
  counted_ = static_cast<std::int64_t>(sim_.cracks().size());
  t0_ = sim_.time();
  res_.curve.push_back({t0_, 0, 0, 0, 0, 0});
}

double LabTestRun::side_distance() const {
  const auto& p = sim_.particles();
  double l = 0, r = 0;
  for (auto i : left_) l += p.x[static_cast<std::size_t>(i)];
  for (auto i : right_) r += p.x[static_cast<std::size_t>(i)];
  return r / static_cast<double>(std::max<std::size_t>(right_.size(), 1)) -
         l / static_cast<double>(std::max<std::size_t>(left_.size(), 1));
}

bool LabTestRun::advance() {
  if (finished_) return false;
  const auto start = std::chrono::steady_clock::now();
  sim_.run(spec_.sample_every_steps);
  const auto& cracks = sim_.cracks();
  for (; counted_ < static_cast<std::int64_t>(cracks.size()); ++counted_)
    (cracks[static_cast<std::size_t>(counted_)].mode == BreakMode::tension ? n_tension_ : n_shear_)++;
  const double elapsed = sim_.time() - t0_, t = sim_.options().thickness_m;
  const double stress = spec_.test == LabTest::tension
                            ? 0.5 * (sim_.group_force(1)[1] - sim_.group_force(2)[1]) / (res_.width_m * t)
                            : 0.5 * (sim_.walls()[1].fy - sim_.walls()[0].fy) / (res_.width_m * t);
  const double strain = 2 * spec_.speed_m_per_s * elapsed / res_.height_m;
  res_.curve.push_back({elapsed, strain, side0_ > 0 ? side_distance() / side0_ - 1 : 0, stress, n_tension_, n_shear_});
  if (stress > res_.peak_stress_Pa) res_.peak_stress_Pa = stress, res_.strain_at_peak = strain;
  if (n_tension_ + n_shear_ > 0 && stress < spec_.stop_fraction * res_.peak_stress_Pa) {
    res_.stop_reason = "stress fell below the stop fraction of the peak";
    finished_ = true;
  } else if (strain >= spec_.max_strain) {
    res_.stop_reason = "maximum strain reached before the stress fell";
    finished_ = true;
  }
  res_.steps = sim_.step_count();
  res_.wall_time_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (finished_) secant_properties(res_);
  return !finished_;
}

namespace {
constexpr std::string_view kLabMagic = "KERFLAB1";
}  // namespace

template <class Self, class Io>
void LabTestRun::state_fields(Self& run, Io& io) {
  auto& spec = run.spec_;
  auto& r = run.res_;
  std::string test = lab_test_names().name(spec.test);  // by name, as before the enum
  io(test, spec.speed_m_per_s, spec.stop_fraction, spec.max_strain, spec.sample_every_steps, spec.quasi_static_check,
     r.curve);
  io(r.peak_stress_Pa, r.strain_at_peak, r.width_m, r.height_m, r.speed_m_per_s, r.time_step_s, r.wall_time_s,
     run.side0_, run.t0_);
  io(r.steps, r.n_particles, r.stop_reason, run.left_, run.right_, run.counted_, run.n_tension_, run.n_shear_,
     run.finished_);
  if constexpr (!std::is_const_v<Self>) spec.test = lab_test_names().parse(test, "test checkpoint");
}

std::string LabTestRun::serialize() const {
  std::string out(kLabMagic);
  serial::Out io{out};
  state_fields(*this, io);
  io(sim_.serialize());
  return out;
}

LabTestRun LabTestRun::deserialize(std::string_view bytes) {
  serial::In io = serial::open_tagged(bytes, kLabMagic, "test checkpoint");
  LabTestRun run;
  state_fields(run, io);
  std::string state;
  io(state);
  io.expect_end("test checkpoint");
  run.sim_ = Simulation::deserialize(state);
  run.res_.test = run.spec_.test;
  if (run.finished_) secant_properties(run.res_);
  return run;
}

LabTestResult run_lab_test(const Simulation& specimen, const LoadingSpec& spec,
                           const std::function<void(const Simulation&, const CurveSample&)>& on_sample,
                           Simulation* final_state) {
  LabTestRun run(specimen, spec);
  bool more = true;
  while (more) {
    more = run.advance();
    if (on_sample) on_sample(run.simulation(), run.result().curve.back());
  }
  LabTestResult res = run.result();
  if (final_state) *final_state = run.simulation();
  return res;
}

}  // namespace kerf::dem
