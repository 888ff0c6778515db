// SPDX-License-Identifier: GPL-3.0-or-later
// The iteration to order N with MPFR, for the amplitudes where the double iteration's
// rounding grows beyond 1e-14 (close to pi), and for the iteration's period errors; defined
// in mp_iteration.cpp. Internal to the core library.
#pragma once

#include "pendulum/amplitude.hpp"
#include "pendulum/approximants.hpp"
#include "pendulum/formulas_mp.hpp"
#include "pendulum/mp_real.hpp"

#include <functional>
#include <optional>
#include <vector>

namespace pendulum::detail {

/// Below this distance from pi iterated_sequence() works with MPFR: at 0.99 pi (d = 0.031)
/// the double iteration's levels are still right to 7e-15, at 0.999 pi only to 6e-14.
inline constexpr double iteration_mp_below = 0.02;

/// Levels 0 to `order` (0 <= order <= max_order, checked by the caller) of the iteration
/// computed with 128 bits and more, rounded once to doubles;
/// a level without a period has a NaN frequency, as in iterated_sequence(). Throws
/// domain_error where the projection does not converge with 2^15 points.
std::vector<fourier_solution> iterated_sequence_mp(const amplitude& theta0, int order);

/// lambda = (w/w0)^2 of levels 0 .. order with `bits` at the exact amplitude x; an unset
/// entry where the projection did not converge (that level and all later ones). Stops after
/// the first level for which `stop` (if given) is true; stores each level's coefficients
/// c_k/theta0 in `coefficients` if given.
std::vector<std::optional<mp::real>> mp_lambdas(const mp::mp_amplitude& x, int order, mpfr_prec_t bits,
                                                const std::function<bool(const mp::real& lambda)>& stop = {},
                                                std::vector<std::vector<mp::real>>* coefficients = nullptr);

}  // namespace pendulum::detail
