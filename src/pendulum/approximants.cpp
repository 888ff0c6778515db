// SPDX-License-Identifier: GPL-3.0-or-later
#include "pendulum/approximants.hpp"

#include "pendulum/amplitude.hpp"
#include "pendulum/bessel_series.hpp"
#include "pendulum/extended_periods.hpp"
#include "pendulum/formulas.hpp"
#include "pendulum/gsl_support.hpp"
#include "pendulum/mp_iteration.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <string>

namespace pendulum {

using std::numbers::pi;

double fourier_solution::theta(double w0_t) const {
    if (!std::isfinite(w0_t)) throw domain_error("time must be finite, got " + format_double(w0_t));
    // A level of the iteration without a period (lambda < 0) has no value at any time.
    if (std::isnan(frequency_ratio)) return std::numeric_limits<double>::quiet_NaN();
    return theta_at_phase(frequency_ratio * w0_t);
}

double fourier_solution::theta_at_phase(double x) const {
    if (!std::isfinite(x)) throw domain_error("phase must be finite, got " + format_double(x));
    double sum = 0.0;
    for (std::size_t k = 0; k < coefficients.size(); ++k) {
        sum += coefficients[k] * std::cos(static_cast<double>(2 * k + 1) * x);
    }
    return sum;
}

double besinc(double x) {
    if (!std::isfinite(x)) throw domain_error("besinc needs a finite argument, got " + format_double(x));
    if (x == 0.0) return 1.0;
    return 2.0 * bessel_j_over_x(1, x);
}

fourier_solution harmonic(const amplitude& a) {
    const double theta0 = a.radians();
    return {1.0, {theta0}};
}

fourier_solution lowest_order(const amplitude& a) {
    const double theta0 = a.radians();
    return {formulas::lowest_frequency(theta0), {theta0}};
}

long double lowest_period_extended(const amplitude& a) {
    return 1 / formulas::lowest_frequency(a.radians_extended());
}

fourier_solution first_order(const amplitude& a) {
    const double theta0 = a.radians();
    // Ratios J_n(theta0)/theta0 keep every digit down to the smallest subnormal amplitude.
    const auto p = formulas::first_order_of(theta0);
    const double c1 = theta0 / (1.0 + p.eta);
    return {p.frequency, {c1, p.eta * c1}};
}

long double first_period_extended(const amplitude& a) {
    return 1 / formulas::first_order_of(a.radians_extended()).frequency;
}

namespace {

/// The second order in extended precision: lambda = (w/w0)^2 and C_{2k+1}/theta0.
struct second_order_parts {
    long double theta0;
    long double lambda;
    long double C[3];
};

second_order_parts second_order_extended(const amplitude& amp) {
    // Every step in extended precision, each Bessel value by its series, and the results
    // rounded once: in doubles the chain of eight Bessel values (a few ulps each), eta and
    // the projection cost up to 10 ulps in the period.
    using real = long double;
    second_order_parts p{};
    const real theta0 = amp.radians_extended();
    p.theta0 = theta0;
    const real j1 = bessel_j_over_x_series(1, theta0);
    const real eta = -bessel_j_over_x_series(3, theta0) / (9 * j1);
    // The projection and lambda in units of theta0: a/theta0 and b/theta0 are of order one.
    const real a_ratio = 1 / (1 + eta);
    const real b_ratio = eta / (1 + eta);
    const real a = theta0 * a_ratio;
    real sum = 0;
    for (int k = 0; k < 3; ++k) {
        // J_{2k-2} with J_{-2} = J_2 (integer-order reflection).
        const real inner = 2 * bessel_j_over_x_series(2 * k + 1, a) * a_ratio +
                           b_ratio * (bessel_j_series(2 * k + 4, a) - bessel_j_series(std::abs(2 * k - 2), a));
        p.C[k] = (k % 2 == 0) ? inner : -inner;
        sum += p.C[k] / ((2 * k + 1) * (2 * k + 1));
    }
    p.lambda = sum;
    return p;
}

}  // namespace

fourier_solution second_order(const amplitude& amp) {
    const auto p = second_order_extended(amp);
    fourier_solution s{static_cast<double>(std::sqrt(p.lambda)), {}};
    for (int k = 0; k < 3; ++k) {
        s.coefficients.push_back(static_cast<double>(p.theta0 * (p.C[k] / ((2 * k + 1) * (2 * k + 1) * p.lambda))));
    }
    return s;
}

long double second_period_extended(const amplitude& amp) { return 1 / std::sqrt(second_order_extended(amp).lambda); }

fourier_solution polynomial(const amplitude& a) {
    const double theta0 = a.radians();
    const double t2 = theta0 * theta0;
    const double t3 = t2 * theta0;
    const double t5 = t3 * t2;
    const double period = formulas::polynomial{}(formulas::view_of(a), 0);
    return {1.0 / period,
            {theta0 + t3 / 192.0 + 17.0 * t5 / 61440.0, -(t3 / 192.0 + t5 / 3072.0), t5 / 20480.0}};
}

namespace {

/// cos(m pi / (4L)) for m = 0 .. 8L - 1: every cosine the rule with L points needs, each
/// correctly rounded (a recurrence in j would lose about j^2 ulps near x = 0).
template <class Real>
std::vector<Real> cosine_table(int L) {
    std::vector<Real> table(static_cast<std::size_t>(8 * L));
    const Real step = std::numbers::pi_v<Real> / (4 * L);
    for (int m = 0; m < 8 * L; ++m) table[static_cast<std::size_t>(m)] = std::cos(m * step);
    return table;
}

/// sin(theta0 u) / theta0, exact for every theta0 in (0, pi), subnormals included.
template <class Real>
Real sine_over(Real theta0, Real u) {
    const Real t = theta0 * u;
    if (theta0 < small_amplitude) return u * (1 - t * t / 6);
    return std::sin(t) / theta0;
}

/// C_{2k+1}/theta0 = (1/(pi theta0)) int_0^{2pi} cos((2k+1)x) sin(theta(x)) dx, k < count,
/// where theta(x) = theta0 sum_j u_j cos((2j+1)x), by the midpoint rule on [0, pi/2] with L
/// points. The integrand is even and antisymmetric about pi/2, so this is the trapezoidal
/// rule on 4L points over the period: its error is the aliasing of the harmonics of
/// sin(theta) above 4L - 2 count, which fall off geometrically.
template <class Real>
std::vector<Real> project_sine(const std::vector<Real>& u, int count, Real theta0, int L,
                               const std::vector<Real>& table) {
    const int period = 8 * L;
    std::vector<Real> C(static_cast<std::size_t>(count), 0);
    std::vector<Real> odd_cos(std::max<std::size_t>(u.size(), static_cast<std::size_t>(count)));
    for (int i = 0; i < L; ++i) {
        // cos((2j+1) x_i) with x_i = (2i+1) pi / (4L) is table[(2j+1)(2i+1) mod 8L].
        const int step = 2 * (2 * i + 1);
        int index = 2 * i + 1;
        for (Real& v : odd_cos) {
            v = table[static_cast<std::size_t>(index)];
            index += step;
            if (index >= period) index -= period;
        }
        Real theta = 0;
        for (std::size_t j = 0; j < u.size(); ++j) theta += u[j] * odd_cos[j];
        const Real f = sine_over(theta0, theta);
        for (int k = 0; k < count; ++k) C[static_cast<std::size_t>(k)] += f * odd_cos[static_cast<std::size_t>(k)];
    }
    for (Real& v : C) v *= Real(2) / L;
    return C;
}

/// The projection with L doubled until two rules agree to 1e-11 (in units of theta0), or to
/// 1e-13 in extended precision. The rules converge geometrically, so the error of the finer
/// one is about the square of that: far below rounding, which a test on the rounding level
/// itself could never see.
template <class Real>
class sine_projector {
public:
    std::vector<Real> operator()(const std::vector<Real>& u, int count, Real theta0) {
        // Harmonics up to 2 count - 1 need 4L > 2 count; the rule's L only grows from level to level.
        L_ = std::max(L_, count / 2 + 16);
        auto coarse = project_sine(u, count, theta0, L_, table(L_));
        const Real agreement = sizeof(Real) > sizeof(double) ? 1e-13 : 1e-11;
        for (;;) {
            auto fine = project_sine(u, count, theta0, 2 * L_, table(2 * L_));
            Real diff = 0;
            for (std::size_t k = 0; k < fine.size(); ++k) diff = std::max(diff, std::fabs(fine[k] - coarse[k]));
            if (diff <= agreement || 2 * L_ >= max_points) return fine;
            L_ *= 2;
            coarse = std::move(fine);
        }
    }

private:
    static constexpr int max_points = 1 << 16;

