// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "pendulum/amplitude.hpp"

#include <vector>

namespace pendulum {

/// The smallest |T_m/T - 1| that is given as a number; below it the error is only known
/// to be smaller.
inline constexpr double smallest_period_error = 1e-300;

/// A method's period error T_m/T - 1 at one amplitude, without cancellation: right to 1e-12
/// relative (doubles where the two periods differ by 1e-2 or more, extended precision for the
/// Bessel methods down to 1e-5, MPFR below), or correctly rounded (precision::correctly_rounded).
struct period_error {
    /// What is known.
    enum class kind {
        value,        ///< `value` is T_m/T - 1
        below_limit,  ///< |T_m/T - 1| < smallest_period_error (value 0)
        no_period,    ///< the method has no period here (order:N close to pi)
        not_computed, ///< the iteration's projection did not converge with 2^15 points
    };
    kind what = kind::value;  ///< what is known
    double value = 0;         ///< T_m/T - 1 where what is kind::value
};

/// How closely a period error is computed: each call says which, no state is kept.
enum class precision {
    drawing,            ///< right to 1e-12 relative: doubles, extended precision, MPFR only where needed
    correctly_rounded,  ///< correctly rounded (MPFR for every closed form and the iteration), for
                        ///< numbers printed to their last digit, as the claims are
};

// The period errors of each method, for the method table (methods.hpp): T_m/T - 1 at
// theta0, with the method's N where it takes one, computed as `p` says.

/// The exact solution: zero.
period_error exact_period_error(const amplitude& theta0, int n, precision p);
/// theta0 cos(w0 t): 1/T - 1.
period_error harmonic_period_error(const amplitude& theta0, int n, precision p);
/// The paper's lowest order.
period_error lowest_period_error(const amplitude& theta0, int n, precision p);
/// The paper's first order.
period_error first_period_error(const amplitude& theta0, int n, precision p);
/// The paper's second order.
period_error second_period_error(const amplitude& theta0, int n, precision p);
/// The polynomial approximant.
period_error polynomial_period_error(const amplitude& theta0, int n, precision p);
/// The iteration to order n.
period_error iterated_period_error(const amplitude& theta0, int n, precision p);
/// Kidd and Fogg.
period_error kidd_fogg_period_error(const amplitude& theta0, int n, precision p);
/// Lima and Arun.
period_error lima_arun_period_error(const amplitude& theta0, int n, precision p);
/// Ganley.
period_error ganley_period_error(const amplitude& theta0, int n, precision p);
/// The period errors of the iteration's levels 0 to `order`, computed with MPFR throughout
/// (close to pi doubles drift at every level); an error below `floor` (at least 1e-300) is
/// kind::below_limit. Throws domain_error for a bad order.
std::vector<period_error> iterated_period_errors(const amplitude& theta0, int order,
                                                 double floor = smallest_period_error);
/// The first level N <= up_to of the iteration with |T_N/T - 1| < tolerance (>= 1e-30), or
/// -1; computed with MPFR.
int first_level_within(const amplitude& theta0, double tolerance, int up_to);
/// n AGM steps.
period_error agm_period_error(const amplitude& theta0, int n, precision p);
/// Denman.
period_error denman_period_error(const amplitude& theta0, int n, precision p);
/// The Taylor series through theta0^(2n).
period_error series_period_error(const amplitude& theta0, int n, precision p);
/// The large-amplitude asymptote.
period_error log_asymptote_period_error(const amplitude& theta0, int n, precision p);

}  // namespace pendulum
