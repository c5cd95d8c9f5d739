// Regenerates validation reports end to end: run_validation CASE|all OUT_DIR (all: OUT_DIR/<case>/ each).
// Cases: k9_trepanning (seconds), soda_lime_cutting (kerf-dem runs: 18 cuts, about 35 min on 2 cores),
// soda_lime_cutting_cut_fitted (the glass fitted to one cut by kerf-dem calibrate_cut: 12 cuts, about 25 min).
// Exit status 0 when the acceptance bands hold, 1 when they do not, 2 for input errors.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <string>

#include "kerf/analytic/trepanning_validation.hpp"
#include "kerf/error.hpp"
#include "soda_lime_cutting.hpp"

namespace {

bool run_k9(const std::filesystem::path& out) {
  const kerf::TrepanningValidation v = kerf::run_k9_trepanning_validation(out);
  for (const auto& file : v.files) fmt::print("wrote {}\n", file.string());
  fmt::print("fitted: axial mean |error| {:.2f} %, torque {:.2f} %; leave-one-out: {:.2f} %, {:.2f} %\n",
             v.measured_fit.axial.fit.mean_abs_error_pct, v.measured_fit.torque.fit.mean_abs_error_pct,
             v.measured_fit.axial.loo.mean_abs_error_pct, v.measured_fit.torque.loo.mean_abs_error_pct);
  for (const auto& failure : v.failures) fmt::print(stderr, "FAILED: {}\n", failure);
  fmt::print("k9_trepanning: {}\n", v.passed() ? "PASSED" : "FAILED");
  return v.passed();
}

bool run_cutting(const std::filesystem::path& out, const std::string& case_name) {
#ifdef KERF_DEM_PROGRAM
  const char* program = std::getenv("KERF_DEM");  // another kerf-dem build, if set
  const kerf::CuttingValidation v =
      kerf::run_soda_lime_cutting_validation(out, program && *program ? program : KERF_DEM_PROGRAM, case_name);
  for (const auto& file : v.files) fmt::print("wrote {}\n", file.string());
  for (const auto& failure : v.failures) fmt::print(stderr, "FAILED: {}\n", failure);
  fmt::print("{}: {}\n", case_name, v.passed() ? "PASSED" : "FAILED");
  return v.passed();
#else
  (void)out;
  throw kerf::InputError("CASE", case_name, "a build with the DEM (kerf-dem)");
#endif
}

}  // namespace

int main(int argc, char** argv) {
  const std::string which = argc == 3 ? argv[1] : "";
  const std::array<std::string, 2> cutting_cases{"soda_lime_cutting", "soda_lime_cutting_cut_fitted"};
  const bool cutting = std::find(cutting_cases.begin(), cutting_cases.end(), which) != cutting_cases.end();
  if (which != "k9_trepanning" && !cutting && which != "all") {
    fmt::print(stderr, "usage: {} k9_trepanning|soda_lime_cutting|soda_lime_cutting_cut_fitted|all OUT_DIR\n",
               argc > 0 ? argv[0] : "run_validation");
    return kerf::kExitInputError;
  }
  try {
    const std::filesystem::path out = argv[2];
    bool passed = true;
    if (which == "k9_trepanning") passed = run_k9(out);
    if (cutting) passed = run_cutting(out, which);
    if (which == "all") {
      passed = run_k9(out / "k9_trepanning");
      for (const std::string& name : cutting_cases) passed = run_cutting(out / name, name) && passed;
    }
    fmt::print("{}\n", passed ? "PASSED" : "FAILED");
    return passed ? 0 : 1;
  } catch (const kerf::InputError& e) {
    fmt::print(stderr, "error: {}\n", e.what());
    return kerf::kExitInputError;
  } catch (const std::exception& e) {
    fmt::print(stderr, "error: {}\n", e.what());
    return kerf::kExitModelError;
  }
}
