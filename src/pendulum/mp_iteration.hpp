// SPDX-License-Identifier: GPL-3.0-or-later
// The iteration to order N with MPFR, for the amplitudes where the double iteration's
// rounding grows beyond 1e-14 (close to pi). Internal to the core library.
#pragma once

#include "pendulum/amplitude.hpp"
#include "pendulum/approximants.hpp"

#include <vector>

namespace pendulum::detail {

/// Below this distance from pi iterated_sequence() works with MPFR: at 0.99 pi (d = 0.031)
/// the double iteration's levels are still right to 7e-15, at 0.999 pi only to 6e-14.
inline constexpr double iteration_mp_below = 0.02;

/// Levels 0 to `order` of the iteration computed with 128 bits and rounded once to doubles;
/// a level without a period has a NaN frequency, as in iterated_sequence(). Throws
/// domain_error where the projection does not converge with 2^15 points.
std::vector<fourier_solution> iterated_sequence_mp(const amplitude& theta0, int order);

}  // namespace pendulum::detail
