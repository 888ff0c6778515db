// SPDX-License-Identifier: GPL-3.0-or-later
// A formula in MPFR, and its period error T_f/T - 1. Each value carries an estimate of the
// bits it has lost (cancellation in + and -, and each function's condition number); an
// error is kept where it stands clear of those lost bits and two precisions agree on it to
// 1e-13, so that rounding noise is never returned as an error.
#include "pendulum/formula.hpp"
#include "pendulum/mp_real.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>

namespace pendulum {

namespace {

using mp::real;
using op = formula_node::op;

/// Precisions tried in turn, each checked against the one before it.
constexpr std::array<mpfr_prec_t, 9> precisions = {128, 192, 256, 384, 512, 768, 1152, 1536, 2304};

/// A value is kept when it is this many bits clear of the rounding and the bits it lost.
constexpr long margin_bits = 56;

/// Two precisions agree when their errors differ by at most this, relative.
constexpr double agreement = 1e-13;

/// A lost-bits count that means "nothing left".
constexpr long all_lost = std::numeric_limits<int>::max();

/// A value in MPFR, the bits of it that cancellation or conditioning have cost, and whether
/// it is exact (every step exact, as MPFR's ternary values tell): an exact zero of a
/// difference is no cancellation.
struct mp_value {
    real v;
    long lost = 0;
    bool exact = false;
};

/// log2 |x| for a regular number; very negative for zero, very positive for inf/NaN.
long magnitude(const real& x) {
    if (mpfr_zero_p(x.get())) return -all_lost / 4;
    if (!mpfr_number_p(x.get())) return all_lost / 4;
    return mp::exponent(x);
}

long plus(long a, long b) { return std::min(all_lost, std::max(0L, a) + std::max(0L, b)); }

/// Above a double's range a value is infinite, as in doubles (and a huge argument of sin,
/// which would cost MPFR millions of bits to reduce, never arises).
void clamp(real& r) {
    if (mpfr_number_p(r.get()) && !mpfr_zero_p(r.get()) && mpfr_get_exp(r.get()) > 1024) {
        mpfr_set_inf(r.get(), mpfr_sgn(r.get()));
    }
}

using mpfr_unary = int (*)(mpfr_ptr, mpfr_srcptr, mpfr_rnd_t);
using mpfr_binary = int (*)(mpfr_ptr, mpfr_srcptr, mpfr_srcptr, mpfr_rnd_t);

mpfr_unary unary_function(op what) {
    switch (what) {
        case op::neg: return mpfr_neg;
        case op::abs: return mpfr_abs;
        case op::sqrt: return mpfr_sqrt;
        case op::atan: return mpfr_atan;
        case op::tanh: return mpfr_tanh;
        case op::exp: return mpfr_exp;
        case op::sinh: return mpfr_sinh;
        case op::cosh: return mpfr_cosh;
        case op::log: return mpfr_log;
        case op::asin: return mpfr_asin;
        case op::acos: return mpfr_acos;
        default: return nullptr;
    }
}

/// Estimated seconds of one node at `bits` (a deterministic count, not a clock): arithmetic,
/// an elementary function, and besselj, whose MPFR series costs grow with |n| and |x|.
double node_seconds(const formula_node& n, mpfr_prec_t bits, double x) {
    if (!std::isfinite(x)) x = 0;  // no work: the value is not finite either
    const double scale = static_cast<double>(bits) / 128;
    switch (n.what) {
        case op::number: case op::pi: case op::theta0: case op::t: case op::add: case op::sub: case op::mul:
        case op::div: case op::neg: case op::abs: return 1e-7 * scale;
        case op::besselj:
            return 2e-6 * std::pow(scale, 1.5) + 5e-3 * std::abs(n.order) / max_bessel_order * std::min(std::fabs(x), 1e3) / 1e3;
        case op::sin: case op::cos: case op::tan:
            // The argument's reduction modulo pi/2 works with its exponent's bits more.
            return 2e-6 * std::pow(scale * (1 + std::max(0.0, std::log2(std::fabs(x) + 1)) / 64), 1.5);
        default: return 2e-6 * std::pow(scale, 1.5);
    }
}

/// The work one formula_period_error may do, in estimated seconds: past it the error is
/// not computed (a gap), so that no formula holds a render for long.
constexpr double work_budget = 0.02;

/// besselj's MPFR series between these |x| costs seconds to minutes for a large |n| (x = 5e5,
/// n = 1000: over 20 s); there the value is left unresolved. |x| above n^2 is asymptotic and fast.
bool bessel_too_costly(int n, double x) {
    const double big = static_cast<double>(n) * n;
    return std::fabs(x) > 1e3 && std::fabs(x) < big;
}

class evaluator {
public:
    evaluator(const std::vector<formula_node>& nodes, const real& theta0, bool theta0_exact, mpfr_prec_t bits, double& work)
        : nodes_(nodes), theta0_(theta0), theta0_exact_(theta0_exact), bits_(bits), work_(work) {}

