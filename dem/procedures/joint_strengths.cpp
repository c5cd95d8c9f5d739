// Weibull-distributed joint strengths (docs/physics-dem.md, "Weibull joint strengths"): each joint of a specimen
// gets its own strength factor w when the specimen is made (weibull_strength_factor, kerf/dem/laws/law.hpp), so that
// a small stressed volume (the few joints at a tool's edge) sees the strong tail of the strengths while a millimetre
// specimen fails at its weakest joints.
#include <random>

#include "kerf/dem/laws/material.hpp"
#include "kerf/dem/procedures/specimen.hpp"

namespace kerf::dem {

void draw_joint_strengths(Simulation& sim, std::uint64_t seed) {
  const BondStiffnessStrength& bond = joint_bond(sim.material());
  if (bond.strength_weibull_modulus == 0) return;
  // A stream of its own (apart from the packing's and the flaws' draws); uniforms in (0, 1) from the generator's
  // top 53 bits (portable), never 0 or 1, so that -ln U is finite and positive.
  std::mt19937_64 rng(seed ^ 0x5EEDB0A7D5A1E1B5ull);
  auto& b = sim.bonds();
  for (std::size_t k = 0; k < b.size(); ++k) {
    const double u = (static_cast<double>(rng() >> 11) + 0.5) * 0x1.0p-53;
    b.set_strength_factor(k, weibull_strength_factor(bond, b.geometry[k].half_length_m, u));
  }
}

}  // namespace kerf::dem
