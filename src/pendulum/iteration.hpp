// SPDX-License-Identifier: GPL-3.0-or-later
// The paper's order-N iteration, written once over the number type: long double for the
// doubles (approximants.cpp), mp::real (MPFR) close to pi and for the period errors
// (mp_iteration.cpp). A level projects sin(theta) of the level before on cos((2k+1)x):
// C_{2k+1}/theta0 = (1/(pi theta0)) int_0^{2pi} cos((2k+1)x) sin(theta(x)) dx, then
// lambda = (w/w0)^2 = sum C_k/(2k+1)^2 and c_k/theta0 = C_k/((2k+1)^2 lambda). Levels 0 and 1
// project sin(theta0 cos x) exactly through J_{2k+1}(theta0). A number type provides the
// primitives below (cos, sin, fabs by argument-dependent lookup for mp::real). Internal to
// the core library.
#pragma once

#include "pendulum/bessel_series.hpp"
#include "pendulum/formulas_mp.hpp"
#include "pendulum/gsl_support.hpp"
#include "pendulum/mp_bessel.hpp"
#include "pendulum/mp_real.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <vector>

namespace pendulum::iteration {

// ---- The primitives, for long double and mp::real.

/// The precision of a number of the type of `like`, in bits.
inline long bits_of(long double) { return std::numeric_limits<long double>::digits; }
/// The precision of `like`, in bits.
inline long bits_of(const mp::real& like) { return like.precision(); }

/// How closely two trapezoid rules (L and 2L intervals) must agree, as an exponent of 2,
/// for the finer one to be kept. The rules converge geometrically (f is analytic and
/// periodic: each doubling squares the error), so agreement to 2^-a leaves the finer rule
/// right to about 2^-2a. Extended precision asks a = bits - 12: its rules are cheap, and
/// the doubles it is rounded to keep the node counts (and so the roundings) they had.
inline long agreement_exponent(long double like) { return bits_of(like) - 12; }
/// For mp::real a = bits/2 + 8: the finer rule right to about 2^-(bits + 16), below the
/// precision's own rounding, with half the nodes that a = bits - 12 needs where the
/// rules' convergence (not the harmonics' count) sets them.
inline long agreement_exponent(const mp::real& like) { return bits_of(like) / 2 + 8; }

/// `v` in the number type (and precision) of `like`.
inline long double number_like(double v, long double) { return v; }
/// `v` with the precision of `like`.
inline mp::real number_like(double v, const mp::real& like) { return mp::real(v, like.precision()); }

/// 2^e in the number type of `like` (e far below the double range for mp::real).
inline long double power_of_two_like(long e, long double) { return std::ldexp(1.0L, static_cast<int>(e)); }
/// 2^e with the precision of `like`.
inline mp::real power_of_two_like(long e, const mp::real& like) {
    mp::real r(1.0, like.precision());
    mpfr_mul_2si(r.get(), r.get(), e, MPFR_RNDN);
    return r;
}

/// acc += a b, each operation rounded to nearest (`scratch` holds the product: no allocation).
inline void add_product(long double& acc, long double a, long double b, long double&) { acc += a * b; }
/// acc += a b for mp::real, in place.
inline void add_product(mp::real& acc, const mp::real& a, const mp::real& b, mp::real& scratch) {
    mpfr_mul(scratch.get(), a.get(), b.get(), MPFR_RNDN);
    mpfr_add(acc.get(), acc.get(), scratch.get(), MPFR_RNDN);
}

/// sin(theta0 u)/theta0, exact for every theta0 in (0, pi), subnormals included: below
/// small_amplitude its Taylor polynomial (the product would underflow).
inline long double sine_over(long double theta0, long double u) {
    const long double t = theta0 * u;
    if (theta0 < small_amplitude) return u * (1 - t * t / 6);
    return std::sin(t) / theta0;
}
/// sin(theta0 u)/theta0 for mp::real, whose exponent range has no underflow here.
inline mp::real sine_over(const mp::real& theta0, const mp::real& u) { return mp::sin(theta0 * u) / theta0; }

/// 2 J_n(x)/x in extended precision: the power series.
inline long double twice_j_over_x(int n, long double x) { return 2 * bessel_j_over_x_series(n, x); }
/// 2 J_n(x)/x for mp::real: J_n correctly rounded (bessel_j_rounded: mpfr_jn's number).
inline mp::real twice_j_over_x(int n, const mp::real& x) { return 2.0 * mp::bessel_j_rounded(n, x) / x; }

// ---- The projection.

/// cos(m pi / (4L)) for m = 0 .. 8L - 1, from the first quadrant by symmetry.
template <class Real>
std::vector<Real> cosine_table(int L, const Real& like) {
    using formulas::pi_like;
    using std::cos;
    const int quarter = 2 * L;  // m = 2L is pi/2
    std::vector<Real> first;
    first.reserve(static_cast<std::size_t>(quarter + 1));
    const Real step = pi_like(like) / static_cast<double>(4 * L);
    for (int m = 0; m <= quarter; ++m) first.push_back(cos(step * static_cast<double>(m)));
    std::vector<Real> table;
    table.reserve(static_cast<std::size_t>(8 * L));
    for (int m = 0; m < 8 * L; ++m) {
        if (m <= quarter) table.push_back(first[static_cast<std::size_t>(m)]);
        else if (m <= 2 * quarter) table.push_back(-first[static_cast<std::size_t>(2 * quarter - m)]);
        else if (m <= 3 * quarter) table.push_back(-first[static_cast<std::size_t>(m - 2 * quarter)]);
        else table.push_back(first[static_cast<std::size_t>(4 * quarter - m)]);
    }
    return table;
}

/// For each k < count, the sum over the nodes m pi/(4L), m < 2L of the given parity, of
/// f(x) cos((2k+1)x), f(x) = sin(theta0 theta(x))/theta0 and theta(x)/theta0 = sum_j u_j
/// cos((2j+1)x); the node 0 has weight 1/2, the node pi/2 (where every odd harmonic
/// vanishes) is left out. `table` holds cos(m pi/(4L)) for m = 0 .. 8L - 1.
template <class Real>
std::vector<Real> node_sums(const std::vector<Real>& u, int count, const Real& theta0, int L, int parity,
                            const std::vector<Real>& table) {
    const int period = 8 * L;
    const Real zero = number_like(0.0, theta0);
    std::vector<Real> S(static_cast<std::size_t>(count), zero);
    std::vector<const Real*> odd_cos(std::max(u.size(), static_cast<std::size_t>(count)));
    Real theta = zero;
    Real scratch = zero;
    for (int m = parity; m < 2 * L; m += 2) {
        // cos((2j+1) x_m) is table[(2j+1) m mod 8L].
        const int step = (2 * m) % period;
        int index = m;
        for (auto& v : odd_cos) {
            v = &table[static_cast<std::size_t>(index)];
            index += step;
            if (index >= period) index -= period;
        }
        theta = zero;
        for (std::size_t j = 0; j < u.size(); ++j) add_product(theta, u[j], *odd_cos[j], scratch);
        Real f = sine_over(theta0, theta);
        if (m == 0) f = f / 2.0;
        for (int k = 0; k < count; ++k) {
            add_product(S[static_cast<std::size_t>(k)], f, *odd_cos[static_cast<std::size_t>(k)], scratch);
        }
    }
    return S;
}

/// The trapezoid rule with `intervals` intervals on the quarter period from its node sums:
/// C_{2k+1}/theta0 = (4/pi) h sum, h = pi/(2 intervals), that is 2 sum/intervals (one
/// rounding: the doubling is exact).
template <class Real>
std::vector<Real> trapezoid(std::vector<Real> sums, int intervals) {
    for (Real& v : sums) v = v * 2.0 / static_cast<double>(intervals);
    return sums;
}

/// C_{2k+1}/theta0 for k < count by the trapezoid rule on a quarter period, its intervals
/// halved until two rules agree to 2^-agreement_exponent. The rules converge
/// geometrically, so the finer one is right to about the square of that. A
/// halving reuses every node (the rule with 2L intervals is the one with L plus the
/// midpoints of its intervals), and L only grows from level to level.
template <class Real>
class projector {
public:
    /// The largest number of intervals tried.
    static constexpr int max_intervals = 1 << 15;

