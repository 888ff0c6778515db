// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "common/errors.hpp"

namespace pendulum::cli {

/// Bad input on the command line (an option, a value, a file it names): reported in one
/// line, exit code 2, nothing written. The one bad-input type of every layer above the core
/// (common/errors.hpp).
using usage_error = common::bad_input;

}  // namespace pendulum::cli
