#pragma once
// How many threads a simulation's steps use: all the caller allows, or one when that is measured faster
// (issue 21, "Sharing cores").
//
// When another process shares one of the cores, the thread on it sets the pace of every barrier: measured on
// the 2-core VM (docs/performance.md, "OpenMP wait policy under contention"), two threads ran at half the
// one-thread rate with libgomp's spinning barriers and at 0.86-0.95 of it sleeping at once, and handing the
// loops out dynamically was slower still. So the engine measures instead: it runs windows of steps (about
// 0.25 s each) with its team, and every so many windows one window with the other choice (one thread if it
// runs all, all if it runs one); a probe faster by a margin becomes the team. Results do not depend on the
// team (every sum is taken in a fixed order; tests/dem/simulation_test.cpp switches the team every few steps and
// compares to the bit), so the choice only moves the speed.
//
//   TeamGovernor g;
//   for (...) { const int n = g.team(omp_get_max_threads()); run steps with n threads; g.observe(steps, now_s); }
#include <cstdint>

namespace kerf::dem {

class TeamGovernor {
 public:
  struct Params {
    double window_s = 0.25;     ///< wall time of one measured window
    int probe_every = 16;       ///< windows of the current team between two probes (the first probe: after one)
    double switch_gain = 1.15;  ///< a probe's rate must exceed the current team's by this factor to switch
  };
  TeamGovernor() = default;
  explicit TeamGovernor(const Params& params) : p_(params) {}

  /// The threads for the next steps, out of the caller's `max_threads` (a new maximum starts afresh).
  int team(int max_threads);
  /// `steps` more steps done; `now_s` a steady clock in seconds. Ends a window once window_s has passed.
  void observe(std::int64_t steps, double now_s);

  bool reduced() const { return reduced_; }  ///< running on one thread out of several
  int switches() const { return switches_; }

 private:
  Params p_;
  int max_ = 0;
  bool reduced_ = false, probing_ = false;
  int windows_since_probe_ = 0, windows_ = 0, switches_ = 0;
  std::int64_t window_steps_ = 0;
  double window_start_s_ = -1, current_rate_ = 0;
};

}  // namespace kerf::dem
