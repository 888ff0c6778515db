// SPDX-License-Identifier: GPL-3.0-or-later
// Period errors T_m/T - 1 without cancellation. Where the two periods differ in their first
// two digits, doubles give the error to 1e-13; closer, both periods are computed again with
// MPFR from the exact amplitude (theta0, or pi - d near pi), with 128 bits and then more, until
// the difference is far above the rounding of the precision used (a closed form starts at the
// first precision an error of at most theta0^2 may need, with the same results).
#include "pendulum/period_error.hpp"

#include "pendulum/approximants.hpp"
#include "pendulum/exact.hpp"
#include "pendulum/extended_periods.hpp"
#include "pendulum/formula_methods.hpp"
#include "pendulum/formulas.hpp"
#include "pendulum/formulas_mp.hpp"
#include "pendulum/approximants_mp.hpp"
#include "pendulum/iteration.hpp"
#include "pendulum/mp_iteration.hpp"
#include "pendulum/mp_real.hpp"
#include "pendulum/period_formulas.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace pendulum {

namespace {

using mp::real;

/// Above this |T_m/T - 1| the doubles' difference is right to 1e-13 relative.
constexpr double double_enough = 1e-2;

/// Below this extended-precision error the doubles' error is surely below double_enough: the
/// two differ by a few units of 2^-53, and the margin is 1e-4.
constexpr long double surely_below_double = 0.99e-2L;
static_assert(surely_below_double < double_enough, "the doubles are skipped only below their own threshold");

/// Periods in extended precision are within about 12 units of 2^-64 (6.5e-19) of the truth
/// (both T_m and T), so their difference is right to 1e-13 relative from this error up.
constexpr long double extended_enough = 1e-5L;
static_assert(std::numeric_limits<long double>::digits >= 64, "the middle tier needs a 64-bit significand");

/// Precisions tried in turn; the last one decides that an error is below 1e-300 (2^-997).
constexpr std::array<mpfr_prec_t, 4> precisions = {128, 256, 512, 1152};

/// The iteration's precisions, closer together: a run stops at the first level its bits
/// cannot resolve, and the next run, which repeats every level, costs less the fewer bits
/// it needs (the convergence figure's errors down to 4e-42 need 200 bits).
constexpr std::array<mpfr_prec_t, 7> iteration_precisions = {128, 192, 256, 384, 512, 768, 1152};
static_assert(iteration_precisions.back() == precisions.back(), "both end where an error is below 1e-300");

/// A difference computed with `bits` is kept when it is this many bits above their rounding.
constexpr long margin_bits = 56;

using mp::exact_amplitude;
using mp::mp_amplitude;

real exact_period(const mp_amplitude& x) { return 1.0 / mp::agm(real(1.0, x.theta.precision()), x.kp); }

/// The error from a period with `bits`: a value, or nothing where it is within rounding.
bool resolved(const real& error, mpfr_prec_t bits) {
    return !error.is_zero() && mp::exponent(error) > -(static_cast<long>(bits) - margin_bits);
}

/// A resolved error as a period_error: below 1e-300 it is only that.
period_error known(const real& error) {
    if (mp::abs(error) < smallest_period_error) return {period_error::kind::below_limit, 0};
    return {period_error::kind::value, error.to_double()};
}

/// Whether an error of at most `bound` is surely not resolved with `bits`: it would have to
/// reach 2^(57 - bits), and below 2^(49 - bits) it cannot, with the run's own rounding
/// (about 2^-bits times a few) far below those 8 bits.
bool surely_unresolved(double bound, mpfr_prec_t bits) {
    return bound < std::ldexp(1.0, static_cast<int>(margin_bits - 7 - bits));
}

}  // namespace

period_error detail::mp_closed_form_error_from(const amplitude& a, int n, mp_period f, std::size_t first) {
    for (std::size_t i = first; i < precisions.size(); ++i) {
        const mpfr_prec_t bits = precisions[i];
        const mp_amplitude x = exact_amplitude(a, bits);
        const real error = f(x, n) / exact_period(x) - 1.0;
        if (resolved(error, bits)) return known(error);
    }
    return {period_error::kind::below_limit, 0};
}

std::size_t detail::foreseen_closed_form_start(const amplitude& a) {
    // Every closed form's error that reaches MPFR is at most theta0^2 at small amplitudes
    // (the harmonic's theta0^2/16 the largest; the log asymptote's stays above 1e-2, in
    // doubles).
    const double theta0 = a.radians();
    const double bound = theta0 * theta0;
    std::size_t i = 0;
    while (i + 1 < precisions.size() && surely_unresolved(bound, precisions[i])) ++i;
    return i;
}

period_error detail::mp_closed_form_error(const amplitude& a, int n, mp_period f) {
    const std::size_t first = foreseen_closed_form_start(a);
    const period_error e = mp_closed_form_error_from(a, n, f, first);
    // The runs skipped would not have resolved this error (else they are run, as before).
    if (first == 0 || e.what != period_error::kind::value ||
        surely_unresolved(std::fabs(e.value), precisions[first - 1])) {
        return e;
    }
    return mp_closed_form_error_from(a, n, f, 0);
}

