// SPDX-License-Identifier: GPL-3.0-or-later
#include "pendulum/period_formulas.hpp"

#include "pendulum/amplitude.hpp"

#include <array>
#include <cmath>
#include <numbers>
#include <string>

namespace pendulum {

namespace {

void check_count(int n, int largest, const char* what) {
    if (n < 0 || n > largest) {
        throw domain_error(std::string(what) + " must be between 0 and " + std::to_string(largest) + ", got " +
                           std::to_string(n));
    }
}

}  // namespace

double period_kidd_fogg(const amplitude& a) { return 1.0 / std::sqrt(a.kp()); }

double period_lima_arun(const amplitude& a) {
    // d = 1 - k': 2 sin^2(theta0/4) without the cancellation of 1 - cos for small theta0; near
    // pi k' is small and 1 - k' has none.
    const double s = std::sin(0.25 * a.radians());
    const double d = a.near_pi() ? 1.0 - a.kp() : 2.0 * s * s;
    // -ln(k')/(1 - k') = 1 + d/2 + d^2/3 + ... with d = 1 - k'.
    if (d < 1e-9) return 1.0 + 0.5 * d;
    // Each form where it has no cancellation: log1p(-d) while k' is not small, ln(k') itself near pi.
    const double log_kp = d < 0.5 ? std::log1p(-d) : std::log(a.kp());
    return -log_kp / d;
}

double period_ganley(const amplitude& a) {
    const double x = 0.5 * std::numbers::sqrt3 * a.radians();
    return std::sqrt(x / std::sin(x));
}

double period_agm(const amplitude& a, int steps) {
    double b = a.kp();
    check_count(steps, max_agm_steps, "the number of AGM steps");
    double x = 1.0;
    for (int i = 0; i < steps; ++i) {
        const double next = 0.5 * (x + b);
        b = std::sqrt(x * b);
        x = next;
    }
    return 1.0 / x;
}

double period_denman(const amplitude& a) {
    const double theta0 = a.radians();
    return 1.0 / (1.0 - theta0 * theta0 / 16.0);
}

double period_series(const amplitude& a, int terms) {
    check_count(terms, max_series_terms, "the number of series terms");
    static constexpr std::array<double, max_series_terms + 1> coefficients = {
#include "pendulum/period_series_coefficients.inc"
    };
    // Horner in theta0^2; every coefficient is positive, so the sum has no cancellation. In
    // extended precision: near pi the sum is up to N times as sensitive to theta0^2 as to
    // its own rounding (6 ulps for N = 20 in doubles).
    const long double t2 = a.radians_extended() * a.radians_extended();
    long double sum = 0;
    for (int n = terms; n >= 0; --n) sum = sum * t2 + coefficients[static_cast<std::size_t>(n)];
    return static_cast<double>(sum);
}

double period_log_asymptote(const amplitude& a) { return 2.0 / std::numbers::pi * std::log(4.0 / a.kp()); }

}  // namespace pendulum
