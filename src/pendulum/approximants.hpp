// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "pendulum/amplitude.hpp"

#include <memory>
#include <vector>

namespace pendulum {

/// A method's w/w0 and coefficients at any precision (MPFR, mp_iteration.hpp): internal.
struct exact_source;

/// A truncated Fourier solution theta(t) = sum_k c_{2k+1} cos((2k+1) w t).
struct fourier_solution {
    double frequency_ratio = 1.0;      ///< w/w0
    std::vector<double> coefficients;  ///< c1, c3, c5, ...
    /// The same solution at any precision, from the exact amplitude (null for a solution made
    /// of its doubles alone): time_reducer forms the phase at large times with it.
    std::shared_ptr<const exact_source> exact{};

    /// The period ratio T/T0 = w0/w (NaN where the solution has no period).
    double period_ratio() const { return 1.0 / frequency_ratio; }
    /// False where the scheme has no real frequency (the order-N iteration close to pi).
    bool exists() const { return frequency_ratio > 0; }
    /// theta at time w0 t.
    double theta(double w0_t) const;
    /// theta at the phase x = (w/w0) w0 t (any real x; exact to rounding for |x| <= pi).
    double theta_at_phase(double x) const;
};

/// The largest order accepted by iterated().
inline constexpr int max_order = 200;

/// Harmonic solution theta0 cos(w0 t) (paper Eq. Lamb.5).
fourier_solution harmonic(const amplitude& theta0);

/// Lowest order: c1 = theta0, (w/w0)^2 = besinc(theta0) = 2 J1(theta0)/theta0 (Eq. Lamb.15.1).
fourier_solution lowest_order(const amplitude& theta0);

/// First order: c1', c3' and w from eta = -J3/(9 J1) (Eqs. Lamb.20, Lamb.21).
fourier_solution first_order(const amplitude& theta0);

/// Second order as in the paper's appendix, with its linearised projection.
fourier_solution second_order(const amplitude& theta0);

/// Taylor polynomials of c1, c3, c5 and of T/T0 through theta0^5 (after Fulcher and Davis).
fourier_solution polynomial(const amplitude& theta0);

/// The paper's iteration carried to `order` (order + 1 harmonics), projecting
/// sin(theta) exactly; orders 0 and 1 equal lowest_order() and first_order(). Close to pi
/// some levels have lambda = (w/w0)^2 <= 0: there frequency_ratio is NaN and exists() false.
fourier_solution iterated(const amplitude& theta0, int order);

/// Every level of the iteration, 0 to `order`: element n is iterated(theta0, n).
std::vector<fourier_solution> iterated_sequence(const amplitude& theta0, int order);

/// The levels as iterated_sequence() computes them at least detail::iteration_mp_below from
/// pi (extended precision, rounded once), at any amplitude: for measuring where MPFR is needed.
std::vector<fourier_solution> iterated_sequence_extended(const amplitude& theta0, int order);

/// Throws domain_error naming the order unless 0 <= order <= max_order.
void check_order(int order);

/// The period of one level of the iteration, with an estimate of its rounding error.
struct level_period {
    double value = 0;     ///< T_N/T0, NaN where the level has no period
    double rounding = 0;  ///< |value - the same level in extended precision|
};

/// The period of every level 0 to `order`, each with its rounding estimate (close to pi the
/// iteration amplifies the rounding of its coefficients).
std::vector<level_period> iterated_periods(const amplitude& theta0, int order);

/// (w/w0)^2 = 2 J1(x) / x, the "besinc" function of optics (1 at x = 0).
double besinc(double x);

}  // namespace pendulum
