#pragma once
// The OpenMP wait policy a run started with, for its provenance (issue 21, "Sharing cores").
//
// kerf leaves the policy to the environment (libgomp's default: spin, then sleep). What holds a run up when
// another process shares a core is the DEM engine's team governor (kerf/dem/engine/team_governor.hpp), which runs one
// thread when that is measured faster; with it, the spinning default lost nothing against sleeping at once
// (OMP_WAIT_POLICY=passive) under contention and was faster on a quiet machine (docs/performance.md, "OpenMP
// wait policy under contention").
#include <string>

namespace kerf {

/// OMP_WAIT_POLICY and GOMP_SPINCOUNT as the environment holds them ("OMP_WAIT_POLICY=passive"), or
/// "libgomp default" when neither is set.
std::string openmp_wait_policy();

}  // namespace kerf
