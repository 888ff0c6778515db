// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Words for a figure, for readers who cannot see it: alt text and a longer description,
// made from the spec and the figure's data.

#include "figures/build_options.hpp"
#include "figures/catalog.hpp"
#include "plot/figure.hpp"
#include "plot/render.hpp"

#include <string>

namespace figures {

/// What a figure shows, in plain text.
struct figure_description {
    std::string alt;   ///< one or two sentences: what is plotted against what (an img's alt)
    std::string text;  ///< a paragraph per panel: axes and their ranges, series, what to notice
};

/// How far a curve must be from the exact one to be seen apart: this fraction of the y axis.
inline constexpr double visible_fraction = 0.01;

/// Describes a built figure of `e` (as build(e, options) makes it): each panel's axes and
/// the ranges of its data, its series and how they are drawn, where each approximation
/// leaves the exact curve by more than visible_fraction of the axis, and where the curves
/// cross the spec's reference lines. The axes' limits are those the paper theme lays out:
/// taken from `drawn` where it laid out the same (plot::panel_frames), else laid out here.
figure_description describe(const entry& e, const plot::figure& built, const build_options& options = {},
                            const plot::drawing* drawn = nullptr);

/// describe for a spec of its own (the figure's one-line description being the spec's
/// description, or its title).
figure_description describe(const figure_spec& spec, const plot::figure& built, const build_options& options = {},
                            const plot::drawing* drawn = nullptr);

}  // namespace figures
