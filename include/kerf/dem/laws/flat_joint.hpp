#pragma once
// The 2D flat-joint contact (Potyondy 2012, 2015; docs/physics-dem.md section 1), as pure functions of
// validated parameters and per-contact state.
//
// The interface between disks 1 and 2 is a segment of half-length R = lambda min(R1, R2) centred at the
// contact point, split into N_r equal elements. Element e has length l_e = 2R / N_r, area A_e = l_e t and
// centroid xi_e along the tangent s = z x n. Normal gap and relative rotation are measured from the
// installed state (the joint starts stress free), so g(xi) = g_s - theta_b xi.
//
//   FlatJointParams p = FlatJointParams::validated(raw);   // InputError naming the key, e.g. "cohesion_MPa"
//   BondGeometry geo = bond_geometry(p, r1, r2, thickness_m);
//   BondResult res = flat_joint_update(p, geo, {gap_m, rotation_rad, shear_increment_m}, shear, bonded, breaks);
//
// The law functions the engine calls (bond_update, bond_retires, ...; kerf/dem/laws/contact_laws.hpp) are below;
// the engine's two-lane path for intact two-element joints is internal (dem/laws/flat_joint_simd.hpp).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <string_view>

#include "kerf/dem/laws/law.hpp"
#include "kerf/field_table.hpp"

namespace kerf::dem {

/// Micro-parameters of the flat joint (docs/physics-dem.md section 1). SI units; the defaults are Yang et al. 2018's
/// Table 1.
struct FlatJointParams {
  static constexpr std::string_view kName = "flat_joint";
  static constexpr std::string_view kDescription = "Potyondy's 2D flat joint (dem/laws/flat_joint)";
  BondStiffnessStrength bond;  ///< Ebar*, kappabar*, sigma_c, c, phi (bonded-element Coulomb envelope), lambda
  double residual_friction_coefficient = 0.577;     ///< mu of unbonded elements (residual friction)
  int n_elements = 2;                               ///< N_r >= 2 (else bending never enters the strength test)
  double tan_friction_angle = 0.46630765815499858;  ///< tan(phi), derived by validated() (hot loop)

