// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Part of the plot layer's renderer; not a public interface.

#include "plot/geometry.hpp"
#include "plot/legend.hpp"
#include "plot/text.hpp"
#include "plot/theme.hpp"
#include "plot/ticks.hpp"

#include <optional>
#include <utility>
#include <vector>

namespace plot {

/// The ticks and limits of an axis: its fixed limits, or the data's with a margin.
tick_set axis_ticks(const axis& a, const std::vector<series>& data, bool horizontal);

/// Fewer ticks on an axis than it asks for, within fixed limits: how crowded labels thin out.
struct tick_limit {
    int max_ticks = 0;   // at most this many major ticks, if positive
    bool fixed = false;  // keep the axis at [lo, hi]
    double lo = 0;
    double hi = 0;
};

/// Everything needed to lay out one panel before it is drawn: ticks, the sizes of its
/// texts, margins, legend. Text sizes are of ink, so that gaps are the same on every side.
struct panel_plan {
    tick_set xt;
    tick_set yt;
    double tick_gap = 0;     // from the frame to the ink of the tick labels, on both axes
    double xtick_gap = 0;    // from the frame to the x tick labels: tick_gap and what y labels hang below it
    double label_gap = 0;   // from the tick labels' ink to the axis label's
    double digit_h = 0;     // ink height of a digit: y tick labels are centred on it
    double ytick_w = 0;     // widest y tick label (of every panel, once margins are shared)
    double own_ytick_w = 0;  // widest y tick label of this panel: its y label stands by them
    double ylabel_h = 0;    // ink height of the y label (its width on the page)
    double xtick_up = 0;    // highest x tick label ink above its baseline
    double xtick_down = 0;  // lowest x tick label ink below its baseline
    double xlabel_h = 0;    // ink height of the x label
    double left = 0;
    double bottom = 0;
    double top = 0;
    double right = 0;
    legend_layout legend;
    std::vector<double> xtick_extent;  // ink width of each x tick label
    std::vector<double> ytick_extent;  // ink height of each y tick label
    tick_limit x_limit;     // what the x locator was allowed
    tick_limit y_limit;     // what the y locator was allowed
};

/// The ink of the tallest line an overlay_label may be (digits, italics, a subscript,
/// parentheses): the line a drawing keeps for it (panel::overlay_line), the same in every frame.
text_ink overlay_line_ink(const text_engine& text, const theme& th);

/// Measures a panel's ticks, labels and legend; margins come from share_margins. The
/// limits, where given, allow fewer ticks than the axes ask for.
panel_plan plan_panel(const text_engine& text, const panel& p, const theme& th, const tick_limit& x_limit = {},
                      const tick_limit& y_limit = {});

/// Whether an axis's major tick labels, where the map puts them, stand apart by half the
/// tick font size; extents are their ink widths (x) or heights (y), one per major tick.
bool tick_labels_fit(const tick_set& t, const std::vector<double>& extents, const axis_map& m, double font_pt);

/// Gives every plan the largest text sizes among them and margins to fit, so that panels
/// drawn beside each other, or alone in files of their own, have the same frame (each y
/// label still stands by its own panel's tick labels, as TeX sets a label by its box).
/// Plans are of a grid with `cols` columns, row-major.
void share_margins(std::vector<panel_plan>& plans, const theme& th, int cols);

/// Fewer ticks where an axis's labels would touch in the cell its panel gets (a figure of a
/// fixed size, small panels, large text): each crowded axis is allowed one tick less, down
/// to two, and the margins are shared again, until every axis fits.
void thin_crowded_ticks(const text_engine& text, const std::vector<panel>& panels, std::vector<panel_plan>& plans,
                        const std::vector<rect>& cells, const theme& th, int cols);

/// Moves axis limits out, free ones and a plot kind's domain alike (all but a range the
/// user set, axis::exact_range), until every point of the data that sets them stands clear
/// of the frame in `cells`, in points, not a share of the range: a marker by its radius, a line by
/// its half width, each and the frame's half width by a gap of a point more, so that no
/// curve runs along a frame line and no marker is cut, at any size, dpi or format.
void keep_data_off_frame(const std::vector<panel>& panels, std::vector<panel_plan>& plans,
                         const std::vector<rect>& cells, const theme& th);

/// Where a panel's data lands: the axes rectangle, the maps, the series in device points.
struct panel_geometry {
    rect area;
    axis_map mx;
    axis_map my;
    std::vector<device_series> dev;
};

/// The maps from the panel's data to device points on the axes rectangle `area` (x, y).
std::pair<axis_map, axis_map> axis_maps(const panel& p, const panel_plan& plan, const rect& area);

/// Maps the panel's data into the axes rectangle `area`; curves are sampled to within
/// `tolerance` points where they pass within `reach` of the rectangle (sample_curve).
panel_geometry place_panel(const panel& p, const panel_plan& plan, const rect& area, double tolerance = 0.05,
                           double reach = 0);

/// The largest rectangle centred in `area` on which one data unit is as long on both axes.
rect equal_aspect_area(const rect& area, const panel_plan& plan);

/// The axes rectangle of a cell, inside the plan's margins.
rect axes_area(const panel_plan& plan, const rect& cell);

/// The panel's axes rectangle in its cell: axes_area, narrowed to equal_aspect_area where
/// the panel asks for one.
rect panel_area(const panel& p, const panel_plan& plan, const rect& cell);

/// The first candidate spot for the legend inside the axes that covers no data, if any.
std::optional<rect> legend_inside(const panel& p, const legend_layout& lg, const panel_geometry& g,
                                  const theme& th);

}  // namespace plot
