// SPDX-License-Identifier: GPL-3.0-or-later
// The core library's use of GSL. The library never touches GSL's error handler, which
// belongs to the program that links it: every GSL routine called here is called only with
// arguments for which GSL's source reaches no error branch (no call of gsl_error), checked
// here before the call. An argument outside those ranges is refused with an exception.
#pragma once

#include <gsl/gsl_math.h>

#include <string>

namespace pendulum {

/// Throws std::runtime_error naming `what` if status is not GSL_SUCCESS.
void check_gsl(int status, const std::string& what);

/// The largest order bessel_j() accepts.
inline constexpr int bessel_j_max_order = 3;

/// The Bessel function J_n(x) for 1 <= n <= bessel_j_max_order and
/// small_amplitude <= |x| <= 4, where GSL's gsl_sf_bessel_Jn_e can neither underflow nor
/// run out of iterations; throws domain_error outside that range.
double bessel_j(int n, double x);

/// J_n(x)/x for 1 <= n <= bessel_j_max_order and |x| <= 4, accurate for every such double
/// x != 0, subnormals included (the power series below |x| = 1e-8, where
/// J_n(x)/x = (x/2)^(n-1) / (2 n!) (1 - x^2/(4(n+1)))).
double bessel_j_over_x(int n, double x);

/// Carlson's R_F(x, y, z) by GSL, for x, y, z >= 0 with every pairwise sum at least
/// 5 DBL_MIN and each below DBL_MAX/5 (GSL's domain); throws std::runtime_error ("the elliptic
/// integral R_F failed: input domain error") outside it.
double carlson_rf(double x, double y, double z);

/// A function of one double for GSL's solvers that throws domain_error where `f` is not
/// finite, so that GSL's own check (an error through its handler) is never reached.
struct finite_function {
    double (*f)(double x, void* params);  ///< the function
    void* params;                         ///< its parameters
    const char* what;                     ///< what it is, for the message

    /// As a gsl_function whose params point to this object (which must outlive it).
    gsl_function as_gsl();
};

/// Amplitudes below this are "small": the power series in theta0 are exact to double there.
inline constexpr double small_amplitude = 1e-8;

}  // namespace pendulum
