// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "pendulum/amplitude.hpp"

namespace pendulum {

/// The largest number of AGM steps accepted by period_agm().
inline constexpr int max_agm_steps = 10;

/// The largest N accepted by period_series(): the series through theta0^(2 N).
inline constexpr int max_series_terms = 20;

/// Kidd and Fogg (Phys. Teach. 40, 81, 2002): T/T0 = 1/sqrt(k'), k' = cos(theta0/2).
double period_kidd_fogg(const amplitude& theta0);

/// Lima and Arun (Am. J. Phys. 74, 892, 2006): T/T0 = -ln(k')/(1 - k').
double period_lima_arun(const amplitude& theta0);

/// Ganley (Am. J. Phys. 53, 73, 1985): T/T0 = sqrt(F theta0 / sin(F theta0)), F = sqrt(3)/2.
double period_ganley(const amplitude& theta0);

/// `steps` steps of the arithmetic-geometric mean from a = 1, b = k' (Carvalhaes and Suppes,
/// Am. J. Phys. 76, 1150, 2008): T/T0 = 1/a_steps; one step gives 2/(1 + k').
double period_agm(const amplitude& theta0, int steps);

/// Denman (1959): T/T0 = 1/(1 - theta0^2/16).
double period_denman(const amplitude& theta0);

/// The Taylor series of T/T0 in theta0 through theta0^(2 terms): 1 + theta0^2/16 + ...
double period_series(const amplitude& theta0, int terms);

/// The large-amplitude asymptote T/T0 = (2/pi) ln(4/k').
double period_log_asymptote(const amplitude& theta0);

}  // namespace pendulum
