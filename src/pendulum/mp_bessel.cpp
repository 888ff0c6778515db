// SPDX-License-Identifier: GPL-3.0-or-later
#include "pendulum/mp_bessel.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace pendulum::mp {

namespace {

/// Bits carried beyond the result's precision: the alternating series loses at most 4 of
/// them for |x| <= 4 (its largest term is below 2^4 times the sum's scale), the recurrence a
/// few more near a zero of some J_m.
constexpr mpfr_prec_t guard_bits = 32;

/// J_m(x) by its power series, as lead * sum, with what bounds its rounding: the largest
/// binary exponent of a term or partial sum and the number of terms.
struct series_parts {
    real lead;            ///< (x/2)^m/m!
    real sum;             ///< sum_k (-x^2/4)^k m!/(k! (m+k)!)
    mpfr_exp_t largest;   ///< the largest exponent of a term or a partial sum of `sum`
    unsigned long terms;  ///< the number of terms added
};

/// The larger of `largest` and the exponent of v (where v is not zero).
mpfr_exp_t with_exponent(mpfr_exp_t largest, const real& v) {
    return v.is_zero() ? largest : std::max(largest, mpfr_get_exp(v.get()));
}

/// Whether the series ends after term k: the terms fall faster than geometrically once
/// k(m+k) > x^2/4, so it ends when the next cannot reach the sum's last bit.
bool series_ends(const real& term, const real& sum, unsigned long k, int m, mpfr_prec_t bits) {
    if (term.is_zero()) return true;
    return k * (static_cast<unsigned long>(m) + k) > 8 &&
           mpfr_get_exp(term.get()) < mpfr_get_exp(sum.get()) - static_cast<mpfr_exp_t>(bits) - 2;
}

/// (x/2)^m/m! with `bits`.
real series_lead(int m, const real& half, mpfr_prec_t bits) {
    real lead(1.0, bits);
    for (int j = 1; j <= m; ++j) {
        mpfr_mul(lead.get(), lead.get(), half.get(), MPFR_RNDN);
        mpfr_div_ui(lead.get(), lead.get(), static_cast<unsigned long>(j), MPFR_RNDN);
    }
    return lead;
}

/// J_m(x) by its power series, with `bits`: (x/2)^m/m! * sum_k (-x^2/4)^k m!/(k! (m+k)!).
series_parts series_of(int m, const real& x, mpfr_prec_t bits) {
    real half(bits);
    mpfr_div_2ui(half.get(), x.get(), 1, MPFR_RNDN);
    real lead = series_lead(m, half, bits);
    real q(bits);  // -x^2/4
    mpfr_sqr(q.get(), half.get(), MPFR_RNDN);
    mpfr_neg(q.get(), q.get(), MPFR_RNDN);
    real sum(1.0, bits);
    real term(1.0, bits);
    mpfr_exp_t largest = mpfr_get_exp(sum.get());
    unsigned long k = 1;
    for (;; ++k) {
        mpfr_mul(term.get(), term.get(), q.get(), MPFR_RNDN);
        mpfr_div_ui(term.get(), term.get(), k * (static_cast<unsigned long>(m) + k), MPFR_RNDN);
        mpfr_add(sum.get(), sum.get(), term.get(), MPFR_RNDN);
        largest = with_exponent(with_exponent(largest, term), sum);
        if (series_ends(term, sum, k, m, bits)) break;
    }
    return {std::move(lead), std::move(sum), largest, k};
}

/// J_m(x) by its power series, with `bits`.
real series(int m, const real& x, mpfr_prec_t bits) {
    const series_parts p = series_of(m, x, bits);
    return p.lead * p.sum;
}

/// The bits of an unsigned number: the least b with n < 2^b.
long bit_width_of(unsigned long n) {
    long b = 0;
    while (n != 0) {
        n >>= 1;
        ++b;
    }
    return b;
}

/// A bound on |J_m(x) - lead * sum| as a power of two, from the series' rounding with `bits`
/// (each rounding to nearest is within 2^-bits of its result, relatively): term k carries
/// at most 3k roundings, each partial sum one, their K terms and partial sums lie below
/// 2^largest, so the sum is within (3.03 K^2 + K + 1) 2^(largest - bits) (the tail beyond
/// the last term is below 2^(largest - bits - 1)); lead's 2m roundings and the product's
/// one add (2m + 2) 2^(largest - bits) relative to lead. Four bits spare.
mpfr_exp_t rounding_bound(int m, const series_parts& p, mpfr_prec_t bits) {
    const long sum_bits = 2 + 2 * bit_width_of(p.terms);  // 4 (K+1)^2 >= 3.03 K^2 + K + 1
    const long lead_bits = bit_width_of(2 * static_cast<unsigned long>(m) + 2);
    return mpfr_get_exp(p.lead.get()) + p.largest - static_cast<mpfr_exp_t>(bits) + std::max(sum_bits, lead_bits) + 4;
}

/// The argument's check of bessel_j_nth.
void check_argument(int n, const real& x, const char* who) {
    if (n < 0) throw std::invalid_argument(std::string(who) + " needs n >= 0, got " + std::to_string(n));
    if (x.is_zero() || !(mp::abs(x) <= 4.0)) throw std::domain_error(std::string(who) + " needs 0 < |x| <= 4");
}

}  // namespace

real bessel_j_nth(int n, const real& x) {
    check_argument(n, x, "bessel_j_nth");
    const mpfr_prec_t bits = x.precision() + guard_bits;
    return real(series(n, real(x, bits), bits), x.precision());
}

real bessel_j_rounded(int n, const real& x) {
    if (n < 0 || x.is_zero() || !(mp::abs(x) <= 4.0)) return bessel_j(n, x);
    const mpfr_prec_t bits = x.precision() + guard_bits;
    const series_parts p = series_of(n, real(x, bits), bits);
    const real j = p.lead * p.sum;
    if (!j.is_zero()) {
        const mpfr_exp_t err = mpfr_get_exp(j.get()) - rounding_bound(n, p, bits);
        if (err > 0 && mpfr_can_round(j.get(), err, MPFR_RNDN, MPFR_RNDN, x.precision()) != 0) {
            return real(j, x.precision());
        }
    }
    return bessel_j(n, x);  // close to a zero of J_n, or a hard case of rounding
}

}  // namespace pendulum::mp
