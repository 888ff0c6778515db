// SPDX-License-Identifier: GPL-3.0-or-later
#include "plot/layout.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <tuple>
#include <utility>

namespace plot {

namespace {

/// Calls f with each value of the series along an axis, and with the ends of its error bars:
/// the bars count in the axis limits as the points do.
template <class F>
void for_each_reach(const series& s, bool horizontal, F f) {
    const auto& v = horizontal ? s.x : s.y;
    for (double d : v) f(d);
    const auto& lower = horizontal ? s.errors.x_lower : s.errors.y_lower;
    const auto& upper = horizontal ? s.errors.x_upper : s.errors.y_upper;
    if (lower.empty() && upper.empty()) return;
    for (std::size_t i = 0; i < v.size(); ++i) {
        const auto [lo, hi] = error_span(v, lower, upper, i);
        f(lo);
        f(hi);
    }
}

}  // namespace

namespace {

/// The extremes of the data that set an axis's limits (error bars too), or the default
/// range where there are none.
std::pair<double, double> data_range(const axis& a, const std::vector<series>& data, bool horizontal) {
    double lo = std::numeric_limits<double>::infinity();
    double hi = -lo;
    for (const auto& s : data) {
        if (!s.autoscale || !s.sets_limits) continue;
        for_each_reach(s, horizontal, [&](double d) {
            if (!std::isfinite(d) || (a.kind == scale::log && !(d > 0))) return;
            lo = std::min(lo, d);
            hi = std::max(hi, d);
        });
    }
    if (!std::isfinite(lo) || !std::isfinite(hi)) return {a.kind == scale::log ? 0.1 : 0.0, 1.0};
    return {lo, hi};
}

/// The axis's locator on [lo, hi].
tick_set locate(const axis& a, double lo, double hi, bool expand) {
    if (a.kind == scale::log) return log_ticks(lo, hi, a.max_ticks, expand);
    if (a.ticks == tick_kind::multiples_of_pi) return pi_ticks(lo, hi, a.max_ticks, expand);
    if (a.ticks == tick_kind::degrees) return degree_ticks(lo, hi, a.max_ticks, expand);
    return linear_ticks(lo, hi, a.max_ticks, expand);
}

}  // namespace

tick_set axis_ticks(const axis& a, const std::vector<series>& data, bool horizontal) {
    auto [lo, hi] = data_range(a, data, horizontal);
    // Data-driven limits get a margin so that no curve runs along the frame.
    // Limits rounded out to the enclosing ticks need none: a margin would push them a
    // whole tick further when the data end just short of one (an amplitude of pi - 1e-6).
    if (a.kind == scale::linear && (!a.min || !a.max) && !a.round_limits) {
        const double margin = a.margin * (hi - lo);
        if (!a.min) lo -= margin;
        if (!a.max) hi += margin;
    }
    if (a.min) lo = *a.min;
    if (a.max) hi = *a.max;
    tick_set t = locate(a, lo, hi, a.round_limits && !(a.min && a.max));
    // A fixed limit stays where it was asked, even if expanding moved the other one.
    if (a.min) t.lo = *a.min;
    if (a.max) t.hi = *a.max;
    return t;
}

panel_plan plan_panel(const text_engine& text, const panel& p, const theme& th, const tick_limit& x_limit,
                      const tick_limit& y_limit) {
    panel_plan plan;
    const auto limited = [](axis a, const tick_limit& limit) {
        if (limit.max_ticks > 0) a.max_ticks = std::min(a.max_ticks, limit.max_ticks);
        if (limit.fixed) {
            a.min = limit.lo;
            a.max = limit.hi;
        }
        return a;
    };
    const axis x = limited(p.x, x_limit);
    const axis y = limited(p.y, y_limit);
    plan.x_limit = x_limit;
    plan.y_limit = y_limit;
    plan.xt = axis_ticks(x, p.data, true);
    plan.yt = axis_ticks(y, p.data, false);
    const text_ink digit = text.ink("0", th.tick_font_pt);
    plan.digit_h = digit.h;
    // Half a digit and a little: the lowest y tick label, centred on the bottom edge, then
    // clears the first x tick label at the same distance from the frame.
    plan.tick_gap = 0.5 * digit.h + 0.15 * th.tick_font_pt;
    plan.label_gap = 0.8 * th.padding_pt;
    for (const auto& l : plan.yt.labels) {
        const text_ink i = text.ink(l, th.tick_font_pt);
        plan.ytick_w = std::max(plan.ytick_w, i.w);
        plan.own_ytick_w = plan.ytick_w;
        plan.ytick_extent.push_back(i.h);
        // Ink below the baseline (the slash of pi/2) hangs that much nearer the x labels.
        plan.xtick_gap = std::max(plan.xtick_gap, plan.tick_gap + std::max(0.0, i.y + i.h - digit.y - digit.h));
    }
    plan.xtick_gap = std::max(plan.xtick_gap, plan.tick_gap);
    for (const auto& l : plan.xt.labels) {
        const text_ink i = text.ink(l, th.tick_font_pt);
        plan.xtick_up = std::max(plan.xtick_up, -i.y);
        plan.xtick_down = std::max(plan.xtick_down, i.y + i.h);
        plan.xtick_extent.push_back(i.w);
    }
    if (!p.y.label.empty()) plan.ylabel_h = text.ink(p.y.label.markup, th.label_font_pt).h;
    if (!p.x.label.empty()) plan.xlabel_h = text.ink(p.x.label.markup, th.label_font_pt).h;
    const double pad = th.padding_pt;
    const double last_xtick_w = plan.xt.labels.empty() ? 0.0 : text.ink(plan.xt.labels.back(), th.tick_font_pt).w;
    // A drawing's line for its changing text holds it beside its label.
    const bool overlay_line = p.frameless && p.overlay_line;
    const double panel_label_h = std::max(p.label.empty() ? 0.0 : text.ink(p.label.markup, th.label_font_pt).h,
                                          overlay_line ? overlay_line_ink(text, th).h : 0.0);
    // The panel label sits above the top y tick label, never beside it.
    plan.top = pad + std::max(0.5 * digit.h, panel_label_h > 0 ? 0.5 * digit.h + plan.label_gap + panel_label_h : 0.0);
    plan.right = pad + 0.5 * last_xtick_w;
    plan.legend = measure_legend(text, p, th);
    return plan;
}

bool tick_labels_fit(const tick_set& t, const std::vector<double>& extents, const axis_map& m, double font_pt) {
    const double gap = 0.5 * font_pt;
    const double lo = std::min(m.d0, m.d1) - 0.01;
    const double hi = std::max(m.d0, m.d1) + 0.01;
    bool any = false;
    double last_d = 0;
    double last_half = 0;
    for (std::size_t i = 0; i < t.major.size() && i < extents.size(); ++i) {
        const double d = m(t.major[i]);
        if (!(d >= lo && d <= hi)) continue;
        const double half = 0.5 * extents[i];
        if (any && std::fabs(d - last_d) < last_half + half + gap) return false;
        any = true;
        last_d = d;
        last_half = half;
    }
    return true;
}

text_ink overlay_line_ink(const text_engine& text, const theme& th) {
    return text.ink("(<i>t</i> = 0 <i>T</i><sub>0</sub>)", th.label_font_pt);
}

namespace {

/// A plan of the panel with fewer ticks on one axis and the same limits, if the locator has
/// one: thinning must not move the limits, or the data would shrink to make room for labels.
std::optional<panel_plan> thinner(const text_engine& text, const panel& p, const theme& th, const panel_plan& plan,
                                  bool horizontal) {
    const tick_set& old = horizontal ? plan.xt : plan.yt;
    tick_limit limit = horizontal ? plan.x_limit : plan.y_limit;
    limit.fixed = true;
    limit.lo = old.lo;
    limit.hi = old.hi;
    const int asked = (horizontal ? p.x : p.y).max_ticks;
    for (int n = std::min(asked, static_cast<int>(old.major.size())) - 1; n >= 2; --n) {
        limit.max_ticks = n;
        panel_plan fewer = plan_panel(text, p, th, horizontal ? limit : plan.x_limit, horizontal ? plan.y_limit : limit);
        const tick_set& t = horizontal ? fewer.xt : fewer.yt;
        if (t.major.size() < old.major.size() && t.major.size() >= 2) return fewer;
    }
    return std::nullopt;
}

}  // namespace

void thin_crowded_ticks(const text_engine& text, const std::vector<panel>& panels, std::vector<panel_plan>& plans,
                        const std::vector<rect>& cells, const theme& th, int cols) {
    for (bool thinned = true; thinned;) {
        thinned = false;
        for (std::size_t i = 0; i < panels.size(); ++i) {
            const panel& p = panels[i];
            if (p.frameless) continue;
            for (const bool horizontal : {true, false}) {
                const auto [mx, my] = axis_maps(p, plans[i], panel_area(p, plans[i], cells[i]));
                const bool fit = horizontal ? tick_labels_fit(plans[i].xt, plans[i].xtick_extent, mx, th.tick_font_pt)
                                            : tick_labels_fit(plans[i].yt, plans[i].ytick_extent, my, th.tick_font_pt);
                if (fit) continue;
                if (auto fewer = thinner(text, p, th, plans[i], horizontal)) {
                    plans[i] = std::move(*fewer);
                    share_margins(plans, th, cols);  // before the next axis is measured
                    thinned = true;
                }
            }
        }
    }
}

namespace {

/// The extent of one series along an axis (log10 of it on a log axis), and how far inside
/// the frame its ink must stay, in points.
struct extent {
    double lo;
    double hi;
    double clear;
};

double clearance(const series& s, const theme& th) {
    const double gap = std::max(1.0, th.line_width_pt);
    const double line = s.line == line_style::none ? 0.0 : 0.5 * th.line_width_pt * s.width_scale;
    const double marker =
        s.marker == marker_style::none ? 0.0 : th.marker_radius_pt * s.marker_scale + 0.5 * th.line_width_pt;
    return std::max(line, marker) + 0.5 * th.frame_width_pt + gap;
}

std::vector<extent> extents(const panel& p, const theme& th, bool horizontal, bool log) {
    std::vector<extent> out;
    for (const auto& s : p.data) {
        if (!s.autoscale || !s.sets_limits) continue;
        if (s.line == line_style::none && s.marker == marker_style::none) continue;
        extent e{std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(), clearance(s, th)};
        for_each_reach(s, horizontal, [&](double v) {
            if (!std::isfinite(v) || (log && !(v > 0))) return;
            const double u = log ? std::log10(v) : v;
            e.lo = std::min(e.lo, u);
            e.hi = std::max(e.hi, u);
        });
        if (e.lo <= e.hi) out.push_back(e);
    }
    return out;
}

}  // namespace

namespace {

/// The limits (lo, hi) widened so that every extent stands its clearance (in points, at
/// `per_pt` axis units a point) inside them.
std::pair<double, double> limits_clear_of(const std::vector<extent>& data, double lo, double hi, double per_pt) {
    for (const extent& e : data) {
        lo = std::min(lo, e.lo - e.clear * per_pt);
        hi = std::max(hi, e.hi + e.clear * per_pt);
    }
    return {lo, hi};
}

/// One round of keep_axis_off_frame: widens t's free limits so that every extent stands
/// clear at the axis' present length; false where nothing moved (or the axis has no length).
bool widen_axis_once(const axis& a, tick_set& t, double length, const std::vector<extent>& data) {
    const bool log = a.kind == scale::log;
    double lo = log ? std::log10(t.lo) : t.lo;
    double hi = log ? std::log10(t.hi) : t.hi;
    if (!(length > 0) || !(hi > lo)) return false;
    const auto [need_lo, need_hi] = limits_clear_of(data, lo, hi, (hi - lo) / length);
    const bool lo_free = !a.min || !a.exact_range;
    const bool hi_free = !a.max || !a.exact_range;
    if (!((lo_free && need_lo < lo) || (hi_free && need_hi > hi))) return false;
    if (lo_free) lo = std::min(lo, need_lo);
    if (hi_free) hi = std::max(hi, need_hi);
    t.lo = log ? std::pow(10.0, lo) : lo;
    t.hi = log ? std::pow(10.0, hi) : hi;
    return true;
}

/// Moves one free axis's limits out until every extent stands clear of the frame. The
/// length in points depends on the limits where the aspect is equal: a few rounds settle it.
void keep_axis_off_frame(const panel& p, panel_plan& plan, const rect& cell, const std::vector<extent>& data,
                         bool horizontal) {
    const axis& a = horizontal ? p.x : p.y;
    tick_set& t = horizontal ? plan.xt : plan.yt;
    for (int round = 0; round < 4; ++round) {
        const rect area = panel_area(p, plan, cell);
        if (!widen_axis_once(a, t, horizontal ? area.w : area.h, data)) return;
    }
}

}  // namespace

void keep_data_off_frame(const std::vector<panel>& panels, std::vector<panel_plan>& plans,
                         const std::vector<rect>& cells, const theme& th) {
    for (std::size_t i = 0; i < panels.size(); ++i) {
        const panel& p = panels[i];
        if (p.frameless) continue;
        for (const bool horizontal : {true, false}) {
            const axis& a = horizontal ? p.x : p.y;
            if (a.min && a.max && a.exact_range) continue;
            const std::vector<extent> data = extents(p, th, horizontal, a.kind == scale::log);
            if (!data.empty()) keep_axis_off_frame(p, plans[i], cells[i], data, horizontal);
        }
    }
}

void share_margins(std::vector<panel_plan>& plans, const theme& th, int /*cols*/) {
    panel_plan m;
    for (const auto& p : plans) {
        m.ytick_w = std::max(m.ytick_w, p.ytick_w);
        m.ylabel_h = std::max(m.ylabel_h, p.ylabel_h);
        m.xtick_up = std::max(m.xtick_up, p.xtick_up);
        m.xtick_down = std::max(m.xtick_down, p.xtick_down);
        m.xlabel_h = std::max(m.xlabel_h, p.xlabel_h);
        m.top = std::max(m.top, p.top);
        m.right = std::max(m.right, p.right);
        m.tick_gap = std::max(m.tick_gap, p.tick_gap);
        m.xtick_gap = std::max(m.xtick_gap, p.xtick_gap);
        m.label_gap = std::max(m.label_gap, p.label_gap);
    }
    const double pad = th.padding_pt;
    for (auto& p : plans) {
        p.ytick_w = m.ytick_w;
        p.ylabel_h = m.ylabel_h;
        p.xtick_up = m.xtick_up;
        p.xtick_down = m.xtick_down;
        p.xlabel_h = m.xlabel_h;
        p.tick_gap = m.tick_gap;
        p.xtick_gap = m.xtick_gap;
        p.label_gap = m.label_gap;
        p.left = pad + (m.ylabel_h > 0 ? m.ylabel_h + m.label_gap : 0.0) + m.ytick_w + m.tick_gap;
        p.bottom = m.xtick_gap + m.xtick_up + m.xtick_down + (m.xlabel_h > 0 ? m.label_gap + m.xlabel_h : 0.0) + pad;
        p.top = m.top;
        p.right = m.right;
    }
}

rect equal_aspect_area(const rect& area, const panel_plan& plan) {
    const double dx = plan.xt.hi - plan.xt.lo;
    const double dy = plan.yt.hi - plan.yt.lo;
    if (!(dx > 0 && dy > 0)) return area;
    const double scale = std::min(area.w / dx, area.h / dy);
    const double w = dx * scale;
    const double h = dy * scale;
    return {area.x + 0.5 * (area.w - w), area.y + 0.5 * (area.h - h), w, h};
}

std::pair<axis_map, axis_map> axis_maps(const panel& p, const panel_plan& plan, const rect& area) {
    return {axis_map{plan.xt.lo, plan.xt.hi, p.x.kind == scale::log, area.x, area.x + area.w},
            axis_map{plan.yt.lo, plan.yt.hi, p.y.kind == scale::log, area.y + area.h, area.y}};
}

panel_geometry place_panel(const panel& p, const panel_plan& plan, const rect& area, double tolerance,
                           double reach) {
    panel_geometry g;
    g.area = area;
    std::tie(g.mx, g.my) = axis_maps(p, plan, area);
    const rect clip{area.x - reach, area.y - reach, area.w + 2 * reach, area.h + 2 * reach};
    for (const auto& s : p.data) g.dev.push_back(to_device(s, g.mx, g.my, clip, tolerance));
    return g;
}

rect axes_area(const panel_plan& plan, const rect& cell) {
    return {cell.x + plan.left, cell.y + plan.top, cell.w - plan.left - plan.right, cell.h - plan.top - plan.bottom};
}

rect panel_area(const panel& p, const panel_plan& plan, const rect& cell) {
    const rect area = axes_area(plan, cell);
    return p.equal_aspect ? equal_aspect_area(area, plan) : area;
}

std::optional<rect> legend_inside(const panel& p, const legend_layout& lg, const panel_geometry& g,
                                  const theme& th) {
    if (lg.entries.empty()) return std::nullopt;
    const rect& area = g.area;
    // At least 1 mm between the legend's ink and the frame or its tick marks; the legend
    // box has half a padding inside.
    const double mm = 72.0 / 25.4;
    const double inset = th.tick_length_pt + mm - 0.5 * th.padding_pt;
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
        // Lines keep their half width and a little more away from the text.
        const double clear = 0.5 * th.line_width_pt + 0.5;
        const rect grown{x - clear, y - clear, lg.w + 2 * clear, lg.h + 2 * clear};
        if (overlap(grown, p.data, g.dev, th.marker_radius_pt) == 0) return box;
    }
    return std::nullopt;
}

}  // namespace plot
