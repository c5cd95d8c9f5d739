// The OpenMP wait policy kerf's programs start with (kerf/openmp_env.hpp).
#include "kerf/openmp_env.hpp"

#include <unistd.h>

#include <cstdlib>

namespace kerf {

void adopt_openmp_wait_policy(char** argv) {
  if (std::getenv("OMP_WAIT_POLICY") || std::getenv("GOMP_SPINCOUNT")) return;  // the user's choice
  if (setenv("OMP_WAIT_POLICY", kOpenMpWaitPolicy, 0) != 0) return;
  execv("/proc/self/exe", argv);
  // Not re-executed (no /proc): go on with the policy libgomp already read. Unset it again so that what
  // openmp_wait_policy() reports is what the runtime uses.
  unsetenv("OMP_WAIT_POLICY");
}

std::string openmp_wait_policy() {
  std::string out;
  for (const char* name : {"OMP_WAIT_POLICY", "GOMP_SPINCOUNT"})
    if (const char* v = std::getenv(name)) {
      if (!out.empty()) out += ' ';
      out.append(name).append("=").append(v);
    }
  return out.empty() ? "libgomp default" : out;
}

}  // namespace kerf
