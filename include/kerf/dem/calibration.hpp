#pragma once
// Automatic calibration of the micro-parameters to macro-properties (seed 000, Section 3; physics-dem.md
// section 3): E, nu, tensile and compressive strength, each within a tolerance.
//
// Method. Two trends are exact for a linear-elastic-brittle assembly loaded quasi-statically: scaling all
// moduli (E*, Ebar*) by a scales E and leaves nu and the strengths unchanged; scaling both bond strengths
// (sigma_c, c) by b scales both strengths and leaves E and nu unchanged. So after every evaluation E* is
// corrected by E_target / E and sigma_c, c by sigma_t,target / sigma_t. What remains are two nearly
// decoupled responses, solved together by a diagonal quasi-Newton (secant) iteration in log variables with
// capped steps: the stiffness ratio (kappa* = kappabar*) for nu, and the cohesion-to-tensile-strength
// ratio c / sigma_c for sigma_c,macro / sigma_t,macro. (GSL's Levenberg-Marquardt with a finite-difference
// Jacobian and its Nelder-Mead simplex were tried first: on the non-smooth DEM response both spent most
// evaluations on rejected or exploratory moves and did not reach 3 % within 16 evaluations; see docs/dem.md.)
//
//   CalibrationResult r = calibrate(specimen, start_material, spec, [](const CalibrationEvaluation& e) { ... });
#include <functional>
#include <string>
#include <vector>

#include "kerf/dem/lab_test.hpp"
#include "kerf/dem/material.hpp"
#include "kerf/dem/simulation.hpp"

namespace kerf::dem {

struct MacroProperties {
  double youngs_modulus_pa = 0, poissons_ratio = 0, tensile_strength_pa = 0, compressive_strength_pa = 0;
};

struct CalibrationSpec {
  MacroProperties targets{71e9, 0.23, 41e6, 330e6};  ///< seed 000 Table 2
  bool free_modulus = true;         ///< effective_modulus_GPa (with bond_effective_modulus_GPa)
  bool free_stiffness_ratio = true; ///< stiffness_ratio (with bond_stiffness_ratio)
  bool free_tensile_strength = true;///< tensile_strength_MPa (cohesion scaled with it)
  bool free_cohesion = true;        ///< cohesion_MPa
  double tolerance = 0.03;          ///< relative, on each of the four
  int max_evaluations = 24;
  LoadingSpec tension, compression;
};

struct CalibrationEvaluation {
  int index = 0;
  Material material;
  MacroProperties macro;
  double max_relative_error = 0;
  double wall_time_s = 0;
};

struct CalibrationResult {
  Material material;  ///< the best evaluated material
  MacroProperties macro;
  double max_relative_error = 0;
  bool converged = false;
  std::vector<CalibrationEvaluation> log;
};

/// Runs tension (for sigma_t) and compression (for E, nu, sigma_c) on a copy of the specimen with `m`.
MacroProperties measure_macro_properties(const Simulation& specimen, const Material& m, const LoadingSpec& tension,
                                         const LoadingSpec& compression);

/// Largest relative deviation of the four properties from the targets.
double max_relative_error(const MacroProperties& got, const MacroProperties& target);

CalibrationResult calibrate(const Simulation& specimen, const Material& start, const CalibrationSpec& spec,
                            const std::function<void(const CalibrationEvaluation&)>& on_evaluation = {});

}  // namespace kerf::dem
