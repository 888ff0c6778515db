// SPDX-License-Identifier: GPL-3.0-or-later
#include "pendulum/gsl_support.hpp"

#include "pendulum/amplitude.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_sf_bessel.h>
#include <gsl/gsl_sf_ellint.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <stdexcept>

namespace pendulum {

void check_gsl(int status, const std::string& what) {
    if (status != GSL_SUCCESS) {
        throw std::runtime_error(what + " failed: " + gsl_strerror(status));
    }
}

double bessel_j(int n, double x) {
    // GSL (specfunc/bessel_Jn.c, bessel_J1.c, bessel.c): J1 underflows only below 2 DBL_MIN;
    // J3 is its Taylor series below |x| = 0.17 ((x/2)^3/6 >= 2e-26 here, no underflow) and the
    // continued fraction CF1 above, which converges in a few dozen of its 10000 steps for
    // |x| <= 4. No error branch is reached in this range.
    if (n < 1 || n > bessel_j_max_order || !(std::fabs(x) >= small_amplitude && std::fabs(x) <= 4.0)) {
        throw domain_error("bessel J" + std::to_string(n) + " needs 1 <= n <= " + std::to_string(bessel_j_max_order) +
                           " and 1e-8 <= |x| <= 4, got x = " + format_double(x));
    }
    gsl_sf_result r;
    check_gsl(gsl_sf_bessel_Jn_e(n, x, &r), "bessel J" + std::to_string(n));
    return r.val;
}

double bessel_j_over_x(int n, double x) {
    if (n < 1 || n > bessel_j_max_order) {
        throw std::invalid_argument("bessel_j_over_x needs 1 <= n <= " + std::to_string(bessel_j_max_order) +
                                    ", got " + std::to_string(n));
    }
    if (std::fabs(x) >= small_amplitude) return bessel_j(n, x) / x;
    // The next term of the series is x^2/(4(n+1)) times smaller: below rounding here.
    const double correction = 1.0 - x * x / (4.0 * (n + 1));
    if (n == 1) return 0.5 * correction;
    if (n == 2) return 0.125 * x * correction;
    double factorial = 1.0;
    for (int i = 2; i <= n; ++i) factorial *= i;
    return std::pow(0.5 * x, n - 1) / (2.0 * factorial) * correction;
}

double carlson_rf(double x, double y, double z) {
    // GSL's domain (specfunc/ellint.c): inside it the duplication converges in fewer than
    // 600 of its 10000 steps (each divides the spread by 4, from at most 2^2048).
    const double lowest = 5.0 * DBL_MIN;
    const double highest = 0.2 * DBL_MAX;
    const bool inside = x >= 0 && y >= 0 && z >= 0 && x + y >= lowest && x + z >= lowest && y + z >= lowest &&
                        std::max({x, y, z}) < highest;
    if (!inside) check_gsl(GSL_EDOM, "the elliptic integral R_F");
    gsl_sf_result r;
    check_gsl(gsl_sf_ellint_RF_e(x, y, z, GSL_PREC_DOUBLE, &r), "the elliptic integral R_F");
    return r.val;
}

gsl_function finite_function::as_gsl() {
    const auto call = [](double x, void* self) {
        const auto* fn = static_cast<const finite_function*>(self);
        const double v = fn->f(x, fn->params);
        if (!std::isfinite(v)) {
            throw domain_error(std::string(fn->what) + " is not finite at " + format_double(x) + ", got " +
                               format_double(v));
        }
        return v;
    };
    return gsl_function{call, this};
}

}  // namespace pendulum