namespace {

real lowest_mp(const mp_amplitude& x, int) { return 1.0 / formulas::lowest_frequency(x.theta); }

real first_mp(const mp_amplitude& x, int) { return 1.0 / formulas::first_order_of(x.theta).frequency; }

/// Extended precision's errors of the iteration are used down to this size (its own
/// rounding stays far below).
constexpr long double extended_error_floor = 1e-12L;

/// The bits that level `order`'s error needs, foreseen in extended precision: the levels'
/// errors from level 2 down to 1e-12, their mean geometric decay carried on to `order`, and
/// the margin. 0 where no level's error is that large (nothing to foresee). Only the
/// iteration's cost depends on it: a run with too few bits stops where they end and more
/// follow, as before.
long foreseen_iteration_bits(const amplitude& a, int order) {
    const long double exact = exact_period_extended(a);
    int first = -1;
    int last = -1;
    long double first_error = 0;
    long double last_error = 0;
    const long double theta0 = a.near_pi() ? a.radians_extended() : a.radians();
    (void)iteration::levels(theta0, order, [&](int n, const iteration::level<long double>& level) {
        if (n < 2 || !(level.lambda > 0)) return false;
        const long double error = std::fabs(1 / (std::sqrt(level.lambda) * exact) - 1);
        if (!(error >= extended_error_floor)) return true;
        if (first < 0) {
            first = n;
            first_error = error;
        }
        last = n;
        last_error = error;
        return false;
    });
    if (first < 0) return 0;
    const long double decay = last > first ? std::pow(last_error / first_error, 1.0L / (last - first)) : 1.0L;
    const long double foreseen = std::log2(last_error) + std::log2(std::min(decay, 1.0L)) * (order - last);
    return margin_bits + static_cast<long>(std::ceil(-foreseen));
}

/// The first of iteration_precisions to run: the fewest that the foreseen bits need, and
/// none beyond the first whose unresolved errors lie below `floor`.
std::size_t first_iteration_precision(const amplitude& a, int order, double floor) {
    const long bits = foreseen_iteration_bits(a, order);
    std::size_t i = 0;
    while (i + 1 < iteration_precisions.size() && iteration_precisions[i] < bits &&
           !(std::ldexp(1.0, -static_cast<int>(iteration_precisions[i] - margin_bits)) < floor)) {
        ++i;
    }
    return i;
}

}  // namespace

std::vector<period_error> iterated_period_errors(const amplitude& a, int order, double floor) {
    check_order(order);
    if (!(floor >= smallest_period_error)) {
        throw domain_error("the floor of period errors must be at least 1e-300, got " + format_double(floor));
    }
    std::vector<period_error> out(static_cast<std::size_t>(order + 1), {period_error::kind::below_limit, 0});
    std::vector<bool> done(out.size(), false);
    // The runs start at the precision the last level is foreseen to need: the runs with
    // fewer bits would stop before it and be repeated.
    const std::size_t first = first_iteration_precision(a, order, floor);
    for (std::size_t p = first; p < iteration_precisions.size(); ++p) {
        const mpfr_prec_t bits = iteration_precisions[p];
        const mp_amplitude x = exact_amplitude(a, bits);
        const real exact = exact_period(x);
        // Where more bits will follow, the levels stop at the first whose error these
        // cannot resolve: the run with more bits computes it and the rest again.
        const bool more_follow =
            bits != iteration_precisions.back() && !(std::ldexp(1.0, -static_cast<int>(bits - margin_bits)) < floor);
        const auto beyond_these_bits = [&](const real& lambda) {
            return more_follow && lambda.sign() > 0 && !resolved(1.0 / (mp::sqrt(lambda) * exact) - 1.0, bits);
        };
        auto lambdas = detail::mp_lambdas(x, order, bits, beyond_these_bits);
        lambdas.resize(out.size());
        bool all = true;
        for (std::size_t n = 0; n < out.size(); ++n) {
            if (done[n]) continue;
            if (!lambdas[n]) {
                out[n] = {period_error::kind::not_computed, 0};
                all = false;
                continue;
            }
            if (!(lambdas[n]->sign() > 0)) {
                out[n] = {period_error::kind::no_period, 0};
                done[n] = true;
                continue;
            }
            const real error = 1.0 / (mp::sqrt(*lambdas[n]) * exact) - 1.0;
            if (resolved(error, bits)) {
                out[n] = known(error);
                done[n] = true;
            } else {
                out[n] = {period_error::kind::below_limit, 0};
                all = false;
            }
        }
        // What is still unresolved lies below 2^-(bits - margin), and that is below the floor.
        if (all || std::ldexp(1.0, -static_cast<int>(bits - margin_bits)) < floor) break;
    }
    return out;
}

