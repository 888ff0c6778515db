// SPDX-License-Identifier: GPL-3.0-or-later
#include "pendulum/seconds.hpp"

#include "pendulum/amplitude.hpp"

#include <cmath>
#include <limits>
#include <numbers>

namespace pendulum {

namespace {

void check_pendulum(double length, double g) {
    if (!(length > 0 && std::isfinite(length))) {
        throw domain_error("the length must be positive and finite, got " + format_double(length));
    }
    if (!(g > 0 && std::isfinite(g))) throw domain_error("g must be positive and finite, got " + format_double(g));
}

}  // namespace

long double small_period_seconds(double length, double g) {
    check_pendulum(length, g);
    // A long double's exponent range holds L/g for every pair of positive doubles.
    return 2 * std::numbers::pi_v<long double> * std::sqrt(static_cast<long double>(length) / g);
}

long double angular_frequency(double length, double g) {
    check_pendulum(length, g);
    return std::sqrt(static_cast<long double>(g) / length);
}

double seconds_per_radian(double length, double g) {
    check_pendulum(length, g);
    return static_cast<double>(std::sqrt(static_cast<long double>(length) / g));
}

double seconds(double ratio, long double small_period_s) {
    const long double value = static_cast<long double>(ratio) * small_period_s;
    if (std::fabs(value) > std::numeric_limits<double>::max()) {
        throw domain_error("the period in seconds, " + format_double(ratio) + " T0, exceeds the largest double");
    }
    return static_cast<double>(value);
}

}  // namespace pendulum
