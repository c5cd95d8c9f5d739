// Calibration of micro-parameters: exact proportional trends plus Powell's hybrid method (GSL) or a secant
// iteration on the remaining 2-D problem (see the header).
#include "kerf/dem/procedures/calibration.hpp"

#include <fmt/format.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_multiroots.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <exception>
#include <memory>
#include <new>
#include <numbers>
#include <optional>
#include <tuple>
#include <utility>

#include "../engine/serial.hpp"
#include "kerf/dem/procedures/specimen.hpp"
#include "kerf/error.hpp"

namespace kerf::dem {

MacroProperties measure_macro_properties(const Simulation& specimen, const LoadingSpec& tension,
                                         const LoadingSpec& compression) {
  const LabTestResult t = run_lab_test(specimen, tension);
  const LabTestResult c = run_lab_test(specimen, compression);
  return {c.youngs_modulus_Pa, c.poissons_ratio, t.peak_stress_Pa, c.peak_stress_Pa};
}

MacroProperties mean_macro_properties(std::span<const SpecimenSource> sources, const Material& m,
                                      const LoadingSpec& tension, const LoadingSpec& compression) {
  if (sources.empty()) throw ModelError("calibrate", "no specimen to evaluate a candidate on");
  MacroProperties sum{0, 0, 0, 0};
  for (const auto& source : sources) {
    const MacroProperties one = measure_macro_properties(source.for_material(m), tension, compression);
    sum.youngs_modulus_Pa += one.youngs_modulus_Pa;
    sum.poissons_ratio += one.poissons_ratio;
    sum.tensile_strength_Pa += one.tensile_strength_Pa;
    sum.compressive_strength_Pa += one.compressive_strength_Pa;
  }
  const double n = static_cast<double>(sources.size());
  return {sum.youngs_modulus_Pa / n, sum.poissons_ratio / n, sum.tensile_strength_Pa / n,
          sum.compressive_strength_Pa / n};
}

double mean_fracture_toughness(std::span<const SpecimenSource> beams, const Material& m,
                               const ToughnessCalibration& t) {
  if (beams.empty()) throw ModelError("calibrate", "no beam to run the toughness test on");
  Material beam_material = m;
  if (t.local_damping) beam_material.local_damping = *t.local_damping;
  double sum = 0;
  for (const auto& beam : beams)
    sum += run_toughness_test(beam.for_material(beam_material), t.test).fracture_toughness_Pa_sqrt_m;
  return sum / static_cast<double>(beams.size());
}

double max_relative_error(const MacroProperties& got, const MacroProperties& target) {
  return std::max({std::abs(got.youngs_modulus_Pa / target.youngs_modulus_Pa - 1),
                   std::abs(got.poissons_ratio / target.poissons_ratio - 1),
                   std::abs(got.tensile_strength_Pa / target.tensile_strength_Pa - 1),
                   std::abs(got.compressive_strength_Pa / target.compressive_strength_Pa - 1)});
}

namespace {

struct Context {
  std::span<const SpecimenSource> sources;
  std::span<const SpecimenSource> beams;  ///< the toughness test's (with spec->toughness)
  const CalibrationSpec* spec;
  const std::function<void(const CalibrationEvaluation&)>* on_evaluation;
  const std::vector<CalibrationEvaluation>* known;  ///< answers from an interrupted run
  Material current;                                 ///< E* and sigma_c here carry the proportional corrections
  CalibrationResult result;
  bool done = false;
  int repeats = 0;             ///< evaluations answered from this run's own log (no new information)
  int best = 0;                ///< the best evaluation's index in result.log
  double ln_lambda_start = 0;  ///< ln lambda of the start (with free_fracture_energy)

