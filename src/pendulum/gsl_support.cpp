// SPDX-License-Identifier: GPL-3.0-or-later
#include "pendulum/gsl_support.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_sf_bessel.h>

#include <cmath>
#include <mutex>
#include <new>
#include <stdexcept>

namespace pendulum {

void use_gsl_status_codes() {
    static std::once_flag once;
    std::call_once(once, [] { gsl_set_error_handler_off(); });
}

integration_workspace make_integration_workspace(std::size_t size) {
    use_gsl_status_codes();
    integration_workspace w(gsl_integration_workspace_alloc(size));
    if (!w) throw std::bad_alloc();
    return w;
}

void check_gsl(int status, const std::string& what) {
    if (status != GSL_SUCCESS) {
        throw std::runtime_error(what + " failed: " + gsl_strerror(status));
    }
}

double bessel_j(int n, double x) {
    use_gsl_status_codes();
    gsl_sf_result r;
    const int status = gsl_sf_bessel_Jn_e(n, x, &r);
    // A value below the smallest double is zero to double precision, not a failure.
    if (status == GSL_EUNDRFLW) return 0.0;
    check_gsl(status, "bessel J" + std::to_string(n));
    return r.val;
}

double bessel_j_over_x(int n, double x) {
    if (n < 1) throw std::invalid_argument("bessel_j_over_x needs n >= 1, got " + std::to_string(n));
    if (std::fabs(x) >= small_amplitude) return bessel_j(n, x) / x;
    // The next term of the series is x^2/(4(n+1)) times smaller: below rounding here.
    const double correction = 1.0 - x * x / (4.0 * (n + 1));
    if (n == 1) return 0.5 * correction;
    if (n == 2) return 0.125 * x * correction;
    double factorial = 1.0;
    for (int i = 2; i <= n; ++i) factorial *= i;
    return std::pow(0.5 * x, n - 1) / (2.0 * factorial) * correction;
}

}  // namespace pendulum
