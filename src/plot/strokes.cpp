// SPDX-License-Identifier: GPL-3.0-or-later
#include "plot/strokes.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace plot {

void set_foreground(cairo_t* cr, const theme& th) {
    cairo_set_source_rgb(cr, th.foreground.r, th.foreground.g, th.foreground.b);
}

void set_color(cairo_t* cr, const theme& th, const series& s) {
    const rgb& c = s.rgb_color ? *s.rgb_color : th.palette[static_cast<std::size_t>(s.color) % th.palette.size()];
    if (s.alpha < 1.0) {
        cairo_set_source_rgba(cr, c.r, c.g, c.b, s.alpha);
    } else {
        cairo_set_source_rgb(cr, c.r, c.g, c.b);
    }
}

double line_width(const theme& th, double width) { return std::max(width, th.min_line_pt); }

void set_line_style(cairo_t* cr, const theme& th, line_style style, double width_scale) {
    const double w = line_width(th, th.line_width_pt * width_scale);
    cairo_set_line_width(cr, w);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    cairo_set_line_cap(cr, style == line_style::dashed ? CAIRO_LINE_CAP_BUTT : CAIRO_LINE_CAP_ROUND);
    switch (style) {
        case line_style::dashed: {
            const double d[] = {5.0 * w, 3.0 * w};
            cairo_set_dash(cr, d, 2, 0);
            break;
        }
        case line_style::dotted: {
            const double d[] = {0.0, 2.2 * w};
            cairo_set_dash(cr, d, 2, 0);
            break;
        }
        case line_style::dash_dot: {
            const double d[] = {5.0 * w, 2.2 * w, 0.5 * w, 2.2 * w};
            cairo_set_dash(cr, d, 4, 0);
            break;
        }
        case line_style::dash_dot_dot: {
            const double d[] = {5.0 * w, 2.2 * w, 0.5 * w, 2.2 * w, 0.5 * w, 2.2 * w};
            cairo_set_dash(cr, d, 6, 0);
            break;
        }
        default: cairo_set_dash(cr, nullptr, 0, 0);
    }
}

void stroke_polyline(cairo_t* cr, const device_series& d, const rect& clip) {
    // Visible runs of the clipped polyline, each simplified, then stroked as one path.
    std::vector<std::vector<std::pair<double, double>>> runs;
    bool open = false;
    const auto& lx = d.line_x();
    const auto& ly = d.line_y();
    for (std::size_t i = 1; i < lx.size(); ++i) {
        double x0 = lx[i - 1], y0 = ly[i - 1], x1 = lx[i], y1 = ly[i];
        if (std::isnan(x0 + y0 + x1 + y1) || !clip_segment(x0, y0, x1, y1, clip)) {
            open = false;
            continue;
        }
        if (!open || runs.back().back() != std::pair{x0, y0}) runs.push_back({{x0, y0}});
        runs.back().emplace_back(x1, y1);
        open = true;
    }
    for (auto& run : runs) {
        // A sampled curve has the vertices it needs and no more; simplifying it would take
        // it further from the curve.
        if (!d.sampled) simplify(run, 0.05);
        cairo_move_to(cr, run.front().first, run.front().second);
        for (std::size_t i = 1; i < run.size(); ++i) cairo_line_to(cr, run[i].first, run[i].second);
    }
    cairo_stroke(cr);
}

namespace {

/// Adds one marker's outline at (x, y) to the path: a circle of radius r, or a square,
/// triangle or diamond of about the circle's area.
void marker_path(cairo_t* cr, marker_style m, double x, double y, double r) {
    cairo_new_sub_path(cr);
    switch (m) {
        case marker_style::filled_square: {
            const double h = 0.886 * r;  // the circle's area
            cairo_rectangle(cr, x - h, y - h, 2 * h, 2 * h);
            return;
        }
        case marker_style::filled_triangle: {
            const double h = 1.35 * r;
            cairo_move_to(cr, x, y - h);
            cairo_line_to(cr, x + 0.866 * h, y + 0.5 * h);
            cairo_line_to(cr, x - 0.866 * h, y + 0.5 * h);
            cairo_close_path(cr);
            return;
        }
        case marker_style::filled_diamond: {
            const double h = 1.25 * r;
            cairo_move_to(cr, x, y - h);
            cairo_line_to(cr, x + h, y);
            cairo_line_to(cr, x, y + h);
            cairo_line_to(cr, x - h, y);
            cairo_close_path(cr);
            return;
        }
        default: cairo_arc(cr, x, y, r, 0, 2 * M_PI); return;
    }
}

/// The radius of the circle a marker of radius r holds, touching its sides (r for a circle).
double inradius(marker_style m, double r) {
    switch (m) {
        case marker_style::filled_square: return 0.886 * r;
        case marker_style::filled_triangle: return 0.5 * 1.35 * r;
        case marker_style::filled_diamond: return 1.25 * r / std::sqrt(2.0);
        default: return r;
    }
}

}  // namespace

