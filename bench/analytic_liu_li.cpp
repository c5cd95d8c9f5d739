// Benchmark of the Liu-Li edge-radius model: throughput and the speed-accuracy trade of the quadrature.
//
//   build/bench/bench_analytic_liu_li [OUT.csv]     (CSV to the file, or to stdout)
//
// Rows: one per (quadrature rule, tolerance): thread CPU time per prediction (both forces) and the relative error of
// the cutting and thrust forces against a reference (Boost Gauss-Kronrod at tolerance 1e-13, depth 20), over a set of
// cases spanning the three friction closures, both lower-limit rules, blunt and sharp edges.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <string>
#include <vector>

#include "bench_util.hpp"
#include "kerf/analytic/forces/liu_li.hpp"
#include "kerf/io.hpp"
#include "kerf/units.hpp"

namespace {

using kerf::bench::relative_error;
using kerf::bench::thread_cpu_seconds;

struct Case {
  kerf::LiuLiParams params;
  double t0_m;
};

std::vector<Case> make_cases() {
  std::vector<Case> cases;
  for (auto closure :
       {kerf::FrictionClosure::constant, kerf::FrictionClosure::merchant, kerf::FrictionClosure::lee_shaffer}) {
    for (auto lower : {kerf::LowerLimitRule::stagnation, kerf::LowerLimitRule::pole}) {
      for (double rake_deg : {-30.0, -10.0, 0.0, 10.0}) {
        for (double ratio : {0.05, 0.3, 1.0, 3.0, 20.0}) {  // t0 / r
          for (double beta_deg : {15.0, 30.0}) {
            kerf::LiuLiParams p;
            p.closure = closure;
            p.lower_limit = lower;
            p.rake_rad = kerf::units::deg_to_rad(rake_deg);
            p.edge_radius_m = 1e-6;
            p.friction_angle_rad = kerf::units::deg_to_rad(beta_deg);
            const double phi = M_PI / 4 - (p.friction_angle_rad - p.rake_rad) / 2;  // MEP
            p.chip_ratio = std::sin(phi) / std::cos(phi - p.rake_rad);
            cases.push_back({p, ratio * 1e-6});
          }
        }
      }
    }
  }
  return cases;
}

}  // namespace

int main(int argc, char** argv) {
  const auto cases = make_cases();
  constexpr double k_s = 1e9;

  std::vector<kerf::ForcePerWidth> reference;
  for (const auto& c : cases) {
    auto p = c.params;
    p.quadrature = {kerf::QuadratureRule::gauss_kronrod, 1e-13, 20};
    reference.push_back(kerf::liu_li_force_per_width(p, k_s, c.t0_m, nullptr).total);
  }

  std::string csv = kerf::csv_line({"rule", "tolerance", "n_cases", "time_per_prediction_us", "predictions_per_s",
                                    "max_rel_error_cutting", "max_rel_error_thrust", "median_rel_error_cutting",
                                    "median_rel_error_thrust"});
  const std::vector<double> tolerances = {1e-3, 1e-4, 1e-6, 1e-8, 1e-10, 1e-12};
  for (auto rule : {kerf::QuadratureRule::gauss_kronrod, kerf::QuadratureRule::tanh_sinh, kerf::QuadratureRule::gsl_qag,
                    kerf::QuadratureRule::gauss_legendre}) {
    for (double tolerance : tolerances) {
      if (rule == kerf::QuadratureRule::gauss_legendre && tolerance != tolerances.front()) continue;  // fixed rule
      std::vector<double> err_c, err_t;
      double sink = 0.0;
      std::size_t n_evaluations = 0;
      const double start = thread_cpu_seconds();
      double elapsed_s = 0.0;
      // Repeat the case set until at least 0.3 s have passed, for a stable rate.
      for (int repeat = 0; elapsed_s < 0.3; ++repeat) {
        for (std::size_t i = 0; i < cases.size(); ++i) {
          auto p = cases[i].params;
          p.quadrature.rule = rule;
          p.quadrature.relative_tolerance = tolerance;
          const auto f = kerf::liu_li_force_per_width(p, k_s, cases[i].t0_m, nullptr).total;
          sink += f.cutting_N_per_m;
          if (repeat == 0) {
            err_c.push_back(relative_error(f.cutting_N_per_m, reference[i].cutting_N_per_m));
            err_t.push_back(relative_error(f.thrust_N_per_m, reference[i].thrust_N_per_m));
          }
        }
        n_evaluations += cases.size();
        elapsed_s = thread_cpu_seconds() - start;
      }
      const auto median = [](std::vector<double> v) {
        std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
        return v[v.size() / 2];
      };
      const double per_prediction_s = elapsed_s / static_cast<double>(n_evaluations);
      csv += kerf::csv_line({std::string(kerf::quadrature_rule_name(rule)),
                             rule == kerf::QuadratureRule::gauss_legendre ? "fixed-30" : fmt::format("{:g}", tolerance),
                             fmt::format("{}", cases.size()), fmt::format("{:.3f}", per_prediction_s * 1e6),
                             fmt::format("{:.0f}", 1.0 / per_prediction_s),
                             fmt::format("{:.3g}", *std::max_element(err_c.begin(), err_c.end())),
                             fmt::format("{:.3g}", *std::max_element(err_t.begin(), err_t.end())),
                             fmt::format("{:.3g}", median(err_c)), fmt::format("{:.3g}", median(err_t))});
      if (sink == 42.0) std::puts("");  // keep the results alive
    }
  }
  if (argc > 1) {
    kerf::write_file_atomically(argv[1], csv);
  } else {
    std::fputs(csv.c_str(), stdout);
  }
  return 0;
}
