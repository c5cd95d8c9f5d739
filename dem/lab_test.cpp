// Tension and compression tests (seed 000, Section 3; physics-dem.md section 3).
#include "kerf/dem/lab_test.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "kerf/error.hpp"

namespace kerf::dem {

LoadingSpec read_loading_spec(ObjectReader& r, const std::string& test) {
  LoadingSpec s;
  s.test = test;
  s.speed_m_per_s = r.get_number_or("speed_m_per_s", 0.05, Range{0.0, 10.0, true, false}, "m/s");
  s.stop_fraction = r.get_number_or("stop_fraction_of_peak", 0.7, Range::open(0.0, 1.0), "");
  s.max_strain = r.get_number_or("max_strain", test == "tension" ? 0.005 : 0.02, Range{0.0, 0.5, true, false}, "");
  s.sample_every_steps = r.get_int_or("sample_every_steps", 50, 1, 1000000);
  s.quasi_static_check = r.get_bool_or("quasi_static_check", true);
  return s;
}

void secant_properties(LabTestResult& res, double fraction) {
  const double target = fraction * res.peak_stress_pa;
  res.youngs_modulus_pa = res.poissons_ratio = 0;
  for (std::size_t k = 1; k < res.curve.size(); ++k) {
    const auto &a = res.curve[k - 1], &b = res.curve[k];
    if (b.stress_pa < target) continue;
    const double w = b.stress_pa > a.stress_pa ? (target - a.stress_pa) / (b.stress_pa - a.stress_pa) : 1.0;
    const double strain = a.axial_strain + w * (b.axial_strain - a.axial_strain);
    const double lateral = a.lateral_strain + w * (b.lateral_strain - a.lateral_strain);
    res.youngs_modulus_pa = strain > 0 ? target / strain : 0;
    // Axial strain is positive in the loading sense: true axial strain is -strain in compression.
    const double true_axial = res.test == "compression" ? -strain : strain;
    res.poissons_ratio = strain > 0 ? -lateral / true_axial : 0;
    return;
  }
}

LabTestResult run_lab_test(const Simulation& specimen, const LoadingSpec& spec,
                           const std::function<void(const Simulation&, const CurveSample&)>& on_sample,
                           Simulation* final_state) {
  const auto start = std::chrono::steady_clock::now();
  Simulation sim = specimen;
  auto& p = sim.particles();
  const std::size_t n = p.size();
  double x_min = 1e300, x_max = -1e300, y_min = 1e300, y_max = -1e300, r_max = 0;
  for (std::size_t i = 0; i < n; ++i) {
    x_min = std::min(x_min, p.x[i] - p.radius[i]);
    x_max = std::max(x_max, p.x[i] + p.radius[i]);
    y_min = std::min(y_min, p.y[i] - p.radius[i]);
    y_max = std::max(y_max, p.y[i] + p.radius[i]);
    r_max = std::max(r_max, p.radius[i]);
  }
  const double width = x_max - x_min, t = sim.options().thickness_m, v = spec.speed_m_per_s;
  double length = y_max - y_min;
  const bool tension = spec.test == "tension";
  if (tension) {
    // Grips: the row of disks whose centres lie within 2 R_max of the top or the bottom.
    double y_top = 0, y_bottom = 0;
    int n_top = 0, n_bottom = 0;
    for (std::size_t i = 0; i < n; ++i) {
      if (p.y[i] < y_min + 2 * r_max) p.group[i] = 1, y_bottom += p.y[i], ++n_bottom;
      else if (p.y[i] > y_max - 2 * r_max) p.group[i] = 2, y_top += p.y[i], ++n_top;
      if (p.group[i]) p.vx[i] = p.omega[i] = 0, p.vy[i] = p.group[i] == 1 ? -v : v;
    }
    if (n_top == 0 || n_bottom == 0) throw ModelError("dem", "tension test: no grip particles found");
    length = y_top / n_top - y_bottom / n_bottom;
  } else {
    sim.add_wall({x_min - width, y_min, x_max + width, y_min, 0, v});
    sim.add_wall({x_max + width, y_max, x_min - width, y_max, 0, -v});
  }
  // Side disks for the lateral strain: the outermost disks in the middle half of the height.
  std::vector<std::size_t> left, right;
  for (std::size_t i = 0; i < n; ++i) {
    if (p.group[i] || std::abs(p.y[i] - 0.5 * (y_min + y_max)) > 0.25 * (y_max - y_min)) continue;
    if (p.x[i] - p.radius[i] < x_min + 0.5 * r_max) left.push_back(i);
    if (p.x[i] + p.radius[i] > x_max - 0.5 * r_max) right.push_back(i);
  }
  const auto side_distance = [&] {
    double l = 0, r = 0;
    for (auto i : left) l += p.x[i];
    for (auto i : right) r += p.x[i];
    return r / static_cast<double>(std::max<std::size_t>(right.size(), 1)) -
           l / static_cast<double>(std::max<std::size_t>(left.size(), 1));
  };
  const double side0 = side_distance();
  sim.invalidate_neighbours();
  sim.initialise();

  LabTestResult res;
  res.test = spec.test;
  res.width_m = width;
  res.height_m = length;
  res.speed_m_per_s = v;
  res.n_particles = n;
  res.time_step_s = sim.time_step();
  const std::size_t cracks0 = sim.cracks().size();
  int n_tension = 0, n_shear = 0;
  std::size_t counted = cracks0;
  const double t0 = sim.time();
  res.curve.push_back({t0, 0, 0, 0, 0, 0});
  while (true) {
    sim.run(spec.sample_every_steps);
    for (; counted < sim.cracks().size(); ++counted)
      (sim.cracks()[counted].mode == BreakMode::tension ? n_tension : n_shear)++;
    const double elapsed = sim.time() - t0;
    double stress;
    if (tension) {
      stress = 0.5 * (sim.group_force(1)[1] - sim.group_force(2)[1]) / (width * t);
    } else {
      stress = 0.5 * (sim.walls()[1].fy - sim.walls()[0].fy) / (width * t);
    }
    const double strain = 2 * v * elapsed / length;
    const CurveSample sample{elapsed, strain, side0 > 0 ? side_distance() / side0 - 1 : 0, stress, n_tension, n_shear};
    res.curve.push_back(sample);
    if (stress > res.peak_stress_pa) res.peak_stress_pa = stress, res.strain_at_peak = strain;
    if (on_sample) on_sample(sim, sample);
    if (n_tension + n_shear > 0 && stress < spec.stop_fraction * res.peak_stress_pa) {
      res.stop_reason = "stress fell below the stop fraction of the peak";
      break;
    }
    if (strain >= spec.max_strain) {
      res.stop_reason = "maximum strain reached before the stress fell";
      break;
    }
  }
  res.steps = sim.step_count();
  secant_properties(res);
  res.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (final_state) *final_state = std::move(sim);
  return res;
}

}  // namespace kerf::dem
