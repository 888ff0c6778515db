// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A number as written, at any precision (MPFR): for the core only, not installed.

#include "pendulum/angle.hpp"
#include "pendulum/mp_real.hpp"

namespace pendulum {

/// The value of a number as written with `bits` of precision, correctly rounded (a double
/// exactly; a text evaluated as parse_angle or parse_expression evaluates it).
mp::real evaluate_written(const written_number& x, mpfr_prec_t bits);

}  // namespace pendulum
