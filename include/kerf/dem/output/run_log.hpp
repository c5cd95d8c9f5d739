#pragma once
// Plain log lines of a running scene, for a batch job or `kerf-dem run ... > log` (the progress bars draw
// only on a terminal): LAMMPS's thermo output and its "Loop time" / "Performance" lines. Fed by
// RunOptions::on_progress (kerf/dem/scene.hpp).
//
//   RunLog log(std::cout, 100);  // a line every 100 samples of a stage, and at its end
//   options.on_progress = [&](const ProgressUpdate& u) { log.report(u); };
//   run_scene(doc, path, options);
//   log.finish(omp_get_max_threads());  // "performance: ..."
//
// The lines (numbers in %g-like form; a field is left out when the stage does not measure it):
//   cut: step 2500 time 1.25e-05 s travel 0.025 mm cutting 1.23 N thrust 0.456 N cracks 12 | 1.1e+06 particle-steps/s
//   | 31 % | ETA 4 min
//   tension: step 4000 time 4e-05 s strain 0.000123 stress 12.3 MPa cracks 3 | 9.8e+05 particle-steps/s | 14 %
//   | ETA 50 s
//   specimen genesis: 4000 of 10500 steps | 2300 steps/s | 38 % | ETA 3 s
//   (the ETA: the time left at the stage's rate so far, as on a terminal; none on a stage's last line)
//   cut: done: 8000 steps of 1755 particles in 10.2 s, 1.38e+06 particle-steps/s
//   cut: resumed at step 5000 travel 0.05 mm (62 %)      (a stage resumed from a checkpoint; its rates and its
//   cut: done: 3000 steps since the resume at step 5000 of 1755 particles in ...   done line count from there)
//   performance: 14.1 s wall, 2 stages, 18500 steps, 1.33e+06 particle-steps/s, 2 threads
#include <chrono>
#include <cstdint>
#include <map>
#include <ostream>
#include <string>
#include <vector>

#include "kerf/dem/scene.hpp"

namespace kerf::dem {

class RunLog {
 public:
  /// `every`: samples (reports) of a stage between lines; at least 1.
  RunLog(std::ostream& out, int every);
  /// One report of RunOptions::on_progress: a line every `every` reports of its stage and at its end
  /// (done = total), then the stage's performance line.
  void report(const ProgressUpdate& update);
  /// The performance line of the whole run: wall time since construction, the finished stages, their steps
  /// (each stage's last sample), particle-steps per second of the stages' own wall time, `threads`.
  void finish(int threads);

 private:
  using Clock = std::chrono::steady_clock;
  struct Stage {
    Clock::time_point start, last_line;
    double last_line_done = 0;        ///< at the last line: units done
    double done_before = 0;           ///< units a checkpoint had done (a resumed stage): not in its ETA's rate
    std::int64_t last_line_step = 0;  ///< and steps
    std::int64_t first_step = 0;      ///< where a resumed stage began (its checkpoint's step); 0 otherwise
    long reports = 0;
    std::int64_t steps = 0;
    double particle_steps = 0, wall_s = 0;
    bool done = false;
  };
  std::ostream& out_;
  int every_;
  Clock::time_point start_;
  std::map<std::string, Stage> stages_;
  int n_stages_ = 0;  ///< finished (a stage run again, as in a calibration, counts each time)
  std::int64_t steps_ = 0;
  double particle_steps_ = 0, stage_wall_s_ = 0;
  void line(const std::string& text);
};

}  // namespace kerf::dem
