// SPDX-License-Identifier: GPL-3.0-or-later
// The paper's iteration to order N with MPFR throughout: the levels close to pi (where the
// double iteration's rounding grows) and the iteration's period errors (period_error.cpp).
#include "pendulum/mp_iteration.hpp"

#include "pendulum/approximants.hpp"
#include "pendulum/iteration.hpp"
#include "pendulum/mp_real.hpp"

#include <cmath>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace pendulum {

using mp::real;

/// lambda = (w/w0)^2 of levels 0 .. order with `bits`; an unset entry where the projection
/// did not converge (that level and all later ones).
std::vector<std::optional<real>> detail::mp_lambdas(const mp::mp_amplitude& x, int order, mpfr_prec_t bits,
                                                    const std::function<bool(const real& lambda)>& stop,
                                                    std::vector<std::vector<real>>* coefficients) {
    std::vector<std::optional<real>> out;
    const bool converged = iteration::levels(real(x.theta, bits), order, [&](int, iteration::level<real> level) {
        out.emplace_back(level.lambda);
        if (coefficients) coefficients->push_back(std::move(level.u));
        return stop && stop(*out.back());
    });
    if (!converged) out.resize(static_cast<std::size_t>(order + 1));
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
