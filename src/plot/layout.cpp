#include "plot/layout.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace plot {

tick_set axis_ticks(const axis& a, const std::vector<series>& data, bool horizontal) {
    double lo = std::numeric_limits<double>::infinity();
    double hi = -lo;
    for (const auto& s : data) {
        if (!s.autoscale) continue;
        const auto& v = horizontal ? s.x : s.y;
        for (double d : v) {
            if (!std::isfinite(d) || (a.kind == scale::log && !(d > 0))) continue;
            lo = std::min(lo, d);
            hi = std::max(hi, d);
        }
    }
    if (!std::isfinite(lo) || !std::isfinite(hi)) {
        lo = a.kind == scale::log ? 0.1 : 0.0;
        hi = 1.0;
    }
    // Data-driven limits get a margin so that no curve runs along the frame.
    if (a.kind == scale::linear && (!a.min || !a.max)) {
        const double margin = a.margin * (hi - lo);
        if (!a.min) lo -= margin;
        if (!a.max) hi += margin;
    }
    if (a.min) lo = *a.min;
    if (a.max) hi = *a.max;
    const bool expand = a.round_limits && !(a.min && a.max);
    tick_set t;
    if (a.kind == scale::log) {
        t = log_ticks(lo, hi, a.max_ticks, expand);
    } else if (a.ticks == tick_kind::multiples_of_pi) {
        t = pi_ticks(lo, hi, a.max_ticks, expand);
    } else if (a.ticks == tick_kind::degrees) {
        t = degree_ticks(lo, hi, a.max_ticks, expand);
    } else {
        t = linear_ticks(lo, hi, a.max_ticks, expand);
    }
    // A fixed limit stays where it was asked, even if expanding moved the other one.
    if (a.min) t.lo = *a.min;
    if (a.max) t.hi = *a.max;
    return t;
}

panel_plan plan_panel(const text_engine& text, const panel& p, const theme& th) {
    panel_plan plan;
    plan.xt = axis_ticks(p.x, p.data, true);
    plan.yt = axis_ticks(p.y, p.data, false);
    const double pad = th.padding_pt;
    double ytick_w = 0;
    double tick_h = 0;
    for (const auto& l : plan.yt.labels) {
        const auto [w, h] = text.measure(l, th.tick_font_pt);
        ytick_w = std::max(ytick_w, w);
        tick_h = std::max(tick_h, h);
    }
    double last_xtick_w = 0;
    for (const auto& l : plan.xt.labels) {
        const auto [w, h] = text.measure(l, th.tick_font_pt);
        tick_h = std::max(tick_h, h);
        last_xtick_w = w;
    }
    const double label_h = text.measure("Xg", th.label_font_pt).second;
    plan.left = pad + (p.y.label.empty() ? 0 : label_h + 0.5 * pad) + ytick_w + 0.6 * pad;
    plan.tick_h = tick_h;
    plan.bottom = pad + (p.x.label.empty() ? 0 : label_h + 0.3 * pad) + tick_h + x_tick_gap(tick_h);
    plan.top = pad + std::max(0.5 * tick_h, p.label.empty() ? 0.0 : label_h);
    plan.right = pad + 0.5 * last_xtick_w;
    plan.legend = measure_legend(text, p, th);
    return plan;
}

panel_geometry place_panel(const panel& p, const panel_plan& plan, const rect& area) {
    panel_geometry g;
    g.area = area;
    g.mx = axis_map{plan.xt.lo, plan.xt.hi, p.x.kind == scale::log, area.x, area.x + area.w};
    g.my = axis_map{plan.yt.lo, plan.yt.hi, p.y.kind == scale::log, area.y + area.h, area.y};
    for (const auto& s : p.data) g.dev.push_back(to_device(s, g.mx, g.my));
    return g;
}

rect axes_area(const panel_plan& plan, const rect& cell) {
    return {cell.x + plan.left, cell.y + plan.top, cell.w - plan.left - plan.right, cell.h - plan.top - plan.bottom};
}

std::optional<rect> legend_inside(const panel& p, const legend_layout& lg, const panel_geometry& g,
                                  const theme& th) {
    if (lg.entries.empty()) return std::nullopt;
    const rect& area = g.area;
    const double inset = 0.8 * th.padding_pt;
    if (lg.w >= area.w - 2 * inset || lg.h >= area.h - 2 * inset) return std::nullopt;
    const double left = area.x + inset;
    const double right = area.x + area.w - inset - lg.w;
    const double middle = area.x + 0.5 * (area.w - lg.w);
    const double top = area.y + inset;
    const double bottom = area.y + area.h - inset - lg.h;
    const double centre = area.y + 0.5 * (area.h - lg.h);
    const std::pair<double, double> spots[] = {{right, top},   {left, top},   {right, bottom}, {left, bottom},
                                               {middle, top},  {middle, bottom}, {right, centre}, {left, centre}};
    for (const auto& [x, y] : spots) {
        const rect box{x, y, lg.w, lg.h};
        if (overlap(box, p.data, g.dev, th.marker_radius_pt) == 0) return box;
    }
    return std::nullopt;
}

}  // namespace plot
