// SPDX-License-Identifier: GPL-3.0-or-later
// The built-in animations, and the build options an animation's frames are built with.
#pragma once

#include "figures/build_options.hpp"
#include "figures/catalog.hpp"
#include "plot/theme.hpp"

#include <vector>

namespace test_support {

/// The built-in animations.
inline std::vector<const figures::entry*> builtin_animations() {
    std::vector<const figures::entry*> out;
    for (const auto& e : figures::catalog()) {
        if (e.spec.animation) out.push_back(&e);
    }
    return out;
}

/// The build options of an animation drawn in `theme`.
inline figures::build_options animated_options(const plot::theme& theme) {
    figures::build_options o = figures::sized_by({}, theme);
    o.animated = true;
    return o;
}

}  // namespace test_support
