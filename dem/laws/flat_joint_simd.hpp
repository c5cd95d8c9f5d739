#pragma once
// Internal: the engine's hand-vectorised path of the flat joint (not part of the public law header). For the
// intact joint of the default interface (N_r = 2, both elements bonded: nearly every joint of a cut) it gives
// the bits of flat_joint_update (tests/dem/flat_joint_test.cpp checks it on random joints and ulp by ulp
// across the strength envelopes).
#include "kerf/dem/laws/flat_joint.hpp"

namespace kerf::dem {

/// Two doubles in one SSE2 register (GCC vector extension): arithmetic lane by lane, each lane the same
/// correctly rounded IEEE operation as on a double, so two-lane code gives the bits of scalar code.
using v2d = double __attribute__((vector_size(16)));

/// |v| lane by lane.
inline v2d lane_abs(v2d v) {
  return v2d{std::abs(v[0]), std::abs(v[1])};
}

/// flat_joint_update for the intact joint of the default interface: N_r = 2 and both elements bonded (nearly
/// every joint of a cut). The same operations on the same values in the same order, hence the same result to
/// the bit, but the two elements' normal, strength and shear arithmetic runs as two-lane vector operations,
/// the bending moment, equal for both elements, is computed once, and the stresses (two divisions) are formed
/// only for a joint near a strength envelope. The divisions dominated the joint loop;
/// tests/dem/flat_joint_test.cpp checks the equality, on random joints and ulp by ulp across the envelopes.
/// Requires p.n_elements == 2 and both elements bonded (the caller tests it).
inline BondResult flat_joint_update_two_bonded(const FlatJointParams& p, const BondGeometry& geo,
                                               const BondKinematics& kin, double* shear_force_N, BreakMode* breaks) {
  const double le = 2.0 * geo.half_length_m / 2;
  const double area = le * geo.thickness_m;
  const double kn_t = geo.normal_stiffness * geo.thickness_m;
  const double ks_area = geo.shear_stiffness * area;
  const double theta = kin.rotation_rad;
  // Element starts and centroids written as the general loop computes them (-R + e l_e), for the same bits.
  const double a0 = -geo.half_length_m + 0 * le, a1 = -geo.half_length_m + 1 * le;
  const v2d xi = {a0 + 0.5 * le, a1 + 0.5 * le};
  const v2d fs = v2d{shear_force_N[0], shear_force_N[1]} - ks_area * kin.shear_increment_m;
  const v2d fn = kn_t * le * (kin.gap_m - theta * xi);
  const double me = -kn_t * theta * le * le * le / 12.0;
  const v2d abs_fs = lane_abs(fs);
  BondResult r;
  // Far from both strength envelopes (nearly every joint of every step) no element can break, and the
  // stresses need not be formed: the test is then made on forces, without the two divisions. The margin,
  // 1e-12 of the terms, is thousands of times the rounding error of either form (a few 1e-16 of the same
  // terms), so this filter only ever passes elements that the exact test below also leaves intact: the
  // break decisions, and so the results, are those of the stress test to the bit (tested near the
  // envelopes in tests/dem/flat_joint_test.cpp). NaN fails the filter and takes the exact test.
  //   tension: fl(fn / A) > sigma_c needs fn / A > sigma_c (rounding is monotone and sigma_c a double);
  //   shear:   fl(|fs| / A) >= fl(c - fl(sigma) tan phi) needs |fs| >= c A - fn tan phi up to a few
  //            rounding errors of c A + |fn| tan phi (both sides times A > 0).
  const double sigma_c = p.bond.tensile_strength_Pa * geo.strength_factor;  // as flat_joint_update forms them
  const double cohesion = p.bond.cohesion_Pa * geo.strength_factor;
  const double tension_bound = sigma_c * area * (1.0 - 1e-12);
  const double cohesion_force = cohesion * area;
  const v2d fn_tan = fn * p.tan_friction_angle;
  const v2d envelope_scale = cohesion_force + lane_abs(fn_tan);
  const auto below_envelopes = (fn < tension_bound) & (abs_fs + 1e-12 * envelope_scale < cohesion_force - fn_tan);
  if (below_envelopes[0] && below_envelopes[1]) {
    breaks[0] = breaks[1] = BreakMode::none;
    shear_force_N[0] = fs[0], shear_force_N[1] = fs[1];
  } else {
    const v2d sigma = fn / area;
    const v2d tau = abs_fs / area;
    const v2d shear_limit = cohesion - sigma * p.tan_friction_angle;
    for (int e = 0; e < 2; ++e) {
      breaks[e] = sigma[e] > sigma_c         ? BreakMode::tension
                  : tau[e] >= shear_limit[e] ? BreakMode::shear
                                             : BreakMode::none;
      r.n_breaking += breaks[e] != BreakMode::none;
      shear_force_N[e] = fs[e];
    }
  }
  r.normal_force_N = 0.0 + fn[0] + fn[1];
  r.shear_force_N = 0.0 + fs[0] + fs[1];
  r.moment_N_m = 0.0 + (fn[0] * xi[0] + me) + (fn[1] * xi[1] + me);
  return r;
}

/// The flat joint's update as the engine calls it: the two-lane path for an intact two-element joint, the
/// general update otherwise (bond_update of the public header). Always inlined: with a loop instantiation per
/// damping choice (simulation.cpp) g++ called it out of line, 6-7 % of the throughput (docs/performance.md).
[[gnu::always_inline]] inline BondResult bond_update_fast(const FlatJointParams& p, const BondGeometry& geo,
                                                          const BondKinematics& kin, double* shear_force_N,
                                                          const std::uint8_t* bonded, BreakMode* breaks) {
  if (p.n_elements == 2 && bonded[0] && bonded[1])
    return flat_joint_update_two_bonded(p, geo, kin, shear_force_N, breaks);
  return bond_update(p, geo, kin, shear_force_N, bonded, breaks);
}

}  // namespace kerf::dem
