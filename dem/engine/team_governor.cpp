// The team size of a simulation's steps, chosen by measured rate (kerf/dem/engine/team_governor.hpp).
#include "kerf/dem/engine/team_governor.hpp"

namespace kerf::dem {

int TeamGovernor::team(int max_threads) {
  if (max_threads != max_) {  // another caller's maximum (a study's item, a new omp_set_num_threads): afresh
    *this = TeamGovernor(p_);
    max_ = max_threads;
  }
  if (max_threads <= 1) return max_threads;
  const bool one = reduced_ != probing_;  // the probe runs the other choice
  return one ? 1 : max_threads;
}

void TeamGovernor::observe(std::int64_t steps, double now_s) {
  if (max_ <= 1) return;
  if (window_start_s_ < 0) {  // the first window starts now
    window_start_s_ = now_s;
    window_steps_ = 0;
    return;
  }
  window_steps_ += steps;
  const double elapsed = now_s - window_start_s_;
  if (elapsed < p_.window_s || window_steps_ == 0) return;
  const double rate = static_cast<double>(window_steps_) / elapsed;
  window_start_s_ = now_s;
  window_steps_ = 0;
  ++windows_;
  if (probing_) {
    probing_ = false;
    windows_since_probe_ = 0;
    if (rate > p_.switch_gain * current_rate_) {
      reduced_ = !reduced_;
      ++switches_;
      current_rate_ = rate;
    }
    return;
  }
  current_rate_ = rate;  // the latest window of the current team
  ++windows_since_probe_;
  if (windows_since_probe_ >= (windows_ == 1 ? 1 : p_.probe_every)) probing_ = true;
}

}  // namespace kerf::dem
