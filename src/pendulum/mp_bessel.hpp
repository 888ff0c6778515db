// SPDX-License-Identifier: GPL-3.0-or-later
// Bessel functions J_n in MPFR, for the errors and the iteration that need more than a
// double. Internal to the core library.
#pragma once

#include "pendulum/mp_real.hpp"

namespace pendulum::mp {

/// J_n(x), n >= 0, for 0 < |x| <= 4: its power series with guard bits, rounded once; within
/// a few units of 2^-precision of max(|J_n|, |J_n+1|) (relative to itself away from its zeros).
real bessel_j_nth(int n, const real& x);

/// J_n(x) correctly rounded to x's precision, the number MPFR's mpfr_jn gives: its power
/// series with guard bits where their rounding bound shows the result rounds correctly
/// (n >= 0, 0 < |x| <= 4), mpfr_jn otherwise (close to a zero of J_n, or a hard case).
real bessel_j_rounded(int n, const real& x);

}  // namespace pendulum::mp
