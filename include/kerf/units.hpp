#pragma once
// Unit conversions. SI inside the code; these run once, at input and output.
//
//   double rake_rad = kerf::units::deg_to_rad(-15.0);
//   double t0_m = kerf::units::um_to_m(1.5);
#include <numbers>

namespace kerf::units {

constexpr double deg_to_rad(double deg) {
  return deg * std::numbers::pi / 180.0;
}
constexpr double rad_to_deg(double rad) {
  return rad * 180.0 / std::numbers::pi;
}

constexpr double nm_to_m(double nm) {
  return nm * 1e-9;
}
constexpr double um_to_m(double um) {
  return um * 1e-6;
}
constexpr double mm_to_m(double mm) {
  return mm * 1e-3;
}
constexpr double m_to_nm(double m) {
  return m * 1e9;
}
constexpr double m_to_um(double m) {
  return m * 1e6;
}
constexpr double m_to_mm(double m) {
  return m * 1e3;
}
constexpr double n_per_mm_to_n_per_m(double f) {
  return f * 1e3;
}  ///< a force per unit width
constexpr double n_per_m_to_n_per_mm(double f) {
  return f * 1e-3;
}

constexpr double mpa_to_pa(double mpa) {
  return mpa * 1e6;
}
constexpr double gpa_to_pa(double gpa) {
  return gpa * 1e9;
}
constexpr double pa_to_mpa(double pa) {
  return pa * 1e-6;
}
constexpr double pa_to_gpa(double pa) {
  return pa * 1e-9;
}

constexpr double m_per_min_to_m_per_s(double v) {
  return v / 60.0;
}
constexpr double m_per_s_to_m_per_min(double v) {
  return v * 60.0;
}

constexpr double percent_to_fraction(double percent) {
  return percent / 100;
}
constexpr double fraction_to_percent(double fraction) {
  return 100 * fraction;
}

constexpr double celsius_to_kelvin(double c) {
  return c + 273.15;
}

}  // namespace kerf::units