    mp_value at(int i) const {
        const auto& n = nodes_[static_cast<std::size_t>(i)];
        if (work_ > work_budget) return {real(std::numeric_limits<double>::quiet_NaN(), bits_), all_lost, false};
        if (n.what != op::besselj) work_ += node_seconds(n, bits_, 0);
        switch (n.what) {
            case op::number: {
                real r(bits_);
                const bool exact = mpfr_strtofr(r.get(), n.digits.c_str(), nullptr, 10, MPFR_RNDN) == 0;
                clamp(r);
                return {std::move(r), 0, exact};
            }
            case op::pi: return {mp::pi(bits_), 0, false};
            case op::theta0: return {real(theta0_, bits_), 0, theta0_exact_};
            case op::t: return {real(bits_), 0, true};  // period formulas have no t
            case op::add: return sum(n, mpfr_add);
            case op::sub: return sum(n, mpfr_sub);
            case op::mul: return product(n, mpfr_mul);
            case op::div: return product(n, mpfr_div);
            case op::agm: return product(n, mpfr_agm);
            case op::pow: return power(n);
            case op::besselj: return bessel(n);
            case op::sin:
            case op::cos:
            case op::tan: return trigonometric(n.what, at(n.a));
            case op::ellipk:
            case op::ellipe: return elliptic(n.what, at(n.a));
            default: return function(n.what, at(n.a));
        }
    }

private:
    mp_value sum(const formula_node& n, mpfr_binary f) const {
        const mp_value a = at(n.a);
        const mp_value b = at(n.b);
        real r(bits_);
        const bool exact = f(r.get(), a.v.get(), b.v.get(), MPFR_RNDN) == 0 && a.exact && b.exact;
        clamp(r);
        const long before = std::max(a.lost, b.lost);
        if (exact || !mpfr_number_p(r.get())) return {std::move(r), before, exact};
        // An inexact zero from numbers is cancellation: nothing of them is left.
        if (r.is_zero()) return {std::move(r), a.v.is_zero() && b.v.is_zero() ? before : all_lost, false};
        const long m = magnitude(r);
        const long la = a.v.is_zero() ? 0 : a.lost + magnitude(a.v) - m;
        const long lb = b.v.is_zero() ? 0 : b.lost + magnitude(b.v) - m;
        return {std::move(r), std::max({0L, la, lb}), false};
    }

    mp_value product(const formula_node& n, mpfr_binary f) const {
        const mp_value a = at(n.a);
        const mp_value b = at(n.b);
        real r(bits_);
        const bool exact = f(r.get(), a.v.get(), b.v.get(), MPFR_RNDN) == 0 && a.exact && b.exact;
        clamp(r);
        return {std::move(r), std::max(a.lost, b.lost), exact};
    }

    mp_value power(const formula_node& n) const {
        const mp_value x = at(n.a);
        const mp_value y = at(n.b);
        real r(bits_);
        const bool exact = mpfr_pow(r.get(), x.v.get(), y.v.get(), MPFR_RNDN) == 0 && x.exact && y.exact;
        clamp(r);
        if (exact) return {std::move(r), 0, true};
        // d(x^y)/x^y = y dx/x + y ln(x) dy/y: y amplifies x's error, ln(x^y) y's.
        const long by_x = plus(x.lost, magnitude(y.v) + 1);
        long ln_r = 0;
        if (mpfr_regular_p(r.get())) {
            ln_r = static_cast<long>(std::log2(std::fabs(static_cast<double>(mpfr_get_exp(r.get()))) + 1)) + 1;
        }
        const long by_y = plus(y.lost, ln_r);
        return {std::move(r), std::max(by_x, by_y), false};
    }

    mp_value bessel(const formula_node& n) const {
        const mp_value x = at(n.a);
        const double xd = x.v.to_double();
        work_ += node_seconds(n, bits_, xd);
        if (bessel_too_costly(n.order, xd)) return {real(std::numeric_limits<double>::quiet_NaN(), bits_), all_lost, false};
        real r(bits_);
        const bool exact = mpfr_jn(r.get(), n.order, x.v.get(), MPFR_RNDN) == 0 && x.exact;
        if (exact) return {std::move(r), 0, true};
        // x J_n'(x)/J_n(x) = x J_{n-1}(x)/J_n(x) - n, estimated in doubles.
        const double ratio = std::fabs(xd * jn(n.order - 1, xd) / jn(n.order, xd) - n.order);
        const double cond = std::isfinite(ratio) ? ratio : std::fabs(xd) + std::abs(n.order) + 1;
        const long cost = r.is_zero() && !x.v.is_zero() ? all_lost : static_cast<long>(std::log2(cond + 1)) + 1;
        return {std::move(r), plus(x.lost, cost), false};
    }

