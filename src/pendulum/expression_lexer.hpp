// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The words both of the core's expression readers share: the angle's (angle.cpp: numbers, pi,
// + - * / and a unit, correctly rounded) and the formula's (formula.cpp: names, functions and
// ^ besides). One rule for spaces and one for what a number is, so "2.5e-3", ".5", "5." and
// "1e" read alike in an angle and in a formula. For the core only, not installed.

#include <algorithm>
#include <cstddef>
#include <string>
#include <string_view>

namespace pendulum::lexer {

/// A digit 0-9 (not the locale's).
inline bool digit(char c) { return c >= '0' && c <= '9'; }

/// A byte that may start a number: a digit or ".".
inline bool number_start(char c) { return digit(c) || c == '.'; }

/// The position after the spaces and tabs from pos.
inline std::size_t skip_space(std::string_view text, std::size_t pos) {
    while (pos < text.size() && (text[pos] == ' ' || text[pos] == '\t')) ++pos;
    return pos;
}

/// The end of the number at pos: digits, one "." and digits, then an exponent only where a
/// digit follows "e" or "E" (and its sign): "1e" is the number 1 followed by "e". Nothing
/// else is taken, so strtod and MPFR never see "inf", "nan" or hex.
inline std::size_t number_end(std::string_view text, std::size_t pos) {
    std::size_t end = pos;
    while (end < text.size() && digit(text[end])) ++end;
    if (end < text.size() && text[end] == '.') {
        ++end;
        while (end < text.size() && digit(text[end])) ++end;
    }
    if (end < text.size() && (text[end] == 'e' || text[end] == 'E')) {
        std::size_t exp = end + 1;
        if (exp < text.size() && (text[exp] == '+' || text[exp] == '-')) ++exp;
        if (exp < text.size() && digit(text[exp])) {
            end = exp;
            while (end < text.size() && digit(text[end])) ++end;
        }
    }
    return end;
}

/// A number's text (from number_end) before its exponent: "2.5" of "2.5e-3".
inline std::string mantissa_of(std::string_view number) {
    return std::string(number.substr(0, std::min(number.find_first_of("eE"), number.size())));
}

/// True where the mantissa has a digit: "." and ".e5" are no numbers.
inline bool has_digit(std::string_view mantissa) { return mantissa.find_first_of("0123456789") != std::string_view::npos; }

}  // namespace pendulum::lexer
