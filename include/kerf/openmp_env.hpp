#pragma once
// How OpenMP threads wait at a barrier when kerf starts them (issue 21, "Sharing cores").
//
// libgomp's default spins up to 300000 iterations at each barrier before it sleeps. A DEM step has several
// barriers, so when another process shares one of the cores, the spinning thread steals that core's time
// slices from the thread it waits for: measured on the 2-core development VM (docs/performance.md, "OpenMP
// wait policy"), 2 threads beside one busy core fell to half the one-thread rate. Sleeping at once
// (OMP_WAIT_POLICY=passive) kept them near the one-thread rate, for about a sixth of the two-thread rate on a
// quiet machine.
//
// libgomp reads its environment once, when it is loaded, before main() runs (a .preinit_array setenv comes
// too late: tried), so a program that wants another default must set it and execute itself again.
//
//   int main(int argc, char** argv) {
//     kerf::adopt_openmp_wait_policy(argv);  // first thing: may replace the process
#include <string>

namespace kerf {

/// The wait policy kerf's programs start OpenMP with unless the user chose one.
inline constexpr const char* kOpenMpWaitPolicy = "passive";

/// When neither OMP_WAIT_POLICY nor GOMP_SPINCOUNT is set, sets OMP_WAIT_POLICY to kOpenMpWaitPolicy and
/// executes /proc/self/exe again with the same arguments (same process, same pid: mpirun and batch schedulers
/// see nothing). Returns normally when the user chose a policy, or when the re-execution is not possible
/// (then with libgomp's default; nothing else changes).
void adopt_openmp_wait_policy(char** argv);

/// The wait policy this process's OpenMP runtime was started with: OMP_WAIT_POLICY and GOMP_SPINCOUNT as
/// the environment holds them ("OMP_WAIT_POLICY=passive", or "libgomp default"), for provenance.
std::string openmp_wait_policy();

}  // namespace kerf