    /// f(x) with the bits its condition |x f'(x)/f(x)| costs, as log2.
    mp_value function(op what, const mp_value& x) const {
        real r(bits_);
        const bool exact = unary_function(what)(r.get(), x.v.get(), MPFR_RNDN) == 0 && x.exact;
        clamp(r);
        if (exact || !mpfr_number_p(r.get())) return {std::move(r), x.lost, exact};
        long cost = 0;
        switch (what) {
            case op::exp:
            case op::sinh:
            case op::cosh: cost = magnitude(x.v) + 1; break;
            case op::log: cost = r.is_zero() ? all_lost : -magnitude(r) + 1; break;
            case op::asin:
            case op::acos: {
                const real gap = 1.0 - mp::abs(x.v);
                cost = gap.is_zero() || (what == op::acos && r.is_zero()) ? all_lost : -magnitude(gap) + 2;
                break;
            }
            default: break;  // sqrt, abs, atan, tanh: condition at most 1
        }
        return {std::move(r), plus(x.lost, cost), false};
    }

    mp_value trigonometric(op what, const mp_value& x) const {
        formula_node node;
        node.what = what;
        work_ += node_seconds(node, bits_, x.v.to_double());
        if (!mpfr_number_p(x.v.get())) return {real(std::numeric_limits<double>::quiet_NaN(), bits_), x.lost, false};
        if (x.v.is_zero()) return {real(what == op::cos ? 1.0 : 0.0, bits_), x.lost, x.exact};
        real s(bits_);
        real c(bits_);
        mpfr_sin_cos(s.get(), c.get(), x.v.get(), MPFR_RNDN);
        // sin: x cos/sin; cos: x sin/cos; tan: x/(sin cos).
        const long ms = magnitude(s);
        const long mc = magnitude(c);
        const long mx = magnitude(x.v);
        real r = what == op::sin ? s : what == op::cos ? c : s / c;
        long cost = what == op::sin ? mx + mc - ms : what == op::cos ? mx + ms - mc : mx - ms - mc;
        if (r.is_zero() || (what == op::tan && c.is_zero())) cost = all_lost;
        return {std::move(r), plus(x.lost, cost + 1), false};
    }

    /// K(m) = pi/(2 agm(1, sqrt(1 - m))); E(m) = K(m) (1 - sum 2^(n-1) c_n^2) along that AGM.
    mp_value elliptic(op what, const mp_value& m) const {
        const real one(1.0, bits_);
        const real gap = one - m.v;  // 1 - m: its cancellation costs what m's error is worth
        if (!mpfr_number_p(m.v.get()) || gap < 0.0) return {real(std::numeric_limits<double>::quiet_NaN(), bits_), m.lost, false};
        if (gap.is_zero()) {
            // m = 1: K is infinite, E is 1; where m is not exact, 1 - m is cancellation.
            const long lost = m.exact ? m.lost : all_lost;
            return {what == op::ellipk ? real(std::numeric_limits<double>::infinity(), bits_) : one, lost, m.exact};
        }
        const long cost = std::max(0L, -magnitude(gap)) + 2;
        real a = one;
        real b = mp::sqrt(gap);
        if (what == op::ellipk) return {mp::pi(bits_) / (2.0 * mp::agm(a, b)), plus(m.lost, cost), false};
        real sum = m.v / 2.0;
        real weight(0.5, bits_);
        for (int i = 0; i < 4 * static_cast<int>(bits_) && mpfr_number_p(sum.get()); ++i) {
            const real c = (a - b) / 2.0;
            const real next = (a + b) / 2.0;
            b = mp::sqrt(a * b);
            a = next;
            weight = weight * 2.0;
            const real term = weight * c * c;
            sum = sum + term;
            if (term.is_zero() || magnitude(term) < magnitude(sum) - static_cast<long>(bits_) - 8) break;
        }
        return {mp::pi(bits_) / (2.0 * a) * (1.0 - sum), plus(m.lost, cost), false};
    }