    /// The projection, or an empty vector where max_intervals intervals do not agree.
    std::vector<Real> operator()(const std::vector<Real>& u, int count, const Real& theta0) {
        using std::fabs;
        const Real agreement = power_of_two_like(-agreement_exponent(theta0), theta0);
        L_ = std::max(L_, count / 2 + 16);
        std::vector<Real> sums = node_sums(u, count, theta0, L_, 0, table(L_, theta0));
        auto coarse = trapezoid(sums, L_);
        for (;;) {
            const auto mid = node_sums(u, count, theta0, L_, 1, table(L_, theta0));
            for (std::size_t k = 0; k < sums.size(); ++k) sums[k] = sums[k] + mid[k];
            auto fine = trapezoid(sums, 2 * L_);
            bool agree = true;
            for (std::size_t k = 0; k < fine.size() && agree; ++k) agree = fabs(fine[k] - coarse[k]) < agreement;
            if (agree) return fine;
            if (2 * L_ >= max_intervals) return {};
            L_ *= 2;
            coarse = std::move(fine);
        }
    }

private:
    const std::vector<Real>& table(int L, const Real& like) {
        auto it = tables_.find(L);
        if (it == tables_.end()) it = tables_.emplace(L, cosine_table(L, like)).first;
        return it->second;
    }

