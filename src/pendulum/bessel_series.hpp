// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

namespace pendulum {

/// Arguments up to this size are summed by the power series (in extended precision the
/// alternating sum loses fewer than 6 bits of its 64 there).
inline constexpr long double bessel_series_limit = 4.0L;

/// J_n(x) for n >= 0 and |x| <= bessel_series_limit by its power series in extended
/// precision: a few units of 2^-64, subnormal x included; throws domain_error otherwise.
long double bessel_j_series(int n, long double x);

/// J_n(x)/x for n >= 1 and 0 < |x| <= bessel_series_limit, the same way.
long double bessel_j_over_x_series(int n, long double x);

}  // namespace pendulum
