// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <stdexcept>

namespace plot {

/// Bad input to the plot layer (an unknown format, a raster too large, a bad date or
/// label): the caller's to correct, with a message naming the value.
class bad_input : public std::invalid_argument {
public:
    using std::invalid_argument::invalid_argument;
};

}  // namespace plot
