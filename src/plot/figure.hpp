// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <utility>
#include <string>
#include <unordered_map>
#include <vector>

namespace plot {

/// An RGB colour with components in [0, 1].
struct rgb {
    double r = 0;  ///< red
    double g = 0;  ///< green
    double b = 0;  ///< blue

    /// Every component equal.
    bool operator==(const rgb&) const = default;
};

/// A text of a figure in the two forms its writers need: Pango markup to draw, and the
/// LaTeX that a LaTeX overlay (pdf_tex, eps_tex) sets in its place. A label made by the
/// program is markup alone, its LaTeX derived from it when an overlay is written; a label
/// from a spec (plot::tex_label) carries the LaTeX made from its TeX by the same parse.
struct label {
    std::string markup;  ///< Pango markup
    std::string latex;   ///< LaTeX for overlays; empty: derived from the markup

    label() = default;
    /// A label made by the program, as markup.
    label(std::string m) : markup(std::move(m)) {}  // NOLINT: implicit, markup is a label
    /// A label made by the program, as markup.
    label(const char* m) : markup(m) {}  // NOLINT: implicit, markup is a label
    /// True when there is nothing to show.
    bool empty() const { return markup.empty(); }
    /// Empties both forms.
    void clear() {
        markup.clear();
        latex.clear();
    }
    /// Both forms equal.
    bool operator==(const label&) const = default;
};

/// How a series' line is drawn.
enum class line_style { none, solid, dashed, dotted, dash_dot, dash_dot_dot };

/// How a series' points are marked.
enum class marker_style { none, open_circle, filled_circle, filled_square, filled_triangle, filled_diamond };

/// A series' error bars: distances below and above each point (>= 0), per point or empty
/// for none; each vector is empty or as long as the series' x.
struct error_bars {
    std::vector<double> x_lower{};  ///< to the left of each point
    std::vector<double> x_upper{};  ///< to the right
    std::vector<double> y_lower{};  ///< below each point
    std::vector<double> y_upper{};  ///< above

    /// True when no point has a bar.
    bool empty() const { return x_lower.empty() && x_upper.empty() && y_lower.empty() && y_upper.empty(); }
    /// Every bar equal.
    bool operator==(const error_bars&) const = default;
};

/// The ends of point i's bars along x (horizontal) or y: [v - lower, v + upper].
std::pair<double, double> error_span(const std::vector<double>& v, const std::vector<double>& lower,
                                     const std::vector<double>& upper, std::size_t i);

/// A hash of a curve's parameter: its bits, mixed (std::hash<double> hashes them byte by
/// byte, a tenth of a sampling's work); 0 and -0, equal, hash alike.
struct parameter_hash {
    std::size_t operator()(double u) const noexcept {
        std::uint64_t b = u == 0 ? 0 : std::bit_cast<std::uint64_t>(u);
        b ^= b >> 33;
        b *= 0xff51afd7ed558ccdULL;
        b ^= b >> 33;
        return static_cast<std::size_t>(b);
    }
};

/// A curve's values at the parameters evaluated.
using curve_values = std::unordered_map<double, std::pair<double, double>, parameter_hash>;

/// A curve given by a function: the points (x(u), y(u)) for u from u0 to u1, a line
/// wherever both are finite (a non-finite value breaks it). The plot layer samples it when
/// it draws, as finely as the device needs for the line to stay within a twentieth of a
/// point of the curve (a 160th on vector surfaces, which viewers zoom).
struct curve {
    double u0 = 0;  ///< first parameter
    double u1 = 1;  ///< last parameter
    std::function<std::pair<double, double>(double)> at{};  ///< (x, y) at a parameter
    int pieces = 32;  ///< the first, even subdivision: fine enough to see every wiggle

    /// The plot layer's memo of its last few samplings: an animation draws the same curve
    /// in every frame (on axes that may be tried with and without a legend above them),
    /// and figures are written to several files at once.
    struct memo {
        struct sampling {
            std::vector<double> key;
            std::vector<double> x;
            std::vector<double> y;
            std::vector<double> u;
        };
        std::mutex lock;
        std::vector<sampling> last;  ///< the most recent last
        /// The curve at each parameter evaluated, up to a bound: a sampling for another
        /// tolerance (the PNG and the PDF of one figure) evaluates the function at the
        /// same parameters again, and functions may be costly (an error in MPFR).
        curve_values values;
    };
    std::shared_ptr<memo> last = std::make_shared<memo>();  ///< see memo
};

/// The curve y = f(x) for x from x0 to x1.
std::shared_ptr<const curve> function_curve(double x0, double x1, std::function<double(double)> f);

/// The curve (x(u), y(u)) for u from u0 to u1, first cut into `pieces`.
std::shared_ptr<const curve> parametric_curve(double u0, double u1, std::function<std::pair<double, double>(double)> at,
                                              int pieces = 32);

/// One curve or set of points, with its legend entry.
struct series {
    // Every member has an initializer, so that an aggregate initialization may name only
    // some (-Wmissing-field-initializers).
    plot::label label{};                    ///< legend text; empty: no entry
    /// A name for the series' data that stays the same when its label changes: unique in its
    /// panel, of [A-Za-z0-9_:.-] only ("exact", "order:6", "theta0:2", "line:1"); empty: none yet.
    std::string id{};
    std::vector<double> x{};                ///< abscissae
    std::vector<double> y{};                ///< ordinates; non-finite values break the line
    /// When set, the line is drawn from this function rather than through the points,
    /// which are then its markers and the samples that set the axis limits and place the
    /// legend (they should lie on the curve).
    std::shared_ptr<const plot::curve> curve{};
    line_style line = line_style::solid;    ///< line style
    marker_style marker = marker_style::none;  ///< marker
    int color = 0;                          ///< index into the theme's palette
    std::optional<rgb> rgb_color{};         ///< a colour of its own, in place of the palette's
    bool autoscale = true;                  ///< false: leaves the axis limits alone (reference lines)
    bool sets_limits = true;                ///< false: data that leaves the axis limits alone and is clipped
    std::string style_key{};                ///< a theme's style for this name replaces line and marker
    /// The theme's style sets only a drawn line (not "none") and leaves the marker alone: a
    /// pendulum's rod, drawn as its method's line is drawn.
    bool style_line_only = false;
    double marker_scale = 1.0;              ///< marker radius in units of the theme's
    double width_scale = 1.0;               ///< line width in units of the theme's
    double alpha = 1.0;                     ///< opacity, 0 (invisible) to 1
    bool overlay = false;                   ///< moves from frame to frame: drawn in the overlay pass
    plot::error_bars errors{};              ///< error bars with caps, in the series' colour
    /// Measured data: its place among its panel's data series (0, 1, ...), which picks its
    /// marker and colour from the theme's data_markers and data_palette; -1 for other series.
    int data_slot = -1;

