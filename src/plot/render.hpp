// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "plot/errors.hpp"
#include "plot/figure.hpp"
#include "plot/theme.hpp"

#include <cairo.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace plot {

/// A page size in points (1/72 inch).
struct page_size {
    double width_pt = 0;   ///< width
    double height_pt = 0;  ///< height
};

/// The size of a figure drawn with a theme: the theme's fixed size, or the panels' size.
page_size figure_size(const figure& fig, const theme& th);

/// What draw_figure draws: everything, what stays the same in every frame of an
/// animation (no overlay series or labels), or only what moves (on top of the former).
enum class draw_pass { all, still, overlay };

struct placed_text;

/// Where a panel's axes landed on the page, in points from the top left, and their limits.
struct panel_frame {
    double x = 0;          ///< left edge of the axes
    double y = 0;          ///< top edge of the axes
    double w = 0;          ///< width
    double h = 0;          ///< height
    double x_lo = 0;       ///< x at the left edge
    double x_hi = 1;       ///< x at the right edge
    double y_lo = 0;       ///< y at the bottom edge
    double y_hi = 1;       ///< y at the top edge
    bool frameless = false;  ///< a drawing without axes
    std::vector<std::string> x_labels;  ///< the x axis' major tick labels as drawn (markup)
    std::vector<std::string> y_labels;  ///< the y axis' major tick labels as drawn (markup)
};

/// A figure that cannot be laid out as asked: its size leaves axes too small to read.
class layout_error : public bad_input {
public:
    using bad_input::bad_input;
};

/// Draws the figure on cr, whose user units are points, filling [0, w] x [0, h]; with
/// `texts`, every text is recorded there (for a LaTeX overlay) instead of drawn. A vector
/// page (`vector`) is painted with the background only if the theme asks for it: a
/// transparent page covers nothing it is placed over (a neighbouring panel's text).
/// Throws std::runtime_error if the theme's font is not installed, layout_error if a panel's
/// axes would be smaller than three times the tick font size either way.
/// With `frames`, each panel's frame is recorded there.
void draw_figure(cairo_t* cr, const figure& fig, const theme& th, page_size size, draw_pass pass = draw_pass::all,
                 std::vector<placed_text>* texts = nullptr, bool vector = false,
                 std::vector<panel_frame>* frames = nullptr);

/// A data series (data_slot >= 0) in the theme's data style: its marker and colour (a
/// colour of its own stays).
void apply_data_style(series& s, const theme& th);

/// The figure with the theme's named styles applied to the series that carry a style key,
/// and its data styles to the data series, as draw_figure draws it.
figure with_theme_styles(const figure& fig, const theme& th);

/// The frames of the figure's panels as draw_figure lays them out at the figure's size.
std::vector<panel_frame> panel_frames(const figure& fig, const theme& th);

/// One series as a raster draws it, in data values: a sampled curve's vertices (NaN
/// between the pieces of a broken line), or the points of any other series.
struct drawn_points {
    std::vector<double> x;  ///< abscissae
    std::vector<double> y;  ///< ordinates
    bool sampled = false;   ///< the vertices of a curve, sampled as a raster at the dpi draws it
};

/// Every panel's series as a raster of the figure at `dpi` draws them (the theme's named
/// styles applied): a curve drawn with a line is sampled as draw_figure samples it, within
/// 0.05 pt; the panels' frames go to `frames`.
std::vector<std::vector<drawn_points>> drawn_data(const figure& fig, const theme& th, double dpi,
                                                  std::vector<panel_frame>& frames);

}  // namespace plot
