// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <stdexcept>

namespace pendulum::cli {

/// Bad input on the command line (an option, a value, a file it names): reported in one
/// line, exit code 2, nothing written.
class usage_error : public std::invalid_argument {
public:
    using std::invalid_argument::invalid_argument;
};

}  // namespace pendulum::cli
