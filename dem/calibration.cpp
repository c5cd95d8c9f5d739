// Calibration of micro-parameters: exact proportional trends plus GSL trust-region least squares.
#include "kerf/dem/calibration.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_multifit_nlinear.h>
#include <gsl/gsl_matrix.h>
#include <gsl/gsl_vector.h>

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

// Optimiser variables (log space, so that a step is a relative change): ln kappa and/or ln(c / sigma_c),
// clamped to ranges where the trends hold (c >= sigma_c: below it the tensile strength follows c, not
// sigma_c, and sigma_c,macro / sigma_t,macro stops responding).
constexpr double kKappaMin = 1.2, kKappaMax = 10.0, kRatioMin = 1.0, kRatioMax = 12.0;
constexpr double kJacobianStep = 0.1;  // in ln: 10 %

Material apply_variables(const Context& ctx, const gsl_vector* x) {
  Material m = ctx.current;
  std::size_t k = 0;
  if (ctx.spec->free_stiffness_ratio) {
    const double kappa = std::clamp(std::exp(gsl_vector_get(x, k++)), kKappaMin, kKappaMax);
    m.contact.stiffness_ratio = m.joint.stiffness_ratio = kappa;
  }
  if (ctx.spec->free_cohesion) {
    const double ratio = std::clamp(std::exp(gsl_vector_get(x, k++)), kRatioMin, kRatioMax);
    m.joint.cohesion_pa = ratio * m.joint.tensile_strength_pa;
  }
  m.joint = FlatJointParams::validated(m.joint, "material");
  return m;
}

/// Residuals ln(nu / nu_t) and ln(R / R_t) with R = sigma_c,macro / sigma_t,macro.
void fill_residuals(const Context& ctx, const MacroProperties& got, gsl_vector* f) {
  const auto& t = ctx.spec->targets;
  std::size_t k = 0;
  if (ctx.spec->free_stiffness_ratio) gsl_vector_set(f, k++, std::log(got.poissons_ratio / t.poissons_ratio));
  if (ctx.spec->free_cohesion)
    gsl_vector_set(f, k++, std::log((got.compressive_strength_pa / got.tensile_strength_pa) /
                                    (t.compressive_strength_pa / t.tensile_strength_pa)));
}

int residuals(const gsl_vector* x, void* params, gsl_vector* f) {
  auto& ctx = *static_cast<Context*>(params);
  if (ctx.done) return GSL_EBADFUNC;  // stop the solver: converged or out of evaluations
  fill_residuals(ctx, evaluate(ctx, apply_variables(ctx, x)), f);
  return GSL_SUCCESS;
}

/// Forward differences with a 10 % step (the DEM response is not smooth on finer scales, so GSL's
/// default step of sqrt(epsilon) would measure noise).
int jacobian(const gsl_vector* x, void* params, gsl_matrix* J) {
  auto& ctx = *static_cast<Context*>(params);
  const std::size_t n = x->size;
  gsl_vector* f0 = gsl_vector_alloc(n);
  gsl_vector* f1 = gsl_vector_alloc(n);
  gsl_vector* xs = gsl_vector_alloc(n);
  int status = residuals(x, params, f0);
  for (std::size_t j = 0; j < n && status == GSL_SUCCESS; ++j) {
    gsl_vector_memcpy(xs, x);
    gsl_vector_set(xs, j, gsl_vector_get(x, j) + kJacobianStep);
    status = residuals(xs, params, f1);
    for (std::size_t i = 0; i < n && status == GSL_SUCCESS; ++i)
      gsl_matrix_set(J, i, j, (gsl_vector_get(f1, i) - gsl_vector_get(f0, i)) / kJacobianStep);
  }
  gsl_vector_free(f0);
  gsl_vector_free(f1);
  gsl_vector_free(xs);
  (void)ctx;
  return status;
}

}  // namespace

CalibrationResult calibrate(const Simulation& specimen, const Material& start, const CalibrationSpec& spec,
                            const std::function<void(const CalibrationEvaluation&)>& on_evaluation) {
  Context ctx{&specimen, &spec, &on_evaluation, start, {}, false};
  // First the exact proportional trends alone, from the start material.
  evaluate(ctx, start);
  const std::size_t n = (spec.free_stiffness_ratio ? 1u : 0u) + (spec.free_cohesion ? 1u : 0u);
  if (n == 0) {
    while (!ctx.done) evaluate(ctx, ctx.current);
    return ctx.result;
  }
  gsl_set_error_handler_off();  // failures come back as status codes
  gsl_multifit_nlinear_parameters params = gsl_multifit_nlinear_default_parameters();
  params.trs = gsl_multifit_nlinear_trs_lm;
  gsl_multifit_nlinear_workspace* w = gsl_multifit_nlinear_alloc(gsl_multifit_nlinear_trust, &params, n, n);
  gsl_vector* x = gsl_vector_alloc(n);
  std::size_t k = 0;
  if (spec.free_stiffness_ratio)
    gsl_vector_set(x, k++, std::log(std::clamp(start.joint.stiffness_ratio, kKappaMin, kKappaMax)));
  if (spec.free_cohesion)
    gsl_vector_set(x, k++, std::log(std::clamp(start.joint.cohesion_pa / start.joint.tensile_strength_pa, kRatioMin, kRatioMax)));
  gsl_multifit_nlinear_fdf fdf{};
  fdf.f = residuals;
  fdf.df = jacobian;
  fdf.fvv = nullptr;
  fdf.n = n;
  fdf.p = n;
  fdf.params = &ctx;
  int status = ctx.done ? GSL_EBADFUNC : gsl_multifit_nlinear_init(x, &fdf, w);
  while (status == GSL_SUCCESS && !ctx.done) {
    status = gsl_multifit_nlinear_iterate(w);
    if (status == GSL_ENOPROG) {  // no progress from the trust region: try the corrected material as is
      gsl_vector_memcpy(x, gsl_multifit_nlinear_position(w));
      status = gsl_multifit_nlinear_init(x, &fdf, w);
    }
  }
  gsl_vector_free(x);
  gsl_multifit_nlinear_free(w);
  return ctx.result;
}

}  // namespace kerf::dem
