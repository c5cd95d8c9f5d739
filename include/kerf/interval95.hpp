#pragma once
// The two-sided 95 % interval of a mean, in one place: the study's replicate statistics (dem/study/study) and the
// soda-lime validation (validation/soda_lime_cutting.cpp) both take their quantile here.
//
//   const double q = kerf::quantile95(n - 1);   // Student's t for n samples
//   interval = {mean - q * standard_error, mean + q * standard_error};
#include <gsl/gsl_cdf.h>

#include <cmath>

namespace kerf {

/// The normal distribution's two-sided 95 % quantile (the value validation reports for a long signal's error).
inline constexpr double kZ95 = 1.96;

/// The two-sided 95 % quantile for an error with these degrees of freedom: Student's t, the normal's kZ95 when
/// they are infinite (or undefined: no standard error).
inline double quantile95(double degrees_of_freedom) {
  return std::isfinite(degrees_of_freedom) && degrees_of_freedom > 0 ? gsl_cdf_tdist_Pinv(0.975, degrees_of_freedom)
                                                                     : kZ95;
}

}  // namespace kerf
