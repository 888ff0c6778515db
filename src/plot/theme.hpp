// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "plot/figure.hpp"

#include <map>
#include <set>
#include <optional>
#include <string>
#include <vector>

namespace plot {

/// A style a theme gives to series of one name (figures name them by method).
struct named_style {
    std::optional<line_style> line;      ///< line style
    std::optional<marker_style> marker;  ///< marker
};

/// How an SVG holds its text.
enum class svg_text_mode {
    path,  ///< outlines of the glyphs: looks the same everywhere, cannot be selected or searched
    text,  ///< <text> elements in the theme's fonts: selectable, searchable, smaller
};

/// What an SVG's width and height are in.
enum class svg_size_unit {
    pt,       ///< points, the figure's size on paper
    px,       ///< CSS pixels (96 to the inch), the same size on a screen
    viewbox,  ///< none, only a viewBox: the figure fills the width the page gives it
};

/// How figures look: fonts, sizes in points, line widths, colours, sizes. Built-in themes
/// and users' themes are style files (see figures/themes.hpp); the defaults here are the
/// paper theme's.
struct theme {
    std::string name;                 ///< theme name
    std::string font_family;          ///< Pango font families, the first preferred, comma-separated
    double tick_font_pt = 7.5;        ///< tick labels
    double label_font_pt = 8.5;       ///< axis labels and panel labels
    double legend_font_pt = 7.0;      ///< legend entries
    double title_font_pt = 9.5;       ///< a figure's title; 0 draws none
    double line_width_pt = 0.8;       ///< series lines
    double frame_width_pt = 0.5;      ///< axes frame and ticks
    double marker_radius_pt = 1.6;    ///< open circles
    double tick_length_pt = 3.0;      ///< major ticks (minor: 60 %)
    double padding_pt = 3.0;          ///< space around text
    rgb foreground{0, 0, 0};          ///< frame, ticks and text
    rgb background{1, 1, 1};          ///< the page
    bool opaque_vector_background = false;  ///< PDF, SVG and EPS paint the background too (PNG and GIF always do)
    std::vector<rgb> palette;         ///< series colours by index
    std::map<std::string, named_style> styles;  ///< styles of named series (style_key)
    /// Markers of measured data series, in turn (distinct from the methods' circles).
    std::vector<marker_style> data_markers{marker_style::filled_square, marker_style::filled_triangle,
                                           marker_style::filled_diamond};
    std::vector<rgb> data_palette{{0, 0, 0}};  ///< colours of measured data series, in turn
    double panel_width_cm = 6.0;      ///< width of one panel, where the figure sets none
    double panel_aspect = 0.75;       ///< panel height / width, where the figure sets none
    double fixed_width_cm = 0;        ///< whole-figure width, or 0 to size by panels
    double fixed_height_cm = 0;       ///< whole-figure height, or 0 to size by panels
    double dpi = 300;                 ///< PNG resolution where none is asked for
    int width_px = 0;                 ///< a raster size asked for in pixels (size_px), or 0
    int height_px = 0;                ///< a raster size asked for in pixels (size_px), or 0
    svg_text_mode svg_text = svg_text_mode::path;  ///< how an SVG holds its text
    svg_size_unit svg_size = svg_size_unit::pt;    ///< what an SVG's width and height are in
    std::set<std::string> given;      ///< keys a user's style file or the command line set: they win over a figure's own
};

/// True if the first family of a comma-separated `font_family` is installed where figures
/// look for fonts: Pango, through fontconfig, resolves it to that very family.
bool font_family_installed(const std::string& font_family);

}  // namespace plot
