// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "pendulum/amplitude.hpp"

#include <string>
#include <string_view>
#include <vector>

namespace pendulum {

/// A text for a message: control characters (C0, DEL, C1), bidirectional controls and bytes
/// that are not UTF-8 escaped (a message is a C string that a terminal shows, and NUL would
/// cut it short); printable UTF-8 as it is.
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

/// A number as written: the text of an expression (an angle, with its unit, or a plain
/// expression), evaluated at whatever precision a result needs, or a double taken exactly.
/// "2pi/3", "2-1e-20" and "pi-1e-300" keep every digit their text has; value() is the one
/// rounding to a double.
class written_number {
public:
    /// The double x itself, exactly.
    written_number(double x);  // NOLINT: a double is a number as written
    /// An angle as parse_angle reads it; throws domain_error as parse_angle does.
    static written_number angle(std::string_view text);
    /// An expression as parse_expression reads it; throws domain_error as it does.
    static written_number expression(std::string_view text);
    /// The value rounded once to a double.
    double value() const { return value_; }
    /// The text as written; empty for a double.
    const std::string& text() const { return text_; }
    /// True where the text may end in a unit (deg, rad).
    bool angle_units() const { return units_; }
    /// True where the value is exactly a double (a double given, or a text such as "3" or
    /// "+1" or "2/2" whose value is one): value() is then the number itself.
    bool exact_double() const { return exact_; }

private:
    written_number() = default;
    /// Reads the text, rounds it once and sees whether that double is the number.
    static written_number parse(std::string_view text, bool units);
    std::string text_;
    bool units_ = false;
    bool exact_ = true;
    double value_ = 0;
};

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
