#pragma once
// The 2D flat-joint contact (Potyondy 2012, 2015; docs physics-dem.md section 1), as pure functions of
// validated parameters and per-contact state.
//
// The interface between disks 1 and 2 is a segment of half-length R = lambda min(R1, R2) centred at the
// contact point, split into N_r equal elements. Element e has length l_e = 2R / N_r, area A_e = l_e t and
// centroid xi_e along the tangent s = z x n. Normal gap and relative rotation are measured from the
// installed state (the joint starts stress free), so g(xi) = g_s - theta_b xi.
//
//   FlatJointParams p = FlatJointParams::validated(raw, "material");
//   FlatJointGeometry geo = flat_joint_geometry(p, r1, r2, thickness_m);
//   FlatJointResult res = flat_joint_update(p, geo, {gap_m, rotation_rad, shear_increment_m}, shear, bonded, breaks);
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <string>

namespace kerf::dem {

/// Two doubles in one SSE2 register (GCC vector extension): arithmetic lane by lane, each lane the same
/// correctly rounded IEEE operation as on a double, so two-lane code gives the bits of scalar code.
using v2d = double __attribute__((vector_size(16)));

/// |v| lane by lane.
inline v2d lane_abs(v2d v) {
  return v2d{std::abs(v[0]), std::abs(v[1])};
}

/// Micro-parameters of the flat joint (physics-dem.md section 1). SI units.
struct FlatJointParams {
  double effective_modulus_pa = 107e9;  ///< Ebar*: k_n = Ebar* / (R1 + R2)
  double stiffness_ratio = 3.1;         ///< kappabar* = k_n / k_s
  double tensile_strength_pa = 200e6;   ///< sigma_c
  double cohesion_pa = 113e6;           ///< c
  double friction_angle_rad = 0.4363323129985824;  ///< phi (25 deg), bonded-element Coulomb envelope
  double friction_coefficient = 0.577;  ///< mu of unbonded elements (residual friction)
  int n_elements = 2;                   ///< N_r >= 2 (else bending never enters the strength test)
  double radius_multiplier = 1.0;       ///< lambda: R = lambda min(R1, R2)
  double tan_friction_angle = 0.46630765815499858;  ///< tan(phi), derived by validated() (hot loop)