  bool toughness_target() const { return spec->toughness && spec->targets.fracture_toughness_Pa_sqrt_m > 0; }
  /// What the best evaluation minimises: the four's largest error, or with a toughness target the largest
  /// error over its tolerance of the five.
  double score(const CalibrationEvaluation& e) const {
    return toughness_target()
               ? std::max(e.max_relative_error / spec->tolerance, e.toughness_error / spec->toughness_tolerance)
               : e.max_relative_error;
  }
  bool converged(const CalibrationEvaluation& e) const {
    return e.max_relative_error <= spec->tolerance &&
           (!toughness_target() || e.toughness_error <= spec->toughness_tolerance);
  }
};

/// The softening joint's fracture energy G_f (the toughness's lever); nullopt for a law without one.
std::optional<double> fracture_energy(const Material& m) {
  return std::visit(
      [](const auto& j) -> std::optional<double> {
        if constexpr (requires { j.fracture_energy_J_per_m2; })
          return j.fracture_energy_J_per_m2;
        else
          return std::nullopt;
      },
      m.joint);
}
void set_fracture_energy(Material& m, double g) {
  std::visit(
      [&](auto& j) {
        if constexpr (requires { j.fracture_energy_J_per_m2; }) j.fracture_energy_J_per_m2 = g;
      },
      m.joint);
}

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
    if (ctx.spec->toughness)
      e.macro.fracture_toughness_Pa_sqrt_m = mean_fracture_toughness(ctx.beams, m, *ctx.spec->toughness);
    e.max_relative_error = max_relative_error(e.macro, ctx.spec->targets);
    if (ctx.toughness_target())
      e.toughness_error =
          std::abs(e.macro.fracture_toughness_Pa_sqrt_m / ctx.spec->targets.fracture_toughness_Pa_sqrt_m - 1);
    e.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  e.index = static_cast<int>(ctx.result.log.size());
  e.material = m;
  ctx.result.log.push_back(e);
  if (ctx.result.log.size() == 1 || ctx.score(e) < ctx.score(ctx.result.log[static_cast<std::size_t>(ctx.best)])) {
    ctx.best = e.index;
    ctx.result.material = m;
    ctx.result.macro = e.macro;
    ctx.result.max_relative_error = e.max_relative_error;
    ctx.result.toughness_error = e.toughness_error;
  }
  if (*ctx.on_evaluation) (*ctx.on_evaluation)(e);
  if (ctx.converged(e)) ctx.done = ctx.result.converged = true;
  if (static_cast<int>(ctx.result.log.size()) >= ctx.spec->max_evaluations) ctx.done = true;
  if (!(e.macro.youngs_modulus_Pa > 0 && e.macro.tensile_strength_Pa > 0 && e.macro.compressive_strength_Pa > 0) ||
      (ctx.spec->toughness && !(e.macro.fracture_toughness_Pa_sqrt_m > 0)))
    throw ModelError("calibrate", "a test gave no usable curve (zero modulus, strength or toughness)");
  // A softening joint's G_f follows the two corrections as b^2 / a (w_c / g_0 kept: the header).
  const std::optional<double> g_f = fracture_energy(m);
  double g_scale = 1;
  // Exact trends (see the header): E ~ E*, both strengths ~ (sigma_c, c) at a fixed c / sigma_c.
  const auto& t = ctx.spec->targets;
  if (ctx.spec->free_modulus) {
    const double a = t.youngs_modulus_Pa / e.macro.youngs_modulus_Pa;
    g_scale /= a;
    std::visit(
        [&](auto& c, auto& j, const auto& c0, const auto& j0) {
          c.effective_modulus_Pa = c0.effective_modulus_Pa * a;
          j.bond.effective_modulus_Pa = j0.bond.effective_modulus_Pa * a;
        },
        ctx.current.contact, ctx.current.joint, m.contact, m.joint);
  }
  if (ctx.spec->free_tensile_strength) {
    const double b = t.tensile_strength_Pa / e.macro.tensile_strength_Pa;
    g_scale *= b * b;
    std::visit(
        [&](auto& j, const auto& j0) {
          j.bond.tensile_strength_Pa = j0.bond.tensile_strength_Pa * b;
          j.bond.cohesion_Pa = j0.bond.cohesion_Pa * b;
        },
        ctx.current.joint, m.joint);
  }
  if (g_f) set_fracture_energy(ctx.current, *g_f * g_scale);
  return e.macro;
}

// Ranges of the iterated variables (c >= sigma_c: below it the tensile strength follows c, not sigma_c, and
// sigma_c,macro / sigma_t,macro stops responding; lambda within a factor kLambdaRange of its start).
constexpr double kKappaMin = 1.2, kKappaMax = 10.0, kRatioMin = 1.0, kRatioMax = 12.0, kLambdaRange = 100.0;
// Trend slopes: d ln nu / d ln kappa, d ln R / d ln(c / sigma_c) (measured on the seed specimen) and
// d ln(K_IC / sigma_t) / d ln lambda (the steady cut's glass; the header); the bounds a secant estimate is kept
// within (every response increases; the R slope grows with c / sigma_c).
constexpr double kSlopeNu = 0.8, kSlopeR = 0.6, kSlopeK = 0.12, kSlopeNuMin = 0.2, kSlopeRMin = 0.15, kSlopeKMin = 0.03,
                 kSlopeMax = 3.0;
// Smallest move of a variable (in ln) that a secant slope is taken over: below it DEM noise dominates.
constexpr double kSecantMinStep = 0.02;

/// The iterated variables: x = (ln kappa*, ln(c / sigma_c), ln lambda), lambda = G_f Ebar* / sigma_c^2.
enum Var : std::size_t { kKappa, kRatio, kLambda, kVars };
using Vars = std::array<double, kVars>;

std::array<bool, kVars> free_vars(const CalibrationSpec& spec) {
  return {spec.free_stiffness_ratio, spec.free_cohesion, spec.free_fracture_energy};
}

/// lambda of a material's micro-parameters (0 without a fracture energy).
double lambda_of(const CalibratedParams& j) {
  return j.fracture_energy_J_per_m2 * j.bond_modulus_Pa / (j.tensile_strength_Pa * j.tensile_strength_Pa);
}

/// The current material with kappa* = kappabar* = exp(x[kKappa]), c = exp(x[kRatio]) sigma_c and
/// G_f = exp(x[kLambda]) sigma_c^2 / Ebar* for the free ones, clamped to their ranges.
Material material_at(const Context& ctx, const Vars& x) {
  Material m = ctx.current;
  std::visit(
      [&](auto& contact, auto& joint) {
        if (ctx.spec->free_stiffness_ratio)
          contact.stiffness_ratio = joint.bond.stiffness_ratio =
              std::exp(std::clamp(x[kKappa], std::log(kKappaMin), std::log(kKappaMax)));
        if (ctx.spec->free_cohesion)
          joint.bond.cohesion_Pa = std::exp(std::clamp(x[kRatio], std::log(kRatioMin), std::log(kRatioMax))) *
                                   joint.bond.tensile_strength_Pa;
        if constexpr (requires { joint.fracture_energy_J_per_m2; })
          if (ctx.spec->free_fracture_energy)
            joint.fracture_energy_J_per_m2 =
                std::exp(std::clamp(x[kLambda], ctx.ln_lambda_start - std::log(kLambdaRange),
                                    ctx.ln_lambda_start + std::log(kLambdaRange))) *
                joint.bond.tensile_strength_Pa * joint.bond.tensile_strength_Pa / joint.bond.effective_modulus_Pa;
        joint = with_path("material", [&] { return std::decay_t<decltype(joint)>::validated(joint); });
      },
      m.contact, m.joint);
  return m;
}

double ln_strength_ratio(const MacroProperties& p) {
  return std::log(p.compressive_strength_Pa / p.tensile_strength_Pa);
}

/// The response each variable steers: ln nu, ln R, ln(K_IC / sigma_t) (0 without a toughness).
Vars responses(const MacroProperties& p) {
  return {std::log(p.poissons_ratio), ln_strength_ratio(p),
          p.fracture_toughness_Pa_sqrt_m > 0 ? std::log(p.fracture_toughness_Pa_sqrt_m / p.tensile_strength_Pa) : 0.0};
}

/// The residuals handed to GSL: f = (ln(nu / nu_target), ln R - ln R_target, ln(K/sigma_t) - ln(K/sigma_t)_target).
/// ln(nu / nu_target) rather than ln nu - ln nu_target, and in trend_slopes ln(nu_b / nu_a), the secant ln nu_b -
/// ln nu_a and steps from ln nu_target - ln nu: each as the two-variable solvers wrote it, so that a four-target
/// calibration repeats the earlier ones to the bit (the last bit moves a brittle specimen's strength).
Vars residuals(const MacroProperties& got, const MacroProperties& t) {
  const Vars y = responses(got), y_t = responses(t);
  return {std::log(got.poissons_ratio / t.poissons_ratio), y[kRatio] - y_t[kRatio], y[kLambda] - y_t[kLambda]};
}

/// The variables of an evaluated material.
Vars vars_of(const Material& m) {
  const CalibratedParams j = calibrated_params(m);
  const double lambda = lambda_of(j);
  return {std::log(j.stiffness_ratio), std::log(j.cohesion_Pa / j.tensile_strength_Pa),
          lambda > 0 ? std::log(lambda) : 0.0};
}

/// The start point.
Vars start_point(const Context& ctx) {
  // c / sigma_c starts at >= 1.5: for c <~ sigma_c the strength ratio barely responds (see the ranges).
  const CalibratedParams j = calibrated_params(ctx.current);
  return {std::log(std::clamp(j.stiffness_ratio, kKappaMin, kKappaMax)),
          std::log(std::clamp(j.cohesion_Pa / j.tensile_strength_Pa, 1.5, kRatioMax)), ctx.ln_lambda_start};
}

constexpr Vars kTrendSlopes{kSlopeNu, kSlopeR, kSlopeK}, kMinSlopes{kSlopeNuMin, kSlopeRMin, kSlopeKMin};

/// The trend slopes (the diagonal Jacobian): each from the secant through the two latest evaluations that
/// moved its variable by more than kSecantMinStep, else the measured trend.
Vars trend_slopes(const Context& ctx) {
  Vars slope = kTrendSlopes;
  std::array<bool, kVars> have{};
  const auto free = free_vars(*ctx.spec);
  for (std::size_t v = 0; v < kVars; ++v) have[v] = !free[v];
  const auto all = [&] { return have[kKappa] && have[kRatio] && have[kLambda]; };
  const auto& log = ctx.result.log;
  for (std::size_t b = log.size(); b-- > 1 && !all();) {
    const CalibratedParams mb = calibrated_params(log[b].material);
    const auto& pb = log[b].macro;
    const Vars yb = responses(pb);
    for (std::size_t a = b; a-- > 0 && !all();) {
      const CalibratedParams ma = calibrated_params(log[a].material);
      const auto& pa = log[a].macro;
      const Vars ya = responses(pa);
      const Vars dx{std::log(mb.stiffness_ratio / ma.stiffness_ratio),
                    std::log((mb.cohesion_Pa / mb.tensile_strength_Pa) / (ma.cohesion_Pa / ma.tensile_strength_Pa)),
                    have[kLambda] ? 0.0 : std::log(lambda_of(mb) / lambda_of(ma))};
      const Vars dy{std::log(pb.poissons_ratio / pa.poissons_ratio), yb[kRatio] - ya[kRatio],
                    yb[kLambda] - ya[kLambda]};
      for (std::size_t v = 0; v < kVars; ++v) {
        if (have[v] || !(std::abs(dx[v]) > kSecantMinStep)) continue;
        slope[v] = std::clamp(dy[v] / dx[v], kMinSlopes[v], kSlopeMax);
        have[v] = true;
      }
    }
  }
  return slope;
}

/// The secant iteration (CalibrationMethod::secant). Diagonal quasi-Newton in log variables: nu responds to
/// kappa, R to c / sigma_c, K / sigma_t to lambda (the off-diagonal responses are weak). Each slope starts
/// from its trend and is re-estimated by the secant through the last two evaluations that moved that variable;
/// steps are capped (30 % in kappa, 40 % in c / sigma_c, a factor 2 in lambda) because the response is not
/// smooth and its slope grows with c / sigma_c.
void solve_secant(Context& ctx) {
  constexpr Vars cap{0.3, 0.4, std::numbers::ln2};
  const Vars x_lo{std::log(kKappaMin), std::log(kRatioMin), ctx.ln_lambda_start - std::log(kLambdaRange)};
  const Vars x_hi{std::log(kKappaMax), std::log(kRatioMax), ctx.ln_lambda_start + std::log(kLambdaRange)};
  const auto free = free_vars(*ctx.spec);
  const Vars y_t = responses(ctx.spec->targets);
  Vars x = start_point(ctx), slope = kTrendSlopes, prev_x{}, prev_y{};
  bool have_prev = false;
  while (!ctx.done) {
    const Vars y = responses(evaluate(ctx, material_at(ctx, x)));
    if (have_prev)
      for (std::size_t v = 0; v < kVars; ++v)
        if (std::abs(x[v] - prev_x[v]) > kSecantMinStep)
          slope[v] = std::clamp((y[v] - prev_y[v]) / (x[v] - prev_x[v]), kMinSlopes[v], kSlopeMax);
    prev_x = x, prev_y = y;
    have_prev = true;
    for (std::size_t v = 0; v < kVars; ++v)
      if (free[v]) x[v] = std::clamp(x[v] + std::clamp((y_t[v] - y[v]) / slope[v], -cap[v], cap[v]), x_lo[v], x_hi[v]);
  }
}

/// The reduced problem handed to GSL: the free ones of x.
struct Reduced {
  Context* ctx;
  std::array<bool, kVars> free;
  std::exception_ptr error;  ///< C++ exceptions must not unwind through GSL's C frames

