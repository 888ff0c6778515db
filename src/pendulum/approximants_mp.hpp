// SPDX-License-Identifier: GPL-3.0-or-later
// The paper's three approximants in MPFR at the exact amplitude, for the exact sources of
// their solutions, the claims and the period errors; defined in approximants.cpp beside
// their double and extended-precision forms. Internal to the core library.
#pragma once

#include "pendulum/mp_iteration.hpp"

namespace pendulum::detail {

/// The paper's lowest order in MPFR at the exact amplitude x.
mp_solution lowest_mp(const mp::mp_amplitude& x);
/// The paper's first order in MPFR at the exact amplitude x.
mp_solution first_mp(const mp::mp_amplitude& x);
/// The paper's second order in MPFR at the exact amplitude x.
mp_solution second_mp(const mp::mp_amplitude& x);

/// T/T0 of the paper's second order in MPFR at the exact amplitude x (the same template as
/// second_order()'s extended precision, approximants.cpp).
mp::real second_period_mp(const mp::mp_amplitude& x, int);

}  // namespace pendulum::detail
