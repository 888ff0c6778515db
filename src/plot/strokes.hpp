#pragma once
// Part of the plot layer's renderer; not a public interface.

#include "plot/geometry.hpp"
#include "plot/theme.hpp"

#include <cairo.h>

namespace plot {

/// Sets the theme's foreground colour (frame, ticks, text).
void set_foreground(cairo_t* cr, const theme& th);

/// Sets the palette colour of a series.
void set_color(cairo_t* cr, const theme& th, int index);

/// Sets width, dash pattern and caps of a line style.
void set_line_style(cairo_t* cr, const theme& th, line_style style);

/// Strokes the polyline clipped to `clip`, each visible run simplified.
void stroke_polyline(cairo_t* cr, const device_series& d, const rect& clip);

/// Draws open circles at the points within `area` (grown by the marker radius).
void draw_markers(cairo_t* cr, const theme& th, const device_series& d, const rect& area);

}  // namespace plot
