// SPDX-License-Identifier: GPL-3.0-or-later
#include "pendulum/period_formulas.hpp"

#include "pendulum/amplitude.hpp"

#include <array>
#include <cmath>
#include <numbers>
#include <string>

namespace pendulum {

namespace {

/// k' = cos(theta0/2) after checking the amplitude.
double complementary_modulus(double theta0) {
    check_amplitude(theta0);
    return std::cos(0.5 * theta0);
}

/// 1 - k' = 2 sin^2(theta0/4), without the cancellation of 1 - cos for small theta0.
double one_minus_kp(double theta0) {
    const double s = std::sin(0.25 * theta0);
    return 2.0 * s * s;
}

void check_count(int n, int largest, const char* what) {
    if (n < 0 || n > largest) {
        throw domain_error(std::string(what) + " must be between 0 and " + std::to_string(largest) + ", got " +
                           std::to_string(n));
    }
}

}  // namespace

double period_kidd_fogg(double theta0) { return 1.0 / std::sqrt(complementary_modulus(theta0)); }

double period_lima_arun(double theta0) {
    check_amplitude(theta0);
    const double d = one_minus_kp(theta0);
    // -ln(k')/(1 - k') = 1 + d/2 + d^2/3 + ... with d = 1 - k'.
    if (d < 1e-9) return 1.0 + 0.5 * d;
    // Each form where it has no cancellation: log1p(-d) while k' is not small, ln(k') itself near pi.
    const double log_kp = d < 0.5 ? std::log1p(-d) : std::log(std::cos(0.5 * theta0));
    return -log_kp / d;
}

double period_ganley(double theta0) {
    check_amplitude(theta0);
    const double x = 0.5 * std::numbers::sqrt3 * theta0;
    return std::sqrt(x / std::sin(x));
}

double period_agm(double theta0, int steps) {
    double b = complementary_modulus(theta0);
    check_count(steps, max_agm_steps, "the number of AGM steps");
    double a = 1.0;
    for (int i = 0; i < steps; ++i) {
        const double next = 0.5 * (a + b);
        b = std::sqrt(a * b);
        a = next;
    }
    return 1.0 / a;
}

double period_denman(double theta0) {
    check_amplitude(theta0);
    return 1.0 / (1.0 - theta0 * theta0 / 16.0);
}

double period_series(double theta0, int terms) {
    check_amplitude(theta0);
    check_count(terms, max_series_terms, "the number of series terms");
    static constexpr std::array<double, max_series_terms + 1> coefficients = {
#include "pendulum/period_series_coefficients.inc"
    };
    // Horner in theta0^2; every coefficient is positive, so the sum has no cancellation.
    const double t2 = theta0 * theta0;
    double sum = 0.0;
    for (int n = terms; n >= 0; --n) sum = sum * t2 + coefficients[static_cast<std::size_t>(n)];
    return sum;
}

double period_log_asymptote(double theta0) {
    return 2.0 / std::numbers::pi * std::log(4.0 / complementary_modulus(theta0));
}

}  // namespace pendulum
