// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Part of the plot layer's renderer; not a public interface.

#include "plot/geometry.hpp"
#include "plot/theme.hpp"

#include <cairo.h>

namespace plot {

/// Sets the theme's foreground colour (frame, ticks, text).
void set_foreground(cairo_t* cr, const theme& th);

/// Sets a series' colour: its own, or the palette's at its index.
void set_color(cairo_t* cr, const theme& th, const series& s);

/// A stroke's width at final size: `width`, or the theme's min_line_pt where that is wider.
double line_width(const theme& th, double width);

/// Sets width, dash pattern and caps of a line style.
void set_line_style(cairo_t* cr, const theme& th, line_style style, double width_scale = 1.0);

/// Strokes the series' line clipped to `clip`: a sampled curve as it is, a polyline through
/// points with each visible run simplified.
void stroke_polyline(cairo_t* cr, const device_series& d, const rect& clip);

/// Draws the series' markers at the points within `area` (grown by the marker radius).
void draw_markers(cairo_t* cr, const theme& th, const series& s, const device_series& d, const rect& area);

/// True for the markers drawn filled.
bool filled(marker_style m);

/// Half the width of an error bar's cap: the marker's radius, so that the cap is as wide as
/// the marker.
double cap_half_width(const theme& th, const series& s);

/// Strokes the error bars with their caps in the current colour, at the theme's line width.
void draw_error_bars(cairo_t* cr, const theme& th, const series& s, const std::vector<device_bar>& bars);

}  // namespace plot
