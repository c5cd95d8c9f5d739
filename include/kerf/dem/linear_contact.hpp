#pragma once
// The linear contact for disk-disk contacts that never had a joint and for disk-wall contacts
// (physics-dem.md section 1, last paragraph): F_n = k_n overlap, k_n = A E* / L with A = 2 min(R) t and
// L = R1 + R2 (disk-wall: L = R1), k_s = k_n / kappa*, incremental shear limited by Coulomb friction.
//
//   LinearContactParams p = LinearContactParams::validated(raw, "material");
//   LinearContactResult f = linear_contact_update(p, r1, r2, t, overlap_m, ds_m, shear_state_n);
#include <string>

namespace kerf::dem {

struct LinearContactParams {
  double effective_modulus_pa = 107e9;  ///< E*
  double stiffness_ratio = 3.1;         ///< kappa* = k_n / k_s
  double friction_coefficient = 0.577;  ///< mu

  static LinearContactParams validated(const LinearContactParams& raw, const std::string& path);
};

/// Normal stiffness k_n [N/m]; r2_m = 0 for a disk-wall contact.
double linear_normal_stiffness(const LinearContactParams& p, double r1_m, double r2_m, double thickness_m);

struct LinearContactResult {
  double normal_force_n = 0;  ///< compression positive (pushes disk 2 away from disk 1 along n)
  double shear_force_n = 0;   ///< on disk 2 along s = z x n
};

/// Updates the stored shear force with the increment `shear_increment_m` (surface 2 relative to 1 along s)
/// and returns the contact force. Overlap <= 0 means no contact: the shear force is reset to zero.
LinearContactResult linear_contact_update(const LinearContactParams& p, double r1_m, double r2_m, double thickness_m,
                                          double overlap_m, double shear_increment_m, double& shear_force_n);

}  // namespace kerf::dem