  /// Checks every field; throws InputError naming "<path>.<key>" with the unit of the JSON key.
  static FlatJointParams validated(const FlatJointParams& raw, const std::string& path);
};

/// Per-joint constants fixed at installation.
struct FlatJointGeometry {
  double half_length_m;     ///< R = lambda min(R1, R2)
  double thickness_m;       ///< out-of-plane thickness t
  double normal_stiffness;  ///< k_n [Pa/m] (stress per gap length)
  double shear_stiffness;   ///< k_s = k_n / kappabar* [Pa/m]
};

/// k_n = Ebar* / (R1 + R2); for a disk-wall joint pass r2 = 0 (L = R1).
FlatJointGeometry flat_joint_geometry(const FlatJointParams& p, double r1_m, double r2_m, double thickness_m);

/// Relative motion of the interface since installation, in the contact frame (n from disk 1 to 2).
struct FlatJointKinematics {
  double gap_m;              ///< g_s: normal gap at the interface centre (opening positive), zero when installed
  double rotation_rad;       ///< theta_b = theta2 - theta1 since installation
  double shear_increment_m;  ///< d_s: shear displacement increment of this step (surface 2 relative to 1, along s)
};

/// Resultant on disk 2 about the interface centre; disk 1 gets the opposite (physics-dem.md eq. 1).
struct FlatJointResult {
  double normal_force_n = 0;  ///< sum F_n,e, tension positive: the force on disk 2 is -F_n n + F_s s
  double shear_force_n = 0;   ///< sum F_s,e along s, on disk 2
  double moment_nm = 0;       ///< sum (F_n,e xi_e + M_e) on disk 2 about the interface centre
  int n_breaking = 0;         ///< elements found over strength this step (applied later by the caller)
};

/// Break mode of an element, as recorded in crack events.
enum class BreakMode : std::uint8_t { none = 0, tension = 1, shear = 2 };

/// Advances the element shear forces by the increment and computes the interface resultant.
///
/// Bonded element: F_n,e = k_n A_e g_e (g_e = g_s - theta_b xi_e), M_e = -k_n theta_b t l_e^3 / 12,
/// F_s,e -= k_s A_e d_s; it is over strength in tension if F_n,e / A_e > sigma_c, else in shear if
/// |F_s,e| / A_e >= c - sigma tan(phi). Unbonded element: only the closed part of the gap carries load,
/// F_n,e = k_n t int_e min(g(xi), 0) dxi, with Coulomb friction |F_s,e| <= mu |F_n,e|.
/// `breaks[e]` is set for elements over strength; the caller applies them after the whole force loop
/// (physics-dem.md section 1), so this function never changes `bonded`.
/// Defined in the header so that the engine's joint loop inlines it: a cut runs 11-18 % faster than with the
/// call (same results to the bit; docs/performance.md).
inline FlatJointResult flat_joint_update(const FlatJointParams& p, const FlatJointGeometry& geo,
                                         const FlatJointKinematics& kin, std::span<double> shear_force_n,
                                         std::span<const std::uint8_t> bonded, std::span<BreakMode> breaks) {
  const int nr = p.n_elements;
  const double le = 2.0 * geo.half_length_m / nr;
  const double area = le * geo.thickness_m;
  const double kn_t = geo.normal_stiffness * geo.thickness_m;  // force per gap per interface length
  const double ks_area = geo.shear_stiffness * area;
  const double theta = kin.rotation_rad;
  const double tan_phi = p.tan_friction_angle;
  FlatJointResult r;
  for (int e = 0; e < nr; ++e) {
    const double a = -geo.half_length_m + e * le;
    const double xi_e = a + 0.5 * le;
    double fn, me;
    double fs = shear_force_n[e] - ks_area * kin.shear_increment_m;  // incremental shear
    breaks[e] = BreakMode::none;
    if (bonded[e]) {
      // Bonded: the whole element is a linear spring, tension or compression.
      fn = kn_t * le * (kin.gap_m - theta * xi_e);
      me = -kn_t * theta * le * le * le / 12.0;
      const double sigma = fn / area;
      const double tau = std::abs(fs) / area;
      if (sigma > p.tensile_strength_pa) {
        breaks[e] = BreakMode::tension;
        ++r.n_breaking;
      } else if (tau >= p.cohesion_pa - sigma * tan_phi) {
        breaks[e] = BreakMode::shear;
        ++r.n_breaking;
      }
    } else {
      // Unbonded: only the closed part of g(xi) = g_s - theta xi carries load (cut at the zero of g).
      const double b = a + le;
      const double ga = kin.gap_m - theta * a, gb = kin.gap_m - theta * b;
      double c = a, d = b;
      if (ga >= 0 && gb >= 0) {
        c = d = a;
      } else if (ga < 0 && gb > 0) {
        d = kin.gap_m / theta;
      } else if (ga > 0 && gb < 0) {
        c = kin.gap_m / theta;
      }
      if (d > c) {
        const double gc = kin.gap_m - theta * c, gd = kin.gap_m - theta * d;
        const double integral = 0.5 * (gc + gd) * (d - c);  // int min(g, 0) dxi (<= 0)
        const double m = 0.5 * (c + d);
        fn = kn_t * integral;
        me = kn_t * (integral * (m - xi_e) - theta * (d - c) * (d - c) * (d - c) / 12.0);
        const double limit = p.friction_coefficient * std::abs(fn);
        fs = std::clamp(fs, -limit, limit);  // Coulomb sliding
      } else {
        fn = me = fs = 0.0;  // open: no contact, no friction
      }
    }
    shear_force_n[e] = fs;
    r.normal_force_n += fn;
    r.shear_force_n += fs;
    r.moment_nm += fn * xi_e + me;
  }
  return r;
}

/// flat_joint_update for the intact joint of the default interface: N_r = 2 and both elements bonded (nearly
/// every joint of a cut). The same operations on the same values in the same order, hence the same result to
/// the bit, but the two elements' normal, strength and shear arithmetic runs as two-lane vector operations,
/// the bending moment, equal for both elements, is computed once, and the stresses (two divisions) are formed
/// only for a joint near a strength envelope. The divisions dominated the joint loop;
/// tests/dem/flat_joint_test.cpp checks the equality, on random joints and ulp by ulp across the envelopes.
/// Requires p.n_elements == 2 and both elements bonded (the caller tests it).
inline FlatJointResult flat_joint_update_two_bonded(const FlatJointParams& p, const FlatJointGeometry& geo,
                                                    const FlatJointKinematics& kin, double* shear_force_n,
                                                    BreakMode* breaks) {
  const double le = 2.0 * geo.half_length_m / 2;
  const double area = le * geo.thickness_m;
  const double kn_t = geo.normal_stiffness * geo.thickness_m;
  const double ks_area = geo.shear_stiffness * area;
  const double theta = kin.rotation_rad;
  // Element starts and centroids written as the general loop computes them (-R + e l_e), for the same bits.
  const double a0 = -geo.half_length_m + 0 * le, a1 = -geo.half_length_m + 1 * le;
  const v2d xi = {a0 + 0.5 * le, a1 + 0.5 * le};
  const v2d fs = v2d{shear_force_n[0], shear_force_n[1]} - ks_area * kin.shear_increment_m;
  const v2d fn = kn_t * le * (kin.gap_m - theta * xi);
  const double me = -kn_t * theta * le * le * le / 12.0;
  const v2d abs_fs = lane_abs(fs);
  FlatJointResult r;
  // Far from both strength envelopes (nearly every joint of every step) no element can break, and the
  // stresses need not be formed: the test is then made on forces, without the two divisions. The margin,
  // 1e-12 of the terms, is thousands of times the rounding error of either form (a few 1e-16 of the same
  // terms), so this filter only ever passes elements that the exact test below also leaves intact: the
  // break decisions, and so the results, are those of the stress test to the bit (tested near the
  // envelopes in tests/dem/flat_joint_test.cpp). NaN fails the filter and takes the exact test.
  //   tension: fl(fn / A) > sigma_c needs fn / A > sigma_c (rounding is monotone and sigma_c a double);
  //   shear:   fl(|fs| / A) >= fl(c - fl(sigma) tan phi) needs |fs| >= c A - fn tan phi up to a few
  //            rounding errors of c A + |fn| tan phi (both sides times A > 0).
  const double tension_bound = p.tensile_strength_pa * area * (1.0 - 1e-12);
  const double cohesion_force = p.cohesion_pa * area;
  const v2d fn_tan = fn * p.tan_friction_angle;
  const v2d envelope_scale = cohesion_force + lane_abs(fn_tan);
  const auto below_envelopes = (fn < tension_bound) & (abs_fs + 1e-12 * envelope_scale < cohesion_force - fn_tan);
  if (below_envelopes[0] && below_envelopes[1]) {
    breaks[0] = breaks[1] = BreakMode::none;
    shear_force_n[0] = fs[0], shear_force_n[1] = fs[1];
  } else {
    const v2d sigma = fn / area;
    const v2d tau = abs_fs / area;
    const v2d shear_limit = p.cohesion_pa - sigma * p.tan_friction_angle;
    for (int e = 0; e < 2; ++e) {
      breaks[e] = sigma[e] > p.tensile_strength_pa ? BreakMode::tension
                  : tau[e] >= shear_limit[e]       ? BreakMode::shear
                                                   : BreakMode::none;
      r.n_breaking += breaks[e] != BreakMode::none;
      shear_force_n[e] = fs[e];
    }
  }
  r.normal_force_n = 0.0 + fn[0] + fn[1];
  r.shear_force_n = 0.0 + fs[0] + fs[1];
  r.moment_nm = 0.0 + (fn[0] * xi[0] + me) + (fn[1] * xi[1] + me);
  return r;
}

/// Elastic energy stored in the bonded elements (normal, bending and shear springs), for energy checks.
double flat_joint_bonded_energy(const FlatJointParams& p, const FlatJointGeometry& geo, const FlatJointKinematics& kin,
                                std::span<const double> shear_force_n, std::span<const std::uint8_t> bonded);

/// Centroid xi_e of element e along the interface.
inline double flat_joint_element_centroid(const FlatJointGeometry& geo, int n_elements, int e) {
  const double le = 2.0 * geo.half_length_m / n_elements;
  return -geo.half_length_m + (e + 0.5) * le;
}

}  // namespace kerf::dem
