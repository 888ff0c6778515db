// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Part of the plot layer's renderer; not a public interface.

#include "plot/text.hpp"
#include "plot/theme.hpp"

#include <string>
#include <vector>

namespace plot {

/// A number for an SVG attribute: at most three decimals, no trailing zeros.
std::string svg_number(double v);

/// SVG <text> elements, one per text, at the places a LaTeX overlay would put them (the
/// same anchors and alignment), in the theme's fonts and colour: markup's italics and bold
/// as font styles, scripts as smaller <tspan>s moved up or down (stacked as the drawing
/// stacks them), prime marks as they are (their glyphs are raised already).
std::string svg_text_elements(const std::vector<placed_text>& texts, const theme& th);

}  // namespace plot
