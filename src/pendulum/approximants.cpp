// SPDX-License-Identifier: GPL-3.0-or-later
#include "pendulum/approximants.hpp"

#include "pendulum/amplitude.hpp"
#include "pendulum/bessel_series.hpp"
#include "pendulum/extended_periods.hpp"
#include "pendulum/formulas.hpp"
#include "pendulum/gsl_support.hpp"
#include "pendulum/mp_iteration.hpp"
#include "pendulum/mp_real.hpp"

#include <algorithm>
#include <array>
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

namespace {

/// theta0 in extended precision from whichever of theta0 and d is the nearer to the exact
/// amplitude (as mp::exact_amplitude takes it): pi - d close to pi, the double theta0 itself
/// elsewhere (an expression's d, e.g. 2pi/3 for pi/3, is rounded twice as coarsely).
long double theta_extended(const amplitude& a) { return a.near_pi() ? a.radians_extended() : a.radians(); }

/// J_n(x) in extended precision (the power series) and in MPFR.
long double j_of(int n, long double x) { return bessel_j_series(n, x); }
mp::real j_of(int n, const mp::real& x) { return mp::bessel_j(n, x); }

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
    for (int k = 0; k < 3; ++k) {
        const Real inner = 2.0 * j_over_x(2 * k + 1, a) * a_ratio + b_ratio * (j_of(2 * k + 4, a) - j_of(std::abs(2 * k - 2), a));
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
    return make_source([a, f](mpfr_prec_t bits) { return f(mp::exact_amplitude(a, bits)); });
}

}  // namespace

fourier_solution harmonic(const amplitude& a) {
    const double theta0 = a.radians();
    return {1.0, {theta0}, make_source([a](mpfr_prec_t bits) {
                return mp_solution{mp::real(1.0, bits), {mp::exact_amplitude(a, bits).theta}};
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
            make_source([a](mpfr_prec_t bits) {
                const auto q = polynomial_of(mp::exact_amplitude(a, bits));
                return mp_solution{1.0 / q[3], {q[0], q[1], q[2]}};
            })};
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
    return make_source([a, n, extra_bits](mpfr_prec_t asked) {
        const mpfr_prec_t bits = asked + extra_bits;
        const auto x = mp::exact_amplitude(a, bits);
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
    sine_projector<long double> project;
    // The coefficients in units of theta0, so that no amplitude underflows.
    std::vector<long double> u{1.0L};
    for (int level = 0; level <= order; ++level) {
        const int count = level + 1;
        std::vector<long double> C;
        if (level <= 1) {
            // Exact in closed form: sin(theta0 cos x) = 2 sum (-1)^k J_{2k+1}(theta0) cos((2k+1)x).
            for (int k = 0; k < count; ++k) {
                const long double j = 2 * bessel_j_over_x_series(2 * k + 1, theta0);
                C.push_back(k % 2 == 0 ? j : -j);
            }
        } else {
            C = project(u, count, theta0);
        }
        const long double lambda = next_level(C, u);
        fourier_solution level_solution;
        for (long double v : u) level_solution.coefficients.push_back(static_cast<double>(theta0 * v));
        // lambda = (w/w0)^2; where it is not positive the level has no real frequency (the
        // scheme breaks down there, close to pi), and the iteration goes on from its c_k.
        const long double ratio = lambda > 0 ? std::sqrt(lambda) : std::numeric_limits<long double>::quiet_NaN();
        level_solution.frequency_ratio = static_cast<double>(ratio);
        level_solution.exact = iteration_source(a, level, ratio, extended_ratio_bits);
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
