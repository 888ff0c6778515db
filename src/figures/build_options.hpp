// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "figures/spec.hpp"

#include <vector>

namespace figures {

/// Choices from the command line that change what a figure shows.
struct build_options {
    std::vector<amplitude> amplitudes;  ///< --theta0: one trajectory panel each, or the panels' amplitude lists
    double panel_width_cm = 6.0;        ///< panel width where the spec gives none (the theme's)
    double panel_aspect = 0.75;         ///< panel aspect where the spec gives none (the theme's)
    bool animated = false;              ///< leave out what moves: add_frame_state adds it per frame
};

}  // namespace figures
