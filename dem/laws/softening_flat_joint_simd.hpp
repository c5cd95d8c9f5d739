#pragma once
// Internal: the engine's fast path of the softening flat joint (not part of the public law header). An intact,
// undamaged two-element joint below both strength envelopes is the flat joint's (the softening law's update gives
// the same bits there), so it takes the flat joint's two-lane path (flat_joint_simd.hpp); any other joint, and one
// that the two-lane path finds over an envelope, takes the softening update.
#include "flat_joint_simd.hpp"
#include "kerf/dem/laws/softening_flat_joint.hpp"

namespace kerf::dem {

/// The softening flat joint's update as the engine calls it (the engine's default for a law with damage calls
/// bond_update; this overload is chosen for this law).
[[gnu::always_inline]] inline BondResult bond_update_fast(const SofteningFlatJointParams& p, const BondGeometry& geo,
                                                          const BondKinematics& kin, double* shear_force_N,
                                                          const std::uint8_t* bonded, BreakMode* breaks,
                                                          double* damage) {
  if (p.n_elements == 2 && bonded[0] && bonded[1] && damage[0] == 0 && damage[1] == 0) {
    const double s0 = shear_force_N[0], s1 = shear_force_N[1];
    const BondResult r = flat_joint_update_two_bonded(p, geo, kin, shear_force_N, breaks);
    if (r.n_breaking == 0) return r;               // within both envelopes: no damage, the flat joint's numbers
    shear_force_N[0] = s0, shear_force_N[1] = s1;  // over one: the softening update decides from the same state
  }
  return bond_update(p, geo, kin, shear_force_N, bonded, breaks, damage);
}

}  // namespace kerf::dem
