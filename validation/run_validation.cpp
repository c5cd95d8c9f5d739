// Regenerates validation reports end to end: run_validation CASE|all OUT_DIR [--replicates N] (all: OUT_DIR/<case>/
// each; --replicates: packings per condition of the cutting cases instead of validation.json's).
// Cases: k9_trepanning (seconds), soda_lime_cutting (kerf-dem runs: 18 cuts, about 35 min on 2 cores),
// soda_lime_cutting_cut_fitted (the glass fitted to one cut by kerf-dem calibrate_cut: 12 cuts, about 25 min).
// The steady-state case's acceptance is the seed-000 study's record, not a run of this program:
// bash scripts/validate.sh soda_lime_cutting_steady (validation/soda_lime_cutting_steady/README.md).
// Exit status 0 when the acceptance bands hold, 1 when they do not, 2 for input errors.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <string>
#include <vector>

#include "k9_trepanning.hpp"
#include "kerf/error.hpp"
#ifdef KERF_WITH_DEM
#include "soda_lime_cutting.hpp"
#endif

namespace {

bool run_k9(const std::filesystem::path& out) {
  const kerf::TrepanningValidation v = kerf::run_k9_trepanning_validation(out);
  for (const auto& file : v.files) fmt::print("wrote {}\n", file.string());
  fmt::print("fitted: axial mean |error| {:.2f} %, torque {:.2f} %; leave-one-out: {:.2f} %, {:.2f} %\n",
             v.measured_fit.axial.fit.mean_abs_error_percent, v.measured_fit.torque.fit.mean_abs_error_percent,
             v.measured_fit.axial.loo.mean_abs_error_percent, v.measured_fit.torque.loo.mean_abs_error_percent);
  for (const auto& failure : v.failures) fmt::print(stderr, "FAILED: {}\n", failure);
  fmt::print("k9_trepanning: {}\n", v.passed() ? "PASSED" : "FAILED");
  return v.passed();
}

bool run_cutting(const std::filesystem::path& out, const std::string& case_name, int replicates) {
#ifdef KERF_WITH_DEM
  const kerf::CuttingValidation v = kerf::run_soda_lime_cutting_validation(out, case_name, replicates);
  for (const auto& file : v.files) fmt::print("wrote {}\n", file.string());
  for (const auto& failure : v.failures) fmt::print(stderr, "FAILED: {}\n", failure);
  fmt::print("{}: {}\n", case_name,
             !v.judged    ? "REPORTED (a reproduction: no pass or fail)"
             : v.passed() ? "PASSED"
                          : "FAILED");
  return v.passed();
#else
  (void)out, (void)replicates;
  throw kerf::InputError("CASE", case_name, "a build with the DEM (kerf-dem)");
#endif
}

}  // namespace

int main(int argc, char** argv) {
  const std::array<std::string, 2> cutting_cases{"soda_lime_cutting", "soda_lime_cutting_cut_fitted"};
  const std::string steady_case = "soda_lime_cutting_steady";
  CLI::App app{
      "Regenerates kerf's validation reports end to end (exit 0: bands hold, or a reproduction without bands "
      "reported; 1: they do not hold; 2: input error)"};
  std::string which;
  std::filesystem::path out;
  int replicates = 0;
  app.add_option("case", which, "the case: k9_trepanning, soda_lime_cutting, soda_lime_cutting_cut_fitted or all")
      ->required()
      ->check(CLI::IsMember(
          std::vector<std::string>{"k9_trepanning", cutting_cases[0], cutting_cases[1], steady_case, "all"}));
  app.add_option("out_dir", out, "where the report goes (all: one folder per case)")->required();
  // Its range (2-100) is checked by run_soda_lime_cutting_validation, as validation.json's.
  app.add_option("--replicates", replicates,
                 "packings per condition of the cutting cases, 2-100 (default: validation.json's); finished ones are "
                 "reused");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : kerf::kExitInputError;
  }
  const bool cutting = std::find(cutting_cases.begin(), cutting_cases.end(), which) != cutting_cases.end();
  try {
    if (which == steady_case)
      throw kerf::InputError("case", which,
                             "k9_trepanning, soda_lime_cutting, soda_lime_cutting_cut_fitted or all (the steady case's "
                             "acceptance is the record of the Yang et al. 2018 study: bash scripts/validate.sh " +
                                 steady_case + ")");
    bool passed = true;
    if (which == "k9_trepanning") passed = run_k9(out);
    if (cutting) passed = run_cutting(out, which, replicates);
    if (which == "all") {
      passed = run_k9(out / "k9_trepanning");
      for (const std::string& name : cutting_cases) passed = run_cutting(out / name, name, replicates) && passed;
    }
    fmt::print("{}\n", passed ? "PASSED" : "FAILED");
    return passed ? 0 : 1;
  } catch (const kerf::InputError& e) {
    fmt::print(stderr, "run_validation: error: {}\n", e.what());
    return kerf::kExitInputError;
  } catch (const std::exception& e) {
    fmt::print(stderr, "run_validation: error: {}\n", e.what());
    return kerf::kExitModelError;
  }
}
