// SPDX-License-Identifier: GPL-3.0-or-later
// Period errors T_m/T - 1 without cancellation. Where the two periods differ in their first
// two digits, doubles give the error to 1e-13; closer, both periods are computed again with
// MPFR from the exact amplitude (theta0, or pi - d near pi), with 128 bits and then more, until
// the difference is far above the rounding of the precision used.
#include "pendulum/period_error.hpp"

#include "pendulum/approximants.hpp"
#include "pendulum/exact.hpp"
#include "pendulum/extended_periods.hpp"
#include "pendulum/mp_bessel.hpp"
#include "pendulum/mp_iteration.hpp"
#include "pendulum/mp_real.hpp"
#include "pendulum/period_formulas.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <string>
#include <optional>
#include <vector>

namespace pendulum {

namespace {

using mp::real;

/// Above this |T_m/T - 1| the doubles' difference is right to 1e-13 relative.
constexpr double double_enough = 1e-2;

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

/// The amplitude, exact, with `bits`: theta0 and k' = cos(theta0/2) (= sin(d/2) near pi).
struct mp_amplitude {
    real theta;
    real kp;
    real one_minus_kp;  ///< 1 - k' without cancellation
};

mp_amplitude exact_amplitude(const amplitude& a, mpfr_prec_t bits) {
    // From d where it is the nearer of the two to the exact amplitude; a double theta0 is
    // the exact amplitude itself (its d is rounded).
    if (a.near_pi() && !a.exact_radians()) {
        const real d(a.from_pi(), bits);
        const real kp = mp::sin(d / 2.0);
        return {mp::pi(bits) - d, kp, 1.0 - kp};
    }
    const real theta(a.radians(), bits);
    const real s = mp::sin(theta / 4.0);
    return {theta, mp::cos(theta / 2.0), 2.0 * s * s};
}

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

using mp_period = real (*)(const mp_amplitude& x, int n);

/// The error of a closed-form period in MPFR, correctly rounded.
period_error mp_closed_form_error(const amplitude& a, int n, mp_period f) {
    for (const mpfr_prec_t bits : precisions) {
        const mp_amplitude x = exact_amplitude(a, bits);
        const real error = f(x, n) / exact_period(x) - 1.0;
        if (resolved(error, bits)) return known(error);
    }
    return {period_error::kind::below_limit, 0};
}

/// A period in extended precision, for the methods that have one.
using extended_period = long double (*)(const amplitude& a);

/// The error of a closed-form period: doubles where they suffice, then extended precision
/// where the method has it and it suffices, MPFR otherwise.
period_error closed_form_error(const amplitude& a, int n, precision p, double (*period)(const amplitude&, int),
                               mp_period f, extended_period extended = nullptr) {
    if (p == precision::correctly_rounded) return mp_closed_form_error(a, n, f);
    // One AGM for both tiers: period_ratio(a) is this, rounded to a double.
    const long double exact = exact_period_extended(a);
    const double fast = period(a, n) / static_cast<double>(exact) - 1;
    if (std::fabs(fast) >= double_enough) return {period_error::kind::value, fast};
    if (extended) {
        const long double error = extended(a) / exact - 1;
        if (std::fabs(error) >= extended_enough) return {period_error::kind::value, static_cast<double>(error)};
    }
    return mp_closed_form_error(a, n, f);
}

real harmonic_mp(const mp_amplitude& x, int) { return real(1.0, x.theta.precision()); }

real lowest_mp(const mp_amplitude& x, int) { return mp::sqrt(x.theta / (2.0 * mp::bessel_j_upto(1, x.theta)[1])); }

/// eta = -J3/(9 J1) and J1/theta0 of the first order.
struct first_order_parts {
    real j1;
    real eta;
};

first_order_parts first_parts(const mp_amplitude& x) {
    const auto j = mp::bessel_j_upto(3, x.theta);
    return {j[1] / x.theta, -j[3] / (9.0 * j[1])};
}

real first_mp(const mp_amplitude& x, int) {
    const auto p = first_parts(x);
    return 1.0 / mp::sqrt(2.0 * p.j1 * (1.0 + p.eta));
}

real second_mp(const mp_amplitude& x, int) {
    // As second_order(): C_{2k+1}/theta0 with a = theta0/(1 + eta), b/theta0 = eta/(1 + eta).
    const auto p = first_parts(x);
    const real a = x.theta / (1.0 + p.eta);
    const real a_ratio = 1.0 / (1.0 + p.eta);
    const real b_ratio = p.eta / (1.0 + p.eta);
    const auto j = mp::bessel_j_upto(8, a);
    real lambda(x.theta.precision());
    for (int k = 0; k < 3; ++k) {
        const auto at = [&](int m) -> const real& { return j[static_cast<std::size_t>(m)]; };
        const real inner = 2.0 * at(2 * k + 1) / a * a_ratio + b_ratio * (at(2 * k + 4) - at(std::abs(2 * k - 2)));
        const real term = inner / static_cast<double>((2 * k + 1) * (2 * k + 1));
        lambda = k % 2 == 0 ? lambda + term : lambda - term;
    }
    return 1.0 / mp::sqrt(lambda);
}

real polynomial_mp(const mp_amplitude& x, int) {
    const real t2 = x.theta * x.theta;
    return 1.0 + t2 / 16.0 + 11.0 * t2 * t2 / 3072.0;
}

real kidd_fogg_mp(const mp_amplitude& x, int) { return 1.0 / mp::sqrt(x.kp); }

real lima_arun_mp(const mp_amplitude& x, int) {
    // ln k' = log1p(-(1 - k')), with 1 - k' itself exact.
    return -mp::apply(mpfr_log1p, -x.one_minus_kp) / x.one_minus_kp;
}

real ganley_mp(const mp_amplitude& x, int) {
    const real f = mp::sqrt(real(3.0, x.theta.precision())) / 2.0 * x.theta;
    return mp::sqrt(f / mp::sin(f));
}

real agm_mp(const mp_amplitude& x, int steps) {
    real a(1.0, x.theta.precision());
    real b = x.kp;
    for (int i = 0; i < steps; ++i) {
        const real next = (a + b) / 2.0;
        b = mp::sqrt(a * b);
        a = next;
    }
    return 1.0 / a;
}

real denman_mp(const mp_amplitude& x, int) { return 1.0 / (1.0 - x.theta * x.theta / 16.0); }

real series_mp(const mp_amplitude& x, int terms) {
    // The exact rationals, not their doubles: the error of the series is far below a double's
    // rounding of its coefficients at small amplitudes.
    static constexpr std::array<std::array<const char*, 2>, max_series_terms + 1> rationals = {{
#include "pendulum/period_series_rationals.inc"
    }};
    const mpfr_prec_t bits = x.theta.precision();
    const real t2 = x.theta * x.theta;
    real sum(bits);
    for (int n = terms; n >= 0; --n) {
        real num(bits);
        real den(bits);
        mpfr_set_str(num.get(), rationals[static_cast<std::size_t>(n)][0], 10, MPFR_RNDN);
        mpfr_set_str(den.get(), rationals[static_cast<std::size_t>(n)][1], 10, MPFR_RNDN);
        sum = sum * t2 + num / den;
    }
    return sum;
}

real log_asymptote_mp(const mp_amplitude& x, int) {
    return 2.0 / mp::pi(x.theta.precision()) * mp::log(4.0 / x.kp);
}

// ---- The iteration to order N, with MPFR throughout.

/// cos(m pi / (4L)) for m = 0 .. 8L - 1, from the first quadrant by symmetry.
std::vector<real> mp_cosine_table(int L, mpfr_prec_t bits) {
    const int quarter = 2 * L;  // m = 2L is pi/2
    std::vector<real> first;
    first.reserve(static_cast<std::size_t>(quarter + 1));
    const real step = mp::pi(bits) / static_cast<double>(4 * L);
    for (int m = 0; m <= quarter; ++m) first.push_back(mp::cos(step * static_cast<double>(m)));
    std::vector<real> table;
    table.reserve(static_cast<std::size_t>(8 * L));
    for (int m = 0; m < 8 * L; ++m) {
        // cos(x) over the four quadrants of the period 8L.
        const int r = m % (8 * L);
        if (r <= quarter) table.push_back(first[static_cast<std::size_t>(r)]);
        else if (r <= 2 * quarter) table.push_back(-first[static_cast<std::size_t>(2 * quarter - r)]);
        else if (r <= 3 * quarter) table.push_back(-first[static_cast<std::size_t>(r - 2 * quarter)]);
        else table.push_back(first[static_cast<std::size_t>(4 * quarter - r)]);
    }
    return table;
}

/// Sums over the nodes m pi/(4L) of the quarter period, m of the given parity: for each
/// k < count, the sum of f(tau) cos((2k+1) tau), f(tau) = sin(theta0 theta(tau))/theta0 and
/// theta(tau)/theta0 = sum_j u_j cos((2j+1) tau); the node tau = 0 has weight 1/2.
/// `table` holds cos(m pi/(4L)) for m = 0 .. 8L - 1.
std::vector<real> mp_node_sums(const std::vector<real>& u, int count, const real& theta0, int L, int parity,
                               const std::vector<real>& table) {
    const mpfr_prec_t bits = theta0.precision();
    const int period = 8 * L;
    std::vector<real> S(static_cast<std::size_t>(count), real(bits));
    const std::size_t width = std::max(u.size(), static_cast<std::size_t>(count));
    std::vector<const real*> odd_cos(width);
    real theta(bits);
    real term(bits);
    real f(bits);
    // The node pi/2 (m = 2L) is left out: every odd harmonic vanishes there.
    for (int m = parity; m < 2 * L; m += 2) {
        const int step = (2 * m) % period;
        int index = m;
        for (auto& v : odd_cos) {
            v = &table[static_cast<std::size_t>(index)];
            index += step;
            if (index >= period) index -= period;
        }
        mpfr_set_zero(theta.get(), 1);
        for (std::size_t j = 0; j < u.size(); ++j) {
            mpfr_mul(term.get(), u[j].get(), odd_cos[j]->get(), MPFR_RNDN);
            mpfr_add(theta.get(), theta.get(), term.get(), MPFR_RNDN);
        }
        // sin(theta0 theta)/theta0
        mpfr_mul(f.get(), theta.get(), theta0.get(), MPFR_RNDN);
        mpfr_sin(f.get(), f.get(), MPFR_RNDN);
        mpfr_div(f.get(), f.get(), theta0.get(), MPFR_RNDN);
        if (m == 0) mpfr_div_2ui(f.get(), f.get(), 1, MPFR_RNDN);
        for (int k = 0; k < count; ++k) {
            mpfr_mul(term.get(), f.get(), odd_cos[static_cast<std::size_t>(k)]->get(), MPFR_RNDN);
            mpfr_add(S[static_cast<std::size_t>(k)].get(), S[static_cast<std::size_t>(k)].get(), term.get(), MPFR_RNDN);
        }
    }
    return S;
}

/// The trapezoid rule with `intervals` intervals on the quarter period from its node sums:
/// C_{2k+1}/theta0 = (4/pi) h sum, h = pi/(2 intervals), that is 2/intervals times the sum.
std::vector<real> mp_trapezoid(const std::vector<real>& sums, int intervals) {
    std::vector<real> C = sums;
    // 2/intervals exactly: a double 2.0/intervals would round where it is no power of two.
    for (real& v : C) {
        mpfr_mul_2ui(v.get(), v.get(), 1, MPFR_RNDN);
        mpfr_div_ui(v.get(), v.get(), static_cast<unsigned long>(intervals), MPFR_RNDN);
    }
    return C;
}

/// C_{2k+1}/theta0 for k < count by the trapezoid rule on a quarter period, its intervals
/// halved until two rules agree to the precision's rounding. A halving reuses every node
/// (the rule with 2L intervals is the one with L plus the midpoints of its intervals), so
/// a level that agrees at once costs 2L sines.
class mp_projector {
public:
    explicit mp_projector(mpfr_prec_t bits) : bits_(bits) {}

