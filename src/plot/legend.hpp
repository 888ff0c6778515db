// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Part of the plot layer's renderer; not a public interface.

#include "plot/geometry.hpp"
#include "plot/render.hpp"
#include "plot/text.hpp"
#include "plot/theme.hpp"

#include <cairo.h>

#include <cstddef>
#include <vector>

namespace plot {

/// Legend geometry: box size and the height of one entry.
struct legend_layout {
    std::vector<std::size_t> entries;  // indices of series with a label
    std::vector<double> text_ws;       // width of each entry's text
    double sample_w = 0;
    double text_w = 0;
    double row_h = 0;
    double w = 0;
    double h = 0;
};

/// How much of the data a box would cover: segments and markers that touch it.
int overlap(const rect& box, const std::vector<series>& data, const std::vector<device_series>& dev,
            double marker_radius);

/// The legend's entries (series with a label) and its size at the theme's legend font.
legend_layout measure_legend(const text_engine& text, const panel& p, const theme& th);

/// True if two series make one legend entry: the same glyph (colour, line, marker, style
/// key) and one label, the second maybe said more fully ("E = 1.6" and "E = 1.6, libration").
bool same_legend_entry(const series& a, const series& b);

/// Where draw_legend_sample and the series' strokes are logged (glyphs_drawn), or null;
/// `at` the panel being drawn.
struct glyph_log {
    drawn_glyphs* out = nullptr;
    std::size_t at = 0;
    const panel* given = nullptr;  // the panel being drawn as the figure gave it (its labels)
};
glyph_log& current_glyph_log();

/// Draws a series' line and marker sample of width w centred at height y.
void draw_legend_sample(cairo_t* cr, const theme& th, const series& s, double x, double y, double w);

/// Draws the legend entries in a column inside box (no frame: the box is free of data).
void draw_legend(cairo_t* cr, const text_engine& text, const theme& th, const panel& p,
                 const legend_layout& l, const rect& box);

/// Entries laid out side by side in lines no wider than max_w: the legend placed outside
/// the axes, when no spot inside is free of data.
std::vector<std::vector<std::size_t>> legend_lines(const legend_layout& l, const theme& th, double max_w);

/// Height of the band that legend_lines need.
double legend_band_height(const legend_layout& l, const theme& th, double max_w);

/// Draws the entries in centred lines filling the band.
void draw_legend_band(cairo_t* cr, const text_engine& text, const theme& th, const panel& p,
                      const legend_layout& l, const rect& band);

}  // namespace plot
