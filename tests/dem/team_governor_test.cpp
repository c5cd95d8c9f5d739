// The team-size governor (kerf/dem/engine/team_governor.hpp) on a synthetic clock: it keeps all threads where they
// are faster, takes one thread where that is faster (a core shared with another process), and comes back when
// the contention ends; one thread allowed: always one.
#include "kerf/dem/engine/team_governor.hpp"

#include <algorithm>
#include <catch2/catch.hpp>
#include <functional>
#include <vector>

using kerf::dem::TeamGovernor;

namespace {

/// Runs the governor for `seconds` of steps in chunks of 16 (as the engine reports them), asking for the team
/// before each chunk (the engine asks every step); a step takes `step_s(team)` seconds. Returns the team of
/// each chunk.
std::vector<int> drive(TeamGovernor& g, int max_threads, double seconds, const std::function<double(int)>& step_s,
                       double& now) {
  std::vector<int> teams;
  const double end = now + seconds;
  while (now < end) {
    const int team = g.team(max_threads);
    teams.push_back(team);
    now += 16 * step_s(team);
    g.observe(16, now);
  }
  return teams;
}

/// The share of the chunks run on `x` threads.
double share(const std::vector<int>& v, int x) {
  return static_cast<double>(std::count(v.begin(), v.end(), x)) / static_cast<double>(v.size());
}

}  // namespace

TEST_CASE("team governor: all threads stay where they are faster, one probe window every 17", "[team_governor]") {
  TeamGovernor g;
  double now = 0;
  g.observe(0, now);  // the engine's first report starts the first window
  const auto quiet = [](int team) { return team == 2 ? 1e-4 / 1.9 : 1e-4; };  // two threads 1.9x
  const std::vector<int> teams = drive(g, 2, 70 * 0.25, quiet, now);
  CHECK(g.switches() == 0);
  CHECK_FALSE(g.reduced());
  // Probes of one thread: a window after the first, then one every 16 windows of the current team. A probe
  // window has half the steps of a two-thread one: about 1 chunk in 33 runs on one thread.
  CHECK(share(teams, 1) > 0.5 / 17 * 0.5);
  CHECK(share(teams, 1) < 2.0 / 17);
}

TEST_CASE("team governor: one thread when it is faster, and all again when the contention ends", "[team_governor]") {
  TeamGovernor g;
  double now = 0;
  g.observe(0, now);
  const auto loaded = [](int team) { return team == 2 ? 2e-4 : 1e-4; };  // two threads at half the one-thread rate
  std::vector<int> teams = drive(g, 2, 40 * 0.25, loaded, now);
  CHECK(g.reduced());
  CHECK(g.switches() == 1);
  // After the switch, about one window in 17 (one chunk in 33: half the steps) probes two threads.
  CHECK(share(std::vector<int>(teams.begin() + static_cast<long>(teams.size() / 4), teams.end()), 2) < 2.0 / 17);
  const auto quiet = [](int team) { return team == 2 ? 1e-4 / 1.9 : 1e-4; };
  teams = drive(g, 2, 40 * 0.25, quiet, now);
  CHECK_FALSE(g.reduced());
  CHECK(g.switches() == 2);
}

TEST_CASE("team governor: a rate within the margin does not switch, and one thread allowed is one", "[team_governor]") {
  TeamGovernor g;
  double now = 0;
  g.observe(0, now);
  const auto close = [](int team) { return team == 2 ? 1e-4 : 1e-4 / 1.1; };  // one thread 10 % faster: noise
  drive(g, 2, 60 * 0.25, close, now);
  CHECK(g.switches() == 0);
  TeamGovernor single;
  single.observe(0, 0);
  for (int w = 0; w < 5; ++w) CHECK(single.team(1) == 1);
  // A new maximum starts afresh: all threads first.
  CHECK(g.team(4) == 4);
  CHECK_FALSE(g.reduced());
}
