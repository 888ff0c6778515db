// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "figures/spec.hpp"
#include "plot/theme.hpp"

#include <memory>
#include <vector>

namespace figures {

/// Choices from the command line that change what a figure shows.
struct build_options {
    std::vector<amplitude> amplitudes;  ///< --theta0: one trajectory panel each, or the panels' amplitude lists
    double panel_width_cm = 6.0;        ///< the theme's panel width: where the spec gives none, or over it if given
    double panel_aspect = 0.75;         ///< the theme's panel aspect: where the spec gives none, or over it if given
    bool panel_width_given = false;     ///< panel_width_cm came from a style file or --set: it wins over the spec's
    bool panel_aspect_given = false;    ///< panel_aspect came from a style file or --set: it wins over the spec's
    bool animated = false;              ///< leave out what moves: add_frame_state adds it per frame
    /// The theme the figure is drawn in: its named styles are the lines the figure's words
    /// speak of (unset: the paper theme's).
    std::shared_ptr<const plot::theme> theme{};
};

/// `o` with the panel size of `theme`: the command line over a style file over a spec over
/// a built-in theme.
inline build_options sized_by(build_options o, const plot::theme& theme) {
    o.panel_width_cm = theme.panel_width_cm;
    o.panel_aspect = theme.panel_aspect;
    o.panel_width_given = theme.given.contains("panel_width_cm");
    o.panel_aspect_given = theme.given.contains("panel_aspect");
    o.theme = std::make_shared<const plot::theme>(theme);
    return o;
}

}  // namespace figures