    /// The projection, or an empty vector where 2^15 intervals do not agree.
    std::vector<real> operator()(const std::vector<real>& u, int count, const real& theta0) {
        L_ = std::max(L_, count / 2 + 16);
        // The nodes of L intervals: the even m of the table for L; their midpoints: the odd m.
        std::vector<real> sums = mp_node_sums(u, count, theta0, L_, 0, table(L_));
        auto coarse = mp_trapezoid(sums, L_);
        for (;;) {
            const auto mid = mp_node_sums(u, count, theta0, L_, 1, table(L_));
            for (std::size_t k = 0; k < sums.size(); ++k) sums[k] = sums[k] + mid[k];
            auto fine = mp_trapezoid(sums, 2 * L_);
            long worst = -100000;
            for (std::size_t k = 0; k < fine.size(); ++k) {
                const real diff = fine[k] - coarse[k];
                if (!diff.is_zero()) worst = std::max(worst, mp::exponent(diff));
            }
            if (worst < -(static_cast<long>(bits_) - 12)) return fine;
            if (2 * L_ >= max_intervals) return {};
            L_ *= 2;
            coarse = std::move(fine);
        }
    }

private:
    static constexpr int max_intervals = 1 << 15;

    const std::vector<real>& table(int L) {
        auto it = tables_.find(L);
        if (it == tables_.end()) it = tables_.emplace(L, mp_cosine_table(L, bits_)).first;
        return it->second;
    }

