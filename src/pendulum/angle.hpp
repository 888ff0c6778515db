// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "pendulum/amplitude.hpp"

#include <string>
#include <string_view>
#include <vector>

namespace pendulum {

/// A text for a message: control characters and DEL as \xNN (a message is a C string that
/// a terminal shows, and NUL would cut it short); every other byte as it is.
std::string message_text(std::string_view text);

/// Evaluates an arithmetic expression with numbers, pi (or π), + - * / and parentheses;
/// a number directly before pi or "(" multiplies it ("9pi/10", "0.9pi"), correctly rounded
/// (MPFR, 1280 bits, checked against 2560). Throws domain_error (a std::invalid_argument)
/// with a message naming the text when it is not such an expression, its value is not
/// finite, or it cancels beyond the working precision.
double parse_expression(std::string_view text);

/// Parses an angle in radians: an expression as for parse_expression, optionally followed
/// by "deg" (or "°") for degrees or "rad" ("162deg", "9pi/10", "pi - 1e-9").
double parse_angle(std::string_view text);

/// Parses an amplitude as parse_angle does, keeping its distance from pi: "pi - 1e-300" is
/// pi - 1e-300 and k' = sin(5e-301), each rounded once from the exact value. Throws
/// domain_error, naming `name`, unless 0 < theta0 < pi with pi - theta0 >= 2.2e-308.
amplitude parse_amplitude(std::string_view text, std::string_view name = "theta0");

/// One piece of an angle expression as the parser reads it, for showing it typeset.
struct angle_token {
    /// What the piece is.
    enum class kind {
        number,      ///< a number: mantissa, and an exponent where written
        pi,          ///< pi or π
        degrees,     ///< the unit deg or °
        radians,     ///< the unit rad
        plus,        ///< binary +
        minus,       ///< binary -
        sign_plus,   ///< unary +
        sign_minus,  ///< unary -
        times,       ///< an explicit *
        divide,      ///< /
        open,        ///< (
        close,       ///< )
    };
    kind type = kind::number;       ///< what it is
    std::string mantissa;           ///< a number's digits and point before its exponent, as written
    std::string exponent;           ///< a number's exponent digits without leading zeros; empty for none
    bool negative_exponent = false; ///< the exponent's sign
};

/// The pieces of an angle expression (as parse_angle reads it), in order; throws as
/// parse_angle does.
std::vector<angle_token> angle_tokens(std::string_view text);

}  // namespace pendulum
