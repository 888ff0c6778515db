// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

namespace pendulum {

/// T0 = 2 pi sqrt(L/g) in seconds, in extended precision: with L or g subnormal (or L/g
/// beyond a double's range) the quotient keeps every digit; throws domain_error unless
/// both are positive and finite.
long double small_period_seconds(double length, double g);

/// w0 = sqrt(g/L) in radians per second, in extended precision; the same domain.
long double angular_frequency(double length, double g);

/// sqrt(L/g), seconds per unit of w0 t, in extended precision and rounded once; the same
/// domain.
double seconds_per_radian(double length, double g);

/// ratio T0 in seconds (a period T/T0 made physical), rounded once to a double; throws
/// domain_error where the value overflows a double.
double seconds(double ratio, long double small_period_s);

}  // namespace pendulum
