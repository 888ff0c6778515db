// SPDX-License-Identifier: GPL-3.0-or-later
#include "pendulum/phase.hpp"

#include "pendulum/amplitude.hpp"

#include <cmath>

namespace pendulum {

double velocity_at_fraction(const exact_solution& solution, double s) {
    if (!std::isfinite(s)) throw domain_error("time must be finite, got " + format_double(s));
    // theta' is odd about t = 0 and about t = T/2, even about T/4; each step is exact.
    double sign = s < 0 ? 1.0 : -1.0;
    s = std::fabs(s);
    s -= std::floor(s);
    if (s > 0.5) {
        s = 1.0 - s;
        sign = -sign;
    }
    if (s > 0.25) s = 0.5 - s;
    const double k = solution.modulus();
    const double kp = solution.complementary_modulus();
    const double quarter = solution.quarter_period();
    if (s <= 0.125) {
        // theta'/w0 = -2 k k' sd(w0 t): exact while dn is far from its minimum k'.
        const auto j = jacobi(4.0 * quarter * s, kp);
        return sign * 2.0 * k * kp * j.sn / j.dn;
    }
    // Near the bottom, with u = K - w0 t small: sd(K - u) = cn(u)/k'.
    const auto j = jacobi(quarter * (1.0 - 4.0 * s), kp);
    return sign * 2.0 * k * j.cn;
}

namespace {

/// theta'/w0 of a Fourier solution: -sum c_k h w sin(angle(h)) over h = 2k + 1, where
/// angle(h) is the harmonic's argument.
template <class Angle>
double velocity_sum(const fourier_solution& solution, Angle angle) {
    const double w = solution.frequency_ratio;
    double sum = 0.0;
    for (std::size_t k = 0; k < solution.coefficients.size(); ++k) {
        const double h = static_cast<double>(2 * k + 1);
        sum -= solution.coefficients[k] * h * w * std::sin(angle(h));
    }
    return sum;
}

}  // namespace

double velocity(const fourier_solution& solution, double w0_t) {
    if (!std::isfinite(w0_t)) throw domain_error("time must be finite, got " + format_double(w0_t));
    const double w = solution.frequency_ratio;
    return velocity_sum(solution, [&](double h) { return h * w * w0_t; });
}

double velocity_at_phase(const fourier_solution& solution, double x) {
    if (!std::isfinite(x)) throw domain_error("phase must be finite, got " + format_double(x));
    return velocity_sum(solution, [x](double h) { return h * x; });
}

double separatrix_velocity(double theta) {
    if (!(std::fabs(theta) <= M_PI)) {
        throw domain_error("the separatrix is drawn for theta in [-pi, pi], got " + format_double(theta));
    }
    return 2.0 * std::cos(0.5 * theta);
}

}  // namespace pendulum
