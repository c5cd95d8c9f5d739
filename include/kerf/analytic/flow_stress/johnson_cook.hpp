#pragma once
// Johnson-Cook flow stress (Shao et al. 2013, Eq. 9; Berezvai et al. 2019, Eq. 6):
//
//   sigma = (A + B eps^n) (1 + C ln(epsdot / epsdot_0)) (1 - T*^m),   T* = (T - T_room) / (T_melt - T_room)
//
// with explicit policies where the equation leaves its domain (see guards.hpp):
//
//   kerf::JohnsonCookParams jc{.A_Pa = 553.1e6, .B_Pa = 600.8e6, .n = 0.234, .C = 0.0134, .m = 1.0,
//                              .reference_strain_rate_per_s = 1.0, .room_temperature_K = 298.15,
//                              .melting_temperature_K = 1733.15};
//   jc.validate("material.johnson_cook");
//   double sigma_Pa = kerf::johnson_cook_stress(jc, {}, 1.0, 1e4, 600.0, nullptr);
#include <string>

#include "kerf/analytic/guards.hpp"

namespace kerf {

struct JohnsonCookParams {
  double A_Pa = 0.0;  ///< yield stress
  double B_Pa = 0.0;  ///< hardening modulus
  double n = 1.0;     ///< hardening exponent
  double C = 0.0;     ///< strain-rate sensitivity
  double m = 1.0;     ///< thermal-softening exponent
  double reference_strain_rate_per_s = 1.0;
  double room_temperature_K = 293.15;
  double melting_temperature_K = 1700.0;

  /// Throws InputError naming `path`.<field> if a value is out of range (A >= 0, B >= 0, n in (0, 1.5],
  /// C >= 0, m > 0, rate_0 > 0, T_room > 0, T_melt > T_room).
  void validate(const std::string& path) const;
};

/// What to do where the Johnson-Cook equation leaves its domain.
enum class StrainRatePolicy {
  clamp,      ///< no rate effect below the reference rate (factor 1); the usual choice
  power_law,  ///< (1 + epsdot/epsdot_0)^C everywhere: smooth, positive, ~ the log form at high rates
};
enum class ColdPolicy {
  clamp,  ///< T < T_room uses T* = 0
  error,  ///< T < T_room is an InputError
};

struct JohnsonCookPolicy {
  StrainRatePolicy strain_rate = StrainRatePolicy::clamp;
  ColdPolicy cold = ColdPolicy::clamp;
};

/// A + B eps^n. eps < 0 is an InputError; eps = 0 raises Guard::zero_strain.
double johnson_cook_hardening(const JohnsonCookParams& jc, double strain, Guards* guards);
/// The strain-rate factor, >= 1 under both policies for rates at or above the reference.
double johnson_cook_rate_factor(const JohnsonCookParams& jc, const JohnsonCookPolicy& policy, double strain_rate_per_s,
                                Guards* guards);
/// 1 - T*^m clamped to [0, 1]; 0 at and above the melting temperature.
double johnson_cook_thermal_factor(const JohnsonCookParams& jc, const JohnsonCookPolicy& policy, double temperature_K,
                                   Guards* guards);
/// The product of the three factors, in Pa; never NaN for finite input.
double johnson_cook_stress(const JohnsonCookParams& jc, const JohnsonCookPolicy& policy, double strain,
                           double strain_rate_per_s, double temperature_K, Guards* guards);

}  // namespace kerf