    /// Every member equal, a curve by being the same curve (and a NaN unequal to itself).
    bool operator==(const series&) const = default;
};

/// Axis scale.
enum class scale { linear, log };

/// Tick locator of an axis.
enum class tick_kind { nice, multiples_of_pi, degrees };

/// One axis: label, range, scale and ticks.
struct axis {
    plot::label label;                  ///< axis label
    std::optional<double> min;          ///< lower limit; from the data when empty
    std::optional<double> max;          ///< upper limit; from the data when empty
    scale kind = scale::linear;         ///< linear or logarithmic
    tick_kind ticks = tick_kind::nice;  ///< tick locator
    int max_ticks = 6;                  ///< at most this many major ticks
    double margin = 0.04;               ///< fraction of the data range added to free limits
    bool round_limits = false;          ///< move free limits out to the enclosing ticks
    /// min and max are a range the user set (a spec's y_range): kept exactly, the data
    /// beyond them clipped. Otherwise a limit given is the data's domain (a plot kind's
    /// [0, pi] of amplitudes), moved out as a free one is until no marker sits on the frame.
    bool exact_range = false;
    /// The paper's range, kept exactly in the paper's files (--paper-files) in place of min
    /// and max; unset: they draw the axis as every other file does.
    std::optional<std::pair<double, double>> paper_range;

    /// Every member equal.
    bool operator==(const axis&) const = default;
};

/// Where a legend goes: automatic picks a spot inside the axes free of data, else a band
/// above the plot; inside takes such a spot or shows no legend (the frame never moves).
enum class legend_place { automatic, inside, none };

/// One plotting area with its axes, series and legend.
struct panel {
    axis x;                               ///< horizontal axis
    axis y;                               ///< vertical axis
    std::vector<series> data;             ///< series, drawn in order
    plot::label label;                    ///< panel label such as "(a)"; empty for none
    legend_place legend = legend_place::automatic;  ///< legend placement
    bool frameless = false;               ///< no frame, ticks or axis labels (a drawing, not a plot)
    bool equal_aspect = false;            ///< one unit is as long on both axes
    plot::label overlay_label;            ///< text that changes per frame (a clock), top left inside, overlay pass
    /// A drawing (frameless) keeps a line above it for overlay_label, beside its label, in
    /// every frame alike: the text never covers the drawing, whatever its size.
    bool overlay_line = false;

    /// Every member equal.
    bool operator==(const panel&) const = default;
};

/// A figure in words, plain text, for readers who cannot see it.
struct figure_words {
    std::string alt;          ///< what it shows in a sentence or two: the SVG's <title> and PDF's Title where there is no title
    std::string description;  ///< what it shows at length: the SVG's <desc> and the PDF's Subject
};

struct drawing;

/// A grid of panels with a physical size.
struct figure {
    int rows = 1;                  ///< grid rows
    int cols = 1;                  ///< grid columns
    double panel_width_cm = 6.0;   ///< width of one panel (paper theme)
    double panel_aspect = 0.75;    ///< panel height / width (paper theme)
    std::vector<panel> panels;     ///< row-major, rows * cols at most
    bool shared_legend = false;    ///< one legend, in the first panel with room inside the axes
    std::vector<panel> peers;      ///< panels drawn alone in other files of this size (one panel each) whose frames these must match
    int place_in_set = 0;          ///< with peers: where this figure's one panel stands among them (0: first)
    plot::label title;             ///< drawn centred above the panels (theme's title_font_pt; 0 hides it)
    /// The figure in words, made when a file that holds them (SVG, PDF) is first written:
    /// finding them costs as much as building the figure. Given the drawing of the file
    /// (render.hpp), they may take its layout in place of laying the figure out again; given
    /// null, they lay it out themselves. Empty: none.
    std::function<figure_words(const drawing*)> words;
};

/// Whether two figures hold the same things to draw: every member but their words.
bool same_content(const figure& a, const figure& b);

/// Escapes text for use inside Pango markup (&, <, >, quotes).
std::string escape_markup(const std::string& text);

}  // namespace plot
