// SPDX-License-Identifier: GPL-3.0-or-later
#include "pendulum/approximants.hpp"

#include "pendulum/amplitude.hpp"
#include "pendulum/gsl_support.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

namespace pendulum {

using std::numbers::pi;

double fourier_solution::theta(double w0_t) const {
    if (!std::isfinite(w0_t)) throw domain_error("time must be finite, got " + format_double(w0_t));
    const double x = frequency_ratio * w0_t;
    double sum = 0.0;
    for (std::size_t k = 0; k < coefficients.size(); ++k) {
        sum += coefficients[k] * std::cos(static_cast<double>(2 * k + 1) * x);
    }
    return sum;
}

double besinc(double x) {
    if (!std::isfinite(x)) throw domain_error("besinc needs a finite argument, got " + format_double(x));
    if (x == 0.0) return 1.0;
    return 2.0 * bessel_j(1, x) / x;
}

fourier_solution harmonic(double theta0) {
    check_amplitude(theta0);
    return {1.0, {theta0}};
}

fourier_solution lowest_order(double theta0) {
    check_amplitude(theta0);
    return {std::sqrt(besinc(theta0)), {theta0}};
}

fourier_solution first_order(double theta0) {
    check_amplitude(theta0);
    const double eta = -bessel_j(3, theta0) / (9.0 * bessel_j(1, theta0));
    const double c1 = theta0 / (1.0 + eta);
    return {std::sqrt(besinc(theta0) * (1.0 + eta)), {c1, eta * c1}};
}

fourier_solution second_order(double theta0) {
    const auto first = first_order(theta0);
    const double a = first.coefficients[0];
    const double b = first.coefficients[1];
    double C[3];
    double sum = 0.0;
    for (int k = 0; k < 3; ++k) {
        // J_{2k-2} with J_{-2} = J_2 (integer-order reflection).
        const double inner =
            2.0 * bessel_j(2 * k + 1, a) + b * (bessel_j(2 * k + 4, a) - bessel_j(std::abs(2 * k - 2), a));
        C[k] = (k % 2 == 0) ? inner : -inner;
        sum += C[k] / ((2 * k + 1) * (2 * k + 1));
    }
    const double lambda = sum / theta0;
    fourier_solution s{std::sqrt(lambda), {}};
    for (int k = 0; k < 3; ++k) s.coefficients.push_back(C[k] / ((2 * k + 1) * (2 * k + 1) * lambda));
    return s;
}

fourier_solution polynomial(double theta0) {
    check_amplitude(theta0);
    const double t2 = theta0 * theta0;
    const double t3 = t2 * theta0;
    const double t5 = t3 * t2;
    const double period = 1.0 + t2 / 16.0 + 11.0 * t2 * t2 / 3072.0;
    return {1.0 / period,
            {theta0 + t3 / 192.0 + 17.0 * t5 / 61440.0, -(t3 / 192.0 + t5 / 3072.0), t5 / 20480.0}};
}

namespace {

/// C_{2k+1} = (1/pi) int_0^{2pi} cos((2k+1)x) sin(theta(x)) dx for k = 0..count-1, where
/// theta(x) = sum_j c_j cos((2j+1)x), by the midpoint rule on [0, pi/2] with L points.
/// The integrand is even and antisymmetric about pi/2, so this equals the trapezoidal rule
/// on 4L points over the whole period: exact for every harmonic below 4L - (2 count - 1).
std::vector<double> project_sine(const std::vector<double>& c, int count, int L) {
    std::vector<double> C(count, 0.0);
    std::vector<double> odd_cos(std::max<std::size_t>(c.size(), count));
    for (int i = 0; i < L; ++i) {
        const double x = (i + 0.5) * pi / (2.0 * L);
        const double c1 = std::cos(x);
        const double two_c2 = 2.0 * std::cos(2.0 * x);
        // cos((2j+3)x) = 2 cos(2x) cos((2j+1)x) - cos((2j-1)x), starting from cos(-x) = cos(x).
        double prev = c1;
        double cur = c1;
        for (std::size_t j = 0; j < odd_cos.size(); ++j) {
            odd_cos[j] = cur;
            const double next = two_c2 * cur - prev;
            prev = cur;
            cur = next;
        }
        double theta = 0.0;
        for (std::size_t j = 0; j < c.size(); ++j) theta += c[j] * odd_cos[j];
        const double f = std::sin(theta);
        for (int k = 0; k < count; ++k) C[k] += f * odd_cos[k];
    }
    for (double& v : C) v *= 2.0 / L;
    return C;
}

/// project_sine with L doubled until two successive rules agree to rounding, relative to
/// the size of the integrand (|sin theta| <= min(1, theta0)).
std::vector<double> project_sine_converged(const std::vector<double>& c, int count, double theta0) {
    const double tolerance = 8.0 * std::numeric_limits<double>::epsilon() * std::min(1.0, theta0);
    int L = 8 * count + 16;
    auto coarse = project_sine(c, count, L);
    for (;;) {
        L *= 2;
        auto fine = project_sine(c, count, L);
        double diff = 0.0;
        for (int k = 0; k < count; ++k) diff = std::max(diff, std::fabs(fine[k] - coarse[k]));
        if (diff <= tolerance || L >= (1 << 16)) return fine;
        coarse = std::move(fine);
    }
}

}  // namespace

fourier_solution iterated(double theta0, int order) {
    return std::move(iterated_sequence(theta0, order).back());
}

std::vector<fourier_solution> iterated_sequence(double theta0, int order) {
    check_amplitude(theta0);
    if (order < 0 || order > max_order) {
        throw domain_error("order must be between 0 and " + std::to_string(max_order) + ", got " +
                           std::to_string(order));
    }
    std::vector<fourier_solution> levels;
    std::vector<double> c{theta0};
    for (int level = 0; level <= order; ++level) {
        const int count = level + 1;
        std::vector<double> C;
        if (level <= 1) {
            // Exact in closed form: sin(theta0 cos x) = 2 sum (-1)^k J_{2k+1}(theta0) cos((2k+1)x).
            for (int k = 0; k < count; ++k) {
                const double j = 2.0 * bessel_j(2 * k + 1, theta0);
                C.push_back(k % 2 == 0 ? j : -j);
            }
        } else {
            C = project_sine_converged(c, count, theta0);
        }
        double sum = 0.0;
        for (int k = 0; k < count; ++k) sum += C[k] / ((2.0 * k + 1) * (2.0 * k + 1));
        const double lambda = sum / theta0;
        c.assign(count, 0.0);
        for (int k = 0; k < count; ++k) c[k] = C[k] / ((2.0 * k + 1) * (2.0 * k + 1) * lambda);
        levels.push_back({std::sqrt(lambda), c});
    }
    return levels;
}

}  // namespace pendulum
