// Calibration of micro-parameters: exact proportional trends plus Powell's hybrid method (GSL) or a secant
// iteration on the remaining 2-D problem (see the header).
#include "kerf/dem/procedures/calibration.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <exception>
#include <memory>
#include <new>
#include <tuple>
#include <utility>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_multiroots.h>

#include "kerf/dem/procedures/specimen.hpp"
#include "../engine/serial.hpp"
#include "kerf/error.hpp"

namespace kerf::dem {

MacroProperties measure_macro_properties(const Simulation& specimen, const LoadingSpec& tension,
                                         const LoadingSpec& compression) {
  const LabTestResult t = run_lab_test(specimen, tension);
  const LabTestResult c = run_lab_test(specimen, compression);
  return {c.youngs_modulus_pa, c.poissons_ratio, t.peak_stress_pa, c.peak_stress_pa};
}

MacroProperties mean_macro_properties(std::span<const SpecimenSource> sources, const Material& m,
                                      const LoadingSpec& tension, const LoadingSpec& compression) {
  if (sources.empty()) throw ModelError("calibrate", "no specimen to evaluate a candidate on");
  MacroProperties sum{0, 0, 0, 0};
  for (const auto& source : sources) {
    const MacroProperties one = measure_macro_properties(source.for_material(m), tension, compression);
    sum.youngs_modulus_pa += one.youngs_modulus_pa;
    sum.poissons_ratio += one.poissons_ratio;
    sum.tensile_strength_pa += one.tensile_strength_pa;
    sum.compressive_strength_pa += one.compressive_strength_pa;
  }
  const double n = static_cast<double>(sources.size());
  return {sum.youngs_modulus_pa / n, sum.poissons_ratio / n, sum.tensile_strength_pa / n, sum.compressive_strength_pa / n};
}

double max_relative_error(const MacroProperties& got, const MacroProperties& target) {
  return std::max({std::abs(got.youngs_modulus_pa / target.youngs_modulus_pa - 1),
                   std::abs(got.poissons_ratio / target.poissons_ratio - 1),
                   std::abs(got.tensile_strength_pa / target.tensile_strength_pa - 1),
                   std::abs(got.compressive_strength_pa / target.compressive_strength_pa - 1)});
}

namespace {

struct Context {
  std::span<const SpecimenSource> sources;
  const CalibrationSpec* spec;
  const std::function<void(const CalibrationEvaluation&)>* on_evaluation;
  const std::vector<CalibrationEvaluation>* known;  ///< answers from an interrupted run
  Material current;  ///< E* and sigma_c here carry the proportional corrections
  CalibrationResult result;
  bool done = false;
  int repeats = 0;  ///< evaluations answered from this run's own log (no new information)
};

/// Evaluates `proposed` as its material file will hold it (or takes its result from this run's log or from
/// `known`), logs it, keeps the best, and applies the proportional corrections to ctx.current.
MacroProperties evaluate(Context& ctx, const Material& proposed) {
  // The file's units (GPa, MPa, degrees) can round the last bit of a value, and a brittle specimen's strength
  // answers even that (a 1-ulp change of E* moved the seed specimen's sigma_c by 0.6 %, 2026-11-26): the
  // candidate is evaluated as written, so that the calibrated file gives what the calibration reports.
  const Material m = read_material(material_to_json(proposed), "calibration candidate");
  for (const auto& e : ctx.result.log) {
    if (!same_micro_parameters(e.material, m)) continue;
    // A repeat tells nothing new: neither logged nor counted, and ctx.current keeps the later corrections.
    // Bounded, so that a solver circling among old points still ends.
    if (++ctx.repeats > ctx.spec->max_evaluations) ctx.done = true;
    return e.macro;
  }
  CalibrationEvaluation e;
  const auto known = std::find_if(ctx.known->begin(), ctx.known->end(),
                                  [&](const CalibrationEvaluation& k) { return same_micro_parameters(k.material, m); });
  if (known != ctx.known->end()) {
    e = *known;
    e.from_checkpoint = true;
  } else {
    const auto start = std::chrono::steady_clock::now();
    e.macro = mean_macro_properties(ctx.sources, m, ctx.spec->tension, ctx.spec->compression);
    e.max_relative_error = max_relative_error(e.macro, ctx.spec->targets);
    e.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  e.index = static_cast<int>(ctx.result.log.size());
  e.material = m;
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
    std::visit(
        [&](auto& c, auto& j, const auto& c0, const auto& j0) {
          c.effective_modulus_pa = c0.effective_modulus_pa * a;
          j.bond.effective_modulus_pa = j0.bond.effective_modulus_pa * a;
        },
        ctx.current.contact, ctx.current.joint, m.contact, m.joint);
  }
  if (ctx.spec->free_tensile_strength) {
    const double b = t.tensile_strength_pa / e.macro.tensile_strength_pa;
    std::visit(
        [&](auto& j, const auto& j0) {
          j.bond.tensile_strength_pa = j0.bond.tensile_strength_pa * b;
          j.bond.cohesion_pa = j0.bond.cohesion_pa * b;
        },
        ctx.current.joint, m.joint);
  }
  return e.macro;
}

// Ranges of the two iterated variables (c >= sigma_c: below it the tensile strength follows c, not
// sigma_c, and sigma_c,macro / sigma_t,macro stops responding).
constexpr double kKappaMin = 1.2, kKappaMax = 10.0, kRatioMin = 1.0, kRatioMax = 12.0;
// Trend slopes measured on the seed specimen: d ln nu / d ln kappa, d ln R / d ln(c / sigma_c); and the
// bounds a secant estimate is kept within (both responses increase; the R slope grows with c / sigma_c).
constexpr double kSlopeNu = 0.8, kSlopeR = 0.6, kSlopeNuMin = 0.2, kSlopeRMin = 0.15, kSlopeMax = 3.0;
// Smallest move of a variable (in ln) that a secant slope is taken over: below it DEM noise dominates.
constexpr double kSecantMinStep = 0.02;

/// The current material with kappa* = kappabar* = exp(ln_kappa) and c = exp(ln_ratio) sigma_c for the free
/// ones, clamped to their ranges.
Material material_at(const Context& ctx, double ln_kappa, double ln_ratio) {
  Material m = ctx.current;
  std::visit(
      [&](auto& contact, auto& joint) {
        if (ctx.spec->free_stiffness_ratio)
          contact.stiffness_ratio = joint.bond.stiffness_ratio =
              std::exp(std::clamp(ln_kappa, std::log(kKappaMin), std::log(kKappaMax)));
        if (ctx.spec->free_cohesion)
          joint.bond.cohesion_pa =
              std::exp(std::clamp(ln_ratio, std::log(kRatioMin), std::log(kRatioMax))) * joint.bond.tensile_strength_pa;
        joint = with_path("material", [&] { return std::decay_t<decltype(joint)>::validated(joint); });
      },
      m.contact, m.joint);
  return m;
}

double ln_strength_ratio(const MacroProperties& p) { return std::log(p.compressive_strength_pa / p.tensile_strength_pa); }

/// The start point in the log variables.
std::pair<double, double> start_point(const Material& start) {
  // c / sigma_c starts at >= 1.5: for c <~ sigma_c the strength ratio barely responds (see the ranges).
  const CalibratedParams j = calibrated_params(start);
  return {std::log(std::clamp(j.stiffness_ratio, kKappaMin, kKappaMax)),
          std::log(std::clamp(j.cohesion_pa / j.tensile_strength_pa, 1.5, kRatioMax))};
}

/// The secant iteration (CalibrationMethod::secant). Diagonal quasi-Newton in log variables: nu responds to
/// kappa, R to c / sigma_c (the off-diagonal responses are weak). Each slope starts from its trend and is
/// re-estimated by the secant through the last two evaluations that moved that variable; steps are capped
/// (30 % in kappa, 40 % in c / sigma_c) because the response is not smooth and its slope grows with c / sigma_c.
void solve_secant(Context& ctx) {
  const auto& spec = *ctx.spec;
  const auto& t = spec.targets;
  const double ln_r_target = std::log(t.compressive_strength_pa / t.tensile_strength_pa);
  auto [ln_kappa, ln_ratio] = start_point(ctx.current);
  double slope_nu = kSlopeNu, slope_r = kSlopeR;
  double prev_ln_kappa = 0, prev_ln_nu = 0, prev_ln_ratio = 0, prev_ln_r = 0;
  bool have_prev = false;
  while (!ctx.done) {
    const MacroProperties got = evaluate(ctx, material_at(ctx, ln_kappa, ln_ratio));
    const double ln_nu = std::log(got.poissons_ratio), ln_r = ln_strength_ratio(got);
    if (have_prev) {
      if (std::abs(ln_kappa - prev_ln_kappa) > kSecantMinStep)
        slope_nu = std::clamp((ln_nu - prev_ln_nu) / (ln_kappa - prev_ln_kappa), kSlopeNuMin, kSlopeMax);
      if (std::abs(ln_ratio - prev_ln_ratio) > kSecantMinStep)
        slope_r = std::clamp((ln_r - prev_ln_r) / (ln_ratio - prev_ln_ratio), kSlopeRMin, kSlopeMax);
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
}

/// The reduced problem handed to GSL: the free ones of x = (ln kappa, ln(c / sigma_c)).
struct Reduced {
  Context* ctx;
  bool kappa_free, ratio_free;
  std::exception_ptr error;  ///< C++ exceptions must not unwind through GSL's C frames

  std::size_t size() const { return (kappa_free ? 1u : 0u) + (ratio_free ? 1u : 0u); }
  /// Full (ln kappa, ln ratio) from the solver's vector (material_at ignores a fixed variable's value).
  std::pair<double, double> full(const gsl_vector* x) const {
    std::size_t i = 0;
    const double ln_kappa = kappa_free ? gsl_vector_get(x, i++) : 0.0;
    const double ln_ratio = ratio_free ? gsl_vector_get(x, i) : 0.0;
    return {ln_kappa, ln_ratio};
  }
  int residual(const gsl_vector* x, gsl_vector* f) {
    // Stop asking for evaluations once done; the driver sees ctx->done and ends.
    if (ctx->done) return GSL_EBADFUNC;
    try {
      const auto [ln_kappa, ln_ratio] = full(x);
      const MacroProperties got = evaluate(*ctx, material_at(*ctx, ln_kappa, ln_ratio));
      const auto& t = ctx->spec->targets;
      std::size_t i = 0;
      if (kappa_free) gsl_vector_set(f, i++, std::log(got.poissons_ratio / t.poissons_ratio));
      if (ratio_free) gsl_vector_set(f, i, ln_strength_ratio(got) - std::log(t.compressive_strength_pa / t.tensile_strength_pa));
      return GSL_SUCCESS;
    } catch (...) {
      error = std::current_exception();
      return GSL_EBADFUNC;
    }
  }
  /// The trend Jacobian: diagonal, each slope from the secant through the two latest evaluations that moved
  /// its variable by more than kSecantMinStep, else the measured trend.
  int jacobian(gsl_matrix* j) const {
    double slope_nu = kSlopeNu, slope_r = kSlopeR;
    bool have_nu = false, have_r = false;
    const auto& log = ctx->result.log;
    for (std::size_t b = log.size(); b-- > 1 && !(have_nu && have_r);) {
      const CalibratedParams mb = calibrated_params(log[b].material);
      const auto& pb = log[b].macro;
      for (std::size_t a = b; a-- > 0 && !(have_nu && have_r);) {
        const CalibratedParams ma = calibrated_params(log[a].material);
        const auto& pa = log[a].macro;
        const double dk = std::log(mb.stiffness_ratio / ma.stiffness_ratio);
        const double dr = std::log((mb.cohesion_pa / mb.tensile_strength_pa) / (ma.cohesion_pa / ma.tensile_strength_pa));
        if (!have_nu && std::abs(dk) > kSecantMinStep) {
          slope_nu = std::clamp(std::log(pb.poissons_ratio / pa.poissons_ratio) / dk, kSlopeNuMin, kSlopeMax);
          have_nu = true;
        }
        if (!have_r && std::abs(dr) > kSecantMinStep) {
          slope_r = std::clamp((ln_strength_ratio(pb) - ln_strength_ratio(pa)) / dr, kSlopeRMin, kSlopeMax);
          have_r = true;
        }
      }
    }
    gsl_matrix_set_zero(j);
    std::size_t i = 0;
    if (kappa_free) gsl_matrix_set(j, i, i, slope_nu), ++i;
    if (ratio_free) gsl_matrix_set(j, i, i, slope_r);
    return GSL_SUCCESS;
  }
};

int reduced_f(const gsl_vector* x, void* params, gsl_vector* f) { return static_cast<Reduced*>(params)->residual(x, f); }
int reduced_df(const gsl_vector*, void* params, gsl_matrix* j) { return static_cast<Reduced*>(params)->jacobian(j); }
int reduced_fdf(const gsl_vector* x, void* params, gsl_vector* f, gsl_matrix* j) {
  auto* r = static_cast<Reduced*>(params);
  const int status = r->residual(x, f);
  return status != GSL_SUCCESS ? status : r->jacobian(j);
}

/// Powell's hybrid method (CalibrationMethod::hybrid) on the reduced problem. GSL's own convergence tests are
/// not used: only the four targets within tolerance (checked after each evaluation) end the calibration,
/// since the residual can be zero while E or sigma_t still wait for their proportional correction (then the
/// next trial point, near the current one, carries it). When GSL reports no progress, the solver is
/// restarted at the best point with a fresh trend Jacobian.
void solve_hybrid(Context& ctx) {
  Reduced reduced{&ctx, ctx.spec->free_stiffness_ratio, ctx.spec->free_cohesion, nullptr};
  const std::size_t n = reduced.size();
  gsl_multiroot_function_fdf fdf{&reduced_f, &reduced_df, &reduced_fdf, n, &reduced};
  const std::unique_ptr<gsl_multiroot_fdfsolver, void (*)(gsl_multiroot_fdfsolver*)> solver(
      gsl_multiroot_fdfsolver_alloc(gsl_multiroot_fdfsolver_hybridsj, n), &gsl_multiroot_fdfsolver_free);
  const std::unique_ptr<gsl_vector, void (*)(gsl_vector*)> x(gsl_vector_alloc(n), &gsl_vector_free);
  if (!solver || !x) throw std::bad_alloc();
  const auto set_start = [&](double ln_kappa, double ln_ratio) {
    std::size_t i = 0;
    if (reduced.kappa_free) gsl_vector_set(x.get(), i++, ln_kappa);
    if (reduced.ratio_free) gsl_vector_set(x.get(), i, ln_ratio);
    return gsl_multiroot_fdfsolver_set(solver.get(), &fdf, x.get());
  };
  gsl_error_handler_t* const previous = gsl_set_error_handler_off();  // statuses are handled here
  int status = std::apply(set_start, start_point(ctx.current));
  while (!ctx.done && !reduced.error) {
    if (status != GSL_SUCCESS) {
      // No progress (GSL_ENOPROG, GSL_ENOPROGJ) or a failed restart: start again from the best point so far
      // (its kappa and c / sigma_c, the current proportional corrections) with a fresh Jacobian.
      const CalibratedParams best = calibrated_params(ctx.result.material);
      status = set_start(std::log(best.stiffness_ratio), std::log(best.cohesion_pa / best.tensile_strength_pa));
      continue;
    }
    status = gsl_multiroot_fdfsolver_iterate(solver.get());
  }
  gsl_set_error_handler(previous);
  if (reduced.error) std::rethrow_exception(reduced.error);
}

}  // namespace

namespace {
// "KERFCAL4" (2: the viscous damping ratio; 3: the specimens are built again on resume, 2026-11-26; 4: the laws
// by name). "KERFCAL3" is still read (the laws as raw variants of 4a34e1f).
constexpr std::uint64_t kEvaluationsMagic = 0x4b45524643414c34, kEvaluationsMagicRawLaws = 0x4b45524643414c33;

/// One evaluation's fields in checkpoint order: io(field...) writes (serial::Out) or reads (serial::In) them.
template <class Self, class Io>
void evaluation_fields(Self& e, Io& io) {
  auto& m = e.material;
  io(m.name, m.density_kg_per_m3, m.local_damping, m.viscous_damping_ratio);
  io(m.contact, m.joint);  // the laws, by name and every field (serial.hpp)
  io(e.macro.youngs_modulus_pa, e.macro.poissons_ratio, e.macro.tensile_strength_pa, e.macro.compressive_strength_pa);
  io(e.index, e.max_relative_error, e.wall_time_s);
}
}  // namespace

std::string serialize_evaluations(const std::vector<CalibrationEvaluation>& log) {
  std::string out;
  serial::Out io{out};
  io(kEvaluationsMagic, static_cast<std::uint64_t>(log.size()));
  for (const auto& e : log) evaluation_fields(e, io);
  return out;
}

std::vector<CalibrationEvaluation> deserialize_evaluations(std::string_view bytes) {
  serial::In io{bytes};
  std::uint64_t magic = 0, n = 0;
  io(magic);
  if (magic != kEvaluationsMagic && magic != kEvaluationsMagicRawLaws)
    throw ModelError("calibrate", "not a list of calibration evaluations of this kerf-dem (KERFCAL4 or KERFCAL3)");
  io.raw_laws = magic == kEvaluationsMagicRawLaws;
  io(n);
  if (n > bytes.size()) throw ModelError("calibrate", "corrupt list of calibration evaluations");
  std::vector<CalibrationEvaluation> log(static_cast<std::size_t>(n));
  for (auto& e : log) evaluation_fields(e, io);
  return log;
}

CalibrationResult calibrate(std::span<const SpecimenSource> sources, const Material& start, const CalibrationSpec& spec,
                            const std::function<void(const CalibrationEvaluation&)>& on_evaluation,
                            const std::vector<CalibrationEvaluation>& known) {
  Context ctx{sources, &spec, &on_evaluation, &known, start, {}, false, 0};
  if (!spec.free_stiffness_ratio && !spec.free_cohesion) {
    // Only the proportional corrections: repeat them until within tolerance.
    while (!ctx.done) evaluate(ctx, ctx.current);
  } else if (spec.method == CalibrationMethod::secant) {
    solve_secant(ctx);
  } else {
    solve_hybrid(ctx);
  }
  return ctx.result;
}

}  // namespace kerf::dem
