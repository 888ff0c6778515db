// SPDX-License-Identifier: GPL-3.0-or-later
#include "pendulum/bessel_series.hpp"

#include "pendulum/amplitude.hpp"

#include <cmath>
#include <limits>
#include <string>

namespace pendulum {

namespace {

/// sum_m (-(x/2)^2)^m / (m! (n+1)(n+2)...(n+m)), the series of J_n(x) / ((x/2)^n / n!).
long double reduced_series(int n, long double x) {
    if (n < 0 || !(std::fabs(x) <= bessel_series_limit)) {
        throw domain_error("the Bessel series needs n >= 0 and |x| <= 4, got n = " + std::to_string(n) +
                           ", x = " + format_double(static_cast<double>(x)));
    }
    const long double y = -0.25L * x * x;
    long double term = 1;
    long double sum = 1;
    for (int m = 1; m < 100; ++m) {
        term *= y / (static_cast<long double>(m) * (m + n));
        sum += term;
        if (std::fabs(term) <= std::numeric_limits<long double>::epsilon() * 1e-3L * std::fabs(sum)) break;
    }
    return sum;
}

/// (x/2)^p / q! in extended precision (its exponent range holds every double x's power).
long double scaled_power(long double x, int p, int q) {
    long double v = 1;
    for (int i = 0; i < p; ++i) v *= 0.5L * x;
    for (int i = 2; i <= q; ++i) v /= i;
    return v;
}

}  // namespace

long double bessel_j_series(int n, long double x) {
    const long double s = reduced_series(n, x);
    return scaled_power(x, n, n) * s;
}

long double bessel_j_over_x_series(int n, long double x) {
    if (n < 1) throw domain_error("J_n(x)/x needs n >= 1, got " + std::to_string(n));
    const long double s = reduced_series(n, x);
    // J_n(x)/x = (x/2)^(n-1) / (2 n!) times the series.
    return scaled_power(x, n - 1, n) * 0.5L * s;
}

}  // namespace pendulum
