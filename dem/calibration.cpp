// Calibration of micro-parameters: exact proportional trends plus GSL trust-region least squares.
#include "kerf/dem/calibration.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "kerf/dem/specimen.hpp"
#include "kerf/error.hpp"

namespace kerf::dem {

MacroProperties measure_macro_properties(const Simulation& specimen, const Material& m, const LoadingSpec& tension,
                                         const LoadingSpec& compression) {
  const Simulation sim = with_material(specimen, m);
  const LabTestResult t = run_lab_test(sim, tension);
  const LabTestResult c = run_lab_test(sim, compression);
  return {c.youngs_modulus_pa, c.poissons_ratio, t.peak_stress_pa, c.peak_stress_pa};
}

double max_relative_error(const MacroProperties& got, const MacroProperties& target) {
  return std::max({std::abs(got.youngs_modulus_pa / target.youngs_modulus_pa - 1),
                   std::abs(got.poissons_ratio / target.poissons_ratio - 1),
                   std::abs(got.tensile_strength_pa / target.tensile_strength_pa - 1),
                   std::abs(got.compressive_strength_pa / target.compressive_strength_pa - 1)});
}

namespace {

struct Context {
  const Simulation* specimen;
  const CalibrationSpec* spec;
  const std::function<void(const CalibrationEvaluation&)>* on_evaluation;
  Material current;  ///< E* and sigma_c here carry the proportional corrections
  CalibrationResult result;
  bool done = false;
};

/// Evaluates `m`, logs it, keeps the best, and applies the proportional corrections to ctx.current.
MacroProperties evaluate(Context& ctx, const Material& m) {
  const auto start = std::chrono::steady_clock::now();
  CalibrationEvaluation e;
  e.index = static_cast<int>(ctx.result.log.size());
  e.material = m;
  e.macro = measure_macro_properties(*ctx.specimen, m, ctx.spec->tension, ctx.spec->compression);
  e.max_relative_error = max_relative_error(e.macro, ctx.spec->targets);
  e.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ctx.result.log.push_back(e);
  if (ctx.result.log.size() == 1 || e.max_relative_error < ctx.result.max_relative_error) {
    ctx.result.material = m;
    ctx.result.macro = e.macro;
    ctx.result.max_relative_error = e.max_relative_error;
  }
  if (*ctx.on_evaluation) (*ctx.on_evaluation)(e);
  if (e.max_relative_error <= ctx.spec->tolerance) ctx.done = ctx.result.converged = true;
  if (static_cast<int>(ctx.result.log.size()) >= ctx.spec->max_evaluations) ctx.done = true;
  if (!(e.macro.youngs_modulus_pa > 0 && e.macro.tensile_strength_pa > 0 && e.macro.compressive_strength_pa > 0))
    throw ModelError("calibrate", "a test gave no usable curve (zero modulus or strength)");
  // Exact trends (see the header): E ~ E*, both strengths ~ (sigma_c, c) at a fixed c / sigma_c.
  const auto& t = ctx.spec->targets;
  if (ctx.spec->free_modulus) {
    const double a = t.youngs_modulus_pa / e.macro.youngs_modulus_pa;
    ctx.current.contact.effective_modulus_pa = m.contact.effective_modulus_pa * a;
    ctx.current.joint.effective_modulus_pa = m.joint.effective_modulus_pa * a;
  }
  if (ctx.spec->free_tensile_strength) {
    const double b = t.tensile_strength_pa / e.macro.tensile_strength_pa;
    ctx.current.joint.tensile_strength_pa = m.joint.tensile_strength_pa * b;
    ctx.current.joint.cohesion_pa = m.joint.cohesion_pa * b;
  }
  return e.macro;
}

// Ranges of the two iterated variables (c >= sigma_c: below it the tensile strength follows c, not
// sigma_c, and sigma_c,macro / sigma_t,macro stops responding).
constexpr double kKappaMin = 1.2, kKappaMax = 10.0, kRatioMin = 1.0, kRatioMax = 12.0;


}  // namespace

CalibrationResult calibrate(const Simulation& specimen, const Material& start, const CalibrationSpec& spec,
                            const std::function<void(const CalibrationEvaluation&)>& on_evaluation) {
  Context ctx{&specimen, &spec, &on_evaluation, start, {}, false};
  const std::size_t n = (spec.free_stiffness_ratio ? 1u : 0u) + (spec.free_cohesion ? 1u : 0u);
  if (n == 0) {
    while (!ctx.done) evaluate(ctx, ctx.current);
    return ctx.result;
  }
  // Diagonal quasi-Newton (secant) iteration in log variables: nu responds to kappa, R = sigma_c,macro /
  // sigma_t,macro to c / sigma_c (the off-diagonal responses are weak). Each slope starts from a trend
  // measured on the seed specimen and is re-estimated by the secant through the last two evaluations that
  // moved that variable; steps are capped (30 % in kappa, 40 % in c / sigma_c) because the response is not
  // smooth and its slope grows with c / sigma_c.
  const auto& t = spec.targets;
  const double ln_r_target = std::log(t.compressive_strength_pa / t.tensile_strength_pa);
  double ln_kappa = std::log(std::clamp(start.joint.stiffness_ratio, kKappaMin, kKappaMax));
  // Start at c / sigma_c >= 1.5: for c <~ sigma_c the strength ratio barely responds (see the header).
  double ln_ratio = std::log(std::clamp(start.joint.cohesion_pa / start.joint.tensile_strength_pa, 1.5, kRatioMax));
  double slope_nu = 0.8, slope_r = 0.6;  // d ln nu / d ln kappa, d ln R / d ln(c / sigma_c)
  double prev_ln_kappa = 0, prev_ln_nu = 0, prev_ln_ratio = 0, prev_ln_r = 0;
  bool have_prev = false;
  while (!ctx.done) {
    Material m = ctx.current;
    if (spec.free_stiffness_ratio) m.contact.stiffness_ratio = m.joint.stiffness_ratio = std::exp(ln_kappa);
    if (spec.free_cohesion) m.joint.cohesion_pa = std::exp(ln_ratio) * m.joint.tensile_strength_pa;
    m.joint = FlatJointParams::validated(m.joint, "material");
    const MacroProperties got = evaluate(ctx, m);
    const double ln_nu = std::log(got.poissons_ratio), ln_r = std::log(got.compressive_strength_pa / got.tensile_strength_pa);
    if (have_prev) {
      // Secant slopes, kept within physical bounds (both responses increase).
      if (std::abs(ln_kappa - prev_ln_kappa) > 0.02) slope_nu = std::clamp((ln_nu - prev_ln_nu) / (ln_kappa - prev_ln_kappa), 0.2, 3.0);
      if (std::abs(ln_ratio - prev_ln_ratio) > 0.02) slope_r = std::clamp((ln_r - prev_ln_r) / (ln_ratio - prev_ln_ratio), 0.15, 3.0);
    }
    prev_ln_kappa = ln_kappa, prev_ln_nu = ln_nu, prev_ln_ratio = ln_ratio, prev_ln_r = ln_r;
    have_prev = true;
    if (spec.free_stiffness_ratio)
      ln_kappa = std::clamp(ln_kappa + std::clamp((std::log(t.poissons_ratio) - ln_nu) / slope_nu, -0.3, 0.3),
                            std::log(kKappaMin), std::log(kKappaMax));
    if (spec.free_cohesion)
      ln_ratio = std::clamp(ln_ratio + std::clamp((ln_r_target - ln_r) / slope_r, -0.4, 0.4), std::log(kRatioMin),
                            std::log(kRatioMax));
  }
  return ctx.result;
}

}  // namespace kerf::dem
