#include "kerf/analytic/flow_stress/thermal.hpp"

#include "kerf/error.hpp"
#include "kerf/json_reader.hpp"

namespace kerf {

void ThermalProperties::validate(const std::string& path, double temperature_lo_K, double temperature_hi_K) const {
  check_number(density_kg_per_m3, path + ".density_kg_per_m3", Range::positive(), "kg/m^3");
  for (double temperature : {temperature_lo_K, temperature_hi_K}) {
    const std::string at = " at " + format_value(temperature) + " K";
    check_number(conductivity_W_per_m_K.at(temperature), path + ".conductivity_W_per_m_K", Range::positive(),
                 "W/(m K)" + at);
    check_number(specific_heat_J_per_kg_K.at(temperature), path + ".specific_heat_J_per_kg_K", Range::positive(),
                 "J/(kg K)" + at);
  }
}

}  // namespace kerf
