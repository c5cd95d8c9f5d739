#pragma once
// Calibration to one measured cut (physics-dem.md section 3, last item: flat-joint parameters calibrated on
// tension and compression need not predict cutting forces; a published fused-silica study re-fitted them
// against one measured cut). kerf-dem fits one number, a factor s on both bond strengths (sigma_c and c):
// by the exact trend of calibration.hpp it scales both macro strengths by s and leaves E and nu unchanged,
// so the fitted material keeps the calibrated stiffness and strength ratio and its strengths are known
// without a new test. The fit drives the mean main force over replicate cuts to a target.
//
//   Material fitted = scale_bond_strengths(calibrated, 1.7, "glass_cut_fitted");
//   double s_next = next_strength_factor({{1.0, 8.45}}, 14.98);  // 1.77: forces taken proportional to s
#include <string>
#include <vector>

#include "kerf/dem/laws/material.hpp"

namespace kerf::dem {

/// The material with sigma_c and c multiplied by `factor` (> 0) and the given name; factor 1 returns `m`
/// itself, name included (so that runs of the unscaled material are recognised as the same runs).
Material scale_bond_strengths(const Material& m, double factor, const std::string& name);

/// One evaluation of a cut calibration: the strength factor and the mean main force it gave.
struct CutCalibrationPoint {
  double strength_factor = 1;
  double main_force_N = 0;
};

/// The next strength factor, s_next = s (F_target / F)^(1 / p) from the last point, with p = d ln F / d ln s
/// the secant slope through the last two points of different factor, kept in [0.5, 2]: replicate means
/// scatter by 10-30 % (docs/dem.md), so a raw secant through two of them can point anywhere. With one point
/// p = 1: quasi-static brittle forces scale with the strengths. The step is capped at a factor 4 either way.
/// Throws ModelError on a non-positive or non-finite force (nothing to scale).
double next_strength_factor(const std::vector<CutCalibrationPoint>& history, double target_main_force_N);

}  // namespace kerf::dem
