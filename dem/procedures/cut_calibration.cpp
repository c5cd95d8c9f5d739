// Calibration to one measured cut: the strength factor and its update (see the header).
#include "kerf/dem/procedures/cut_calibration.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "kerf/error.hpp"

namespace kerf::dem {

Material scale_bond_strengths(const Material& m, double factor, const std::string& name) {
  if (!(factor > 0) || !std::isfinite(factor))
    throw ModelError("dem", fmt::format("bond strength factor {} is not a positive number", factor));
  if (factor == 1) return m;
  Material out = m;
  out.name = name;
  std::visit(
      [&](auto& j) {
        j.bond.tensile_strength_Pa *= factor;
        j.bond.cohesion_Pa *= factor;
      },
      out.joint);
  return out;
}

double next_strength_factor(const std::vector<CutCalibrationPoint>& history, double target_main_force_N) {
  if (history.empty()) throw ModelError("dem", "cut calibration: no evaluation to step from");
  const CutCalibrationPoint& last = history.back();
  if (!(last.main_force_N > 0) || !std::isfinite(last.main_force_N))
    throw ModelError("dem", fmt::format("cut calibration: the mean main force at strength factor {} is {} N; it must "
                                        "be positive to scale the strengths towards {} N",
                                        last.strength_factor, last.main_force_N, target_main_force_N));
  double slope = 1;
  for (auto it = history.rbegin() + 1; it != history.rend(); ++it) {
    if (it->strength_factor == last.strength_factor || !(it->main_force_N > 0)) continue;
    const double p =
        std::log(last.main_force_N / it->main_force_N) / std::log(last.strength_factor / it->strength_factor);
    if (std::isfinite(p)) slope = std::clamp(p, 0.5, 2.0);
    break;
  }
  const double step = std::clamp(std::pow(target_main_force_N / last.main_force_N, 1 / slope), 0.25, 4.0);
  return last.strength_factor * step;
}

}  // namespace kerf::dem
