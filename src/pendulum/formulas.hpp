// SPDX-License-Identifier: GPL-3.0-or-later
// The closed-form period formulas T/T0 (and the frequencies w/w0 of the paper's lowest and
// first orders), each written once over the number type: double for drawing, long double for
// the errors' middle tier, mp::real (MPFR, formulas_mp.hpp) for the correctly rounded tier.
// A formula reads the amplitude through amplitude_view and calls only the primitives below
// (sqrt, sin, log, pi_like, ...), which each number type provides: <cmath> and the overloads
// here for double and long double, pendulum::mp for mp::real (found by argument-dependent
// lookup). Internal to the core library: the installed headers do not include it.
//
// A new period formula is one struct here with a templated call operator, and one row of
// the method table (methods.cpp) naming closed_form_period<F> and closed_form_period_error<F>
// (formula_methods.hpp).
#pragma once

#include "pendulum/amplitude.hpp"
#include "pendulum/bessel_series.hpp"
#include "pendulum/gsl_support.hpp"

#include <array>
#include <cmath>
#include <numbers>
#include <type_traits>

namespace pendulum::formulas {

/// The amplitude as a formula reads it, in one number type.
template <class Real>
struct amplitude_view {
    Real theta;         ///< theta0
    Real k;             ///< k = sin(theta0/2)
    Real kp;            ///< k' = cos(theta0/2)
    Real one_minus_kp;  ///< 1 - k' without cancellation (2 sin^2(theta0/4), or 1 - k' near pi)
};

/// The view in doubles: k and k' from the amplitude (exact near pi), 1 - k' as 1 - k' near
/// pi and 2 sin^2(theta0/4) elsewhere.
inline amplitude_view<double> view_of(const amplitude& a) {
    const double s = std::sin(0.25 * a.radians());
    return {a.radians(), a.k(), a.kp(), a.near_pi() ? 1.0 - a.kp() : 2.0 * s * s};
}

/// The view in extended precision: theta0, k and k' from the amplitude's extended values.
inline amplitude_view<long double> view_extended(const amplitude& a) {
    const long double kp = a.kp_extended();
    return {a.radians_extended(), a.k_extended(), kp, 1 - kp};
}

// ---- The primitives for double and long double.

/// 1 in the number type of `like`.
template <class Real>
    requires std::is_floating_point_v<Real>
Real one_like(Real) {
    return 1;
}
/// 0 in the number type of `like`.
template <class Real>
    requires std::is_floating_point_v<Real>
Real zero_like(Real) {
    return 0;
}
/// pi in the number type of `like`.
template <class Real>
    requires std::is_floating_point_v<Real>
Real pi_like(Real) {
    return std::numbers::pi_v<Real>;
}
/// sqrt(3)/2 in the number type of `like`.
template <class Real>
    requires std::is_floating_point_v<Real>
Real half_sqrt3_like(Real) {
    return Real(0.5) * std::numbers::sqrt3_v<Real>;
}
/// ln k' from k' and d = 1 - k', each where it has no cancellation: log1p(-d) while k' is
/// not small, ln k' itself near pi.
template <class Real>
    requires std::is_floating_point_v<Real>
Real log_kp(Real kp, Real d) {
    return d < Real(0.5) ? std::log1p(-d) : std::log(kp);
}
/// J_n(x)/x in doubles: GSL, and its power series below 1e-8.
inline double j_over_x(int n, double x) { return bessel_j_over_x(n, x); }
/// J_n(x)/x in extended precision: the power series.
inline long double j_over_x(int n, long double x) { return bessel_j_over_x_series(n, x); }

/// The Taylor coefficients of T/T0 in theta0^2 as doubles (a_0 = 1, a_1 = 1/16, ...).
inline constexpr std::array<double, 21> series_coefficients = {
#include "pendulum/period_series_coefficients.inc"
};
/// a_n of the Taylor series in the number type of `like` (the doubles above for floating
/// types; the exact rationals for mp::real).
template <class Real>
    requires std::is_floating_point_v<Real>
Real series_coefficient(int n, Real) {
    return series_coefficients[static_cast<std::size_t>(n)];
}

// ---- The formulas: T/T0 for the amplitude, with the method's N where it takes one.

/// theta0 cos(w0 t): T/T0 = 1.
struct harmonic {
    /// T/T0.
    template <class Real>
    Real operator()(const amplitude_view<Real>& x, int) const {
        return one_like(x.kp);
    }
};

/// The Taylor polynomial through theta0^4 (Fulcher and Davis): 1 + theta0^2/16 + 11 theta0^4/3072.
struct polynomial {
    /// T/T0.
    template <class Real>
    Real operator()(const amplitude_view<Real>& x, int) const {
        const Real t2 = x.theta * x.theta;
        return 1.0 + t2 / 16.0 + 11.0 * t2 * t2 / 3072.0;
    }
};

/// Kidd and Fogg (Phys. Teach. 40, 81, 2002): T/T0 = 1/sqrt(k').
struct kidd_fogg {
    /// T/T0.
    template <class Real>
    Real operator()(const amplitude_view<Real>& x, int) const {
        using std::sqrt;
        return 1.0 / sqrt(x.kp);
    }
};

/// Lima and Arun (Am. J. Phys. 74, 892, 2006): T/T0 = -ln(k')/(1 - k').
struct lima_arun {
    /// T/T0.
    template <class Real>
    Real operator()(const amplitude_view<Real>& x, int) const {
        const Real& d = x.one_minus_kp;
        if constexpr (std::is_floating_point_v<Real>) {
            // -ln(k')/d = 1 + d/2 + d^2/3 + ...: below 1e-9 the first two terms are exact to
            // rounding (and d may be 0, for a subnormal theta0).
            if (d < Real(1e-9)) return 1.0 + 0.5 * d;
        }
        return -log_kp(x.kp, d) / d;
    }
};

/// Ganley (Am. J. Phys. 53, 73, 1985): T/T0 = sqrt(F theta0 / sin(F theta0)), F = sqrt(3)/2.
struct ganley {
    /// T/T0.
    template <class Real>
    Real operator()(const amplitude_view<Real>& x, int) const {
        using std::sin;
        using std::sqrt;
        const Real f = half_sqrt3_like(x.theta) * x.theta;
        return sqrt(f / sin(f));
    }
};

/// `steps` steps of the arithmetic-geometric mean from a = 1, b = k' (Carvalhaes and Suppes,
/// Am. J. Phys. 76, 1150, 2008): T/T0 = 1/a_steps; one step gives 2/(1 + k').
struct agm {
    /// T/T0.
    template <class Real>
    Real operator()(const amplitude_view<Real>& x, int steps) const {
        using std::sqrt;
        Real a = one_like(x.kp);
        Real b = x.kp;
        for (int i = 0; i < steps; ++i) {
            Real next = 0.5 * (a + b);
            b = sqrt(a * b);
            a = next;
        }
        return 1.0 / a;
    }
};

/// Denman (1959): T/T0 = 1/(1 - theta0^2/16).
struct denman {
    /// T/T0.
    template <class Real>
    Real operator()(const amplitude_view<Real>& x, int) const {
        return 1.0 / (1.0 - x.theta * x.theta / 16.0);
    }
};

/// The Taylor series of T/T0 in theta0 through theta0^(2 terms), by Horner in theta0^2 (every
/// coefficient is positive: no cancellation).
struct series {
    /// T/T0.
    template <class Real>
    Real operator()(const amplitude_view<Real>& x, int terms) const {
        const Real t2 = x.theta * x.theta;
        Real sum = zero_like(x.theta);
        for (int n = terms; n >= 0; --n) sum = sum * t2 + series_coefficient(n, x.theta);
        return sum;
    }
};

/// The large-amplitude asymptote T/T0 = (2/pi) ln(4/k').
struct log_asymptote {
    /// T/T0.
    template <class Real>
    Real operator()(const amplitude_view<Real>& x, int) const {
        using std::log;
        return 2.0 / pi_like(x.kp) * log(4.0 / x.kp);
    }
};

/// Molina (Phys. Teach. 35, 489, 1997): T/T0 = (sin(theta0)/theta0)^(-3/8), the power as the
/// cube of three square roots. Beyond pi/2, sin(theta0) = 2 k k' keeps its digits up to pi;
/// below, sin(theta0) itself does down to subnormal theta0 (where k = theta0/2 would not).
struct molina {
    /// T/T0.
    template <class Real>
    Real operator()(const amplitude_view<Real>& x, int) const {
        using std::sin;
        using std::sqrt;
        const Real ratio = x.kp < x.k ? 2.0 * x.k * x.kp / x.theta : sin(x.theta) / x.theta;
        const Real eighth = sqrt(sqrt(sqrt(ratio)));
        return 1.0 / (eighth * eighth * eighth);
    }
};

// ---- The paper's lowest and first orders: their frequencies w/w0 (T/T0 = 1/frequency).

/// Lowest order: (w/w0)^2 = besinc(theta0) = 2 J1(theta0)/theta0 (Eq. Lamb.15.1).
template <class Real>
Real lowest_frequency(const Real& theta) {
    using std::sqrt;
    return sqrt(2.0 * j_over_x(1, theta));
}

/// The first order's eta = -J3/(9 J1) and frequency w/w0 = sqrt(2 (J1/theta0) (1 + eta))
/// (Eqs. Lamb.20, Lamb.21), from the ratios J_n(theta0)/theta0.
template <class Real>
struct first_order_parts {
    Real j1;         ///< J1(theta0)/theta0
    Real eta;        ///< -J3/(9 J1)
    Real frequency;  ///< w/w0
};

/// The first order's parts at theta0.
template <class Real>
first_order_parts<Real> first_order_of(const Real& theta) {
    using std::sqrt;
    Real j1 = j_over_x(1, theta);
    Real eta = -j_over_x(3, theta) / (9.0 * j1);
    Real frequency = sqrt(2.0 * j1 * (1.0 + eta));
    return {std::move(j1), std::move(eta), std::move(frequency)};
}

}  // namespace pendulum::formulas
