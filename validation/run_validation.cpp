// Regenerates validation reports end to end: run_validation CASE|all OUT_DIR (all: OUT_DIR/<case>/ each)
// Exit status 0 when the acceptance bands hold, 1 when they do not, 2 for input errors.
#include <fmt/format.h>

#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>

#include "kerf/analytic/trepanning_validation.hpp"
#include "kerf/error.hpp"

int main(int argc, char** argv) {
  const std::string which = argc == 3 ? argv[1] : "";
  if (which != "k9_trepanning" && which != "all") {
    fmt::print(stderr, "usage: {} k9_trepanning|all OUT_DIR\n", argc > 0 ? argv[0] : "run_validation");
    return kerf::kExitInputError;
  }
  try {
    const std::filesystem::path out = which == "all" ? std::filesystem::path(argv[2]) / "k9_trepanning" : argv[2];
    const kerf::TrepanningValidation v = kerf::run_k9_trepanning_validation(out);
    for (const auto& file : v.files) fmt::print("wrote {}\n", file.string());
    fmt::print("fitted: axial mean |error| {:.2f} %, torque {:.2f} %; leave-one-out: {:.2f} %, {:.2f} %\n",
               v.measured_fit.axial.fit.mean_abs_error_pct, v.measured_fit.torque.fit.mean_abs_error_pct,
               v.measured_fit.axial.loo.mean_abs_error_pct, v.measured_fit.torque.loo.mean_abs_error_pct);
    for (const auto& failure : v.failures) fmt::print(stderr, "FAILED: {}\n", failure);
    fmt::print("{}\n", v.passed() ? "PASSED" : "FAILED");
    return v.passed() ? 0 : 1;
  } catch (const kerf::InputError& e) {
    fmt::print(stderr, "error: {}\n", e.what());
    return kerf::kExitInputError;
  } catch (const std::exception& e) {
    fmt::print(stderr, "error: {}\n", e.what());
    return kerf::kExitModelError;
  }
}
