#pragma once
// The linear contact for disk-disk contacts that never had a joint and for disk-wall contacts
// (docs/physics-dem.md section 1, last paragraph): F_n = k_n overlap, k_n = A E* / L with A = 2 min(R) t and
// L = R1 + R2 (disk-wall: L = R1), k_s = k_n / kappa*, incremental shear limited by Coulomb friction.
//
//   LinearContactParams p = LinearContactParams::validated(raw);
//   ContactResult f = contact_update(p, r1, r2, t, overlap_m, ds_m, shear_state_N);
#include <string_view>

#include "kerf/dem/laws/law.hpp"
#include "kerf/field_table.hpp"

namespace kerf::dem {

struct LinearContactParams {
  static constexpr std::string_view kName = "linear";
  static constexpr std::string_view kDescription = "linear spring with Coulomb friction (dem/laws/linear_contact)";
  double effective_modulus_Pa = 107e9;  ///< E*
  double stiffness_ratio = 3.1;         ///< kappa* = k_n / k_s
  double friction_coefficient = 0.577;  ///< mu

  /// The keys, units, ranges and meanings of the parameters (the material's keys for this law).
  static const FieldTable<LinearContactParams>& fields();
  /// Checks every field; InputError names the key.
  static LinearContactParams validated(const LinearContactParams& raw);
  bool operator==(const LinearContactParams&) const = default;
};

/// Normal stiffness k_n [N/m]; r2_m = 0 for a disk-wall contact.
double linear_normal_stiffness(const LinearContactParams& p, double r1_m, double r2_m, double thickness_m);

// --- the law's functions for the engine (kerf/dem/laws/contact_laws.hpp, concept ContactLawParams) ---

/// Updates the stored shear force with the increment `shear_increment_m` (surface 2 relative to 1 along s)
/// and returns the contact force. Overlap <= 0 means no contact: the shear force is reset to zero.
ContactResult contact_update(const LinearContactParams& p, double r1_m, double r2_m, double thickness_m,
                             double overlap_m, double shear_increment_m, double& shear_force_N);

/// k_n and k_s = k_n / kappa* (no rotational stiffness of its own).
inline TimeStepStiffness contact_time_step_stiffness(const LinearContactParams& p, double r1_m, double r2_m,
                                                     double thickness_m) {
  const double kn = linear_normal_stiffness(p, r1_m, r2_m, thickness_m);
  return {kn, kn / p.stiffness_ratio, 0.0};
}

/// Elastic energy: 1/2 k_n overlap^2 + 1/2 F_s^2 / k_s (zero when the disks do not touch).
double contact_energy(const LinearContactParams& p, double r1_m, double r2_m, double thickness_m, double overlap_m,
                      double shear_force_N);

/// The same contact with another friction coefficient (a tool face's own friction; frictionless genesis).
inline LinearContactParams with_friction(LinearContactParams p, double mu) {
  p.friction_coefficient = mu;
  return p;
}

}  // namespace kerf::dem
