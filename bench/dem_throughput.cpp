// DEM throughput benchmark (issue 4): particle-steps per second of a jointed specimen in unconfined
// compression, for 1 and 2 threads, and the cost versus particle count. CSV on stdout.
//
//   build/bench/bench_dem_throughput [steps] [paper] > dem_throughput.csv   (paper: the seed specimen only)
//
// Cases: "paper" is the seed 000 calibration specimen (1 mm x 2 mm, radii 7.5-10 um, ~7000 disks) with the
// full genesis; "scaling_N" are random specimens of about N disks (same radii, aspect 1:2) made with a
// shorter genesis (growth 1500, relax 300 steps), which is enough for timing.
#include <omp.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <string>

#include "kerf/dem/procedures/specimen.hpp"

using namespace kerf::dem;

namespace {

/// Times `steps` steps of the specimen compressed between platens at 0.05 m/s each (elastic range).
double time_steps(const Simulation& specimen, int threads, int steps) {
  omp_set_num_threads(threads);
  Simulation sim = specimen;
  const auto& p = sim.particles();
  double y_min = 1e300, y_max = -1e300;
  for (std::size_t i = 0; i < p.size(); ++i)
    y_min = std::min(y_min, p.y[i] - p.radius[i]), y_max = std::max(y_max, p.y[i] + p.radius[i]);
  sim.add_wall({-1, y_min, 1, y_min, 0, 0.05});
  sim.add_wall({1, y_max, -1, y_max, 0, -0.05});
  sim.invalidate_neighbours();
  sim.initialise();
  sim.run(50);  // warm-up
  const auto start = std::chrono::steady_clock::now();
  sim.run(steps);
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void row(const char* name, const Simulation& sim, int threads, int steps, double wall) {
  const double n = static_cast<double>(sim.particles().size());
  std::size_t bonds = 0;
  for (auto a : sim.bonds().active) bonds += a;
  std::printf("%s,%zu,%zu,%d,%d,%.4f,%.4g,%.1f\n", name, sim.particles().size(), bonds, threads, steps, wall,
              n * steps / wall, static_cast<double>(sim.memory_bytes()) / n);
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  const int steps = argc > 1 ? std::atoi(argv[1]) : 2000;
  std::printf("case,n_particles,n_joints,threads,steps,wall_s,particle_steps_per_s,engine_bytes_per_particle\n");
  Material m;
  SpecimenSpec paper;
  SpecimenReport report;
  omp_set_num_threads(2);
  const Simulation specimen = make_specimen(m, paper, report);
  for (int threads : {1, 2}) row("paper", specimen, threads, steps, time_steps(specimen, threads, steps));
  if (argc > 2 && std::string(argv[2]) == "paper") return 0;
  for (int n : {2000, 8000, 32000, 128000}) {
    SpecimenSpec s;
    const double area =
        n * std::numbers::pi * (7.5e-6 * 7.5e-6 + 7.5e-6 * 10e-6 + 10e-6 * 10e-6) / 3 / s.packing_fraction;
    s.width_m = std::sqrt(area / 2);
    s.height_m = 2 * s.width_m;
    s.growth_steps = 1500;
    s.relax_steps = 300;
    omp_set_num_threads(2);
    const Simulation sim = make_specimen(m, s, report);
    const int k = std::max(100, static_cast<int>(static_cast<long>(steps) * 8000 / n));
    const std::string name = "scaling_" + std::to_string(n);
    for (int threads : {1, 2}) row(name.c_str(), sim, threads, k, time_steps(sim, threads, k));
  }
}