    int L_ = 0;
    std::map<int, std::vector<Real>> tables_;
};

// ---- The levels.

/// One level of the iteration: lambda = (w/w0)^2 and the coefficients c_k/theta0.
template <class Real>
struct level {
    Real lambda;           ///< (w/w0)^2 (not positive where the level has no period)
    std::vector<Real> u;   ///< c1/theta0, c3/theta0, ...
};

/// The projection of level `n` (n + 1 harmonics) from the coefficients `u` of the level
/// before: in closed form for n <= 1, else by `project` (empty where it did not converge).
template <class Real>
std::vector<Real> projection_of(int n, const std::vector<Real>& u, const Real& theta0, projector<Real>& project) {
    if (n > 1) return project(u, n + 1, theta0);
    // sin(theta0 cos x) = 2 sum (-1)^k J_{2k+1}(theta0) cos((2k+1)x).
    std::vector<Real> C;
    for (int k = 0; k <= n; ++k) {
        const Real j = twice_j_over_x(2 * k + 1, theta0);
        C.push_back(k % 2 == 0 ? j : -j);
    }
    return C;
}

/// The level from its projection C (in units of theta0).
template <class Real>
level<Real> level_of(const std::vector<Real>& C) {
    level<Real> out{number_like(0.0, C.front()), {}};
    for (std::size_t k = 0; k < C.size(); ++k) out.lambda = out.lambda + C[k] / static_cast<double>((2 * k + 1) * (2 * k + 1));
    for (std::size_t k = 0; k < C.size(); ++k) {
        out.u.push_back(C[k] / (static_cast<double>((2 * k + 1) * (2 * k + 1)) * out.lambda));
    }
    return out;
}

/// Levels 0 .. order at theta0 (in the number type and precision of theta0), each handed to
/// `visit(n, level)` as it is made; `visit` returns true to stop after it. Returns false
/// where a projection did not converge (at that level: later levels are not made).
template <class Real, class Visit>
bool levels(const Real& theta0, int order, Visit&& visit) {
    projector<Real> project;
    std::vector<Real> u{number_like(1.0, theta0)};
    for (int n = 0; n <= order; ++n) {
        const auto C = projection_of(n, u, theta0, project);
        if (C.empty()) return false;
        auto next = level_of(C);
        u = next.u;
        if (visit(n, std::move(next))) break;
    }
    return true;
}

}  // namespace pendulum::iteration
