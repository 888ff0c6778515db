// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace pendulum::cli {

/// Evaluates an arithmetic expression with numbers, pi (or π), + - * / and parentheses;
/// a number directly before pi or "(" multiplies it ("9pi/10", "0.9pi"). Throws
/// std::invalid_argument with a message naming the text when it is not such an expression
/// or its value is not finite.
double parse_expression(std::string_view text);

/// Parses an angle in radians: an expression as for parse_expression, optionally followed
/// by "deg" (or "°") for degrees or "rad" ("162deg", "9pi/10", "pi - 1e-9").
double parse_angle(std::string_view text);

/// Splits a comma-separated list; empty items are kept so that they can be reported.
std::vector<std::string> split_list(std::string_view text);

}  // namespace pendulum::cli
