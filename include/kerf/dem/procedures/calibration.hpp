#pragma once
// Automatic calibration of the micro-parameters to macro-properties (Yang et al. 2018, Section 3; physics-dem.md
// section 3): E, nu, tensile and compressive strength, each within a tolerance.
//
// Method. Two trends are exact for a linear-elastic-brittle assembly loaded quasi-statically: scaling all
// moduli (E*, Ebar*) by a scales E and leaves nu and the strengths unchanged; scaling both bond strengths
// (sigma_c, c) by b scales both strengths and leaves E and nu unchanged. So after every evaluation E* is
// corrected by E_target / E and sigma_c, c by sigma_t,target / sigma_t. What remains is a 2-D root problem
// in log variables, x = (ln kappa*, ln(c / sigma_c)) (kappa* = kappabar*), f = (ln nu - ln nu_target,
// ln R - ln R_target) with R = sigma_c,macro / sigma_t,macro. Two solvers (CalibrationSpec::method):
//  - hybrid: GSL's gsl_multiroot_fdfsolver_hybridsj (Powell's hybrid dogleg with a trust region). Its
//    Jacobian comes from the near-proportional trends, diagonal (d ln nu / d ln kappa from 0.8, d ln R /
//    d ln(c / sigma_c) from 0.6, re-estimated by secants through the evaluation history whenever GSL asks
//    for a fresh one; between those GSL updates it by Broyden), so no DEM evaluation is spent on finite
//    differences. Variables are clamped to their ranges inside the function.
//  - secant: a hand-written diagonal secant iteration with capped steps (the method before the hybrid).
// Evaluations are memoised by their exact micro-parameters (a repeated point is not re-run, and is not
// counted against max_evaluations), and `known` answers evaluations from an interrupted run: calibrate is
// deterministic given its answers, so a resumed calibration repeats the uninterrupted one exactly.
// Each candidate is evaluated on the specimen its SpecimenSource builds for it: from a genesis, the specimen a
// scene with the same spec and that material builds, to the bit (the packing does not depend on the material).
//
// A fifth target, the fracture toughness (issue 37; docs/dem.md, "Fracture toughness"): with a toughness test
// (CalibrationSpec::toughness, its beams from their own SpecimenSources) each candidate also runs the notched
// beam, and K_IC is a target within its own tolerance. Its lever is the softening flat joint's fracture energy
// G_f (free_fracture_energy). Its exact trend: with w_c / g_0 = 2 G_f k_n / sigma_c^2 fixed, i.e. G_f scaled by
// b^2 / a when the strengths are scaled by b and the moduli by a, every force of the assembly scales by b and
// every length it moves by b / a, so K_IC scales by b and K_IC / sigma_t does not move. G_f follows the two
// corrections so (for any softening glass being calibrated), and a third iterated variable remains,
// ln lambda with lambda = G_f Ebar* / sigma_c^2 (a length: w_c / g_0 times half the bond's R1 + R2), and a third
// residual, ln(K_IC / sigma_t) - ln(K_IC / sigma_t)_target (its trend slope 0.12, measured on the steady cut's
// glass between G_f = 1.8 and 5.4 J/m^2: docs/notes/2026-11-29-softening-joint.md).
//
//   std::vector<SpecimenSource> sources{SpecimenSource::genesis(compact_packing(spec), spec, EngineSettings{})};
//   CalibrationResult r = calibrate(sources, start_material, cal, [](const CalibrationEvaluation& e) { ... });
//   // after a kill: the evaluations saved by serialize_evaluations are answered, not re-run
//   CalibrationResult same = calibrate(sources, start_material, cal, on_evaluation, deserialize_evaluations(bytes));
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "kerf/dem/engine/simulation.hpp"
#include "kerf/dem/laws/material.hpp"
#include "kerf/dem/procedures/lab_test.hpp"
#include "kerf/dem/procedures/specimen.hpp"
#include "kerf/dem/procedures/toughness.hpp"

