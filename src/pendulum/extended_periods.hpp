// SPDX-License-Identifier: GPL-3.0-or-later
// Periods T/T0 in extended precision (x87 long double, 64-bit significand), each within a
// few units of 2^-64: the middle tier of the period errors, between doubles and MPFR.
// Internal to the core library: the installed headers do not include it.
#pragma once

#include "pendulum/amplitude.hpp"

namespace pendulum {

/// The AGM of a, b > 0 in extended precision.
long double agm_extended(long double a, long double b);

/// The exact T/T0 = 1/AGM(1, k'), from the amplitude's k' in extended precision.
long double exact_period_extended(const amplitude& theta0);

/// T/T0 of the lowest order, 1/sqrt(besinc(theta0)), in extended precision.
long double lowest_period_extended(const amplitude& theta0);

/// T/T0 of the first order in extended precision.
long double first_period_extended(const amplitude& theta0);

/// T/T0 of the second order in extended precision.
long double second_period_extended(const amplitude& theta0);

}  // namespace pendulum