    const std::vector<Real>& table(int L) {
        auto it = tables_.find(L);
        if (it == tables_.end()) it = tables_.emplace(L, cosine_table<Real>(L)).first;
        return it->second;
    }

    int L_ = 0;
    std::map<int, std::vector<Real>> tables_;
};

/// One level from its projection C (in units of theta0): lambda = sum C_k/(2k+1)^2 and the
/// new u_k = C_k / ((2k+1)^2 lambda). Returns lambda.
template <class Real>
Real next_level(const std::vector<Real>& C, std::vector<Real>& u) {
    Real lambda = 0;
    for (std::size_t k = 0; k < C.size(); ++k) lambda += C[k] / Real((2 * k + 1) * (2 * k + 1));
    u.resize(C.size());
    for (std::size_t k = 0; k < C.size(); ++k) u[k] = C[k] / ((2 * k + 1) * (2 * k + 1) * lambda);
    return lambda;
}

}  // namespace

void check_order(int order) {
    if (order < 0 || order > max_order) {
        throw domain_error("order must be between 0 and " + std::to_string(max_order) + ", got " +
                           std::to_string(order));
    }
}

fourier_solution iterated(const amplitude& theta0, int order) {
    return std::move(iterated_sequence(theta0, order).back());
}

std::vector<fourier_solution> iterated_sequence(const amplitude& a, int order) {
    check_order(order);
    // Close to pi the double iteration's rounding grows at every level: MPFR there.
    if (a.from_pi() < detail::iteration_mp_below) return detail::iterated_sequence_mp(a, order);
    const double theta0 = a.radians();
    std::vector<fourier_solution> levels;
    sine_projector<double> project;
    // The coefficients in units of theta0, so that no amplitude underflows.
    std::vector<double> u{1.0};
    for (int level = 0; level <= order; ++level) {
        const int count = level + 1;
        std::vector<double> C;
        if (level <= 1) {
            // Exact in closed form: sin(theta0 cos x) = 2 sum (-1)^k J_{2k+1}(theta0) cos((2k+1)x).
            for (int k = 0; k < count; ++k) {
                const double j = 2.0 * bessel_j_over_x(2 * k + 1, theta0);
                C.push_back(k % 2 == 0 ? j : -j);
            }
        } else {
            C = project(u, count, theta0);
        }
        const double lambda = next_level(C, u);
        fourier_solution level_solution;
        for (double v : u) level_solution.coefficients.push_back(theta0 * v);
        // lambda = (w/w0)^2; where it is not positive the level has no real frequency (the
        // scheme breaks down there, close to pi), and the iteration goes on from its c_k.
        level_solution.frequency_ratio = lambda > 0 ? std::sqrt(lambda) : std::nan("");
        levels.push_back(std::move(level_solution));
    }
    return levels;
}

std::vector<level_period> iterated_periods(const amplitude& a, int order) {
    const double theta0 = a.radians();
    const auto levels = iterated_sequence(a, order);
    // The same iteration in extended precision, every level projected (no double Bessel
    // values), so that the difference shows how far the double run's rounding has grown.
    sine_projector<long double> project;
    std::vector<long double> u{1.0L};
    std::vector<level_period> out;
    for (int level = 0; level <= order; ++level) {
        const long double lambda = next_level(project(u, level + 1, static_cast<long double>(theta0)), u);
        const double value = levels[static_cast<std::size_t>(level)].period_ratio();
        if (!(lambda > 0) || std::isnan(value)) {
            out.push_back({std::nan(""), std::nan("")});
            continue;
        }
        const long double extended = 1 / std::sqrt(lambda);
        out.push_back({value, static_cast<double>(std::fabs(value - extended))});
    }
    return out;
}

}  // namespace pendulum
