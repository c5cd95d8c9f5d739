#pragma once
// The 2D parallel bond (Potyondy & Cundall 2004; docs/references.md): a finite strip of cement of
// half-width R = lambda min(R1, R2) across the contact, out-of-plane thickness t, area A = 2 R t and second
// moment I = t (2R)^3 / 12, acting in parallel with the unbonded (linear) contact of the same pair.
//
// Installed stress free, it carries F_n = k_n A g_s (tension positive), M = -k_n I theta_b and an
// incremental shear force F_s -= k_s A d_s. The largest stresses at the bond periphery are
//   sigma_max = F_n / A + |M| R / I,   tau_max = |F_s| / A;
// the bond breaks in tension when sigma_max > sigma_c, else in shear when tau_max >= c - (F_n / A) tan(phi)
// (the Coulomb envelope of Itasca's linear parallel bond model, which reduces to Potyondy & Cundall's shear
// strength c at phi = 0). A broken bond is removed at once, with its force, moment and stiffness; the
// pair then interacts through the unbonded contact alone. Unlike the flat joint, a bond has no residual
// elements: one element per bond, one crack event per break.
//
//   ParallelBondParams p = ParallelBondParams::validated(raw);
//   BondResult r = bond_update(p, bond_geometry(p, r1, r2, t), {gap_m, rotation_rad, ds_m}, &shear, &bonded, &mode);
#include <cmath>
#include <cstdint>
#include <string_view>

#include "kerf/dem/laws/law.hpp"
#include "kerf/field_table.hpp"

namespace kerf::dem {

struct ParallelBondParams {
  static constexpr std::string_view kName = "parallel_bond";
  static constexpr std::string_view kDescription =
      "Potyondy and Cundall's 2D parallel bond, beside the unbonded contact (dem/laws/parallel_bond)";
  BondStiffnessStrength bond;  ///< Ebar*, kappabar*, sigma_c (at the periphery), c, phi, lambda (R: the half-width)
  double tan_friction_angle = 0.46630765815499858;  ///< tan(phi), derived by validated()

  static const FieldTable<ParallelBondParams>& fields();
  /// Checks every field and derives tan(phi); InputError names the key.
  static ParallelBondParams validated(const ParallelBondParams& raw);
  bool operator==(const ParallelBondParams&) const = default;
};

/// k_n = Ebar* / (R1 + R2) (r2 = 0: a disk-wall bond, L = R1), k_s = k_n / kappabar*, R = lambda min(R1, R2).
BondGeometry bond_geometry(const ParallelBondParams& p, double r1_m, double r2_m, double thickness_m);

/// The bond's force and moment on disk 2 and its strength test (one element; see the header comment).
inline BondResult bond_update(const ParallelBondParams& p, const BondGeometry& geo, const BondKinematics& kin,
                              double* shear_force_N, const std::uint8_t* bonded, BreakMode* breaks) {
  breaks[0] = BreakMode::none;
  if (!bonded[0]) {  // removed at its break: carries nothing
    shear_force_N[0] = 0;
    return {};
  }
  const double r = geo.half_length_m, t = geo.thickness_m;
  const double area = 2 * r * t, inertia = t * (2 * r) * (2 * r) * (2 * r) / 12.0;
  BondResult res;
  res.normal_force_N = geo.normal_stiffness * area * kin.gap_m;
  res.moment_N_m = -geo.normal_stiffness * inertia * kin.rotation_rad;
  res.shear_force_N = shear_force_N[0] - geo.shear_stiffness * area * kin.shear_increment_m;
  shear_force_N[0] = res.shear_force_N;
  const double sigma_mean = res.normal_force_N / area;
  const double sigma_max = sigma_mean + std::abs(res.moment_N_m) * r / inertia;
  const double tau_max = std::abs(res.shear_force_N) / area;
  // This bond's strengths: the material's times its factor w (Weibull strengths; w = 1: the material's to the bit).
  if (sigma_max > p.bond.tensile_strength_Pa * geo.strength_factor)
    breaks[0] = BreakMode::tension;
  else if (tau_max >= p.bond.cohesion_Pa * geo.strength_factor - sigma_mean * p.tan_friction_angle)
    breaks[0] = BreakMode::shear;
  res.n_breaking = breaks[0] != BreakMode::none;
  return res;
}

// --- the law's functions for the engine (kerf/dem/laws/contact_laws.hpp, concept BondLawParams) ---

inline int bond_elements(const ParallelBondParams&) {
  return 1;
}
/// The bond acts in parallel with the unbonded contact of its pair (Potyondy & Cundall's bonded-particle model).
constexpr bool bond_keeps_contact(const ParallelBondParams&) {
  return true;
}
/// A broken bond is removed from the model at once.
constexpr bool bond_retires_on_break(const ParallelBondParams&) {
  return true;
}
inline bool bond_retires(const ParallelBondParams&, const BondGeometry&, const BondKinematics&, const BondResult&,
                         double, const std::uint8_t* bonded) {
  return !bonded[0];
}
/// k_n A, k_s A and the bending stiffness k_n I (interface_time_step_stiffness).
inline TimeStepStiffness bond_time_step_stiffness(const ParallelBondParams&, const BondGeometry& g) {
  return interface_time_step_stiffness(g);
}
/// 1/2 k_n A g^2 + 1/2 k_n I theta^2 + 1/2 F_s^2 / (k_s A) while bonded.
double bond_energy(const ParallelBondParams& p, const BondGeometry& geo, const BondKinematics& kin,
                   const double* shear_force_N, const std::uint8_t* bonded);
/// The whole bond: centred on the contact, 2R long.
inline ElementPlace bond_element_place(const ParallelBondParams&, const BondGeometry& geo, int) {
  return {0.0, 2 * geo.half_length_m};
}

}  // namespace kerf::dem
