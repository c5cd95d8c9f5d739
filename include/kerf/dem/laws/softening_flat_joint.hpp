#pragma once
// The softening flat joint: Potyondy's flat joint (kerf/dem/laws/flat_joint.hpp) whose bonded elements soften in
// tension after their strength instead of breaking at it, Hillerborg's fictitious crack (Hillerborg, Modeer and
// Petersson 1976) per element, with a linear softening as PFC's soft-bond model. One key more than the flat joint:
// the fracture energy G_f per unit element area (fracture_energy_J_per_m2). With G_f = 0 it is the flat joint, to
// the bit (tests/dem/softening_flat_joint_test.cpp runs both on one specimen).
//
// Per bonded element e (area A_e = l_e t, centroid xi_e): its opening g_e = g_s - theta_b xi_e (the flat joint's
// stress is sigma = k_n g_e) and a damage D_e in [0, 1], the law's state (zero at installation, kept by the engine
// per element, BondStore::element_state, as doubles it does not read), a function of the largest opening the element
// has reached:
//
//   g_0 = sigma_c / k_n           the opening at the strength (per bond: k_n = Ebar* / (R1 + R2))
//   w_c = 2 G_f / sigma_c         the softening opening (0 when sigma_c = 0: no strength, nothing to soften)
// (sigma_c and c times the joint's strength factor w with Weibull strengths: g_0 w, w_c / w; G_f is the material's)
//   g_f = g_0 + w_c               the opening at which the element carries no more tension
//   D(g) = 0 for g <= g_0,   1 - g_0 (g_f - g) / (g w_c) for g_0 < g < g_f,   1 for g >= g_f
//   D_e <- max(D_e, D(g_e))       (irreversible)
//
// so that on the envelope the stress (1 - D) k_n g = sigma_c (g_f - g) / w_c falls linearly from sigma_c at g_0 to
// zero at g_f. Opened from rest to g_f, an element takes the work sigma_c g_f / 2 per area:
//
//   W_e = A_e (sigma_c^2 / (2 k_n) + G_f),
//
// G_f being the energy beyond the flat joint's element (which, breaking at its strength, loses its stored
// sigma_c^2 / (2 k_n) per area). The softening slope in PFC's terms: a softening factor g_0 / w_c of k_n.
//
// A damaged bonded element (D > 0) along its length: the open part (g(xi) > 0) has the secant stiffness
// (1 - D) k_n, the closed part k_n (the crack closes; compression is undamaged):
//
//   F_n,e = C_n + (1 - D) (k_n A_e g_e - C_n),   M_e = C_m + (1 - D) (-k_n theta_b t l_e^3 / 12 - C_m),
//
// C the closed part's load (as an unbonded element's: element_closed_load). Unloading and reloading follow the
// secant, back to zero force at zero opening, until the opening passes the largest reached. Shear: stiffness
// (1 - D) k_s, the elastic shear displacement kept as D grows,
//
//   F_s,e <- F_s,e (1 - D_new) / (1 - D_old) - (1 - D_new) k_s A_e d_s,
//
// strength (1 - D) (c - sigma tan(phi)) with sigma = F_n,e / A_e: the flat joint's Coulomb envelope, scaled. (Scaling
// the cohesion alone, (1 - D) c - sigma tan(phi), would break every softening element in shear with no shear force
// at all once k_n g tan(phi) > c, about 1.2 g_0 for Yang et al. 2018's Table 1: the tensile softening would never
// finish.)
// Elastic energy of a damaged element: 1/2 k_n t [int min(g, 0)^2 + (1 - D) int max(g, 0)^2] + F_s^2 / (2 (1 - D)
// k_s A_e). An undamaged element whose stress stays within sigma_c is the flat joint's, to the bit (the same
// Coulomb envelope c - sigma tan(phi)). Breaks: in tension when D reaches 1 (g_e >= g_f), in shear on the damaged
// envelope; then exactly as the flat joint's (a crack event, an unbonded element carrying compression and
// friction; bond_element_broken sets its damage to 1 when the engine applies the break). The time step takes the
// undamaged stiffness, the largest.
//
//   SofteningFlatJointParams p = SofteningFlatJointParams::validated(raw);  // InputError naming the key
//   BondResult r = bond_update(p, geo, kin, shear, bonded, breaks, damage);   // damage: bond_elements(p) doubles
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <string_view>

#include "kerf/dem/laws/flat_joint.hpp"
#include "kerf/dem/laws/law.hpp"
#include "kerf/field_table.hpp"

