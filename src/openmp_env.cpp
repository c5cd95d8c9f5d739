// The OpenMP wait policy a run started with (kerf/openmp_env.hpp).
#include "kerf/openmp_env.hpp"

#include <cstdlib>

namespace kerf {

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
