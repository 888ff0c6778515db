// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace pendulum::cli {

/// Splits a comma-separated list; empty items are kept so that they can be reported.
std::vector<std::string> split_list(std::string_view text);

}  // namespace pendulum::cli