namespace kerf::dem {

/// The flat joint's parameters (its keys, its defaults: the base) and the fracture energy.
struct SofteningFlatJointParams : FlatJointParams {
  static constexpr std::string_view kName = "softening_flat_joint";
  static constexpr std::string_view kDescription =
      "the flat joint with a linear tensile softening after its strength: a fracture energy per element area "
      "(Hillerborg's fictitious crack; dem/laws/softening_flat_joint)";
  double fracture_energy_J_per_m2 = 0;  ///< G_f per unit element area, beyond sigma_c^2 / (2 k_n)
  double softening_opening_m = 0;       ///< w_c = 2 G_f / sigma_c (0 when sigma_c = 0), derived by validated()
  /// The law's state per element (BondLawWithState): its damage D_e, one double that the engine keeps for it
  /// (BondStore::element_state) and a specimen file holds as "element_damage".
  static constexpr std::array<std::string_view, 1> kElementState{"damage"};

  /// The flat joint's keys, then fracture_energy_J_per_m2.
  static const FieldTable<SofteningFlatJointParams>& fields();
  /// Checks every field, derives tan(phi) and w_c; InputError names the key (e.g. "fracture_energy_J_per_m2").
  static SofteningFlatJointParams validated(const SofteningFlatJointParams& raw);
  bool operator==(const SofteningFlatJointParams&) const = default;
};

/// The closed part [c, d] of element [a, a + l_e] under the gap profile g(xi) = g_s - theta xi: where g < 0, cut at
/// the zero of g when it changes sign inside; c = d when the element is open everywhere. The flat joint's
/// unbonded-element arithmetic, operation for operation (flat_joint_update keeps its own copy inline: its machine
/// code is measured; tests/dem/softening_flat_joint_test.cpp checks the two to the bit).
struct ClosedPart {
  double start_m, end_m;  ///< c, d along s
};
inline ClosedPart element_closed_part(double gap_m, double theta, double a, double le) {
  const double b = a + le;
  const double ga = gap_m - theta * a, gb = gap_m - theta * b;
  double c = a, d = b;
  if (ga >= 0 && gb >= 0) {
    c = d = a;
  } else if (ga < 0 && gb > 0) {
    d = gap_m / theta;
  } else if (ga > 0 && gb < 0) {
    c = gap_m / theta;
  }
  return {c, d};
}

/// The load of a closed part [c, d] (d > c) of an element: F_n = k_n t int_c^d g dxi (<= 0, compression) and its
/// moment about the element's centroid xi_e; `kn_t` = k_n t.
struct ElementLoad {
  double normal_force_N, moment_N_m;
};
inline ElementLoad element_closed_load(double kn_t, double gap_m, double theta, const ClosedPart& part, double xi_e) {
  const double c = part.start_m, d = part.end_m;
  const double gc = gap_m - theta * c, gd = gap_m - theta * d;
  const double integral = 0.5 * (gc + gd) * (d - c);  // int min(g, 0) dxi (<= 0)
  const double m = 0.5 * (c + d);
  return {kn_t * integral, kn_t * (integral * (m - xi_e) - theta * (d - c) * (d - c) * (d - c) / 12.0)};
}

/// D(g) of the header for an element of a bond of normal stiffness k_n and strength factor w at opening g: the
/// joint's strength w sigma_c and softening opening 2 G_f / (w sigma_c) (its fracture energy is the material's).
inline double softening_damage(const SofteningFlatJointParams& p, const BondGeometry& geo, double opening_m) {
  const double w_c = p.softening_opening_m / geo.strength_factor;
  const double g0 = p.bond.tensile_strength_Pa * geo.strength_factor / geo.normal_stiffness, gf = g0 + w_c;
  if (!(opening_m > g0)) return 0.0;
  if (!(opening_m < gf)) return 1.0;
  return std::clamp(1.0 - g0 * (gf - opening_m) / (opening_m * w_c), 0.0, 1.0);
}

/// The softening flat joint's update (the header's equations): element shear forces advanced, the damage of every
/// bonded element advanced in place, the interface resultant returned; `breaks[e]` flags the elements that break
/// (the caller applies them after the whole loop, as the flat joint's). Undamaged elements within their strength
/// give the flat joint's numbers to the bit.
inline BondResult softening_flat_joint_update(const SofteningFlatJointParams& p, const BondGeometry& geo,
                                              const BondKinematics& kin, std::span<double> shear_force_N,
                                              std::span<const std::uint8_t> bonded, std::span<BreakMode> breaks,
                                              std::span<double> damage) {
  const int nr = p.n_elements;
  const double le = 2.0 * geo.half_length_m / nr;
  const double area = le * geo.thickness_m;
  const double kn_t = geo.normal_stiffness * geo.thickness_m;
  const double ks_area = geo.shear_stiffness * area;
  const double theta = kin.rotation_rad;
  const double tan_phi = p.tan_friction_angle;
  const double sigma_c = p.bond.tensile_strength_Pa * geo.strength_factor;  // this joint's strengths, as the flat
  const double cohesion = p.bond.cohesion_Pa * geo.strength_factor;         // joint forms them
  BondResult r;
  for (int e = 0; e < nr; ++e) {
    const double a = -geo.half_length_m + e * le;
    const double xi_e = a + 0.5 * le;
    double fn, me;
    double fs = shear_force_N[e] - ks_area * kin.shear_increment_m;  // incremental shear (undamaged)
    breaks[e] = BreakMode::none;
    if (bonded[e]) {
      // The flat joint's bonded element first: force, moment and stress, the same operations in the same order.
      fn = kn_t * le * (kin.gap_m - theta * xi_e);
      me = -kn_t * theta * le * le * le / 12.0;
      const double sigma = fn / area;
      if (damage[e] == 0 && !(sigma > sigma_c && p.softening_opening_m > 0)) {
        // Undamaged and within its tensile strength (or without softening): the flat joint's element.
        const double tau = std::abs(fs) / area;
        if (sigma > sigma_c) {
          breaks[e] = BreakMode::tension;
          ++r.n_breaking;
        } else if (tau >= cohesion - sigma * tan_phi) {
          breaks[e] = BreakMode::shear;
          ++r.n_breaking;
        }
      } else {
        // Softening: the damage from the largest opening, the open part at the secant stiffness.
        const double d_old = damage[e];
        const double d = std::max(d_old, softening_damage(p, geo, kin.gap_m - theta * xi_e));
        damage[e] = d;
        const ClosedPart closed = element_closed_part(kin.gap_m, theta, a, le);
        const ElementLoad c = closed.end_m > closed.start_m ? element_closed_load(kn_t, kin.gap_m, theta, closed, xi_e)
                                                            : ElementLoad{0.0, 0.0};
        fn = c.normal_force_N + (1 - d) * (fn - c.normal_force_N);
        me = c.moment_N_m + (1 - d) * (me - c.moment_N_m);
        const double keep = d_old < 1 ? (1 - d) / (1 - d_old) : 0.0;
        fs = keep * shear_force_N[e] - (1 - d) * ks_area * kin.shear_increment_m;
        if (d >= 1) {
          breaks[e] = BreakMode::tension;
          ++r.n_breaking;
        } else if (std::abs(fs) / area >= (1 - d) * (cohesion - fn / area * tan_phi)) {
          breaks[e] = BreakMode::shear;
          ++r.n_breaking;
        }
      }
    } else {
      // Unbonded: the flat joint's element (the closed part carries compression, with Coulomb friction).
      const ClosedPart closed = element_closed_part(kin.gap_m, theta, a, le);
      if (closed.end_m > closed.start_m) {
        const ElementLoad load = element_closed_load(kn_t, kin.gap_m, theta, closed, xi_e);
        fn = load.normal_force_N;
        me = load.moment_N_m;
        const double limit = p.residual_friction_coefficient * std::abs(fn);
        fs = std::clamp(fs, -limit, limit);
      } else {
        fn = me = fs = 0.0;
      }
    }
    shear_force_N[e] = fs;
    r.normal_force_N += fn;
    r.shear_force_N += fs;
    r.moment_N_m += fn * xi_e + me;
  }
  return r;
}

/// Elastic energy stored in the bonded elements, damaged ones at their secant stiffness (the header's formula).
double softening_flat_joint_bonded_energy(const SofteningFlatJointParams& p, const BondGeometry& geo,
                                          const BondKinematics& kin, std::span<const double> shear_force_N,
                                          std::span<const std::uint8_t> bonded, std::span<const double> damage);

// --- the law's functions for the engine (kerf/dem/laws/contact_laws.hpp, concept BondLawParams) ---
// The flat joint's own serve where they take the base (bond_elements, bond_keeps_contact, bond_retires_on_break,
// bond_geometry, bond_retires, bond_time_step_stiffness, bond_element_place); the update and the energy take the
// damage, and the flat joint's, without it, are deleted for this law so that no caller can take them by mistake.

inline BondResult bond_update(const SofteningFlatJointParams& p, const BondGeometry& geo, const BondKinematics& kin,
                              double* shear_force_N, const std::uint8_t* bonded, BreakMode* breaks, double* damage) {
  const auto n = static_cast<std::size_t>(p.n_elements);
  return softening_flat_joint_update(p, geo, kin, {shear_force_N, n}, {bonded, n}, {breaks, n}, {damage, n});
}
BondResult bond_update(const SofteningFlatJointParams&, const BondGeometry&, const BondKinematics&, double*,
                       const std::uint8_t*, BreakMode*) = delete;

inline double bond_energy(const SofteningFlatJointParams& p, const BondGeometry& geo, const BondKinematics& kin,
                          const double* shear_force_N, const std::uint8_t* bonded, const double* damage) {
  const auto n = static_cast<std::size_t>(p.n_elements);
  return softening_flat_joint_bonded_energy(p, geo, kin, {shear_force_N, n}, {bonded, n}, {damage, n});
}
double bond_energy(const SofteningFlatJointParams&, const BondGeometry&, const BondKinematics&, const double*,
                   const std::uint8_t*) = delete;

/// An element whose break the engine applies: wholly damaged (`damage`: its one double of state).
inline void bond_element_broken(const SofteningFlatJointParams&, double* damage) {
  *damage = 1;
}

}  // namespace kerf::dem
