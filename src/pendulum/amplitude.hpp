// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

namespace pendulum {

/// Thrown for an argument outside a function's domain; the message names the value.
class domain_error : public std::invalid_argument {
public:
    using std::invalid_argument::invalid_argument;
};

/// Formats a double so that it reads back to the same value (shortest round-trip form).
std::string format_double(double x);

/// Throws domain_error unless 0 < theta0 < pi; `name` is used in the message.
void check_amplitude(double theta0, std::string_view name = "theta0");

}  // namespace pendulum