  std::size_t size() const { return static_cast<std::size_t>(std::count(free.begin(), free.end(), true)); }
  /// Full x from the solver's vector (material_at ignores a fixed variable's value).
  Vars full(const gsl_vector* x) const {
    Vars out{};
    for (std::size_t v = 0, i = 0; v < kVars; ++v)
      if (free[v]) out[v] = gsl_vector_get(x, i++);
    return out;
  }
  void set(gsl_vector* x, const Vars& v) const {
    for (std::size_t k = 0, i = 0; k < kVars; ++k)
      if (free[k]) gsl_vector_set(x, i++, v[k]);
  }
  int residual(const gsl_vector* x, gsl_vector* f) {
    // Stop asking for evaluations once done; the driver sees ctx->done and ends.
    if (ctx->done) return GSL_EBADFUNC;
    try {
      set(f, residuals(evaluate(*ctx, material_at(*ctx, full(x))), ctx->spec->targets));
      return GSL_SUCCESS;
    } catch (...) {
      error = std::current_exception();
      return GSL_EBADFUNC;
    }
  }
  int jacobian(gsl_matrix* j) const {
    const Vars slope = trend_slopes(*ctx);
    gsl_matrix_set_zero(j);
    for (std::size_t v = 0, i = 0; v < kVars; ++v)
      if (free[v]) gsl_matrix_set(j, i, i, slope[v]), ++i;
    return GSL_SUCCESS;
  }
};

int reduced_f(const gsl_vector* x, void* params, gsl_vector* f) {
  return static_cast<Reduced*>(params)->residual(x, f);
}
int reduced_df(const gsl_vector*, void* params, gsl_matrix* j) {
  return static_cast<Reduced*>(params)->jacobian(j);
}
int reduced_fdf(const gsl_vector* x, void* params, gsl_vector* f, gsl_matrix* j) {
  auto* r = static_cast<Reduced*>(params);
  const int status = r->residual(x, f);
  return status != GSL_SUCCESS ? status : r->jacobian(j);
}

/// Powell's hybrid method (CalibrationMethod::hybrid) on the reduced problem. GSL's own convergence tests are
/// not used: only the targets within tolerance (checked after each evaluation) end the calibration, since the
/// residual can be zero while E or sigma_t still wait for their proportional correction (then the next trial
/// point, near the current one, carries it). When GSL reports no progress, the solver is restarted at the
/// best point with a fresh trend Jacobian.
void solve_hybrid(Context& ctx) {
  Reduced reduced{&ctx, free_vars(*ctx.spec), nullptr};
  const std::size_t n = reduced.size();
  gsl_multiroot_function_fdf fdf{&reduced_f, &reduced_df, &reduced_fdf, n, &reduced};
  const std::unique_ptr<gsl_multiroot_fdfsolver, void (*)(gsl_multiroot_fdfsolver*)> solver(
      gsl_multiroot_fdfsolver_alloc(gsl_multiroot_fdfsolver_hybridsj, n), &gsl_multiroot_fdfsolver_free);
  const std::unique_ptr<gsl_vector, void (*)(gsl_vector*)> x(gsl_vector_alloc(n), &gsl_vector_free);
  if (!solver || !x) throw std::bad_alloc();
  const auto set_start = [&](const Vars& v) {
    reduced.set(x.get(), v);
    return gsl_multiroot_fdfsolver_set(solver.get(), &fdf, x.get());
  };
  gsl_error_handler_t* const previous = gsl_set_error_handler_off();  // statuses are handled here
  int status = set_start(start_point(ctx));
  while (!ctx.done && !reduced.error) {
    if (status != GSL_SUCCESS) {
      // No progress (GSL_ENOPROG, GSL_ENOPROGJ) or a failed restart: start again from the best point so far
      // (its variables, the current proportional corrections) with a fresh Jacobian.
      status = set_start(vars_of(ctx.result.material));
      continue;
    }
    status = gsl_multiroot_fdfsolver_iterate(solver.get());
  }
  gsl_set_error_handler(previous);
  if (reduced.error) std::rethrow_exception(reduced.error);
}

}  // namespace

