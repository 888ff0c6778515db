// SPDX-License-Identifier: GPL-3.0-or-later
#include "pendulum/mp_bessel.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace pendulum::mp {

namespace {

/// Bits carried beyond the result's precision: the alternating series loses at most 4 of
/// them for |x| <= 4 (its largest term is below 2^4 times the sum's scale), the recurrence a
/// few more near a zero of some J_m.
constexpr mpfr_prec_t guard_bits = 32;

/// J_m(x) by its power series, with `bits`: (x/2)^m/m! * sum_k (-x^2/4)^k m!/(k! (m+k)!).
real series(int m, const real& x, mpfr_prec_t bits) {
    real half(bits);
    mpfr_div_2ui(half.get(), x.get(), 1, MPFR_RNDN);
    real lead(1.0, bits);
    for (int j = 1; j <= m; ++j) {
        mpfr_mul(lead.get(), lead.get(), half.get(), MPFR_RNDN);
        mpfr_div_ui(lead.get(), lead.get(), static_cast<unsigned long>(j), MPFR_RNDN);
    }
    real q(bits);  // -x^2/4
    mpfr_sqr(q.get(), half.get(), MPFR_RNDN);
    mpfr_neg(q.get(), q.get(), MPFR_RNDN);
    real sum(1.0, bits);
    real term(1.0, bits);
    for (unsigned long k = 1;; ++k) {
        mpfr_mul(term.get(), term.get(), q.get(), MPFR_RNDN);
        mpfr_div_ui(term.get(), term.get(), k * (static_cast<unsigned long>(m) + k), MPFR_RNDN);
        mpfr_add(sum.get(), sum.get(), term.get(), MPFR_RNDN);
        // The terms fall faster than geometrically once k(m+k) > x^2/4: stop when the next
        // cannot reach the sum's last bit.
        if (mpfr_zero_p(term.get()) ||
            (k * (static_cast<unsigned long>(m) + k) > 8 &&
             mpfr_get_exp(term.get()) < mpfr_get_exp(sum.get()) - static_cast<mpfr_exp_t>(bits) - 2))
            break;
    }
    return lead * sum;
}

}  // namespace

std::vector<real> bessel_j_upto(int n, const real& x) {
    if (n < 0) throw std::invalid_argument("bessel_j_upto needs n >= 0, got " + std::to_string(n));
    if (x.is_zero() || !(mp::abs(x) <= 4.0))
        throw std::domain_error("bessel_j_upto needs 0 < |x| <= 4");
    const mpfr_prec_t bits = x.precision() + guard_bits;
    const real wide = real(x, bits);
    std::vector<real> j(static_cast<std::size_t>(n) + 2, real(bits));
    j[static_cast<std::size_t>(n) + 1] = series(n + 1, wide, bits);
    j[static_cast<std::size_t>(n)] = series(n, wide, bits);
    // J_{m-1} = (2m/x) J_m - J_{m+1}.
    real two_over_x(bits);
    mpfr_ui_div(two_over_x.get(), 2, wide.get(), MPFR_RNDN);
    real step(bits);
    for (int m = n; m >= 1; --m) {
        const auto i = static_cast<std::size_t>(m);
        mpfr_mul(step.get(), two_over_x.get(), j[i].get(), MPFR_RNDN);
        mpfr_mul_ui(step.get(), step.get(), static_cast<unsigned long>(m), MPFR_RNDN);
        mpfr_sub(j[i - 1].get(), step.get(), j[i + 1].get(), MPFR_RNDN);
    }
    std::vector<real> out;
    out.reserve(static_cast<std::size_t>(n) + 1);
    for (int m = 0; m <= n; ++m) out.push_back(real(j[static_cast<std::size_t>(m)], x.precision()));
    return out;
}

}  // namespace pendulum::mp
