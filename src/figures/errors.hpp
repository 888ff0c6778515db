// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <stdexcept>

namespace figures {

/// Bad input to the figures layer (an unknown figure or theme, a spec or animation that
/// cannot be drawn as asked): the caller's to correct, with a message naming the value.
class bad_input : public std::invalid_argument {
public:
    using std::invalid_argument::invalid_argument;
};

}  // namespace figures