namespace {
// "KERFCAL5" (2: the viscous damping ratio; 3: the specimens are built again on resume, 2026-11-26; 4: the laws
// by name; 5: the toughness test's K_IC and error). "KERFCAL4" (no toughness) and "KERFCAL3" (the laws as raw
// variants of 4a34e1f) are still read.
constexpr std::uint64_t kEvaluationsMagic = 0x4b45524643414c35, kEvaluationsMagicNoToughness = 0x4b45524643414c34,
                        kEvaluationsMagicRawLaws = 0x4b45524643414c33;

/// One evaluation's fields in checkpoint order: io(field...) writes (serial::Out) or reads (serial::In) them.
template <class Self, class Io>
void evaluation_fields(Self& e, Io& io, bool toughness = true) {
  auto& m = e.material;
  io(m.name, m.density_kg_per_m3, m.local_damping, m.viscous_damping_ratio);
  io(m.contact, m.joint);  // the laws, by name and every field (serial.hpp)
  io(e.macro.youngs_modulus_Pa, e.macro.poissons_ratio, e.macro.tensile_strength_Pa, e.macro.compressive_strength_Pa);
  io(e.index, e.max_relative_error, e.wall_time_s);
  if (toughness) io(e.macro.fracture_toughness_Pa_sqrt_m, e.toughness_error);
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
  if (magic != kEvaluationsMagic && magic != kEvaluationsMagicNoToughness && magic != kEvaluationsMagicRawLaws)
    throw ModelError("calibrate",
                     "not a list of calibration evaluations of this kerf-dem (KERFCAL5, KERFCAL4 or KERFCAL3)");
  io.raw_laws = magic == kEvaluationsMagicRawLaws;
  io(n);
  if (n > bytes.size()) throw ModelError("calibrate", "corrupt list of calibration evaluations");
  std::vector<CalibrationEvaluation> log(static_cast<std::size_t>(n));
  for (auto& e : log) evaluation_fields(e, io, magic == kEvaluationsMagic);
  return log;
}

void check_calibration_start(const CalibrationSpec& spec, const Material& start) {
  if (!spec.free_fracture_energy) return;
  const std::optional<double> g_f = fracture_energy(start);
  if (!g_f || !(*g_f > 0))
    throw InputError("material.fracture_energy_J_per_m2", g_f ? fmt::format("{}", *g_f) : "none",
                     "a bond_model softening_flat_joint with a fracture energy > 0 to start from, when "
                     "calibration.free has fracture_energy_J_per_m2");
  if (!spec.toughness || !(spec.targets.fracture_toughness_Pa_sqrt_m > 0))
    throw InputError("calibration.targets.fracture_toughness_MPa_sqrt_m", "none",
                     "a toughness target (and a calibration.toughness test) when calibration.free has "
                     "fracture_energy_J_per_m2");
}

CalibrationResult calibrate(std::span<const SpecimenSource> sources, const Material& start, const CalibrationSpec& spec,
                            const std::function<void(const CalibrationEvaluation&)>& on_evaluation,
                            const std::vector<CalibrationEvaluation>& known, std::span<const SpecimenSource> beams) {
  if (spec.toughness && beams.empty()) throw ModelError("calibrate", "a toughness test without beams to run it on");
  Context ctx{sources, beams, &spec, &on_evaluation, &known, start, {}, false, 0};
  check_calibration_start(spec, start);
  if (spec.free_fracture_energy) ctx.ln_lambda_start = std::log(lambda_of(calibrated_params(start)));
  if (!spec.free_stiffness_ratio && !spec.free_cohesion && !spec.free_fracture_energy) {
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
