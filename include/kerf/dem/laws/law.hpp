#pragma once
// What the DEM's contact laws share: the types a law's functions take and return. A law is a parameter
// struct (validated once) and pure functions of it, overloaded on that struct; the engine calls them from
// loops instantiated once per law (kerf/dem/laws/contact_laws.hpp lists the laws and the functions each supplies;
// docs/dem-contact-laws.md says how to add one).
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "kerf/field_table.hpp"

namespace kerf::dem {

/// Break mode of a bond element, as recorded in crack events.
enum class BreakMode : std::uint8_t { none = 0, tension = 1, shear = 2 };

/// Per-bond constants fixed at installation, as the engine stores them for every bond. Every bond law of kerf bonds
/// a 2D interface: a strip of half-length R across the contact, out-of-plane thickness t, with normal and shear
/// stiffness per area.
struct BondInterface {
  double half_length_m;     ///< R = lambda min(R1, R2)
  double thickness_m;       ///< out-of-plane thickness t
  double normal_stiffness;  ///< k_n [Pa/m] (stress per gap length)
  double shear_stiffness;   ///< k_s [Pa/m]
};

/// What the law functions take: the interface and the joint's strength factor w, its strengths being w sigma_c and
/// w c (Weibull-distributed joint strengths, drawn once per joint when a specimen is made: draw_joint_strengths;
/// 1 for every joint of a material without a Weibull modulus). The engine keeps the factors apart from the
/// interfaces (BondStore::strength_factor), and none without a modulus: its joint loop reads no more memory then.
struct BondGeometry : BondInterface {
  double strength_factor = 1.0;
};

/// The stiffness and strength every bond law of kerf has (the concept BondLawParams requires it as the member
/// `bond`), with one field table: what calibration moves and reports, by name, whatever the law. SI; the
/// defaults are Yang et al. 2018's Table 1.
struct BondStiffnessStrength {
  double effective_modulus_Pa = 107e9;             ///< Ebar*: k_n = Ebar* / (R1 + R2)
  double stiffness_ratio = 3.1;                    ///< kappabar* = k_n / k_s
  double tensile_strength_Pa = 200e6;              ///< sigma_c
  double cohesion_Pa = 113e6;                      ///< c
  double friction_angle_rad = 0.4363323129985824;  ///< phi (25 deg) of the shear envelope c - sigma tan(phi)
  double radius_multiplier = 1.0;                  ///< lambda: R = lambda min(R1, R2)
  /// m of the joints' Weibull-distributed strengths (0: every joint has sigma_c and c): a joint of half-length R
  /// gets w sigma_c and w c, w drawn with mean (R_ref / R)^(1/m) (weibull_strength_factor).
  double strength_weibull_modulus = 0;
  double strength_reference_half_length_m = 10 * 1e-6;  ///< R_ref (10 um as the key reads it): mean strength sigma_c

  /// The keys of the block (each bond law's table embeds it: kerf::embedded_fields).
  static const FieldTable<BondStiffnessStrength>& fields();
  bool operator==(const BondStiffnessStrength&) const = default;
};

/// The bonded interface of both registered bond laws: k_n = Ebar* / (R1 + R2) (r2 = 0: a disk-wall bond,
/// L = R1), k_s = k_n / kappabar*, half-length R = lambda min(R1, R2).
inline BondGeometry interface_geometry(double effective_modulus_Pa, double stiffness_ratio, double radius_multiplier,
                                       double r1_m, double r2_m, double thickness_m) {
  const double r_min = r2_m > 0 ? std::min(r1_m, r2_m) : r1_m;
  const double kn = effective_modulus_Pa / (r1_m + r2_m);
  return {{radius_multiplier * r_min, thickness_m, kn, kn / stiffness_ratio}, 1.0};
}
inline BondGeometry interface_geometry(const BondStiffnessStrength& b, double r1_m, double r2_m, double thickness_m) {
  return interface_geometry(b.effective_modulus_Pa, b.stiffness_ratio, b.radius_multiplier, r1_m, r2_m, thickness_m);
}

/// The strength factor w of a joint of half-length R (docs/physics-dem.md, "Weibull joint strengths"): the
/// weakest-link law of a volume V, P_f(sigma) = 1 - exp(-(V / V_0) (sigma / sigma_0)^m), for a joint (V = 2 R t, t
/// the same for all) drawn by inversion from a uniform U in (0, 1):
///   w = (R_ref / R)^(1/m) (-ln U)^(1/m) / Gamma(1 + 1/m),
/// so that joints of half-length R_ref have mean strength sigma_c; formed in logarithms (finite for every m > 0:
/// a tiny m gives w = 0, the joint as weak as can be, never NaN). m = 0: 1 whatever U.
inline double weibull_strength_factor(const BondStiffnessStrength& b, double half_length_m, double uniform) {
  const double m = b.strength_weibull_modulus;
  if (m == 0) return 1.0;
  return std::exp((std::log(b.strength_reference_half_length_m / half_length_m) + std::log(-std::log(uniform))) / m -
                  std::lgamma(1 + 1 / m));
}

/// Relative motion of a bonded interface since installation, in the contact frame (n from disk 1 to 2).
struct BondKinematics {
  double gap_m;              ///< g_s: normal gap at the interface centre (opening positive), zero when installed
  double rotation_rad;       ///< theta_b = theta2 - theta1 since installation
  double shear_increment_m;  ///< d_s: shear displacement increment of this step (surface 2 relative to 1, along s)
};

/// Resultant of a bond on disk 2 about the interface centre; disk 1 gets the opposite.
struct BondResult {
  double normal_force_N = 0;  ///< tension positive: the force on disk 2 is -F_n n + F_s s
  double shear_force_N = 0;   ///< along s, on disk 2
  double moment_N_m = 0;      ///< on disk 2 about the interface centre
  int n_breaking = 0;         ///< elements found over strength this step (applied after the force loop)
};

/// Where element e of a bond lies along the interface (a crack event's place and length).
struct ElementPlace {
  double centroid_m;  ///< xi_e along s from the interface centre
  double length_m;    ///< l_e
};

/// Stiffnesses a contact adds to each of its two disks for the stable time step: normal and shear
/// translational [N/m], and the rotational stiffness of the contact itself (bending) [N m/rad].
struct TimeStepStiffness {
  double normal, shear, bending;
};

/// The interface as one strip 2R x t: k_n 2R t, k_s 2R t and the bending stiffness k_n t (2R)^3 / 12.
inline TimeStepStiffness interface_time_step_stiffness(const BondGeometry& g) {
  const double len = 2 * g.half_length_m, t = g.thickness_m;
  return {g.normal_stiffness * len * t, g.shear_stiffness * len * t, g.normal_stiffness * t * len * len * len / 12.0};
}

/// Force of an unbonded contact on disk 2.
struct ContactResult {
  double normal_force_N = 0;  ///< compression positive (pushes disk 2 away from disk 1 along n)
  double shear_force_N = 0;   ///< along s = z x n
};

}  // namespace kerf::dem
