#include "kerf/analytic/flow_stress/johnson_cook.hpp"

#include <cmath>

#include "kerf/error.hpp"
#include "kerf/json_reader.hpp"
#include "kerf/units.hpp"

namespace kerf {

void JohnsonCookParams::validate(const std::string& path) const {
  const auto field = [&](const char* name) { return path + "." + name; };
  check_field(units::pa_to_mpa(A_Pa), path, "A_MPa", Range::non_negative(), "MPa");
  check_field(units::pa_to_mpa(B_Pa), path, "B_MPa", Range::non_negative(), "MPa");
  check_field(n, path, "n", Range{0.0, 1.5, true, false}, "");
  check_field(C, path, "C", Range::non_negative(), "");
  check_field(m, path, "m", Range::positive(), "");
  check_field(reference_strain_rate_per_s, path, "reference_strain_rate_per_s", Range::positive(), "1/s");
  check_field(room_temperature_K, path, "room_temperature_K", Range::positive(), "K");
  check_field(melting_temperature_K, path, "melting_temperature_K", Range::above(room_temperature_K),
              "K (above room_temperature_K)");
  if (A_Pa + B_Pa <= 0.0) throw InputError(field("A_MPa"), "0", "A + B > 0 (a material with strength)");
}

double johnson_cook_hardening(const JohnsonCookParams& jc, double strain, Guards* guards) {
  if (!(strain >= 0.0) || !std::isfinite(strain)) {
    throw InputError("strain", format_value(strain), "a finite, non-negative plastic strain");
  }
  if (strain == 0.0) {
    raise(guards, Guard::zero_strain);
    return jc.A_Pa;
  }
  return jc.A_Pa + jc.B_Pa * std::pow(strain, jc.n);
}

double johnson_cook_rate_factor(const JohnsonCookParams& jc, const JohnsonCookPolicy& policy, double strain_rate_per_s,
                                Guards* guards) {
  if (!(strain_rate_per_s >= 0.0) || !std::isfinite(strain_rate_per_s)) {
    throw InputError("strain_rate_per_s", format_value(strain_rate_per_s), "a finite, non-negative strain rate");
  }
  const double ratio = strain_rate_per_s / jc.reference_strain_rate_per_s;
  if (policy.strain_rate == StrainRatePolicy::power_law) {
    if (ratio < 1.0) raise(guards, Guard::strain_rate_below_reference);
    return std::pow(1.0 + ratio, jc.C);
  }
  if (ratio < 1.0) {
    // ln(ratio) < 0 would weaken the material and turn the factor negative below exp(-1/C).
    raise(guards, Guard::strain_rate_below_reference);
    return 1.0;
  }
  return 1.0 + jc.C * std::log(ratio);
}

double johnson_cook_thermal_factor(const JohnsonCookParams& jc, const JohnsonCookPolicy& policy, double temperature_K,
                                   Guards* guards) {
  if (!std::isfinite(temperature_K) || temperature_K <= 0.0) {
    throw InputError("temperature_K", format_value(temperature_K), "a finite absolute temperature > 0 K");
  }
  if (temperature_K >= jc.melting_temperature_K) {
    raise(guards, Guard::temperature_at_or_above_melt);
    return 0.0;
  }
  if (temperature_K < jc.room_temperature_K) {
    if (policy.cold == ColdPolicy::error) {
      throw InputError("temperature_K", format_value(temperature_K),
                       "a temperature at or above the Johnson-Cook room temperature " +
                           format_value(jc.room_temperature_K) + " K (policy 'error')");
    }
    // pow() of a negative T* is NaN for non-integer m: use T* = 0 (no softening).
    raise(guards, Guard::temperature_below_room);
    return 1.0;
  }
  const double homologous =
      (temperature_K - jc.room_temperature_K) / (jc.melting_temperature_K - jc.room_temperature_K);
  // m = 1 is the common case (steels, aluminium, SiC here); pow() is a fifth of an Oxley solve's time.
  return 1.0 - (jc.m == 1.0 ? homologous : std::pow(homologous, jc.m));
}

double johnson_cook_stress(const JohnsonCookParams& jc, const JohnsonCookPolicy& policy, double strain,
                           double strain_rate_per_s, double temperature_K, Guards* guards) {
  const double thermal = johnson_cook_thermal_factor(jc, policy, temperature_K, guards);
  return johnson_cook_hardening(jc, strain, guards) * johnson_cook_rate_factor(jc, policy, strain_rate_per_s, guards) *
         thermal;
}

}  // namespace kerf