bool filled(marker_style m) { return m != marker_style::none && m != marker_style::open_circle; }

void draw_markers(cairo_t* cr, const theme& th, const series& s, const device_series& d, const rect& area) {
    const double outline = line_width(th, 0.75 * th.line_width_pt);
    // A translucent filled marker is one fill out to where its outline's ink ends (its sides
    // moved out by half the outline's width): the outline stroked over the fill would blend
    // the rim's inner half twice, a ring on each marker and rings along a streak of them,
    // and cost a second rasterisation.
    const bool one_fill = filled(s.marker) && s.alpha < 1.0;
    const double r0 = th.marker_radius_pt * s.marker_scale;
    const double r = one_fill ? r0 * (1 + 0.5 * outline / inradius(s.marker, r0)) : r0;
    cairo_set_dash(cr, nullptr, 0, 0);
    cairo_set_line_width(cr, outline);
    for (std::size_t i = 0; i < d.x.size(); ++i) {
        if (std::isnan(d.x[i] + d.y[i])) continue;
        if (d.x[i] < area.x - r0 || d.x[i] > area.x + area.w + r0 || d.y[i] < area.y - r0 ||
            d.y[i] > area.y + area.h + r0) {
            continue;
        }
        marker_path(cr, s.marker, d.x[i], d.y[i], r);
    }
    if (one_fill) {
        cairo_fill(cr);
        return;
    }
    if (filled(s.marker)) {
        cairo_fill_preserve(cr);
    } else if (s.line != line_style::none || !d.bars.empty()) {
        // An open marker on its own series' line or bars stays open: they do not run through it.
        cairo_save(cr);
        cairo_set_source_rgb(cr, th.background.r, th.background.g, th.background.b);
        cairo_fill_preserve(cr);
        cairo_restore(cr);
    }
    cairo_stroke(cr);
}

double cap_half_width(const theme& th, const series& s) { return th.marker_radius_pt * s.marker_scale; }

void draw_error_bars(cairo_t* cr, const theme& th, const series& s, const std::vector<device_bar>& bars) {
    if (bars.empty()) return;
    const double c = cap_half_width(th, s);
    cairo_set_dash(cr, nullptr, 0, 0);
    cairo_set_line_width(cr, line_width(th, th.line_width_pt * s.width_scale));
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_BUTT);
    for (const auto& b : bars) {
        cairo_move_to(cr, b.x0, b.y0);
        cairo_line_to(cr, b.x1, b.y1);
        for (const auto& [x, y] : {std::pair{b.x0, b.y0}, std::pair{b.x1, b.y1}}) {
            cairo_move_to(cr, b.vertical ? x - c : x, b.vertical ? y : y - c);
            cairo_line_to(cr, b.vertical ? x + c : x, b.vertical ? y : y + c);
        }
    }
    cairo_stroke(cr);
}

double marker_reach(const theme& th, const series& s) {
    double outline = 1.0;  // a circle's radius, in radii
    switch (s.marker) {
        case marker_style::filled_square: outline = 0.886 * std::sqrt(2.0); break;
        case marker_style::filled_triangle: outline = 1.35; break;
        case marker_style::filled_diamond: outline = 1.25; break;
        default: break;
    }
    return outline * th.marker_radius_pt * s.marker_scale + 0.5 * line_width(th, 0.75 * th.line_width_pt);
}

double tick_length_clear(double x, double y, double ux, double uy, double length, const std::vector<keep_out>& discs,
                         double gap) {
    for (const keep_out& d : discs) {
        // |w + s u| = R on the way out from (x, y): s^2 + 2 b s + c = 0.
        const double wx = x - d.x;
        const double wy = y - d.y;
        const double reach = d.r + gap;
        const double b = ux * wx + uy * wy;
        const double c = wx * wx + wy * wy - reach * reach;
        if (c <= 0) return 0;  // starts within the disc
        const double disc = b * b - c;
        if (disc < 0 || b >= 0) continue;  // misses it, or heads away from it
        length = std::min(length, -b - std::sqrt(disc));
    }
    return std::max(length, 0.0);
}

namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();

/// The values of s where k0 + s k1 lies in [lo, hi], as an interval (empty: lo > hi).
std::pair<double, double> linear_within(double k0, double k1, double lo, double hi) {
    if (std::abs(k1) < 1e-12) return k0 >= lo && k0 <= hi ? std::pair{-infinity, infinity} : std::pair{1.0, -1.0};
    const double a = (lo - k0) / k1;
    const double b = (hi - k0) / k1;
    return {std::min(a, b), std::max(a, b)};
}

