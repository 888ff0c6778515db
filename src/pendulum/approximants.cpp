// SPDX-License-Identifier: GPL-3.0-or-later
#include "pendulum/approximants.hpp"

#include "pendulum/amplitude.hpp"
#include "pendulum/bessel_series.hpp"
#include "pendulum/extended_periods.hpp"
#include "pendulum/formulas.hpp"
#include "pendulum/gsl_support.hpp"
#include "pendulum/iteration.hpp"
#include "pendulum/approximants_mp.hpp"
#include "pendulum/mp_iteration.hpp"
#include "pendulum/mp_real.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <string>

namespace pendulum {

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

namespace {

/// theta0 in extended precision from whichever of theta0 and d is the nearer to the exact
/// amplitude (as mp::exact_amplitude takes it): pi - d close to pi, the double theta0 itself
/// elsewhere (an expression's d, e.g. 2pi/3 for pi/3, is rounded twice as coarsely).
long double theta_extended(const amplitude& a) { return a.near_pi() ? a.radians_extended() : a.radians(); }

/// J_n(x) in extended precision (the power series) and in MPFR (correctly rounded, as
/// mpfr_jn gives it, by the power series where that rounds correctly).
long double j_of(int n, long double x) { return bessel_j_series(n, x); }
mp::real j_of(int n, const mp::real& x) { return mp::bessel_j_rounded(n, x); }

/// The second order's parts in units of theta0: lambda = (w/w0)^2 and C_{2k+1}/theta0.
template <class Real>
struct second_order_parts {
    Real lambda;         ///< (w/w0)^2
    std::vector<Real> C; ///< C_1, C_3, C_5 over theta0
};

/// The second order as in the paper's appendix, in one number type (extended precision for
/// the doubles, MPFR for the exact tier): the projection of sin(theta) on the first order's
/// motion, a = theta0/(1 + eta), b/theta0 = eta/(1 + eta), J_{-2} = J_2.
template <class Real>
second_order_parts<Real> second_order_of(const Real& theta0) {
    using formulas::j_over_x;
    using formulas::zero_like;
    const auto p = formulas::first_order_of(theta0);
    const Real a_ratio = 1.0 / (1.0 + p.eta);
    const Real b_ratio = p.eta / (1.0 + p.eta);
    const Real a = theta0 * a_ratio;
    second_order_parts<Real> out{zero_like(theta0), {}};
    // J_0, J_2, ..., J_8 at a, each once (J_2 enters twice).
    std::array<Real, 5> even{j_of(0, a), j_of(2, a), j_of(4, a), j_of(6, a), j_of(8, a)};
    const auto j_even = [&even](int n) -> const Real& { return even[static_cast<std::size_t>(n / 2)]; };
    for (int k = 0; k < 3; ++k) {
        const Real inner = 2.0 * j_over_x(2 * k + 1, a) * a_ratio + b_ratio * (j_even(2 * k + 4) - j_even(std::abs(2 * k - 2)));
        out.C.push_back(k % 2 == 0 ? inner : -inner);
        out.lambda = out.lambda + out.C.back() / static_cast<double>((2 * k + 1) * (2 * k + 1));
    }
    return out;
}

/// NaN with `bits`.
mp::real mp_nan(mpfr_prec_t bits) {
    mp::real r(bits);
    mpfr_set_nan(r.get());
    return r;
}

/// The solution in MPFR from lambda = (w/w0)^2 and the coefficients over theta0 (u_k), or
/// from C_k = (2k+1)^2 lambda u_k where `projected` is set.
mp_solution mp_from(const mp::real& theta0, const mp::real& lambda, const std::vector<mp::real>& u, bool projected) {
    mp_solution s{lambda.sign() > 0 ? mp::sqrt(lambda) : mp_nan(theta0.precision()), {}};
    for (std::size_t k = 0; k < u.size(); ++k) {
        const double h2 = static_cast<double>((2 * k + 1) * (2 * k + 1));
        s.coefficients.push_back(projected ? theta0 * (u[k] / (h2 * lambda)) : theta0 * u[k]);
    }
    return s;
}

}  // namespace

mp_solution detail::lowest_mp(const mp::mp_amplitude& x) { return {formulas::lowest_frequency(x.theta), {x.theta}}; }

mp_solution detail::first_mp(const mp::mp_amplitude& x) {
    const auto q = formulas::first_order_of(x.theta);
    const mp::real c1 = x.theta / (1.0 + q.eta);
    return {q.frequency, {c1, q.eta * c1}};
}

mp_solution detail::second_mp(const mp::mp_amplitude& x) {
    const auto q = second_order_of(x.theta);
    return mp_from(x.theta, q.lambda, q.C, true);
}

namespace {

/// A source from one of the MPFR solutions above at the exact amplitude a.
std::shared_ptr<const exact_source> source_of(const amplitude& a, mp_solution (*f)(const mp::mp_amplitude&)) {
    return make_source(a, [f](const amplitude_source& x, mpfr_prec_t bits) { return f(x(bits)); });
}

}  // namespace

fourier_solution harmonic(const amplitude& a) {
    const double theta0 = a.radians();
    return {1.0, {theta0}, make_source(a, [](const amplitude_source& x, mpfr_prec_t bits) {
                return mp_solution{mp::real(1.0, bits), {x(bits).theta}};
            })};
}

fourier_solution lowest_order(const amplitude& a) {
    const double theta0 = a.radians();
    return {formulas::lowest_frequency(theta0), {theta0}, source_of(a, detail::lowest_mp)};
}

long double lowest_period_extended(const amplitude& a) {
    return 1 / formulas::lowest_frequency(a.radians_extended());
}

fourier_solution first_order(const amplitude& a) {
    // In extended precision from the amplitude's extended theta0 (exact near pi), rounded
    // once: the ratios J_n(theta0)/theta0 keep every digit down to the smallest subnormal
    // amplitude, and c3' = eta c1' its last bit (in doubles it was off by up to 9 ulps).
    const long double theta0 = theta_extended(a);
    const auto p = formulas::first_order_of(theta0);
    const long double c1 = theta0 / (1 + p.eta);
    return {static_cast<double>(p.frequency), {static_cast<double>(c1), static_cast<double>(p.eta * c1)},
            source_of(a, detail::first_mp)};
}

long double first_period_extended(const amplitude& a) {
    return 1 / formulas::first_order_of(a.radians_extended()).frequency;
}

fourier_solution second_order(const amplitude& amp) {
    // Every step in extended precision, each Bessel value by its series, and the results
    // rounded once: in doubles the chain of eight Bessel values (a few ulps each), eta and
    // the projection cost up to 10 ulps in the period.
    const long double theta0 = theta_extended(amp);
    const auto p = second_order_of(theta0);
    fourier_solution s{static_cast<double>(std::sqrt(p.lambda)), {}, source_of(amp, detail::second_mp)};
    for (int k = 0; k < 3; ++k) {
        s.coefficients.push_back(static_cast<double>(theta0 * (p.C[k] / ((2 * k + 1) * (2 * k + 1) * p.lambda))));
    }
    return s;
}

long double second_period_extended(const amplitude& amp) {
    return 1 / std::sqrt(second_order_of(amp.radians_extended()).lambda);
}

mp::real detail::second_period_mp(const mp::mp_amplitude& x, int) { return 1.0 / mp::sqrt(second_order_of(x.theta).lambda); }

namespace {

/// The polynomial's c1, c3, c5 and T/T0 in one number type.
template <class Real>
std::array<Real, 4> polynomial_of(const formulas::amplitude_view<Real>& x) {
    const Real t2 = x.theta * x.theta;
    const Real t3 = t2 * x.theta;
    const Real t5 = t3 * t2;
    return {x.theta + t3 / 192.0 + 17.0 * t5 / 61440.0, -(t3 / 192.0 + t5 / 3072.0), t5 / 20480.0,
            formulas::polynomial{}(x, 0)};
}

}  // namespace

fourier_solution polynomial(const amplitude& a) {
    // In extended precision from the extended theta0 (exact near pi), rounded once: c5 =
    // theta0^5/20480 in doubles was off by up to 5.6 ulps.
    auto view = formulas::view_extended(a);
    view.theta = theta_extended(a);
    const auto p = polynomial_of(view);
    return {static_cast<double>(1 / p[3]),
            {static_cast<double>(p[0]), static_cast<double>(p[1]), static_cast<double>(p[2])},
            make_source(a, [](const amplitude_source& x, mpfr_prec_t bits) {
                const auto q = polynomial_of(x(bits));
                return mp_solution{1.0 / q[3], {q[0], q[1], q[2]}};
            })};
}

void check_order(int order) {
    if (order < 0 || order > max_order) {
        throw domain_error("order must be between 0 and " + std::to_string(max_order) + ", got " +
                           std::to_string(order));
    }
}

fourier_solution iterated(const amplitude& theta0, int order) {
    return std::move(iterated_sequence(theta0, order).back());
}

namespace {

/// How many bits of w/w0 the extended iteration keeps: its rounding grows from level to
/// level and towards pi, to 2^-57.1 relative measured at d = 0.0201 (2^-61 at d >= 1).
constexpr int extended_ratio_bits = 56;

/// Level n of the iteration in MPFR at the exact amplitude, for a level's exact_source.
/// Close to pi the iteration amplifies the rounding of every level: a run with p bits whose
/// levels agree with the run at p/2 to 1e-15 (2^-49.8) amplifies by less than 2^(p/2 - 49),
/// so `extra_bits` = p/2 more than asked keep w/w0 within 2^-(bits - 16) at any precision
/// asked (without them a phase at pi - 1e-12, order 92, came from a 73-bit run: off by 1e-7).
std::shared_ptr<const exact_source> iteration_source(const amplitude& a, int n, long double known_ratio,
                                                     int known_bits, mpfr_prec_t extra_bits = 0) {
    return make_source(a, [a, n, extra_bits](const amplitude_source& amplitude_at, mpfr_prec_t asked) {
        const mpfr_prec_t bits = asked + extra_bits;
        const auto x = amplitude_at(bits);
        std::vector<std::vector<mp::real>> u;
        const auto lambdas = detail::mp_lambdas(x, n, bits, {}, &u);
        if (lambdas.size() <= static_cast<std::size_t>(n) || !lambdas[static_cast<std::size_t>(n)]) {
            throw domain_error("the iteration's projection does not converge at order " + std::to_string(n) +
                               " for theta0 = " + format_amplitude(a));
        }
        return mp_from(x.theta, *lambdas[static_cast<std::size_t>(n)], u[static_cast<std::size_t>(n)], false);
    }, known_ratio, known_bits);
}

}  // namespace

std::vector<fourier_solution> iterated_sequence(const amplitude& a, int order) {
    check_order(order);
    // Close to pi the iteration's rounding grows at every level: MPFR there.
    if (a.from_pi() >= detail::iteration_mp_below) return iterated_sequence_extended(a, order);
    mpfr_prec_t bits = 0;
    auto levels = detail::iterated_sequence_mp(a, order, &bits);
    // Their w/w0 agree with a run at half the bits to 1e-15, and are rounded to doubles.
    for (std::size_t n = 0; n < levels.size(); ++n) {
        levels[n].exact = iteration_source(a, static_cast<int>(n), levels[n].frequency_ratio, 49, bits / 2);
    }
    return levels;
}

std::vector<fourier_solution> iterated_sequence_extended(const amplitude& a, int order) {
    check_order(order);
    // Every level in extended precision and rounded once: in doubles the levels' rounding
    // grows to about 100 ulps at d = 0.02 from pi (order 37), in extended precision it stays
    // 2^11 times smaller, below half an ulp of the doubles.
    const long double theta0 = theta_extended(a);
    std::vector<fourier_solution> levels;
    // The coefficients in units of theta0, so that no amplitude underflows.
    const bool converged = iteration::levels(theta0, order, [&](int n, const iteration::level<long double>& level) {
        fourier_solution s;
        for (long double v : level.u) s.coefficients.push_back(static_cast<double>(theta0 * v));
        // lambda = (w/w0)^2; where it is not positive the level has no real frequency (the
        // scheme breaks down there, close to pi), and the iteration goes on from its c_k.
        const long double ratio =
            level.lambda > 0 ? std::sqrt(level.lambda) : std::numeric_limits<long double>::quiet_NaN();
        s.frequency_ratio = static_cast<double>(ratio);
        s.exact = iteration_source(a, n, ratio, extended_ratio_bits);
        levels.push_back(std::move(s));
        return false;
    });
    if (!converged) {
        throw domain_error("the iteration's projection does not converge at order " + std::to_string(levels.size()) +
                           " for theta0 = " + format_amplitude(a));
    }
    return levels;
}

std::vector<level_period> iterated_periods(const amplitude& a, int order) {
    const double theta0 = a.radians();
    const auto levels = iterated_sequence(a, order);
    // The same iteration in extended precision from the double theta0, so that the
    // difference shows how far the double run's rounding has grown.
    std::vector<long double> lambdas;
    (void)iteration::levels(static_cast<long double>(theta0), order, [&](int, const iteration::level<long double>& level) {
        lambdas.push_back(level.lambda);
        return false;
    });
    std::vector<level_period> out;
    for (std::size_t n = 0; n < levels.size(); ++n) {
        const double value = levels[n].period_ratio();
        if (n >= lambdas.size() || !(lambdas[n] > 0) || std::isnan(value)) {
            out.push_back({std::nan(""), std::nan("")});
            continue;
        }
        const long double extended = 1 / std::sqrt(lambdas[n]);
        out.push_back({value, static_cast<double>(std::fabs(value - extended))});
    }
    return out;
}

}  // namespace pendulum
