// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace pendulum::cli {

/// Splits a comma-separated list (a comma inside parentheses does not split: "f(a, b)" is one
/// item); empty items are kept so that they can be reported.
std::vector<std::string> split_list(std::string_view text);

/// Text from the user as a message quotes it: control characters and NUL as \xNN, so that
/// the message (a C string in an exception) is not cut short and cannot drive the terminal.
std::string shown_text(std::string_view text);

}  // namespace pendulum::cli
