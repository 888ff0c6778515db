// SPDX-License-Identifier: GPL-3.0-or-later
// The paper's iteration to order N with MPFR throughout: the levels close to pi (where the
// double iteration's rounding grows) and the iteration's period errors (period_error.cpp).
#include "pendulum/mp_iteration.hpp"

#include "pendulum/approximants.hpp"
#include "pendulum/formulas_mp.hpp"
#include "pendulum/mp_bessel.hpp"
#include "pendulum/mp_real.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace pendulum {

using mp::real;

namespace {


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

}  // namespace

/// lambda = (w/w0)^2 of levels 0 .. order with `bits`; an unset entry where the projection
/// did not converge (that level and all later ones).
std::vector<std::optional<real>> detail::mp_lambdas(const mp::mp_amplitude& x, int order, mpfr_prec_t bits,
                                                    const std::function<bool(const real& lambda)>& stop,
                                                    std::vector<std::vector<real>>* coefficients) {
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


namespace {

/// The iteration's levels with `bits`, rounded to doubles.
std::vector<fourier_solution> mp_sequence(const amplitude& a, int order, mpfr_prec_t bits) {
    const mp::mp_amplitude x = mp::exact_amplitude(a, bits);
    std::vector<std::vector<real>> u;
    const auto lambdas = detail::mp_lambdas(x, order, bits, {}, &u);
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

std::vector<fourier_solution> detail::iterated_sequence_mp(const amplitude& a, int order, mpfr_prec_t* bits_used) {
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
        if (differs < 0) {
            if (bits_used) *bits_used = bits;
            return fine;
        }
        if (bits >= 2048) {
            throw domain_error("the iteration at order " + std::to_string(differs) + " for theta0 = " +
                               format_amplitude(a) + " cannot be computed to 1e-15 with 2048 bits");
        }
        coarse = std::move(fine);
    }
}


}  // namespace pendulum
