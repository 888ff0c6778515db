// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "common/errors.hpp"

namespace figures {

/// Bad input to the figures layer (an unknown figure or theme, a spec or animation that
/// cannot be drawn as asked): the one bad-input type of every layer above the core
/// (common/errors.hpp).
using bad_input = common::bad_input;

}  // namespace figures
