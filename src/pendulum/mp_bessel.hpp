// SPDX-License-Identifier: GPL-3.0-or-later
// Bessel functions J_0 .. J_n of one argument in MPFR, for the errors and the iteration that
// need more than a double. Internal to the core library.
#pragma once

#include "pendulum/mp_real.hpp"

#include <vector>

namespace pendulum::mp {

/// J_0(x) .. J_n(x), n >= 0, for 0 < |x| <= 4, each within a few units of 2^-precision of the
/// largest of them (relative to itself away from the zeros of J_m): the two highest by their
/// power series, the rest by the recurrence downwards, which is stable there. One call costs
/// about as much as two of MPFR's mpfr_jn, whatever n.
std::vector<real> bessel_j_upto(int n, const real& x);

/// J_n(x), n >= 0, for 0 < |x| <= 4: element n of bessel_j_upto(n, x), the same number
/// (its power series with guard bits, rounded once), without the others.
real bessel_j_nth(int n, const real& x);

/// J_n(x) correctly rounded to x's precision, the number MPFR's mpfr_jn gives: its power
/// series with guard bits where their rounding bound shows the result rounds correctly
/// (n >= 0, 0 < |x| <= 4), mpfr_jn otherwise (close to a zero of J_n, or a hard case).
real bessel_j_rounded(int n, const real& x);

}  // namespace pendulum::mp