/// The values of s where (x, y) + s (ux, uy) lies within `reach` of (cx, cy) (empty: lo > hi).
std::pair<double, double> within_disc(double x, double y, double ux, double uy, double cx, double cy, double reach) {
    const double wx = x - cx;
    const double wy = y - cy;
    const double b = ux * wx + uy * wy;
    const double disc = b * b - (wx * wx + wy * wy - reach * reach);
    if (disc < 0) return {1.0, -1.0};
    return {-b - std::sqrt(disc), -b + std::sqrt(disc)};
}

/// The first s in [0, length] where (x, y) + s (ux, uy) comes within `reach` of the
/// segment's centre line (a capsule: its end discs and the band between); infinity if none.
double entry_into(double x, double y, double ux, double uy, double length, const ink_segment& g, double reach) {
    double first = infinity;
    const auto consider = [&](std::pair<double, double> s) {
        if (s.first <= s.second && s.second >= 0 && s.first <= length) first = std::min(first, std::max(s.first, 0.0));
    };
    consider(within_disc(x, y, ux, uy, g.x0, g.y0, reach));
    consider(within_disc(x, y, ux, uy, g.x1, g.y1, reach));
    const double len = std::hypot(g.x1 - g.x0, g.y1 - g.y0);
    if (len > 0) {
        const double vx = (g.x1 - g.x0) / len;
        const double vy = (g.y1 - g.y0) / len;
        const double wx = x - g.x0;
        const double wy = y - g.y0;
        // Across the segment within reach, along it between its ends.
        const auto across = linear_within(wx * vy - wy * vx, ux * vy - uy * vx, -reach, reach);
        const auto along = linear_within(wx * vx + wy * vy, ux * vx + uy * vy, 0, len);
        consider({std::max(across.first, along.first), std::min(across.second, along.second)});
    }
    return first;
}

}  // namespace

void add_ink_near_frame(std::vector<ink_segment>& out, const std::vector<double>& x, const std::vector<double>& y,
                        double r, const rect& area, double band) {
    const double m = r + band;
    const rect outer{area.x - m, area.y - m, area.w + 2 * m, area.h + 2 * m};
    const rect inner{area.x + m, area.y + m, area.w - 2 * m, area.h - 2 * m};
    for (std::size_t i = 1; i < x.size() && i < y.size(); ++i) {
        const double x0 = x[i - 1], y0 = y[i - 1], x1 = x[i], y1 = y[i];
        if (std::isnan(x0 + y0 + x1 + y1)) continue;
        const double left = std::min(x0, x1), right = std::max(x0, x1);
        const double top = std::min(y0, y1), bottom = std::max(y0, y1);
        const bool meets_outer =
            right >= outer.x && left <= outer.x + outer.w && bottom >= outer.y && top <= outer.y + outer.h;
        const bool inside_inner =
            left > inner.x && right < inner.x + inner.w && top > inner.y && bottom < inner.y + inner.h;
        if (meets_outer && !inside_inner) out.push_back({x0, y0, x1, y1, r});
    }
}

double tick_length_clear(double x, double y, double ux, double uy, double length, const tick_clearance& ink,
                         double gap) {
    length = tick_length_clear(x, y, ux, uy, length, ink.discs, gap);
    for (const ink_segment& g : ink.segments) {
        if (!(length > 0)) break;
        length = std::min(length, entry_into(x, y, ux, uy, length, g, g.r + gap));
    }
    return std::max(length, 0.0);
}

double tick_mark_length(double x, double y, double ux, double uy, double length, const tick_clearance& ink,
                        double gap, const rect& area, double corner) {
    // Along its side: a tick mark across x (ux == 0) lies on the top or bottom side.
    const bool across_x = std::abs(ux) < std::abs(uy);
    const double along = across_x ? x : y;
    const double lo = across_x ? area.x : area.y;
    const double hi = across_x ? area.x + area.w : area.y + area.h;
    if (along - lo < corner || hi - along < corner) return 0;
    const double l = tick_length_clear(x, y, ux, uy, length, ink, gap);
    return l >= min_tick_fraction * length ? l : 0;
}

namespace {

thread_local tick_marks_record* current_record = nullptr;

}  // namespace

tick_marks_record::tick_marks_record() : outer_(current_record) { current_record = this; }

tick_marks_record::~tick_marks_record() { current_record = outer_; }

void tick_marks_record::add(const tick_mark& t) {
    if (current_record) current_record->marks_.push_back(t);
}

}  // namespace plot
