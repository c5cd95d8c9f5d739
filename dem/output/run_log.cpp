// Log lines of a running scene (kerf/dem/output/run_log.hpp).
#include "kerf/dem/output/run_log.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "kerf/io.hpp"

namespace kerf::dem {

RunLog::RunLog(std::ostream& out, int every) : out_(out), every_(std::max(1, every)), start_(Clock::now()) {}

void RunLog::line(const std::string& text) {
  out_ << text << '\n';
  out_.flush();  // `tail -f` on the log sees each line as it comes
}

void RunLog::report(const ProgressUpdate& u) {
  const auto now = Clock::now();
  auto [it, is_new] = stages_.try_emplace(u.stage);
  Stage& s = it->second;
  if (is_new || s.done) s = Stage{now, now};  // a stage run again starts afresh
  if (u.resumed) {  // where a checkpoint left it: the work before is not this process's, nor in its rates
    s.last_line_done = s.done_before = u.done;
    if (u.sample) s.last_line_step = s.first_step = u.sample->step;
    line(fmt::format("{}: resumed at step {}{} ({:.0f} %)", u.stage, s.first_step,
                     u.sample && u.sample->travel_mm ? fmt::format(" travel {:.4g} mm", *u.sample->travel_mm) : "",
                     u.total > 0 ? 100 * u.done / u.total : 100.0));
    return;
  }
  if (u.done == 0 && u.done != u.total) return;  // the start
  ++s.reports;
  if (u.sample) {
    s.steps = u.sample->step - s.first_step;  // this process's
    s.particle_steps = static_cast<double>(s.steps) * static_cast<double>(u.sample->n_particles);
  }
  const bool end = u.done >= u.total;
  if (s.reports % every_ != 0 && !end) return;
  // The rate since the previous line: of particle-steps when the stage has samples (its end jumps `done` to
  // the total), else of the stage's unit.
  const double since = std::chrono::duration<double>(now - s.last_line).count();
  const double rate = since <= 0 ? 0
                      : u.sample ? static_cast<double>(u.sample->step - s.last_line_step) *
                                       static_cast<double>(u.sample->n_particles) / since
                                 : (u.done - s.last_line_done) / since;
  std::string text = u.stage + ":";
  if (u.sample) {
    const SampleState& x = *u.sample;
    text += fmt::format(" step {}", x.step);
    if (x.time_s > 0) text += fmt::format(" time {:.4g} s", x.time_s);
    if (x.travel_mm) text += fmt::format(" travel {:.4g} mm", *x.travel_mm);
    if (x.strain) text += fmt::format(" strain {:.4g}", *x.strain);
    if (x.stress_MPa) text += fmt::format(" stress {:.4g} MPa", *x.stress_MPa);
    if (x.main_force_N) text += fmt::format(" cutting {:.4g} N", *x.main_force_N);
    if (x.thrust_force_N) text += fmt::format(" thrust {:.4g} N", *x.thrust_force_N);
    text += fmt::format(" cracks {}", x.cracks);
  } else {
    text += fmt::format(" {:.0f} of {:.0f} {}", u.done, u.total, u.unit);
  }
  text += fmt::format(" | {:.3g} {}/s | {:.0f} %", rate, u.sample ? "particle-steps" : u.unit,
                      u.total > 0 ? 100 * u.done / u.total : 100.0);
  // The time left at the stage's rate so far, as the terminal's progress says it (kerf::eta_seconds).
  const double stage_s = std::chrono::duration<double>(now - s.start).count();
  const std::string eta = end ? "" : eta_text(eta_seconds(s.done_before, u.done, u.total, stage_s));
  if (!eta.empty()) text += " | " + eta;
  line(text);
  s.last_line = now;
  s.last_line_done = u.done;
  // A genesis reports its steps as `done` until its last sample.
  s.last_line_step = u.sample ? u.sample->step : static_cast<std::int64_t>(u.unit == "steps" ? u.done : 0);
  if (end) {
    s.done = true;
    s.wall_s = std::chrono::duration<double>(now - s.start).count();
    ++n_stages_;
    steps_ += s.steps;
    particle_steps_ += s.particle_steps;
    stage_wall_s_ += s.wall_s;
    const std::size_t n = u.sample ? u.sample->n_particles : 0;
    line(fmt::format("{}: done: {} steps{} of {} particles in {:.3g} s, {:.3g} particle-steps/s", u.stage, s.steps,
                     s.first_step > 0 ? fmt::format(" since the resume at step {}", s.first_step) : "", n, s.wall_s,
                     s.wall_s > 0 ? s.particle_steps / s.wall_s : 0.0));
  }
}

void RunLog::finish(int threads) {
  const double wall = std::chrono::duration<double>(Clock::now() - start_).count();
  line(fmt::format("performance: {:.3g} s wall, {} stages, {} steps, {:.3g} particle-steps/s, {} threads", wall,
                   n_stages_, steps_, stage_wall_s_ > 0 ? particle_steps_ / stage_wall_s_ : 0.0, threads));
}

}  // namespace kerf::dem