namespace kerf::dem {

struct MacroProperties {
  double youngs_modulus_Pa = 0, poissons_ratio = 0, tensile_strength_Pa = 0, compressive_strength_Pa = 0;
  double fracture_toughness_Pa_sqrt_m = 0;  ///< K_IC of the toughness test; 0: not measured (as a target: none)
};

/// The calibration's fifth test: a notched beam (its specimen from the calibration's own SpecimenSources for
/// beams) and the local damping it runs with.
struct ToughnessCalibration {
  ToughnessSpec test;
  std::optional<double> local_damping;  ///< the beam's local damping; unset: the candidate's own
};

enum class CalibrationMethod { hybrid, secant };

struct CalibrationSpec {
  MacroProperties targets{71e9, 0.23, 41e6, 330e6};  ///< Yang et al. 2018, Table 2
  bool free_modulus = true;                          ///< effective_modulus_GPa (with bond_effective_modulus_GPa)
  bool free_stiffness_ratio = true;                  ///< stiffness_ratio (with bond_stiffness_ratio)
  bool free_tensile_strength = true;                 ///< tensile_strength_MPa (cohesion scaled with it)
  bool free_cohesion = true;                         ///< cohesion_MPa
  double tolerance = 0.03;                           ///< relative, on each of the four
  int max_evaluations = 24;                          ///< DEM evaluations (memoised repeats are free)
  CalibrationMethod method = CalibrationMethod::hybrid;
  /// Packings a candidate is evaluated on (the scene's seed and the next ones): its macro-properties are their
  /// mean, so the calibration centres the population of specimens rather than one packing.
  int packings = 1;
  LoadingSpec tension, compression;
  /// The toughness test: K_IC measured on every candidate (the mean over the beams' packings), a target when
  /// targets.fracture_toughness_Pa_sqrt_m > 0.
  std::optional<ToughnessCalibration> toughness;
  bool free_fracture_energy = false;  ///< fracture_energy_J_per_m2 (softening_flat_joint): the toughness's lever
  double toughness_tolerance = 0.10;  ///< relative, on K_IC
};

struct CalibrationEvaluation {
  int index = 0;
  Material material;
  MacroProperties macro;
  double max_relative_error = 0;  ///< of the four lab-test properties
  double toughness_error = 0;     ///< |K_IC / K_IC,target - 1|; 0 without a toughness target
  double wall_time_s = 0;
  bool from_checkpoint = false;  ///< answered from `known` (wall_time_s is the original run's)
};

struct CalibrationResult {
  Material material;  ///< the best evaluated material
  MacroProperties macro;
  double max_relative_error = 0;  ///< of the four lab-test properties
  double toughness_error = 0;     ///< of K_IC; 0 without a toughness target
  bool converged = false;
  std::vector<CalibrationEvaluation> log;
};

/// Runs tension (for sigma_t) and compression (for E, nu, sigma_c) on copies of the specimen (its material).
MacroProperties measure_macro_properties(const Simulation& specimen, const LoadingSpec& tension,
                                         const LoadingSpec& compression);

/// Largest relative deviation of the four properties from the targets.
double max_relative_error(const MacroProperties& got, const MacroProperties& target);

/// The mean macro-properties of `m` over the sources' specimens (one tension and one compression test each).
MacroProperties mean_macro_properties(std::span<const SpecimenSource> sources, const Material& m,
                                      const LoadingSpec& tension, const LoadingSpec& compression);

/// The mean K_IC of `m` over the beams' specimens (one toughness test each, with the test's damping).
double mean_fracture_toughness(std::span<const SpecimenSource> beams, const Material& m, const ToughnessCalibration& t);

/// InputError unless a free fracture energy has a softening joint with G_f > 0 to start from and a toughness
/// target with its test.
void check_calibration_start(const CalibrationSpec& spec, const Material& start);

/// `sources`: the packings each candidate is evaluated on (their mean; CalibrationSpec::packings of them).
/// `known`: evaluations of an interrupted run of the same calibration (same specimens, start and spec); an
/// evaluation whose micro-parameters equal one of them bit for bit takes its result instead of running.
/// `beams`: the toughness test's packings (required with CalibrationSpec::toughness).
/// check_calibration_start(spec, start) first.
CalibrationResult calibrate(std::span<const SpecimenSource> sources, const Material& start, const CalibrationSpec& spec,
                            const std::function<void(const CalibrationEvaluation&)>& on_evaluation = {},
                            const std::vector<CalibrationEvaluation>& known = {},
                            std::span<const SpecimenSource> beams = {});

/// Bit-exact binary form of a list of evaluations (native endianness: read back by the same build), for
/// checkpoints of a calibration.
std::string serialize_evaluations(const std::vector<CalibrationEvaluation>& log);
std::vector<CalibrationEvaluation> deserialize_evaluations(std::string_view bytes);

}  // namespace kerf::dem