    const std::vector<formula_node>& nodes_;
    const real& theta0_;
    bool theta0_exact_;
    mpfr_prec_t bits_;
    double& work_;
};

/// The amplitude and k' with `bits`, from the exact amplitude (pi - d close to pi where the
/// double theta0 is rounded).
struct mp_amplitude {
    real theta;
    real kp;
    bool exact;  ///< theta is the amplitude itself (a double), not pi - d rounded
};

mp_amplitude exact_amplitude(const amplitude& a, mpfr_prec_t bits) {
    if (a.near_pi() && !a.exact_radians()) {
        const real d(a.from_pi(), bits);
        return {mp::pi(bits) - d, mp::sin(d / 2.0), false};
    }
    const real theta(a.radians(), bits);
    return {theta, mp::cos(theta / 2.0), true};
}

mp_value evaluate_mp(const formula& f, const mp_amplitude& x, mpfr_prec_t bits, double& work) {
    return evaluator(f.nodes(), x.theta, x.exact, bits, work).at(static_cast<int>(f.nodes().size()) - 1);
}

/// How many bits of a value computed with `bits` are left after it lost `lost`.
long left_bits(mpfr_prec_t bits, long lost) { return static_cast<long>(bits) - std::min(lost, all_lost / 2) - margin_bits; }

/// One precision's error: what it is, and how many bits of it can be trusted.
struct error_at {
    real error;       ///< T_f/T - 1
    long left = 0;    ///< bits of T_f/T that are right
    bool finite = true;
};

error_at error_with(const formula& f, const amplitude& a, mpfr_prec_t bits, double& work) {
    const mp_amplitude x = exact_amplitude(a, bits);
    const mp_value value = evaluate_mp(f, x, bits, work);
    const real ratio = value.v * mp::agm(real(1.0, bits), x.kp);  // T_f/T = T_f agm(1, k')
    const bool finite = mpfr_number_p(ratio.get()) != 0;
    // Not finite: whether it is so for certain depends on the bits lost on the way only.
    const long left = left_bits(bits, value.lost) - (finite ? std::max(0L, magnitude(ratio)) : 0L);
    return {ratio - 1.0, left, finite};
}

/// True where the two errors agree to `agreement`, relative.
bool agree(const real& a, const real& b) {
    if (a.is_zero() || b.is_zero()) return a.is_zero() && b.is_zero();
    return mp::abs((a - b) / b) <= agreement;
}

}  // namespace

period_error formula_period_error(const formula& f, const amplitude& theta0) {
    std::optional<error_at> previous;
    double work = 0;
    for (const mpfr_prec_t bits : precisions) {
        if (work > work_budget) break;
        error_at now = error_with(f, theta0, bits, work);
        if (!now.finite) {
            // Not finite with bits to spare: the formula has no value here.
            if (now.left > 0) return {period_error::kind::no_period, 0};
            previous.reset();
            continue;
        }
        const bool resolved = !now.error.is_zero() && magnitude(now.error) > -now.left;
        if (resolved && previous && previous->finite && agree(now.error, previous->error)) {
            if (mp::abs(now.error) < smallest_period_error) return {period_error::kind::below_limit, 0};
            return {period_error::kind::value, now.error.to_double()};
        }
        // Below 1e-300 with the bits to tell: the error is only that small.
        constexpr long limit_bits = 1010;  // 2^-1010 < 1e-3 * 1e-300
        if (now.left > limit_bits && mp::abs(now.error) < smallest_period_error) return {period_error::kind::below_limit, 0};
        previous = std::move(now);
    }
    return {period_error::kind::not_computed, 0};
}

double formula_error_seconds(const formula& f) {
    double seconds = 0;
    for (const mpfr_prec_t bits : precisions) {
        for (const auto& n : f.nodes()) seconds += node_seconds(n, bits, 1e3);
    }
    return std::min(seconds, work_budget);
}

double formula_period(const formula& f, const amplitude& theta0) {
    if (!theta0.near_pi() || theta0.exact_radians()) return f.value(theta0.radians());
    // Close to pi from an expression: the double theta0 is rounded, the exact amplitude is not.
    std::optional<double> previous;
    double work = 0;
    for (const mpfr_prec_t bits : precisions) {
        const mp_amplitude x = exact_amplitude(theta0, bits);
        const mp_value value = evaluate_mp(f, x, bits, work);
        const double v = value.v.to_double();
        if (left_bits(bits, value.lost) > 53 && previous && (v == *previous || std::fabs(v - *previous) <= 1e-15 * std::fabs(v))) return v;
        if (!std::isfinite(v) && left_bits(bits, value.lost) > 0) return std::numeric_limits<double>::quiet_NaN();
        previous = v;
    }
    return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace pendulum