  /// The keys, units, ranges and meanings of the parameters (the material's keys for this law).
  static const FieldTable<FlatJointParams>& fields();
  /// Checks every field and derives tan(phi); InputError names the key (e.g. "n_elements").
  static FlatJointParams validated(const FlatJointParams& raw);
  bool operator==(const FlatJointParams&) const = default;
};

/// k_n = Ebar* / (R1 + R2); for a disk-wall joint pass r2 = 0 (L = R1).
BondGeometry bond_geometry(const FlatJointParams& p, double r1_m, double r2_m, double thickness_m);

/// Advances the element shear forces by the increment and computes the interface resultant.
///
/// Bonded element: F_n,e = k_n A_e g_e (g_e = g_s - theta_b xi_e), M_e = -k_n theta_b t l_e^3 / 12,
/// F_s,e -= k_s A_e d_s; it is over strength in tension if F_n,e / A_e > sigma_c, else in shear if
/// |F_s,e| / A_e >= c - sigma tan(phi) (both strengths times the joint's factor w, BondGeometry). Unbonded element:
/// only the closed part of the gap carries load, F_n,e = k_n t int_e min(g(xi), 0) dxi, with Coulomb friction |F_s,e|
/// <= mu |F_n,e|. `breaks[e]` is set for elements over strength; the caller applies them after the whole force loop
/// (docs/physics-dem.md section 1), so this function never changes `bonded`.
/// Defined in the header so that the engine's joint loop inlines it: a cut runs 11-18 % faster than with the
/// call (same results to the bit; docs/performance.md).
inline BondResult flat_joint_update(const FlatJointParams& p, const BondGeometry& geo, const BondKinematics& kin,
                                    std::span<double> shear_force_N, std::span<const std::uint8_t> bonded,
                                    std::span<BreakMode> breaks) {
  const int nr = p.n_elements;
  const double le = 2.0 * geo.half_length_m / nr;
  const double area = le * geo.thickness_m;
  const double kn_t = geo.normal_stiffness * geo.thickness_m;  // force per gap per interface length
  const double ks_area = geo.shear_stiffness * area;
  const double theta = kin.rotation_rad;
  const double tan_phi = p.tan_friction_angle;
  const double sigma_c = p.bond.tensile_strength_Pa * geo.strength_factor;  // this joint's strengths (w = 1: the
  const double cohesion = p.bond.cohesion_Pa * geo.strength_factor;         // material's, to the bit)
  BondResult r;
  for (int e = 0; e < nr; ++e) {
    const double a = -geo.half_length_m + e * le;
    const double xi_e = a + 0.5 * le;
    double fn, me;
    double fs = shear_force_N[e] - ks_area * kin.shear_increment_m;  // incremental shear
    breaks[e] = BreakMode::none;
    if (bonded[e]) {
      // Bonded: the whole element is a linear spring, tension or compression.
      fn = kn_t * le * (kin.gap_m - theta * xi_e);
      me = -kn_t * theta * le * le * le / 12.0;
      const double sigma = fn / area;
      const double tau = std::abs(fs) / area;
      if (sigma > sigma_c) {
        breaks[e] = BreakMode::tension;
        ++r.n_breaking;
      } else if (tau >= cohesion - sigma * tan_phi) {
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
        const double limit = p.residual_friction_coefficient * std::abs(fn);
        fs = std::clamp(fs, -limit, limit);  // Coulomb sliding
      } else {
        fn = me = fs = 0.0;  // open: no contact, no friction
      }
    }
    shear_force_N[e] = fs;
    r.normal_force_N += fn;
    r.shear_force_N += fs;
    r.moment_N_m += fn * xi_e + me;
  }
  return r;
}

/// Elastic energy stored in the bonded elements (normal, bending and shear springs), for energy checks.
double flat_joint_bonded_energy(const FlatJointParams& p, const BondGeometry& geo, const BondKinematics& kin,
                                std::span<const double> shear_force_N, std::span<const std::uint8_t> bonded);

/// Centroid xi_e of element e along the interface.
inline double flat_joint_element_centroid(const BondGeometry& geo, int n_elements, int e) {
  const double le = 2.0 * geo.half_length_m / n_elements;
  return -geo.half_length_m + (e + 0.5) * le;
}

// --- the law's functions for the engine (kerf/dem/laws/contact_laws.hpp, concept BondLawParams) ---

/// State per bond: N_r elements (shear force and bonded flag each).
inline int bond_elements(const FlatJointParams& p) {
  return p.n_elements;
}
/// The flat joint replaces the unbonded contact of its pair: a broken element carries compression itself.
constexpr bool bond_keeps_contact(const FlatJointParams&) {
  return false;
}
/// Broken elements stay in the joint (compression and friction), so a break does not end the joint.
constexpr bool bond_retires_on_break(const FlatJointParams&) {
  return false;
}

inline BondResult bond_update(const FlatJointParams& p, const BondGeometry& geo, const BondKinematics& kin,
                              double* shear_force_N, const std::uint8_t* bonded, BreakMode* breaks) {
  const auto n = static_cast<std::size_t>(p.n_elements);
  return flat_joint_update(p, geo, kin, {shear_force_N, n}, {bonded, n}, {breaks, n});
}

/// A fully broken joint whose interface is open everywhere (g_s - |theta_b| R > 0) and whose disks no longer
/// overlap carries no force under either model: the engine hands the pair over to the unbonded contact.
/// The predictable test first: almost every joint still has a bonded element, while the sign of the surface
/// gap is a coin toss (a mispredicted branch per joint).
inline bool bond_retires(const FlatJointParams& p, const BondGeometry& geo, const BondKinematics& kin,
                         const BondResult& r, double surface_gap_m, const std::uint8_t* bonded) {
  for (int e = 0; e < p.n_elements; ++e)
    if (bonded[e]) return false;  // nearly every joint: at e = 0
  return r.n_breaking == 0 && surface_gap_m > 0 && kin.gap_m > std::abs(kin.rotation_rad) * geo.half_length_m;
}

/// The interface as one strip (interface_time_step_stiffness).
inline TimeStepStiffness bond_time_step_stiffness(const FlatJointParams&, const BondGeometry& g) {
  return interface_time_step_stiffness(g);
}

inline double bond_energy(const FlatJointParams& p, const BondGeometry& geo, const BondKinematics& kin,
                          const double* shear_force_N, const std::uint8_t* bonded) {
  const auto n = static_cast<std::size_t>(p.n_elements);
  return flat_joint_bonded_energy(p, geo, kin, {shear_force_N, n}, {bonded, n});
}

inline ElementPlace bond_element_place(const FlatJointParams& p, const BondGeometry& geo, int e) {
  return {flat_joint_element_centroid(geo, p.n_elements, e), 2 * geo.half_length_m / p.n_elements};
}

}  // namespace kerf::dem
