// SPDX-License-Identifier: GPL-3.0-or-later
// The primitives of formulas.hpp for mp::real (MPFR), in pendulum::mp so that a formula
// finds them by argument-dependent lookup: each rounds once to the argument's precision.
// Internal to the core library.
#pragma once

#include "pendulum/amplitude.hpp"
#include "pendulum/formulas.hpp"
#include "pendulum/mp_bessel.hpp"
#include "pendulum/mp_real.hpp"

#include <array>
#include <utility>

namespace pendulum::mp {

/// 1 with the precision of `like`.
inline real one_like(const real& like) { return real(1.0, like.precision()); }
/// 0 with the precision of `like`.
inline real zero_like(const real& like) { return real(like.precision()); }
/// pi with the precision of `like`.
inline real pi_like(const real& like) { return pi(like.precision()); }
/// sqrt(3)/2 with the precision of `like`.
inline real half_sqrt3_like(const real& like) { return sqrt(real(3.0, like.precision())) / 2.0; }
/// ln(1 + x).
inline real log1p(const real& x) { return apply(mpfr_log1p, x); }
/// ln k' = log1p(-d) from d = 1 - k', exact itself.
inline real log_kp(const real&, const real& d) { return log1p(-d); }
/// J_n(x)/x, 0 <= n, 0 < |x| <= 4.
inline real j_over_x(int n, const real& x) { return bessel_j_nth(n, x) / x; }

/// a_n of the Taylor series of T/T0 in theta0^2 from its exact rational: the error of the
/// series is far below a double's rounding of its coefficients at small amplitudes.
inline real series_coefficient(int n, const real& like) {
    static constexpr std::array<std::array<const char*, 2>, formulas::series_coefficients.size()> rationals = {{
#include "pendulum/period_series_rationals.inc"
    }};
    real num(like.precision());
    real den(like.precision());
    mpfr_set_str(num.get(), rationals[static_cast<std::size_t>(n)][0], 10, MPFR_RNDN);
    mpfr_set_str(den.get(), rationals[static_cast<std::size_t>(n)][1], 10, MPFR_RNDN);
    return num / den;
}

/// The amplitude in MPFR.
using mp_amplitude = formulas::amplitude_view<real>;

/// The amplitude, exact, with `bits`: theta0, k = sin(theta0/2), k' = cos(theta0/2) (= sin(d/2)
/// near pi) and 1 - k' without cancellation.
inline mp_amplitude exact_amplitude(const amplitude& a, mpfr_prec_t bits) {
    // From d where it is the nearer of the two to the exact amplitude; a double theta0 is
    // the exact amplitude itself (its d is rounded).
    // sin and cos of one angle by one call (each correctly rounded, as by two).
    real sine(bits);
    real cosine(bits);
    if (a.near_pi() && !a.exact_radians()) {
        const real d(a.from_pi(), bits);
        mpfr_sin_cos(sine.get(), cosine.get(), (d / 2.0).get(), MPFR_RNDN);
        real d_kp = 1.0 - sine;
        return {pi(bits) - d, std::move(cosine), std::move(sine), std::move(d_kp)};
    }
    const real theta(a.radians(), bits);
    const real s = sin(theta / 4.0);
    mpfr_sin_cos(sine.get(), cosine.get(), (theta / 2.0).get(), MPFR_RNDN);
    return {theta, std::move(sine), std::move(cosine), 2.0 * s * s};
}

}  // namespace pendulum::mp
