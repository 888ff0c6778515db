// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "pendulum/approximants.hpp"
#include "pendulum/exact.hpp"

namespace pendulum {

/// The exact angular velocity theta'/w0 at time t = s T (s in exact periods); negative
/// while the pendulum swings back from theta0. Exact to rounding up to theta0 = pi - 1e-9.
double velocity_at_fraction(const exact_solution& solution, double s);

/// The angular velocity theta'/w0 of a Fourier solution at time w0 t.
double velocity(const fourier_solution& solution, double w0_t);

/// The angular velocity theta'/w0 of a Fourier solution at the phase x = (w/w0) w0 t.
double velocity_at_phase(const fourier_solution& solution, double x);

/// The upper branch of the separatrix: theta'/w0 = 2 cos(theta/2), for theta in [-pi, pi].
double separatrix_velocity(double theta);

}  // namespace pendulum
