// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "common/errors.hpp"

namespace plot {

/// Bad input to the plot layer (an unknown format, a raster too large, a bad date or
/// label): the one bad-input type of every layer above the core (common/errors.hpp).
using bad_input = common::bad_input;

}  // namespace plot