int first_level_within(const amplitude& a, double tolerance, int up_to) {
    check_order(up_to);
    // 128 bits resolve errors down to 2^-72, far below any tolerance a double can state.
    constexpr mpfr_prec_t bits = 128;
    const mp_amplitude x = exact_amplitude(a, bits);
    const real exact = exact_period(x);
    const auto within = [&](const real& lambda) {
        return lambda.sign() > 0 && mp::abs(1.0 / (mp::sqrt(lambda) * exact) - 1.0) < tolerance;
    };
    const auto lambdas = detail::mp_lambdas(x, up_to, bits, within);
    for (std::size_t n = 0; n < lambdas.size(); ++n) {
        if (!lambdas[n]) {
            throw domain_error("the iteration's projection does not converge at level " + std::to_string(n) +
                               " for theta0 = pi - " + format_double(a.from_pi()));
        }
        if (within(*lambdas[n])) return static_cast<int>(n);
    }
    return -1;
}

/// The error of a closed-form period: doubles where they suffice, then extended precision
/// where the method has it and it suffices, MPFR otherwise.
period_error closed_form_error(const amplitude& a, int n, precision p, double (*period)(const amplitude&, int),
                               mp_period f, extended_period extended) {
    if (p == precision::correctly_rounded) return detail::mp_closed_form_error(a, n, f);
    // One AGM for both tiers: period_ratio(a) is this, rounded to a double.
    const long double exact = exact_period_extended(a);
    // Extended precision first where the method has it: an error below surely_below_double
    // there is below double_enough in doubles too (the two differ by about 1e-15), so the
    // doubles' period is not needed.
    const long double error = extended ? extended(a) / exact - 1 : std::numeric_limits<long double>::quiet_NaN();
    if (!(std::fabs(error) < surely_below_double)) {
        const double fast = period(a, n) / static_cast<double>(exact) - 1;
        if (std::fabs(fast) >= double_enough) return {period_error::kind::value, fast};
    }
    if (std::fabs(error) >= extended_enough) return {period_error::kind::value, static_cast<double>(error)};
    return detail::mp_closed_form_error(a, n, f);
}

period_error exact_period_error(const amplitude&, int, precision) { return {period_error::kind::value, 0}; }

period_error harmonic_period_error(const amplitude& a, int n, precision p) {
    return closed_form_period_error<formulas::harmonic>(a, n, p);
}
period_error lowest_period_error(const amplitude& a, int n, precision p) {
    return closed_form_error(
        a, n, p, [](const amplitude& t, int) { return lowest_order(t).period_ratio(); }, lowest_mp,
        lowest_period_extended);
}
period_error first_period_error(const amplitude& a, int n, precision p) {
    return closed_form_error(
        a, n, p, [](const amplitude& t, int) { return first_order(t).period_ratio(); }, first_mp,
        first_period_extended);
}
period_error second_period_error(const amplitude& a, int n, precision p) {
    return closed_form_error(
        a, n, p, [](const amplitude& t, int) { return second_order(t).period_ratio(); }, detail::second_period_mp,
        second_period_extended);
}
period_error polynomial_period_error(const amplitude& a, int n, precision p) {
    return closed_form_error(
        a, n, p, [](const amplitude& t, int) { return polynomial(t).period_ratio(); },
        closed_form_period_mp<formulas::polynomial>);
}
period_error iterated_period_error(const amplitude& a, int n, precision p) {
    // The double iteration where its own rounding (measured against extended precision) is
    // far below the error; MPFR otherwise.
    const auto level = iterated_periods(a, n).back();
    if (p == precision::drawing && !std::isnan(level.value)) {
        const double exact = period_ratio(a);
        const double error = level.value / exact - 1;
        const double uncertainty = level.rounding / exact + 4 * std::numeric_limits<double>::epsilon();
        if (std::fabs(error) >= 1e12 * uncertainty) return {period_error::kind::value, error};
    }
    return iterated_period_errors(a, n).back();
}
period_error kidd_fogg_period_error(const amplitude& a, int n, precision p) {
    return closed_form_period_error<formulas::kidd_fogg>(a, n, p);
}
period_error lima_arun_period_error(const amplitude& a, int n, precision p) {
    return closed_form_period_error<formulas::lima_arun>(a, n, p);
}
period_error ganley_period_error(const amplitude& a, int n, precision p) {
    return closed_form_period_error<formulas::ganley>(a, n, p);
}
period_error agm_period_error(const amplitude& a, int n, precision p) {
    return closed_form_error(a, n, p, period_agm, closed_form_period_mp<formulas::agm>);
}
period_error denman_period_error(const amplitude& a, int n, precision p) {
    return closed_form_period_error<formulas::denman>(a, n, p);
}
period_error series_period_error(const amplitude& a, int n, precision p) {
    return closed_form_error(a, n, p, period_series, closed_form_period_mp<formulas::series>);
}
period_error log_asymptote_period_error(const amplitude& a, int n, precision p) {
    return closed_form_period_error<formulas::log_asymptote>(a, n, p);
}

}  // namespace pendulum
