// SPDX-License-Identifier: GPL-3.0-or-later
// The one type of bad input above the core: plot::bad_input, figures::bad_input and
// pendulum::cli::usage_error are names of it, so one handler maps it to exit code 2.
// Header-only, and every layer may include src/common (tests/layering_test.sh).
#pragma once

#include <stdexcept>

namespace common {

/// Bad input (an option, a value, a spec or style file, a format, a label): the caller's to
/// correct, reported in one line naming the value, exit code 2, nothing written.
class bad_input : public std::invalid_argument {
public:
    using std::invalid_argument::invalid_argument;
};

}  // namespace common
