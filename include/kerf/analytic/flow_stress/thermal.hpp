#pragma once
// Thermal properties of a workpiece, each linear in temperature (constant when the slope is zero):
//
//   kerf::LinearInTemperature k{.value_at_reference = 52.61, .slope_per_K = -0.0281, .reference_K = 273.15};
//   double k_at_600K = k.at(600.0);   // W/(m K)
#include <string>

namespace kerf {

struct LinearInTemperature {
  double value_at_reference = 0.0;
  double slope_per_K = 0.0;
  double reference_K = 273.15;

  double at(double temperature_K) const { return value_at_reference + slope_per_K * (temperature_K - reference_K); }
};

struct ThermalProperties {
  double density_kg_per_m3 = 0.0;
  LinearInTemperature conductivity_W_per_m_K;
  LinearInTemperature specific_heat_J_per_kg_K;

  /// Throws InputError naming `path`.<field> unless density > 0 and conductivity and specific heat are
  /// positive at `temperature_lo_K` and `temperature_hi_K` (the range a model will use them in).
  void validate(const std::string& path, double temperature_lo_K, double temperature_hi_K) const;
};

}  // namespace kerf
