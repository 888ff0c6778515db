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

    /// Both equal.
    bool operator==(const named_style&) const = default;
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

/// The sizes of a figure's three kinds of text, in points.
struct text_sizes {
    double tick_pt = 0;    ///< tick labels
    double label_pt = 0;   ///< axis and panel labels
    double legend_pt = 0;  ///< legend entries

    /// All three equal.
    bool operator==(const text_sizes&) const = default;
};

/// How figures look: fonts, sizes in points, line widths, colours, sizes. Built-in themes
/// and users' themes are style files (see figures/themes.hpp); the defaults here are the
/// paper theme's before its journal minimum (paper.toml sets min_text_pt and larger text).
struct theme {
    std::string name;                 ///< theme name
    std::string font_family;          ///< Pango font families, the first preferred, comma-separated
    double tick_font_pt = 7.5;        ///< tick labels
    double label_font_pt = 8.5;       ///< axis labels and panel labels
    double legend_font_pt = 7.0;      ///< legend entries
    double title_font_pt = 9.5;       ///< a figure's title; 0 draws none
    /// The smallest text at final size (a journal's minimum lettering, 8 pt); 0: no minimum.
    double min_text_pt = 0;
    /// The smallest superscript or subscript at final size (6 pt); 0: no minimum.
    double min_script_pt = 0;
    /// The thinnest line at final size (a journal's minimum line weight, 0.5 pt): every stroke
    /// (series, markers' outlines, error bars, frame, ticks) is drawn at least this wide; 0: no minimum.
    double min_line_pt = 0;
    /// The largest LaTeX document size (--tex-font-size) whose overlays show what the PDF
    /// shows: the layout decides which tick labels and legends a figure keeps at the largest
    /// text of either (decided_sizes); 0: each route decides at its own sizes.
    double tex_agree_pt = 0;
    /// The sizes a theme made for a LaTeX overlay decides its contents at (those of the theme
    /// it was made from); unset: decided_sizes of this theme's own.
    std::optional<text_sizes> decided_at;
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

    /// Every member equal: the same look, and the same layout of any figure.
    bool operator==(const theme&) const = default;
};

/// True if the first family of a comma-separated `font_family` is installed where figures
/// look for fonts: Pango, through fontconfig, resolves it to that very family.
bool font_family_installed(const std::string& font_family);

}  // namespace plot