    mpfr_prec_t bits_;
    int L_ = 0;
    std::map<int, std::vector<real>> tables_;
};

/// lambda = (w/w0)^2 of levels 0 .. order with `bits`; an unset entry where the projection
/// did not converge (that level and all later ones).
std::vector<std::optional<real>> mp_lambdas(const mp_amplitude& x, int order, mpfr_prec_t bits,
                                            const std::function<bool(const real& lambda)>& stop = {},
                                            std::vector<std::vector<real>>* coefficients = nullptr) {
    std::vector<std::optional<real>> out;
    mp_projector project(bits);
    std::vector<real> u{real(1.0, bits)};
    for (int level = 0; level <= order; ++level) {
        const int count = level + 1;
        std::vector<real> C;
        if (level <= 1) {
            for (int k = 0; k < count; ++k) {
                const real j = 2.0 * mp::bessel_j(2 * k + 1, x.theta) / x.theta;
                C.push_back(k % 2 == 0 ? j : -j);
            }
        } else {
            C = project(u, count, x.theta);
            if (C.empty()) {
                out.resize(static_cast<std::size_t>(order + 1));
                return out;
            }
        }
        real lambda(bits);
        for (std::size_t k = 0; k < C.size(); ++k) lambda = lambda + C[k] / static_cast<double>((2 * k + 1) * (2 * k + 1));
        u.clear();
        for (std::size_t k = 0; k < C.size(); ++k) u.push_back(C[k] / (static_cast<double>((2 * k + 1) * (2 * k + 1)) * lambda));
        out.emplace_back(lambda);
        if (coefficients) coefficients->push_back(u);
        if (stop && stop(lambda)) break;
    }
    return out;
}

}  // namespace

namespace {

/// The iteration's levels with `bits`, rounded to doubles.
std::vector<fourier_solution> mp_sequence(const amplitude& a, int order, mpfr_prec_t bits) {
    const mp_amplitude x = exact_amplitude(a, bits);
    std::vector<std::vector<real>> u;
    const auto lambdas = mp_lambdas(x, order, bits, {}, &u);
    std::vector<fourier_solution> levels;
    for (std::size_t n = 0; n < lambdas.size(); ++n) {
        if (!lambdas[n]) {
            throw domain_error("the iteration's projection does not converge at order " + std::to_string(n) +
                               " for theta0 = " + format_amplitude(a));
        }
        fourier_solution s;
        s.frequency_ratio = lambdas[n]->sign() > 0 ? mp::sqrt(*lambdas[n]).to_double() : std::nan("");
        for (const real& v : u[n]) s.coefficients.push_back((v * x.theta).to_double());
        levels.push_back(std::move(s));
    }
    return levels;
}

}  // namespace

std::vector<fourier_solution> detail::iterated_sequence_mp(const amplitude& a, int order) {
    check_order(order);
    // Close to pi the iteration amplifies rounding enormously (at pi - 1e-12 doubles give
    // T_92/T0 = 22.26 and T_90/T0 = 13.30 where the iteration itself gives 26.59 and 15.06,
    // tests/data/make_iteration_near_pi.py): the precision is doubled until every level's
    // frequency agrees with the run at half the bits to 1e-15.
    auto coarse = mp_sequence(a, order, 128);
    for (mpfr_prec_t bits = 256;; bits *= 2) {
        auto fine = mp_sequence(a, order, bits);
        int differs = -1;
        for (std::size_t n = 0; n < fine.size() && differs < 0; ++n) {
            const double wc = coarse[n].frequency_ratio;
            const double wf = fine[n].frequency_ratio;
            const bool agree = (std::isnan(wc) && std::isnan(wf)) || std::fabs(wc / wf - 1) <= 1e-15;
            if (!agree) differs = static_cast<int>(n);
        }
        if (differs < 0) return fine;
        if (bits >= 2048) {
            throw domain_error("the iteration at order " + std::to_string(differs) + " for theta0 = " +
                               format_amplitude(a) + " cannot be computed to 1e-15 with 2048 bits");
        }
        coarse = std::move(fine);
    }
}

std::vector<period_error> iterated_period_errors(const amplitude& a, int order, double floor) {
    check_order(order);
    if (!(floor >= smallest_period_error)) {
        throw domain_error("the floor of period errors must be at least 1e-300, got " + format_double(floor));
    }
    std::vector<period_error> out(static_cast<std::size_t>(order + 1), {period_error::kind::below_limit, 0});
    std::vector<bool> done(out.size(), false);
    for (const mpfr_prec_t bits : iteration_precisions) {
        const mp_amplitude x = exact_amplitude(a, bits);
        const real exact = exact_period(x);
        // Where more bits will follow, the levels stop at the first whose error these
        // cannot resolve: the run with more bits computes it and the rest again.
        const bool more_follow =
            bits != iteration_precisions.back() && !(std::ldexp(1.0, -static_cast<int>(bits - margin_bits)) < floor);
        const auto beyond_these_bits = [&](const real& lambda) {
            return more_follow && lambda.sign() > 0 && !resolved(1.0 / (mp::sqrt(lambda) * exact) - 1.0, bits);
        };
        auto lambdas = mp_lambdas(x, order, bits, beyond_these_bits);
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
    const auto lambdas = mp_lambdas(x, up_to, bits, within);
    for (std::size_t n = 0; n < lambdas.size(); ++n) {
        if (!lambdas[n]) {
            throw domain_error("the iteration's projection does not converge at level " + std::to_string(n) +
                               " for theta0 = pi - " + format_double(a.from_pi()));
        }
        if (within(*lambdas[n])) return static_cast<int>(n);
    }
    return -1;
}

period_error exact_period_error(const amplitude&, int, precision) { return {period_error::kind::value, 0}; }

period_error harmonic_period_error(const amplitude& a, int n, precision p) {
    return closed_form_error(a, n, p, [](const amplitude&, int) { return 1.0; }, harmonic_mp);
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
        a, n, p, [](const amplitude& t, int) { return second_order(t).period_ratio(); }, second_mp,
        second_period_extended);
}
period_error polynomial_period_error(const amplitude& a, int n, precision p) {
    return closed_form_error(a, n, p, [](const amplitude& t, int) { return polynomial(t).period_ratio(); }, polynomial_mp);
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
    return closed_form_error(a, n, p, [](const amplitude& t, int) { return period_kidd_fogg(t); }, kidd_fogg_mp);
}
period_error lima_arun_period_error(const amplitude& a, int n, precision p) {
    return closed_form_error(a, n, p, [](const amplitude& t, int) { return period_lima_arun(t); }, lima_arun_mp);
}
period_error ganley_period_error(const amplitude& a, int n, precision p) {
    return closed_form_error(a, n, p, [](const amplitude& t, int) { return period_ganley(t); }, ganley_mp);
}
period_error agm_period_error(const amplitude& a, int n, precision p) { return closed_form_error(a, n, p, period_agm, agm_mp); }
period_error denman_period_error(const amplitude& a, int n, precision p) {
    return closed_form_error(a, n, p, [](const amplitude& t, int) { return period_denman(t); }, denman_mp);
}
period_error series_period_error(const amplitude& a, int n, precision p) { return closed_form_error(a, n, p, period_series, series_mp); }
period_error log_asymptote_period_error(const amplitude& a, int n, precision p) {
    return closed_form_error(a, n, p, [](const amplitude& t, int) { return period_log_asymptote(t); }, log_asymptote_mp);
}

}  // namespace pendulum
