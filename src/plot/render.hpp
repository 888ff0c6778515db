// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "plot/errors.hpp"
#include "plot/figure.hpp"
#include "plot/theme.hpp"

#include <cairo.h>

#include <optional>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace plot {

/// A page size in points (1/72 inch).
struct page_size {
    double width_pt = 0;   ///< width
    double height_pt = 0;  ///< height
};

/// What is wrong with the theme's text sizes, or "": a size (tick, label, legend, title)
/// below min_text_pt, or one whose superscripts and subscripts (script_metrics::size of it)
/// fall below min_script_pt. The message names the key, its value and what to do.
std::string text_size_problem(const theme& th);

/// One legend per figure: an entry that an earlier panel of `panels` (in the figure's order)
/// shows is left out of the later ones, the earlier taking the fuller label; every panel
/// keeps the entries of its own. Still figures and animations alike.
void one_legend(const std::vector<panel*>& panels);

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

/// Collects, while it lives, what the layout of the figures this thread draws leaves out
/// and why (a legend without room), one line each, once; the innermost collector of a
/// thread gets them.
class layout_notes {
public:
    /// Starts collecting this thread's notes.
    layout_notes();
    /// Hands collecting back to the collector it replaced.
    ~layout_notes();
    layout_notes(const layout_notes&) = delete;
    layout_notes& operator=(const layout_notes&) = delete;

    /// The lines noted so far, in order.
    const std::vector<std::string>& lines() const { return lines_; }

    /// Gives a line to this thread's innermost collector, if any (a line it has is not repeated).
    static void note(const std::string& line);

private:
    std::vector<std::string> lines_;
    layout_notes* outer_ = nullptr;
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

/// A figure as a file's drawing laid it out: the figure and theme drawn (alive while this
/// is), whether on pixels, and where its panels' axes landed.
struct drawing {
    const figure* fig = nullptr;        ///< the figure drawn
    const theme* th = nullptr;          ///< in this theme
    bool raster = false;                ///< on pixels (a curve sampled to half a pixel: legends may move)
    std::vector<panel_frame> frames;    ///< each panel's frame
};

/// panel_frames, taken from `drawn` where it laid out the same: a vector drawing of a figure
/// with the same content (same_content, after the theme's styles) at its figure_size in an
/// equal theme; else laid out as panel_frames does.
std::vector<panel_frame> panel_frames(const figure& fig, const theme& th, const drawing* drawn);

/// How many times this process has laid out a figure (each draw_figure), for tests: a
/// figure's words take the layout of the file being written instead of adding their own.
std::size_t figure_layouts();

/// The markers of one series as draw_figure places them, in points from the page's top left.
struct marker_centres_of {
    std::vector<std::pair<double, double>> centres;  ///< each drawn marker's centre
    double radius = 0;                                ///< the markers' radius
    bool spaced = false;                              ///< spaced 1.5 diameters apart (a method's markers)
};

/// Every panel's series' markers as draw_figure draws them at the figure's size: a method's
/// markers spaced at least 1.5 diameters apart on the page, measured data's every point.
std::vector<std::vector<marker_centres_of>> marker_centres(const figure& fig, const theme& th);

/// A glyph as stroked: a legend entry's sample, or a series in its panel.
struct glyph {
    std::string label;                           ///< the entry's label; a series' label in the figure given
    std::size_t panel = 0;                       ///< the panel drawn in (a legend band: the first)
    line_style line = line_style::none;          ///< the line stroked; none: no line
    double width_scale = 1.0;                    ///< its width in units of the theme's line width
    marker_style marker = marker_style::none;    ///< the marker drawn; none: no marker
    int color = 0;                               ///< palette index
    std::optional<rgb> rgb_color;                ///< a colour of its own
};

/// What draw_figure strokes of a figure's legends and series, glyph by glyph.
struct drawn_glyphs {
    std::vector<glyph> legend;  ///< every legend entry drawn, in the order drawn
    std::vector<glyph> series;  ///< every series drawn with a line or markers
};

/// The legend entries and series of a figure as draw_figure draws them with `th`.
drawn_glyphs glyphs_drawn(const figure& fig, const theme& th);

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

/// Each curve that `drawn` (a vector drawing of `fig`, in any theme) drew with a line, at
/// the vertices it drew, in data values (NaN between the pieces of a broken line): from the
/// curve's memo, so found with no evaluation, and the same whatever else drew the figure
/// before. Empty where `drawn` is a raster or of another figure.
std::unordered_map<const curve*, std::vector<std::pair<double, double>>> drawn_curve_values(const figure& fig,
                                                                                             const drawing& drawn);

}  // namespace plot
