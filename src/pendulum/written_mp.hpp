// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A number as written, at any precision (MPFR): for the core only, not installed.

#include "pendulum/angle.hpp"
#include "pendulum/mp_real.hpp"

#include <cstddef>
#include <gmp.h>

#include <optional>

namespace pendulum {

/// The value of a number as written with `bits` of precision, correctly rounded (a double
/// exactly; a text evaluated as parse_angle or parse_expression evaluates it).
mp::real evaluate_written(const written_number& x, mpfr_prec_t bits);

/// A rational number (GMP), owned.
class rational {
public:
    rational() { mpq_init(q_); }
    ~rational() { mpq_clear(q_); }
    rational(const rational& o) : rational() { mpq_set(q_, o.q_); }
    rational& operator=(const rational& o) {
        mpq_set(q_, o.q_);
        return *this;
    }
    /// The GMP number, for reading and writing.
    mpq_ptr get() { return q_; }
    /// The GMP number, for reading.
    mpq_srcptr get() const { return q_; }

private:
    mpq_t q_;
};

/// A number a + b pi with a and b rational: the exact value of every number the angle
/// language writes with numbers, pi, + - * / and units (2pi/3, 120deg, 2-1e-20, pi-1e-9).
struct rational_pi {
    rational a;  ///< the rational part
    rational b;  ///< the multiple of pi
};

/// The most bits a numerator or denominator of exact_written's values may take on the way:
/// a product of large exponents (1e-99999*1e-99999*...) would otherwise take seconds and
/// memory for a value only MPFR can decide anyway.
inline constexpr std::size_t max_exact_bits = std::size_t{1} << 20;

/// The exact value of a number as written, where it is a + b pi with a, b rational: a double
/// itself, or a text with no product of two multiples of pi, decimal exponents within
/// 100000 and every value on the way within max_exact_bits; nothing otherwise (then only
/// its MPFR value is known).
std::optional<rational_pi> exact_written(const written_number& x);

}  // namespace pendulum
