#pragma once
// Part of the plot layer's renderer; not a public interface.

#include "plot/geometry.hpp"
#include "plot/legend.hpp"
#include "plot/text.hpp"
#include "plot/theme.hpp"
#include "plot/ticks.hpp"

#include <optional>
#include <vector>

namespace plot {

/// The ticks and limits of an axis: its fixed limits, or the data's with a margin.
tick_set axis_ticks(const axis& a, const std::vector<series>& data, bool horizontal);

/// Space between the axis and the x tick labels: at least half a label's height, so the
/// lowest y tick label, centred on the bottom edge, never meets the first x tick label.
inline double x_tick_gap(double tick_h) { return 0.5 * tick_h + 0.5; }

/// Everything needed to lay out one panel before it is drawn: ticks, margins, legend.
struct panel_plan {
    double tick_h = 0;
    tick_set xt;
    tick_set yt;
    double left = 0;
    double bottom = 0;
    double top = 0;
    double right = 0;
    legend_layout legend;
};

/// Measures a panel's ticks, labels and legend and the margins they need.
panel_plan plan_panel(const text_engine& text, const panel& p, const theme& th);

/// Where a panel's data lands: the axes rectangle, the maps, the series in device points.
struct panel_geometry {
    rect area;
    axis_map mx;
    axis_map my;
    std::vector<device_series> dev;
};

/// Maps the panel's data into the axes rectangle `area`.
panel_geometry place_panel(const panel& p, const panel_plan& plan, const rect& area);

/// The axes rectangle of a cell, inside the plan's margins.
rect axes_area(const panel_plan& plan, const rect& cell);

/// The first candidate spot for the legend inside the axes that covers no data, if any.
std::optional<rect> legend_inside(const panel& p, const legend_layout& lg, const panel_geometry& g,
                                  const theme& th);

}  // namespace plot
