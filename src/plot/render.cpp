// SPDX-License-Identifier: GPL-3.0-or-later
#include "plot/render.hpp"

#include "plot/geometry.hpp"
#include "plot/handles.hpp"
#include "plot/latex_overlay.hpp"
#include "plot/layout.hpp"
#include "plot/preflight.hpp"
#include "plot/legend.hpp"
#include "plot/strokes.hpp"
#include "plot/text.hpp"
#include "plot/ticks.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>

namespace plot {

std::string escape_markup(const std::string& text) {
    std::string out;
    for (char c : text) {
        switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            case '\'': out += "&apos;"; break;
            default: out += c;
        }
    }
    return out;
}

namespace {

/// A size in points as a message shows it: at most three decimals.
std::string shown_pt(double pt) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3f", pt);
    std::string s = buf;
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
    return s;
}

}  // namespace

std::string text_size_problem(const theme& th) {
    const double script = script_metrics{}.size;
    const std::pair<const char*, double> sizes[] = {{"tick_font_pt", th.tick_font_pt},
                                                    {"label_font_pt", th.label_font_pt},
                                                    {"legend_font_pt", th.legend_font_pt},
                                                    {"title_font_pt", th.title_font_pt}};
    for (const auto& [key, pt] : sizes) {
        if (pt == 0 && std::string_view(key) == "title_font_pt") continue;  // no title
        const std::string is = std::string(key) + " = " + shown_pt(pt);
        if (pt < th.min_text_pt) {
            return is + " is below the theme's min_text_pt = " + shown_pt(th.min_text_pt) +
                   " (the smallest text at final size): raise " + key + " to " + shown_pt(th.min_text_pt) +
                   " or more, or lower min_text_pt";
        }
        if (script * pt < th.min_script_pt) {
            // The least size whose scripts reach the minimum, rounded up to the shown digits.
            const double least = std::ceil(th.min_script_pt / script * 100 - 1e-9) / 100;
            return is + " sets superscripts and subscripts at " + shown_pt(script * pt) +
                   " pt, below the theme's min_script_pt = " + shown_pt(th.min_script_pt) + ": raise " + key +
                   " to " + shown_pt(least) + " or more (scripts are " + shown_pt(script) +
                   " of the text), or lower min_script_pt";
        }
    }
    return {};
}

page_size figure_size(const figure& fig, const theme& th) {
    constexpr double pt_per_cm = 72.0 / 2.54;
    const double w = fig.panel_width_cm * pt_per_cm * fig.cols;
    const double h = fig.panel_width_cm * pt_per_cm * fig.panel_aspect * fig.rows;
    const double fixed_w = th.fixed_width_cm * pt_per_cm;
    const double fixed_h = th.fixed_height_cm * pt_per_cm;
    // A width or a height alone scales the panels' size to it.
    if (fixed_w > 0 && fixed_h > 0) return {fixed_w, fixed_h};
    if (fixed_w > 0) return {fixed_w, fixed_w * h / w};
    if (fixed_h > 0) return {fixed_h * w / h, fixed_h};
    return {w, h};
}

namespace {

/// How closely a sampled curve follows its function on the surface of cr, in points: the
/// line drawn stays within a twentieth of a point of the curve, or half a pixel of a raster
/// surface where that is finer; on a vector surface, which a viewer zooms, within an eighth
/// of a twentieth. Cairo rounds path coordinates to 1/256 of a device unit (a point on a
/// vector surface), which takes up part of that.
double curve_tolerance(double units_per_point, bool raster) {
    constexpr double at_size = 0.05;
    const double rounding = std::sqrt(0.5) / 256 / units_per_point;
    if (!raster) return at_size / 8 - rounding;
    return std::min(at_size, 0.5 / units_per_point) - rounding;
}

/// curve_tolerance on the surface of cr.
double curve_tolerance(cairo_t* cr) {
    double dx = 1.0;
    double dy = 0.0;
    cairo_user_to_device_distance(cr, &dx, &dy);
    const double units_per_point = std::hypot(dx, dy) > 0 ? std::hypot(dx, dy) : 1.0;
    return curve_tolerance(units_per_point, cairo_surface_get_type(cairo_get_target(cr)) == CAIRO_SURFACE_TYPE_IMAGE);
}

/// The gap a tick mark keeps from the ink of markers and lines: half its width and half a point.
double tick_gap(const theme& th) { return 0.5 * line_width(th, th.frame_width_pt) + 0.5; }

/// Tick marks of an axis, from the frame inwards, on both sides, by the tick rules
/// (tick_mark_length): each stops tick_gap short of the markers' and lines' ink, or is not
/// drawn where that leaves a stub, or within a tick length and tick_gap of the perpendicular
/// side, where it would close a box with that side's tick marks in a corner of the frame.
void draw_ticks(cairo_t* cr, const theme& th, const tick_set& t, const axis_map& m, const rect& area, bool horizontal,
                const tick_clearance& ink) {
    const double width = line_width(th, th.frame_width_pt);
    const double gap = tick_gap(th);
    const auto mark = [&](double x, double y, double ux, double uy, double len) {
        const double l = tick_mark_length(x, y, ux, uy, len, ink, gap, area, th.tick_length_pt + gap);
        if (!(l > 0)) return;
        cairo_move_to(cr, x, y);
        cairo_line_to(cr, x + l * ux, y + l * uy);
        tick_marks_record::add({x, y, x + l * ux, y + l * uy, width, len});
    };
    auto tick = [&](double v, double len) {
        const double d = m(v);
        if (std::isnan(d)) return;
        if (horizontal) {
            if (d < area.x - 0.01 || d > area.x + area.w + 0.01) return;
            mark(d, area.y + area.h, 0, -1, len);
            mark(d, area.y, 0, 1, len);
        } else {
            if (d < area.y - 0.01 || d > area.y + area.h + 0.01) return;
            mark(area.x, d, 1, 0, len);
            mark(area.x + area.w, d, -1, 0, len);
        }
    };
    for (double v : t.major) tick(v, th.tick_length_pt);
    for (double v : t.minor) tick(v, 0.6 * th.tick_length_pt);
    cairo_stroke(cr);
}

/// Which parts of a figure a pass draws.
struct pass_gate {
    draw_pass pass = draw_pass::all;

    /// Whether the pass draws a part, one that moves or one that stays.
    bool draws(bool moves) const {
        switch (pass) {
            case draw_pass::all: return true;
            case draw_pass::still: return !moves;
            case draw_pass::overlay: return moves;
        }
        return true;
    }
};

/// Where a panel's legend goes, as decided at the sizes the contents are decided at.
enum class legend_spot {
    none,    ///< no legend
    inside,  ///< inside the axes where it covers no data (a band above them if none is free)
    band,    ///< in a row of its own above the axes
};

/// Where a legend band above a cell's axes goes, `top` its top: over the axes, from their
/// left edge (the frame, not the page's edge, where the y label's margin starts) to the
/// cell's right padding, which the axes leave only for half their last tick label; or, not
/// `over_axes`, across the cell.
rect legend_band_rect(const legend_layout& lg, const theme& th, const panel_plan& plan, const rect& cell, double top,
                      bool over_axes) {
    const double pad = th.padding_pt;
    const double x = over_axes ? cell.x + plan.left : cell.x + pad;
    const double w = std::max(0.0, over_axes ? cell.w - plan.left - pad : cell.w - 2 * pad);
    return rect{x, top, w, legend_band_height(lg, th, w)};
}

/// Whether a band with `plan`'s legend over `cell` may span the axes alone: at `th`'s sizes
/// it takes no more lines than across the cell, or the axes keep three quarters of their
/// height (and three tick lines) under its extra lines; else it goes across the cell.
bool band_spans_axes(const panel_plan& plan, const theme& th, const rect& cell) {
    const double across = legend_band_rect(plan.legend, th, plan, cell, 0, false).h;
    const double over = legend_band_rect(plan.legend, th, plan, cell, 0, true).h;
    if (over <= across) return true;
    rect squeezed = cell;
    squeezed.y += over;
    squeezed.h -= over;
    const double least = 3 * th.tick_font_pt;
    return axes_area(plan, squeezed).h >= std::max(least, 0.75 * axes_area(plan, cell).h);
}

/// The panel's geometry and its legend's place: inside the axes, or in `band` (a row of
/// its own above the cell, which the layout made room for). legend_spot::inside falls back
/// to a band at the top of the cell, moving the axes down, where the legend is automatic
/// and no spot inside is free.
struct placed_panel {
    panel_geometry g;
    std::optional<rect> legend_box;
    std::optional<rect> legend_band;
};

placed_panel place_with_legend(const theme& th, const panel& p, const panel_plan& plan, const rect& cell,
                               legend_spot spot, const std::optional<rect>& band, double tolerance) {
    const double pad = th.padding_pt;
    // Curves are followed closely where their lines show: within a line width of the axes.
    const double reach = th.line_width_pt;
    placed_panel out{place_panel(p, plan, panel_area(p, plan, cell), tolerance, reach), std::nullopt, std::nullopt};
    const legend_layout& lg = plan.legend;
    if (spot == legend_spot::none || lg.entries.empty()) return out;
    if (spot == legend_spot::band) {
        out.legend_band = band;
        return out;
    }
    out.legend_box = legend_inside(p, lg, out.g, th);
    if (out.legend_box || p.legend != legend_place::automatic) return out;
    const rect band_here = legend_band_rect(lg, th, plan, cell, cell.y + 0.3 * pad, band_spans_axes(plan, th, cell));
    rect area = out.g.area;
    area.y += band_here.h;
    area.h -= band_here.h;
    out.g = place_panel(p, plan, area, tolerance, reach);
    out.legend_band = band_here;
    return out;
}

/// Whether a series' markers are spaced on the page (a method's circles; not measured data,
/// whose every point is a measurement, nor what moves in an animation).
bool spaces_markers(const series& s) {
    return s.marker != marker_style::none && s.data_slot < 0 && !s.overlay;
}

/// A marker already placed by an earlier series of the panel: its centre and the least
/// distance another marker keeps from it.
struct disc {
    double x = 0;
    double y = 0;
    double apart = 0;
};

/// Whether point i of d stands clear of every disc of `taken`.
bool clear_of(const device_series& d, std::size_t i, const std::vector<disc>& taken) {
    return std::all_of(taken.begin(), taken.end(),
                       [&](const disc& t) { return std::hypot(d.x[i] - t.x, d.y[i] - t.y) >= t.apart; });
}

/// Whether the kept markers stand at least `spacing` apart from one another.
bool all_apart(const device_series& d, const std::vector<std::size_t>& kept, double spacing) {
    for (std::size_t a = 0; a < kept.size(); ++a) {
        for (std::size_t b = a + 1; b < kept.size(); ++b) {
            if (std::hypot(d.x[kept[a]] - d.x[kept[b]], d.y[kept[a]] - d.y[kept[b]]) < spacing) return false;
        }
    }
    return true;
}

/// The markers of a series whose points stand evenly along x (orders 0, 1, 2, ...; times
/// on a grid) at a whole step: every k-th point from the first, the least k that keeps them
/// `spacing` apart, one that reaches the last point where one does (markers symmetric where
/// the data is); points not finite (gaps) are skipped. Empty if the points are not evenly
/// spaced along x.
std::vector<std::size_t> strided_markers(const device_series& d, double spacing) {
    const std::size_t n = std::min(d.x.size(), d.y.size());
    if (n < 3) return {};
    const auto finite = [&d](std::size_t i) { return std::isfinite(d.x[i]) && std::isfinite(d.y[i]); };
    if (!finite(0) || !finite(1)) return {};
    const double step = d.x[1] - d.x[0];
    for (std::size_t i = 2; i < n; ++i) {
        const double want = d.x[0] + static_cast<double>(i) * step;
        if (finite(i) && !(std::fabs(d.x[i] - want) <= 1e-6 * std::fabs(step) * static_cast<double>(i))) return {};
    }
    std::vector<std::size_t> best;
    for (std::size_t k = 1; k < n; ++k) {
        std::vector<std::size_t> kept;
        for (std::size_t i = 0; i < n; i += k) {
            if (finite(i)) kept.push_back(i);
        }
        if (!all_apart(d, kept, spacing)) continue;
        if (best.empty()) best = kept;
        if (kept.back() == n - 1) return kept.size() * 4 >= best.size() * 3 ? kept : best;
        if (kept.size() * 4 < best.size() * 3) break;
    }
    return best;
}

/// The markers of a series (indices into d) that stand at least `spacing` apart on the
/// page from every marker kept before them, the first kept, and clear of `taken`.
std::vector<std::size_t> greedy_markers(const device_series& d, double spacing, const std::vector<disc>& taken = {}) {
    std::vector<std::size_t> kept;
    for (std::size_t i = 0; i < d.x.size() && i < d.y.size(); ++i) {
        if (!std::isfinite(d.x[i]) || !std::isfinite(d.y[i])) continue;
        const bool apart = std::all_of(kept.begin(), kept.end(), [&](std::size_t j) {
            return std::hypot(d.x[i] - d.x[j], d.y[i] - d.y[j]) >= spacing;
        });
        if (apart && clear_of(d, i, taken)) kept.push_back(i);
    }
    return kept;
}

/// The markers of a series (indices into d) that stand at least `spacing` apart on the
/// page and clear of the markers of earlier series (`taken`): evenly spaced points at a
/// whole step (strided_markers, less those an earlier series' marker stands for) where
/// that keeps half as many as greedy_markers or more; else greedy_markers: a series sampled
/// finely where it moves slowly (a plateau) or drawn small keeps a marker every `spacing`.
std::vector<std::size_t> spaced_markers(const device_series& d, double spacing, const std::vector<disc>& taken = {}) {
    std::vector<std::size_t> kept = greedy_markers(d, spacing, taken);
    std::vector<std::size_t> strided = strided_markers(d, spacing);
    std::erase_if(strided, [&](std::size_t i) { return !clear_of(d, i, taken); });
    if (!strided.empty() && 2 * strided.size() >= kept.size()) return strided;
    return kept;
}

/// The markers a panel draws of each series (indices into dev) and whether a series' own
/// markers crowd: a series' markers stand 1.5 diameters apart (spaced_markers), and as far
/// (1.5 times the two diameters' mean) from every marker an earlier series of the panel
/// draws inside `area`: where markers of two series would pile, the earlier stands for
/// both. Measured data and what moves keep every point and keep nothing off (spaces_markers).
struct marker_choice {
    std::vector<std::vector<std::size_t>> kept;
    std::vector<bool> crowded;
};

marker_choice choose_markers(const theme& th, const panel& p, const std::vector<device_series>& dev, const rect& area) {
    marker_choice out{std::vector<std::vector<std::size_t>>(p.data.size()), std::vector<bool>(p.data.size(), false)};
    std::vector<std::pair<std::pair<double, double>, double>> placed;  // centre, diameter
    for (std::size_t k = 0; k < p.data.size() && k < dev.size(); ++k) {
        const device_series& d = dev[k];
        const std::size_t n = std::min(d.x.size(), d.y.size());
        if (!spaces_markers(p.data[k])) {
            for (std::size_t i = 0; i < n; ++i) out.kept[k].push_back(i);
            continue;
        }
        const double diameter = 2 * th.marker_radius_pt * p.data[k].marker_scale;
        std::vector<disc> taken;
        for (const auto& [c, other] : placed) taken.push_back({c.first, c.second, 0.75 * (diameter + other)});
        out.kept[k] = spaced_markers(d, 1.5 * diameter, taken);
        std::size_t finite = 0;
        for (std::size_t i = 0; i < n; ++i) finite += std::isfinite(d.x[i] + d.y[i]);
        out.crowded[k] = greedy_markers(d, 1.5 * diameter).size() != finite;
        for (std::size_t i : out.kept[k]) {
            const bool inside =
                d.x[i] >= area.x && d.x[i] <= area.x + area.w && d.y[i] >= area.y && d.y[i] <= area.y + area.h;
            if (inside) placed.push_back({{d.x[i], d.y[i]}, diameter});
        }
    }
    return out;
}

/// The series as drawn: markers chosen by choose_markers; a series whose own markers would
/// crowd is drawn as a thin line through all its points, with the markers that stand
/// apart, and so is one that `alike` names (a series of the same legend entry crowds in
/// another panel: the entry's glyph shows what each of its series draws). `crowded` says
/// which series are drawn with that line.
struct spaced_series {
    std::vector<device_series> markers;  // per series: the markers drawn
    std::vector<bool> crowded;           // per series: drawn as a line too
};

spaced_series space_markers(const theme& th, const panel& p, const panel_geometry& g,
                            const std::vector<bool>& alike = {}) {
    const marker_choice chosen = choose_markers(th, p, g.dev, g.area);
    spaced_series out{g.dev, chosen.crowded};
    for (std::size_t k = 0; k < p.data.size(); ++k) {
        if (k < alike.size() && alike[k] && spaces_markers(p.data[k])) out.crowded[k] = true;
        if (!spaces_markers(p.data[k])) continue;
        device_series& d = out.markers[k];
        d.x.clear();
        d.y.clear();
        for (std::size_t i : chosen.kept[k]) {
            d.x.push_back(g.dev[k].x[i]);
            d.y.push_back(g.dev[k].y[i]);
        }
    }
    return out;
}

/// The width of the line through a crowded series, in units of the series' line width.
constexpr double crowded_width = 0.6;

/// The line through a crowded series: its curve sampled as a line of its own is (within
/// curve_tolerance of it; the markers stand on it), or through its points if it has none.
void stroke_crowded(cairo_t* cr, const theme& th, const series& s, const panel_geometry& g, std::size_t k,
                    const rect& clip) {
    device_series line = g.dev[k];
    line.sampled = static_cast<bool>(s.curve);
    // Not observed: whether a series crowds depends on the layout tried (the curves test
    // looks for every observed sampling in the file); the typeset test measures these lines.
    if (s.curve) sample_curve(*s.curve, g.mx, g.my, clip, curve_tolerance(cr), line.lx, line.ly, nullptr, false);
    set_color(cr, th, s);
    set_line_style(cr, th, line_style::solid, crowded_width * s.width_scale);
    stroke_polyline(cr, line, clip);
}

/// Logs series k as draw_series strokes it (glyphs_drawn): its line, or the thin line of a
/// crowded series of markers only, and its marker where any is drawn.
void log_series(const series& s, std::size_t k, const spaced_series& spaced) {
    const glyph_log& log = current_glyph_log();
    if (!log.out) return;
    glyph g{s.label.markup, log.at, s.line, s.width_scale, marker_style::none, s.color, s.rgb_color};
    if (log.given && k < log.given->data.size()) g.label = log.given->data[k].label.markup;
    if (s.line == line_style::none && spaced.crowded[k]) {
        g.line = line_style::solid;
        g.width_scale = crowded_width * s.width_scale;
    }
    if (!spaced.markers[k].x.empty()) g.marker = s.marker;
    if (g.line != line_style::none || g.marker != marker_style::none) log.out->series.push_back(g);
}

/// The panel's lines, error bars and markers (those whose centre is inside, spaced by
/// space_markers) clipped to the axes: automatic limits leave the markers room (layout), a
/// range the user set may put them on the frame, where they are cut cleanly. A drawing's
/// markers are whole.
void draw_series(cairo_t* cr, const theme& th, const panel& p, const panel_geometry& g, const spaced_series& spaced,
                 const pass_gate& gate) {
    const rect& area = g.area;
    const double reach = th.line_width_pt;
    cairo_save(cr);
    cairo_rectangle(cr, area.x, area.y, area.w, area.h);
    cairo_clip(cr);
    const rect clip{area.x - reach, area.y - reach, area.w + 2 * reach, area.h + 2 * reach};
    for (std::size_t k = 0; k < p.data.size(); ++k) {
        const auto& s = p.data[k];
        if (!gate.draws(s.overlay)) continue;
        log_series(s, k, spaced);
        if (s.line == line_style::none) {
            if (spaced.crowded[k]) stroke_crowded(cr, th, s, g, k, clip);
            continue;
        }
        set_color(cr, th, s);
        set_line_style(cr, th, s.line, s.width_scale);
        stroke_polyline(cr, g.dev[k], clip);
    }
    // Error bars over the lines and under the markers, clipped to the axes as the lines are.
    for (std::size_t k = 0; k < p.data.size(); ++k) {
        if (g.dev[k].bars.empty() || !gate.draws(p.data[k].overlay)) continue;
        set_color(cr, th, p.data[k]);
        draw_error_bars(cr, th, p.data[k], g.dev[k].bars);
    }
    if (p.frameless) {  // a drawing (a pendulum's bob) has no frame to cut its markers at
        cairo_restore(cr);
        cairo_save(cr);
    }
    // draw_markers keeps markers whose centre is within a radius of the rect it is given.
    const double inward = th.marker_radius_pt - 1e-6 * (area.w + area.h);
    const rect centres{area.x + inward, area.y + inward, area.w - 2 * inward, area.h - 2 * inward};
    for (std::size_t k = 0; k < p.data.size(); ++k) {
        if (p.data[k].marker == marker_style::none || !gate.draws(p.data[k].overlay)) continue;
        set_color(cr, th, p.data[k]);
        draw_markers(cr, th, p.data[k], spaced.markers[k], centres);
    }
    cairo_restore(cr);
}

/// The markers draw_series draws that stay put (those of an animation's moving parts
/// move), as discs of their ink.
std::vector<keep_out> drawn_markers(const theme& th, const panel& p, const spaced_series& spaced, const rect& area) {
    std::vector<keep_out> discs;
    for (std::size_t k = 0; k < p.data.size(); ++k) {
        const series& s = p.data[k];
        if (s.marker == marker_style::none || s.overlay) continue;
        const double reach = marker_reach(th, s);
        const device_series& d = spaced.markers[k];
        for (std::size_t i = 0; i < d.x.size() && i < d.y.size(); ++i) {
            // Drawn where the centre is inside the axes (draw_series).
            if (d.x[i] >= area.x && d.x[i] <= area.x + area.w && d.y[i] >= area.y && d.y[i] <= area.y + area.h) {
                discs.push_back({d.x[i], d.y[i], reach});
            }
        }
    }
    return discs;
}

/// The ink of a series' error bars, each bar and its two caps, as segments tick marks stop short of.
void add_bar_ink(std::vector<ink_segment>& out, const theme& th, const series& s, const device_series& d) {
    const double r = 0.5 * line_width(th, th.line_width_pt * s.width_scale);
    const double c = cap_half_width(th, s);
    for (const device_bar& b : d.bars) {
        out.push_back({b.x0, b.y0, b.x1, b.y1, r});
        for (const auto& [x, y] : {std::pair{b.x0, b.y0}, std::pair{b.x1, b.y1}}) {
            out.push_back({b.vertical ? x - c : x, b.vertical ? y : y - c, b.vertical ? x + c : x, b.vertical ? y : y + c, r});
        }
    }
}

/// The ink that stays put which tick marks stop short of: drawn_markers, and the lines and
/// error bars draw_series strokes, where they pass near the frame.
tick_clearance tick_ink(const theme& th, const panel& p, const panel_geometry& g, const spaced_series& spaced) {
    tick_clearance ink{drawn_markers(th, p, spaced, g.area), {}};
    const double band = th.tick_length_pt + tick_gap(th);
    for (std::size_t k = 0; k < p.data.size(); ++k) {
        const series& s = p.data[k];
        if (s.overlay) continue;
        const device_series& d = g.dev[k];
        if (s.line != line_style::none) {
            add_ink_near_frame(ink.segments, d.line_x(), d.line_y(),
                               0.5 * line_width(th, th.line_width_pt * s.width_scale), g.area, band);
        } else if (spaced.crowded[k]) {
            add_ink_near_frame(ink.segments, d.x, d.y,
                               0.5 * line_width(th, crowded_width * th.line_width_pt * s.width_scale), g.area, band);
        }
        add_bar_ink(ink.segments, th, s, d);
    }
    return ink;
}

/// The panel as its legend shows it: a series of markers only that crowds (space_markers)
/// with the thin line it is drawn with (stroke_crowded); a series with a line of its own
/// shows that line.
panel as_shown(const panel& p, const std::vector<bool>& crowded) {
    panel shown = p;
    for (std::size_t k = 0; k < shown.data.size() && k < crowded.size(); ++k) {
        series& s = shown.data[k];
        if (!crowded[k] || s.line != line_style::none) continue;
        s.line = line_style::solid;
        s.width_scale *= crowded_width;
    }
    return shown;
}

/// The frame, the ticks and the tick labels, all at tick_gap from the frame: x labels on one
/// baseline below their highest ink (and below the ink of y labels that hang under their
/// baseline), y labels with their ink ending there, centred on a digit's height. Returns the
/// x labels' baseline.
double draw_frame_and_ticks(cairo_t* cr, const text_engine& text, const theme& th, const panel_plan& plan,
                            const panel_geometry& g, const tick_clearance& ink) {
    const rect& area = g.area;
    set_foreground(cr, th);
    cairo_set_dash(cr, nullptr, 0, 0);
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_BUTT);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_MITER);
    cairo_set_line_width(cr, line_width(th, th.frame_width_pt));
    cairo_rectangle(cr, area.x, area.y, area.w, area.h);
    cairo_stroke(cr);
    draw_ticks(cr, th, plan.xt, g.mx, area, true, ink);
    draw_ticks(cr, th, plan.yt, g.my, area, false, ink);
    const double x_baseline = area.y + area.h + plan.xtick_gap + plan.xtick_up;
    for (std::size_t i = 0; i < plan.xt.major.size(); ++i) {
        const double d = g.mx(plan.xt.major[i]);
        if (d < area.x - 0.01 || d > area.x + area.w + 0.01) continue;
        const text_ink ink = text.ink(plan.xt.labels[i], th.tick_font_pt);
        text.draw_on_baseline(plan.xt.labels[i], th.tick_font_pt, d - ink.x - 0.5 * ink.w, x_baseline, false, 0.5);
    }
    for (std::size_t i = 0; i < plan.yt.major.size(); ++i) {
        const double d = g.my(plan.yt.major[i]);
        if (d < area.y - 0.01 || d > area.y + area.h + 0.01) continue;
        const text_ink ink = text.ink(plan.yt.labels[i], th.tick_font_pt);
        text.draw_on_baseline(plan.yt.labels[i], th.tick_font_pt, area.x - plan.tick_gap - ink.x - ink.w,
                              d + 0.5 * plan.digit_h, false, 1.0);
    }
    return x_baseline;
}

/// Axis labels at label_gap from their own panel's tick labels, panel label above the top
/// tick label.
void draw_axis_labels(const text_engine& text, const theme& th, const panel& p, const panel_plan& plan,
                      const rect& area, double x_baseline) {
    if (!p.x.label.empty()) {
        const text_ink ink = text.ink(p.x.label.markup, th.label_font_pt);
        const double top = x_baseline + plan.xtick_down + plan.label_gap;
        text.draw_on_baseline(p.x.label, th.label_font_pt, area.x + 0.5 * area.w - ink.x - 0.5 * ink.w, top - ink.y,
                              false, 0.5);
    }
    if (!p.y.label.empty()) {
        // Turned by -90 degrees: the text's down is the page's right.
        const text_ink ink = text.ink(p.y.label.markup, th.label_font_pt);
        const double right = area.x - plan.tick_gap - plan.own_ytick_w - plan.label_gap;
        text.draw_on_baseline(p.y.label, th.label_font_pt, right - (ink.y + ink.h),
                              area.y + 0.5 * area.h + ink.x + 0.5 * ink.w, true, 0.5);
    }
    if (!p.label.empty()) {
        const text_ink ink = text.ink(p.label.markup, th.label_font_pt);
        const double bottom = area.y - 0.5 * plan.digit_h - plan.label_gap;
        text.draw_on_baseline(p.label, th.label_font_pt, area.x - ink.x, bottom - (ink.y + ink.h));
    }
}

/// Notes the drawn markers whose ink reaches across the frame, which draw_series cuts at
/// it: a range the user set puts them there (automatic limits leave them room).
void note_markers_on_frame(const panel& p, const panel_plan& plan, const std::vector<keep_out>& discs,
                           const rect& area) {
    const auto cut = std::count_if(discs.begin(), discs.end(), [&](const keep_out& d) {
        return d.x - d.r < area.x || d.x + d.r > area.x + area.w || d.y - d.r < area.y || d.y + d.r > area.y + area.h;
    });
    if (cut == 0) return;
    const auto range = [](const char* axis, const tick_set& t) {
        char buf[96];
        std::snprintf(buf, sizeof buf, "%s from %.6g to %.6g", axis, t.lo, t.hi);
        return std::string(buf);
    };
    std::string set = p.x.exact_range ? range("x", plan.xt) : "";
    if (p.y.exact_range) set += (set.empty() ? "" : " and ") + range("y", plan.yt);
    const bool papers = p.y.paper_range && p.y.min == p.y.paper_range->first && p.y.max == p.y.paper_range->second;
    const std::string name = p.label.empty() ? "a panel" : "panel " + markup_text(p.label.markup);
    const std::string whose = set.empty()       ? ": its axes' range"
                              : papers ? ": the paper's range (" + set + ")"
                                       : ": the range set (" + set + ")";
    layout_notes::note(name + whose + " puts " + std::to_string(cut) + (cut == 1 ? " marker" : " markers") +
                       " on the frame, cut there; widen the range to show them whole");
}

/// A panel's changing text (a clock): a drawing's on the line it keeps above itself, after
/// its label (panel::overlay_line); else inside the top left corner, which a phase portrait
/// leaves free.
void draw_overlay_label(const text_engine& text, const theme& th, const panel& p, const rect& area) {
    const double pad = th.padding_pt;
    if (!(p.frameless && p.overlay_line)) {
        text.draw(p.overlay_label, th.label_font_pt, area.x + pad, area.y + pad, 0.0, 0.0);
        return;
    }
    double x = area.x;
    if (!p.label.empty()) {
        const text_ink ink = text.ink(p.label.markup, th.label_font_pt);
        x += ink.x + ink.w + th.label_font_pt;
    }
    text.draw(p.overlay_label, th.label_font_pt, x, area.y - 0.4 * pad, 0.0, 1.0);  // as the label
}

/// Draws one panel as `placed` (place_with_legend) puts it and its legend; `alike` names
/// the series drawn crowded (space_markers) for a series of their legend entry elsewhere.
void draw_panel(cairo_t* cr, const text_engine& text, const theme& th, const panel& p, const panel_plan& plan,
                const placed_panel& placed, const std::vector<bool>& alike, const pass_gate& gate) {
    const double pad = th.padding_pt;
    const rect& area = placed.g.area;
    const spaced_series spaced = space_markers(th, p, placed.g, alike);
    draw_series(cr, th, p, placed.g, spaced, gate);
    if (!p.overlay_label.empty() && gate.draws(true)) {
        set_foreground(cr, th);
        draw_overlay_label(text, th, p, area);
    }
    if (!gate.draws(false)) return;
    if (p.frameless) {
        // A drawing: only its title and legend.
        set_foreground(cr, th);
        if (!p.label.empty()) text.draw(p.label, th.label_font_pt, area.x, area.y - 0.4 * pad, 0.0, 1.0);
    } else {
        const tick_clearance ink = tick_ink(th, p, placed.g, spaced);
        note_markers_on_frame(p, plan, ink.discs, area);
        const double x_baseline = draw_frame_and_ticks(cr, text, th, plan, placed.g, ink);
        draw_axis_labels(text, th, p, plan, area, x_baseline);
    }
    if (!placed.legend_box && !placed.legend_band) return;
    const panel shown = as_shown(p, spaced.crowded);
    if (placed.legend_box) draw_legend(cr, text, th, shown, plan.legend, *placed.legend_box);
    if (placed.legend_band) draw_legend_band(cr, text, th, shown, plan.legend, *placed.legend_band);
}

/// True if every panel's legend would list the same entries, drawn alike: one legend can
/// then stand for all. Panels of different kinds each keep their own.
bool same_legend_entries(const std::vector<panel>& panels) {
    const auto entries = [](const panel& p) {
        std::vector<std::size_t> v;  // legend entries refer to series by index
        for (std::size_t i = 0; i < p.data.size(); ++i) {
            if (!p.data[i].label.empty()) v.push_back(i);
        }
        return v;
    };
    const auto first = entries(panels.front());
    for (const auto& p : panels) {
        const auto these = entries(p);
        if (these.size() != first.size()) return false;
        for (std::size_t i = 0; i < these.size(); ++i) {
            if (these[i] != first[i]) return false;
            const series& a = panels.front().data[first[i]];
            const series& b = p.data[these[i]];
            if (a.label.markup != b.label.markup || a.line != b.line || a.marker != b.marker || a.color != b.color) {
                return false;
            }
        }
    }
    return true;
}

}  // namespace

void apply_data_style(series& s, const theme& th) {
    const auto slot = static_cast<std::size_t>(s.data_slot);
    if (!th.data_markers.empty()) s.marker = th.data_markers[slot % th.data_markers.size()];
    if (!th.data_palette.empty() && !s.rgb_color) s.rgb_color = th.data_palette[slot % th.data_palette.size()];
}

/// One series in the theme's style: a data file's slot, then the style of its key (a rod,
/// style_line_only, takes only the key's line, and none of "none").
void apply_theme_style(series& s, const theme& th) {
    if (s.data_slot >= 0) apply_data_style(s, th);
    const auto it = s.style_key.empty() ? th.styles.end() : th.styles.find(s.style_key);
    if (it == th.styles.end()) return;
    const named_style& st = it->second;
    if (s.style_line_only) {
        if (st.line && *st.line != line_style::none) s.line = *st.line;
        return;
    }
    if (st.line) s.line = *st.line;
    if (st.marker) s.marker = *st.marker;
}

figure with_theme_styles(const figure& fig, const theme& th) {
    figure styled = fig;
    for (auto* panels : {&styled.panels, &styled.peers}) {  // peers planned as their own files draw them
        for (auto& p : *panels) {
            for (auto& s : p.data) apply_theme_style(s, th);
        }
    }
    return styled;
}

namespace {

thread_local layout_notes* current_notes = nullptr;

/// The theme at the sizes a figure's contents are decided at (decided_sizes).
theme deciding_theme(const theme& th) {
    theme d = th;
    const text_sizes at = decided_sizes(th);
    d.tick_font_pt = at.tick_pt;
    d.label_font_pt = at.label_pt;
    d.legend_font_pt = at.legend_pt;
    return d;
}

/// The figure's panels and, after them, its peers (panels of other files of the set).
std::vector<panel> panels_with_peers(const figure& fig) {
    std::vector<panel> all = fig.panels;
    all.insert(all.end(), fig.peers.begin(), fig.peers.end());
    return all;
}

/// The grid's cells below `top`, one per panel.
std::vector<rect> make_cells(const figure& fig, page_size size, double top) {
    const double cw = size.width_pt / fig.cols;
    const double ch = (size.height_pt - top) / fig.rows;
    std::vector<rect> cells;
    for (std::size_t i = 0; i < fig.panels.size(); ++i) {
        cells.push_back(
            rect{static_cast<double>(i % fig.cols) * cw, top + static_cast<double>(i / fig.cols) * ch, cw, ch});
    }
    return cells;
}

/// Every planned panel (the peers too) gets a cell the size of this figure's.
std::vector<rect> planned_cells(const std::vector<rect>& own, std::size_t planned) {
    std::vector<rect> all = own;
    if (!all.empty()) all.resize(planned, all.front());
    return all;
}

/// The panels planned at the theme's sizes: margins shared, crowded ticks thinned, data
/// kept off the frame. With `decided`, each axis starts from the ticks decided there, so
/// that a tick label that had to go at the deciding sizes goes here too.
std::vector<panel_plan> plan_panels(const text_engine& text, const std::vector<panel>& planned, const theme& th,
                                    const std::vector<rect>& cells, int cols,
                                    const std::vector<panel_plan>* decided) {
    std::vector<panel_plan> plans;
    for (std::size_t i = 0; i < planned.size(); ++i) {
        plans.push_back(decided ? plan_panel(text, planned[i], th, (*decided)[i].x_limit, (*decided)[i].y_limit)
                                : plan_panel(text, planned[i], th));
    }
    share_margins(plans, th, cols);
    thin_crowded_ticks(text, planned, plans, cells, th, cols);
    keep_data_off_frame(planned, plans, cells, th);
    return plans;
}

/// The figure's title, centred above everything at padding from the top; its height with
/// the space below it, or 0.
double draw_title(cairo_t* cr, const text_engine& text, const figure& fig, const theme& th, page_size size,
                  const pass_gate& gate) {
    if (fig.title.empty() || !(th.title_font_pt > 0)) return 0;
    const text_ink ink = text.ink(fig.title.markup, th.title_font_pt);
    if (gate.draws(false)) {
        set_foreground(cr, th);
        text.draw_on_baseline(fig.title, th.title_font_pt, 0.5 * size.width_pt - ink.x - 0.5 * ink.w,
                              th.padding_pt - ink.y, false, 0.5);
    }
    return th.padding_pt + ink.h + 0.5 * th.padding_pt;
}

std::string number_text(const char* format, double value) {
    char buf[32];
    std::snprintf(buf, sizeof buf, format, value);
    return buf;
}

/// Axes too small to read are an error, not a figure: less than three tick font sizes.
void check_room(const figure& fig, const std::vector<panel_plan>& plans, const std::vector<rect>& cells,
                const theme& th, page_size size) {
    const double least = 3 * th.tick_font_pt;
    for (std::size_t i = 0; i < fig.panels.size(); ++i) {
        const rect area = axes_area(plans[i], cells[i]);
        if (area.w >= least && area.h >= least) continue;
        constexpr double cm = 2.54 / 72;
        const auto cm_of = [&](double pt) { return number_text("%.1f", pt * cm); };
        throw layout_error("a figure of " + cm_of(size.width_pt) + " x " + cm_of(size.height_pt) +
                           " cm leaves panel " + std::to_string(i + 1) + " of " + std::to_string(fig.panels.size()) +
                           " axes of " + cm_of(std::max(area.w, 0.0)) + " x " + cm_of(std::max(area.h, 0.0)) +
                           " cm, too small for " + number_text("%.3g", th.tick_font_pt) +
                           " pt text: make the figure larger (figure_width_cm and figure_height_cm, or "
                           "panel_width_cm) or its text smaller (tick_font_pt, label_font_pt, legend_font_pt)");
    }
}

void record_frames(const figure& fig, const std::vector<panel_plan>& plans, const std::vector<rect>& cells,
                   std::vector<panel_frame>* frames) {
    if (!frames) return;
    frames->clear();
    for (std::size_t i = 0; i < fig.panels.size(); ++i) {
        const rect a = panel_area(fig.panels[i], plans[i], cells[i]);
        frames->push_back(panel_frame{a.x, a.y, a.w, a.h, plans[i].xt.lo, plans[i].xt.hi, plans[i].yt.lo,
                                      plans[i].yt.hi, fig.panels[i].frameless, plans[i].xt.labels,
                                      plans[i].yt.labels});
    }
}

/// A panel as a note names it: its label as text, or its place in the figure.
std::string panel_name(const panel& p, std::size_t i) {
    const std::string label = p.label.empty() ? std::string() : markup_text(p.label.markup);
    return label.empty() ? "panel " + std::to_string(i + 1) : "panel " + label;
}

/// Everything draw_figure has decided before it draws the panels.
struct figure_layout {
    const figure* fig = nullptr;
    std::vector<panel> planned;        // the panels, then the peers
    std::vector<panel_plan> plans;     // at the theme's sizes
    std::vector<panel_plan> decided;   // at the sizes the contents are decided at
    theme deciding;
    std::vector<rect> cells;
    double title_h = 0;
};

/// Where each panel's own legend goes: inside the axes where the legend at the deciding
/// sizes finds room, else in a band above them (an automatic legend) or none, and said.
/// A band is a row of its own above the cell; every cell of its row moves down by the
/// row's highest band, so that the row's axes stay level, and the files of a set (peers)
/// by the highest band of any of them.
struct own_legends {
    std::vector<legend_spot> spots;
    std::vector<std::optional<rect>> bands;
};

/// Whether panel i's axes in the cell `squeezed` keep three quarters of their height in its
/// own cell, and room to read (three tick lines), at the deciding sizes.
bool axes_keep_room(const figure_layout& f, std::size_t i, const rect& squeezed) {
    const double least = 3 * f.deciding.tick_font_pt;
    const rect area = axes_area(f.decided[i], squeezed);
    const rect before = axes_area(f.decided[i], f.cells[i]);
    return area.w >= least && area.h >= std::max(least, 0.75 * before.h);
}

/// In the files of one panel each (a set of peers), a band that would squeeze the axes below
/// three quarters of their height (or below room to read, three tick lines), at the deciding
/// sizes, goes: those panels show no legend, and say so, as a shared legend does. Every
/// file of a set decides alike, as their bands are the same.
void drop_bands_without_room(const figure_layout& f, std::vector<double>& row_band, own_legends& out,
                             const pass_gate& gate) {
    const figure& fig = *f.fig;
    if (fig.peers.empty()) return;  // a whole figure's band moves its rows down; they keep their height
    for (std::size_t i = 0; i < fig.panels.size(); ++i) {
        double& band = row_band[i / static_cast<std::size_t>(fig.cols)];
        if (band <= 0) continue;
        rect squeezed = f.cells[i];
        squeezed.y += band;
        squeezed.h -= band;
        if (!axes_keep_room(f, i, squeezed)) band = 0;
    }
    for (std::size_t i = 0; i < fig.panels.size(); ++i) {
        if (out.spots[i] != legend_spot::band || row_band[i / static_cast<std::size_t>(fig.cols)] > 0) continue;
        out.spots[i] = legend_spot::none;
        out.bands[i].reset();
        if (gate.draws(false)) {
            layout_notes::note(panel_name(fig.panels[i], i) + ": no legend: no spot inside its axes is free of data, "
                               "and a band above them would leave the axes less than three quarters of their "
                               "height, at " + number_text("%.4g", f.deciding.legend_font_pt) +
                               " pt legend text (the size a LaTeX overlay sets it at, or the theme's); name the "
                               "lines in the caption, or make the panels larger (panel_width_cm)");
        }
    }
}

/// After legend bands moved the cells down (shorter axes): the deciding plans' crowded
/// ticks are thinned again in `deciding_cells` (the cells moved by the bands at the deciding
/// sizes, the same in every route, and no larger than the cells), and the theme's plans
/// made again from them in the cells, data kept off the frame: every route thins alike.
void replan_in_cells(const text_engine& text, figure_layout& f, const theme& th, const std::vector<rect>& deciding_cells) {
    thin_crowded_ticks(text, f.planned, f.decided, planned_cells(deciding_cells, f.planned.size()), f.deciding,
                       f.fig->cols);
    f.plans = plan_panels(text, f.planned, th, planned_cells(f.cells, f.planned.size()), f.fig->cols, &f.decided);
}

/// The tick labels of an axis as a note lists them.
std::string listed(const std::vector<std::string>& labels) {
    std::string out;
    for (const auto& l : labels) out += (out.empty() ? "" : ", ") + markup_text(l);
    return out.empty() ? "none" : out;
}

/// Whether panel i's own legend (of the planned panels: the figure's, then its peers, in a
/// cell the size of the first) has a spot inside its axes free of data, at the deciding
/// sizes, with its cell moved down by `shift` (the band of its row).
bool legend_fits_inside(cairo_t* cr, const figure_layout& f, std::size_t i, double shift) {
    const panel& p = f.planned[i];
    const panel_plan& d = f.decided[i];
    rect cell = i < f.fig->panels.size() ? f.cells[i] : f.cells.front();
    cell.y += shift;
    cell.h -= shift;
    const auto g = place_panel(p, d, panel_area(p, d, cell), curve_tolerance(cr), f.deciding.line_width_pt);
    return d.legend.entries.empty() || legend_inside(p, d.legend, g, f.deciding).has_value();
}

/// The cell a band above panel i spans: its own and the cells to its right in its row up to
/// the first panel with a legend of its own (their row moves down by the band anyway), so
/// that the band takes fewer lines and every panel of the row keeps more of its height (a
/// drawing of the pendulum under the five entries of two starts' legend stays a drawing).
/// Decided at the deciding sizes, as band_spans_axes is.
rect band_cell(const figure_layout& f, std::size_t i) {
    const figure& fig = *f.fig;
    rect cell = f.cells[i];
    const auto cols = static_cast<std::size_t>(fig.cols);
    const std::size_t row_end = std::min(fig.panels.size(), (i / cols + 1) * cols);
    for (std::size_t k = i + 1; k < row_end && f.plans[k].legend.entries.empty(); ++k) {
        cell.w = f.cells[k].x + f.cells[k].w - cell.x;
    }
    return cell;
}

/// One round of place_own_legends: each panel's spot with its row moved down by row_band,
/// and the band each row then needs (its highest band; the peers' in row 0).
struct row_bands {
    std::vector<double> deciding;  // at the deciding sizes: what decisions are made with
    std::vector<double> drawn;     // at the theme's: what the cells move by
};

row_bands own_legend_round(cairo_t* cr, const theme& th, const figure_layout& f, const std::vector<double>& row_band,
                           own_legends& out) {
    const figure& fig = *f.fig;
    const auto row = [&](std::size_t i) { return i < fig.panels.size() ? i / static_cast<std::size_t>(fig.cols) : 0; };
    row_bands need{std::vector<double>(row_band.size(), 0.0), std::vector<double>(row_band.size(), 0.0)};
    const double pad = th.padding_pt;
    for (std::size_t i = 0; i < f.planned.size() && !fig.panels.empty(); ++i) {
        const bool own = i < fig.panels.size();
        if (own) {
            out.spots[i] = legend_spot::inside;
            out.bands[i].reset();
        }
        if (legend_fits_inside(cr, f, i, row_band[row(i)])) continue;
        const bool automatic = f.planned[i].legend == legend_place::automatic;
        if (own) out.spots[i] = automatic ? legend_spot::band : legend_spot::none;
        if (!automatic) continue;
        // Decided at the deciding sizes, so that every route spans alike.
        const rect cell = own ? band_cell(f, i) : f.cells.front();
        const bool over_axes = band_spans_axes(f.decided[i], f.deciding, cell);
        const rect band = legend_band_rect(f.plans[i].legend, th, f.plans[i], cell, cell.y + (own ? 0.3 * pad : 0),
                                           over_axes);
        if (own) out.bands[i] = band;
        need.drawn[row(i)] = std::max(need.drawn[row(i)], band.h);
        const double deciding = legend_band_rect(f.decided[i].legend, f.deciding, f.decided[i], cell, 0, over_axes).h;
        need.deciding[row(i)] = std::max(need.deciding[row(i)], std::max(deciding, band.h));
    }
    return need;
}

/// Where each panel's own legend goes, decided with the cells where they end: a panel whose
/// legend fits inside its axes in its own cell may lose that room when a band above another
/// panel of its row moves the row down; it is decided again there (a band of its own, in
/// the row's band), until no row needs a higher band. Moves the cells down by their bands.
own_legends place_own_legends(cairo_t* cr, const text_engine& text, const theme& th, figure_layout& f,
                              const pass_gate& gate) {
    const figure& fig = *f.fig;
    const std::size_t n = fig.panels.size();
    own_legends out{std::vector<legend_spot>(n, legend_spot::inside), std::vector<std::optional<rect>>(n)};
    std::vector<double> deciding_band(static_cast<std::size_t>(fig.rows), 0.0);
    std::vector<double> row_band(deciding_band.size(), 0.0);
    // Decided with the bands at the deciding sizes, alike in every route. Bands only grow,
    // so a few rounds settle (each round's highest band is one of a few).
    for (std::size_t round = 0; round <= f.planned.size(); ++round) {
        const row_bands need = own_legend_round(cr, th, f, deciding_band, out);
        row_band = need.drawn;
        bool higher = false;
        for (std::size_t r = 0; r < deciding_band.size(); ++r) {
            higher = higher || need.deciding[r] > deciding_band[r];
            deciding_band[r] = std::max(deciding_band[r], need.deciding[r]);
        }
        if (!higher) break;
    }
    for (std::size_t i = 0; i < n && gate.draws(false); ++i) {
        if (out.spots[i] != legend_spot::none) continue;
        layout_notes::note(panel_name(fig.panels[i], i) + ": no legend: no spot inside its axes is free of data at " +
                           number_text("%.4g", f.deciding.legend_font_pt) +
                           " pt legend text, and legend = \"inside\" allows no band above them");
    }
    drop_bands_without_room(f, row_band, out, gate);
    bool moved = false;
    std::vector<rect> deciding_cells = f.cells;
    for (std::size_t i = 0; i < n; ++i) {
        const std::size_t r = i / static_cast<std::size_t>(fig.cols);
        const double h = row_band[r];
        const double d = h > 0 ? deciding_band[r] : 0.0;  // a band dropped for room is dropped in both
        f.cells[i].y += h;
        f.cells[i].h -= h;
        deciding_cells[i].y += d;
        deciding_cells[i].h -= d;
        moved = moved || h > 0;
    }
    if (moved) replan_in_cells(text, f, th, deciding_cells);
    return out;
}

/// The panels of a shared legend's set in the set's order, as indices into planned: the
/// figure's panels, or, for a file of one panel of a figure (peers), the figure's panels in
/// their order.
std::vector<std::size_t> set_order(const figure& fig) {
    std::vector<std::size_t> order;
    if (fig.peers.empty()) {
        for (std::size_t i = 0; i < fig.panels.size(); ++i) order.push_back(i);
        return order;
    }
    const std::size_t own = std::min<std::size_t>(fig.place_in_set, fig.peers.size());
    for (std::size_t i = 0; i < own; ++i) order.push_back(1 + i);
    order.push_back(0);
    for (std::size_t i = own; i < fig.peers.size(); ++i) order.push_back(1 + i);
    return order;
}

/// The first panel of the set whose axes have room inside for the legend, at the deciding sizes.
std::optional<std::size_t> shared_legend_panel(cairo_t* cr, const figure_layout& f) {
    const legend_layout& lg = f.decided[0].legend;
    for (std::size_t i : set_order(*f.fig)) {
        const rect cell = i < f.cells.size() ? f.cells[i] : f.cells.front();
        const auto g = place_panel(f.planned[i], f.decided[i], axes_area(f.decided[i], cell), curve_tolerance(cr),
                                   f.deciding.line_width_pt);
        if (legend_inside(f.planned[i], lg, g, f.deciding)) return i;
    }
    return std::nullopt;
}

/// Whether a band of height `band` leaves the files of one panel each room: their axes keep
/// three quarters of their height (and room to read), or the band would squeeze the plots
/// it names. Decided at the deciding sizes.
bool band_leaves_room(const figure_layout& f, page_size size, double band) {
    const std::vector<rect> these = make_cells(*f.fig, size, f.title_h + band + 0.3 * f.deciding.padding_pt);
    for (std::size_t i = 0; i < f.fig->panels.size(); ++i) {
        if (!axes_keep_room(f, i, these[i])) return false;
    }
    return true;
}

/// Where a shared legend goes: the panel that shows it inside its axes, or a band across
/// the top, or neither.
struct shared_legend {
    legend_layout lg;
    std::optional<std::size_t> panel;
    std::optional<rect> band;  // drawn by this file (the first of its set)
};

/// A shared legend goes to the first panel of the set with room for it inside the axes;
/// failing that, to a band across the top, which moves the cells down. Every file of a
/// figure decides alike, so exactly one of them shows the legend, and all of them leave
/// room for a band, which keeps their frames in line; files too small for a band above
/// their axes (band_leaves_room) have no legend, and the first file of the set says so: a
/// caption names the lines. Every panel shows the same series, so the first panel's
/// entries stand for all.
shared_legend place_shared_legend(cairo_t* cr, const text_engine& text, const theme& th, figure_layout& f,
                                  page_size size) {
    const figure& fig = *f.fig;
    shared_legend out{f.plans[0].legend, shared_legend_panel(cr, f), std::nullopt};
    if (out.panel || out.lg.entries.empty()) return out;
    // From the first column's axes (margins are shared) to the page's right padding.
    const rect page{0, f.title_h + 0.3 * th.padding_pt, size.width_pt, size.height_pt};
    const bool first_file = fig.peers.empty() || fig.place_in_set == 0;
    const bool over_axes = band_spans_axes(f.decided[0], f.deciding, page);
    const double decided_band = legend_band_rect(f.decided[0].legend, f.deciding, f.decided[0], page, 0, over_axes).h;
    if (!fig.peers.empty() && !band_leaves_room(f, size, decided_band)) {
        if (first_file) {
            layout_notes::note(
                "no legend: no panel of the set has room for it inside its axes, nor its files for a band above "
                "them, at " + number_text("%.4g", f.deciding.legend_font_pt) +
                " pt legend text (the size a LaTeX overlay sets it at, or the theme's); name the lines in the "
                "caption, or make the panels larger (panel_width_cm)");
        }
        return out;
    }
    const rect band_rect = legend_band_rect(out.lg, th, f.plans[0], page, page.y, over_axes);
    const double band = band_rect.h;
    if (first_file) out.band = band_rect;
    f.cells = make_cells(fig, size, f.title_h + band + 0.3 * th.padding_pt);
    replan_in_cells(text, f, th, make_cells(fig, size, f.title_h + std::max(band, decided_band) + 0.3 * th.padding_pt));
    return out;
}

/// The plans the PDF of an overlay shows: the figure's layout decided at the PDF's sizes
/// (as_pdf), its legends placed as there; its notes are the PDF's, kept quiet here.
std::vector<panel_plan> pdf_plans(cairo_t* cr, const text_engine& text, const figure_layout& f, const theme& as_pdf,
                                  page_size size, bool shared) {
    figure_layout p;
    p.fig = f.fig;
    p.planned = f.planned;
    p.deciding = as_pdf;
    p.title_h = f.title_h;
    p.cells = make_cells(*f.fig, size, f.title_h);
    const std::vector<rect> cells = planned_cells(p.cells, p.planned.size());
    p.decided = plan_panels(text, p.planned, as_pdf, cells, f.fig->cols, nullptr);
    p.plans = plan_panels(text, p.planned, as_pdf, cells, f.fig->cols, &p.decided);
    const layout_notes quiet;
    if (shared) {
        place_shared_legend(cr, text, as_pdf, p, size);
    } else {
        place_own_legends(cr, text, as_pdf, p, pass_gate{draw_pass::overlay});
    }
    return p.plans;
}

/// A LaTeX overlay whose text is larger than the sizes its PDF decides at (a theme's
/// decided_at, which latex_sized_theme sets) decides at its own: where that gives an axis
/// other tick labels than the PDF shows, it says so, axis by axis, so that the routes never
/// differ silently.
void note_route_changes(cairo_t* cr, const text_engine& text, const figure_layout& f, const theme& th,
                        page_size size, bool shared) {
    if (!th.decided_at) return;
    const text_sizes& pdf = *th.decided_at;
    if (f.deciding.tick_font_pt <= pdf.tick_pt && f.deciding.label_font_pt <= pdf.label_pt &&
        f.deciding.legend_font_pt <= pdf.legend_pt) {
        return;  // decided as the PDF is
    }
    theme as_pdf = f.deciding;
    as_pdf.tick_font_pt = pdf.tick_pt;
    as_pdf.label_font_pt = pdf.label_pt;
    as_pdf.legend_font_pt = pdf.legend_pt;
    const std::vector<panel_plan> shown = pdf_plans(cr, text, f, as_pdf, size, shared);
    for (std::size_t i = 0; i < f.fig->panels.size(); ++i) {
        for (const bool horizontal : {true, false}) {
            const auto& here = (horizontal ? f.plans[i].xt : f.plans[i].yt).labels;
            const auto& there = (horizontal ? shown[i].xt : shown[i].yt).labels;
            if (here == there) continue;
            layout_notes::note(panel_name(f.fig->panels[i], i) + ": " + (horizontal ? "x" : "y") +
                               " tick labels " + listed(here) + ", not " + listed(there) + " as the PDF shows: " +
                               number_text("%.4g", f.deciding.tick_font_pt) +
                               " pt tick labels need the room; set tex_agree_pt in the style file to the "
                               "document's size (--tex-font-size) for the same ticks in both");
        }
    }
}

}  // namespace

layout_notes::layout_notes() : outer_(current_notes) { current_notes = this; }

layout_notes::~layout_notes() { current_notes = outer_; }

void layout_notes::note(const std::string& line) {
    if (!current_notes) return;
    auto& lines = current_notes->lines_;
    if (std::find(lines.begin(), lines.end(), line) == lines.end()) lines.push_back(line);
}

namespace {

/// True if a series of the figure (or of its peers) takes a style from the theme: a
/// style key, or a data file's slot.
bool has_style_keys(const figure& fig) {
    const auto keyed = [](const panel& p) {
        return std::any_of(p.data.begin(), p.data.end(),
                           [](const series& s) { return !s.style_key.empty() || s.data_slot >= 0; });
    };
    return std::any_of(fig.panels.begin(), fig.panels.end(), keyed) ||
           std::any_of(fig.peers.begin(), fig.peers.end(), keyed);
}

/// Refuses a figure that cannot be drawn (its grid, the theme's colours and text sizes) and
/// notes angles written two ways (once, not for the overlay pass).
void check_drawable(const figure& fig, const theme& th, draw_pass pass) {
    if (fig.rows < 1 || fig.cols < 1 || fig.panels.size() > static_cast<std::size_t>(fig.rows * fig.cols)) {
        throw std::invalid_argument("figure grid is too small for its panels");
    }
    if (th.palette.empty()) throw bad_input("theme has no colours");
    if (const std::string why = text_size_problem(th); !why.empty()) throw bad_input(why);
    if (pass != draw_pass::overlay) {
        if (const std::string why = angle_notation_problem(fig); !why.empty()) layout_notes::note(why);
    }
}

/// The planned panels (the figure's, then its peers) in the set's order (set_order).
std::vector<panel*> in_order(std::vector<panel>& planned, const std::vector<std::size_t>& order) {
    std::vector<panel*> out;
    for (std::size_t i : order) {
        if (i < planned.size()) out.push_back(&planned[i]);
    }
    return out;
}

/// The series (planned panel, series) that one legend entry stands for, for every entry of
/// the planned panels (same_legend_entry), taken before one_legend leaves the later ones
/// unlabelled.
using entry_groups = std::vector<std::vector<std::pair<std::size_t, std::size_t>>>;

entry_groups legend_entries(const std::vector<panel>& planned, const std::vector<std::size_t>& order) {
    entry_groups groups;
    for (std::size_t i : order) {
        for (std::size_t k = 0; i < planned.size() && k < planned[i].data.size(); ++k) {
            const series& s = planned[i].data[k];
            if (s.label.empty()) continue;
            const auto same = std::find_if(groups.begin(), groups.end(), [&](const auto& g) {
                return same_legend_entry(planned[g.front().first].data[g.front().second], s);
            });
            if (same == groups.end()) {
                groups.push_back({{i, k}});
            } else {
                same->push_back({i, k});
            }
        }
    }
    return groups;
}

/// Whether a peer (a panel of another file of the set) has a series whose markers are
/// spaced and that shares a legend entry with another series.
bool peer_shares_markers(const figure_layout& f, std::size_t i, const entry_groups& entries) {
    return std::any_of(entries.begin(), entries.end(), [&](const auto& g) {
        return g.size() > 1 && std::any_of(g.begin(), g.end(), [&](const auto& m) {
                   return m.first == i && spaces_markers(f.planned[i].data[m.second]);
               });
    });
}

/// Which series of each planned panel are drawn crowded (space_markers): those whose own
/// markers crowd in their panel as placed (a peer in a cell of the figure's size), and every
/// series of a legend entry one of whose series does, so that the entry's glyph draws
/// what each of them draws.
std::vector<std::vector<bool>> crowded_alike(cairo_t* cr, const theme& th, const figure_layout& f,
                                             const std::vector<placed_panel>& placed, const entry_groups& entries) {
    std::vector<std::vector<bool>> crowded(f.planned.size());
    for (std::size_t i = 0; i < f.planned.size(); ++i) {
        const panel& p = f.planned[i];
        if (i < placed.size()) {
            crowded[i] = space_markers(th, p, placed[i].g).crowded;
        } else if (!f.cells.empty() && peer_shares_markers(f, i, entries)) {
            const rect area = panel_area(p, f.plans[i], f.cells.front());
            crowded[i] = space_markers(th, p, place_panel(p, f.plans[i], area, curve_tolerance(cr), th.line_width_pt))
                             .crowded;
        }
        crowded[i].resize(p.data.size(), false);
    }
    for (const auto& g : entries) {
        const bool any = std::any_of(g.begin(), g.end(), [&](const auto& m) { return crowded[m.first][m.second]; });
        for (const auto& m : g) crowded[m.first][m.second] = crowded[m.first][m.second] || any;
    }
    return crowded;
}

/// Draws the figure's panels as placed, their series drawn crowded as `crowded` says
/// (crowded_alike), after recording their frames.
void draw_placed(cairo_t* cr, const text_engine& text, const theme& th, figure_layout& f,
                 const std::vector<placed_panel>& placed, const std::vector<std::vector<bool>>& crowded,
                 std::vector<panel_frame>* frames, const pass_gate& gate) {
    const figure& fig = *f.fig;
    f.plans.resize(fig.panels.size());
    record_frames(fig, f.plans, f.cells, frames);
    glyph_log& log = current_glyph_log();
    for (std::size_t i = 0; i < fig.panels.size(); ++i) {
        log.at = i;
        log.given = &fig.panels[i];
        draw_panel(cr, text, th, f.planned[i], f.plans[i], placed[i], crowded[i], gate);
    }
    log.at = 0;
    log.given = nullptr;
}

}  // namespace

namespace {

/// Layouts done by this process (figure_layouts).
std::atomic<std::size_t> layouts_done{0};

}  // namespace

std::size_t figure_layouts() { return layouts_done.load(std::memory_order_relaxed); }

void draw_figure(cairo_t* cr, const figure& unstyled, const theme& th, page_size size, draw_pass pass,
                 std::vector<placed_text>* texts, bool vector, std::vector<panel_frame>* frames) {
    layouts_done.fetch_add(1, std::memory_order_relaxed);
    const bool any_key = has_style_keys(unstyled);
    const figure styled = any_key ? with_theme_styles(unstyled, th) : figure{};
    const figure& fig = any_key ? styled : unstyled;
    check_drawable(fig, th, pass);
    text_engine text(cr, th.font_family);
    text.record_into(texts);
    const pass_gate gate{pass};
    if ((!vector || th.opaque_vector_background) && gate.draws(false)) {
        cairo_set_source_rgb(cr, th.background.r, th.background.g, th.background.b);
        cairo_paint(cr);
    }
    // Shared margins keep the axes of neighbouring panels aligned, and those of panels drawn
    // alone in files of their own (the peers, each in a cell the size of this figure's):
    // a peer is planned as its own file plans it, crowded ticks thinned and all, so that
    // every file of the set reaches the same margins. Plans past the panels are the peers'.
    // What the figure shows (which ticks, where the legend goes) is decided first at the
    // deciding sizes, the same for a PDF and its LaTeX overlays; then laid out at the theme's.
    figure_layout f;
    f.fig = &fig;
    f.planned = panels_with_peers(fig);
    // One legend per figure: shared, where every panel lists the same entries; else each
    // panel's own entries, those an earlier panel of the set shows left out (one_legend).
    const bool shared = fig.shared_legend && !fig.panels.empty() && same_legend_entries(f.planned);
    const entry_groups entries = legend_entries(f.planned, set_order(fig));
    if (!shared) one_legend(in_order(f.planned, set_order(fig)));
    f.deciding = deciding_theme(th);
    f.title_h = draw_title(cr, text, fig, th, size, gate);
    f.cells = make_cells(fig, size, f.title_h);
    const std::vector<rect> cells = planned_cells(f.cells, f.planned.size());
    f.decided = plan_panels(text, f.planned, f.deciding, cells, fig.cols, nullptr);
    f.plans = plan_panels(text, f.planned, th, cells, fig.cols, &f.decided);
    if (!shared) {
        const own_legends own = place_own_legends(cr, text, th, f, gate);
        if (gate.draws(false)) note_route_changes(cr, text, f, th, size, false);
        check_room(fig, f.plans, f.cells, th, size);
        std::vector<placed_panel> placed;
        for (std::size_t i = 0; i < fig.panels.size(); ++i) {
            placed.push_back(place_with_legend(th, f.planned[i], f.plans[i], f.cells[i], own.spots[i], own.bands[i],
                                               curve_tolerance(cr)));
        }
        draw_placed(cr, text, th, f, placed, crowded_alike(cr, th, f, placed, entries), frames, gate);
        return;
    }
    const shared_legend one = place_shared_legend(cr, text, th, f, size);
    if (gate.draws(false)) note_route_changes(cr, text, f, th, size, true);
    check_room(fig, f.plans, f.cells, th, size);
    std::vector<placed_panel> placed;
    for (std::size_t i = 0; i < fig.panels.size(); ++i) {
        const bool here = one.panel && i == *one.panel;
        if (here) f.plans[i].legend = one.lg;
        placed.push_back(place_with_legend(th, f.planned[i], f.plans[i], f.cells[i],
                                           here ? legend_spot::inside : legend_spot::none, std::nullopt,
                                           curve_tolerance(cr)));
    }
    const std::vector<std::vector<bool>> crowded = crowded_alike(cr, th, f, placed, entries);
    if (one.band && gate.draws(false)) {
        draw_legend_band(cr, text, th, as_shown(f.planned[0], crowded[0]), one.lg, *one.band);
    }
    draw_placed(cr, text, th, f, placed, crowded, frames, gate);
}

std::vector<panel_frame> panel_frames(const figure& fig, const theme& th) {
    const page_size size = figure_size(fig, th);
    const surface_ptr surface(cairo_recording_surface_create(CAIRO_CONTENT_COLOR_ALPHA, nullptr));
    check_cairo(cairo_surface_status(surface.get()), "a recording surface");
    const context_ptr cr(cairo_create(surface.get()));
    check_cairo(cairo_status(cr.get()), "a drawing context");
    std::vector<panel_frame> frames;
    draw_figure(cr.get(), fig, th, size, draw_pass::all, nullptr, false, &frames);
    return frames;
}

bool same_content(const figure& a, const figure& b) {
    // Every member of plot::figure but words.
    return a.rows == b.rows && a.cols == b.cols && a.panel_width_cm == b.panel_width_cm &&
           a.panel_aspect == b.panel_aspect && a.shared_legend == b.shared_legend &&
           a.place_in_set == b.place_in_set && a.title == b.title && a.panels == b.panels && a.peers == b.peers;
}

namespace {

/// Whether `drawn` laid out what draw_figure lays out of fig in th on a vector page: the same
/// theme, and the same content once the theme's styles are applied (as draw_figure applies them).
bool laid_out_alike(const figure& fig, const theme& th, const drawing& drawn) {
    if (!drawn.fig || !drawn.th || drawn.raster || drawn.frames.size() != fig.panels.size()) return false;
    if (!(*drawn.th == th)) return false;
    if (same_content(fig, *drawn.fig)) return true;
    return same_content(with_theme_styles(fig, th), with_theme_styles(*drawn.fig, th));
}

}  // namespace

std::vector<panel_frame> panel_frames(const figure& fig, const theme& th, const drawing* drawn) {
    if (drawn && laid_out_alike(fig, th, *drawn)) return drawn->frames;
    return panel_frames(fig, th);
}

drawn_glyphs glyphs_drawn(const figure& fig, const theme& th) {
    drawn_glyphs out;
    glyph_log& log = current_glyph_log();
    const glyph_log outer = log;
    log = glyph_log{&out, 0, nullptr};
    try {
        panel_frames(fig, th);
    } catch (...) {
        log = outer;
        throw;
    }
    log = outer;
    return out;
}

std::vector<std::vector<marker_centres_of>> marker_centres(const figure& unstyled, const theme& th) {
    const figure fig = with_theme_styles(unstyled, th);
    const std::vector<panel_frame> frames = panel_frames(fig, th);
    std::vector<std::vector<marker_centres_of>> out;
    for (std::size_t i = 0; i < fig.panels.size() && i < frames.size(); ++i) {
        const panel& p = fig.panels[i];
        const panel_frame& f = frames[i];
        const axis_map mx{f.x_lo, f.x_hi, p.x.kind == scale::log, f.x, f.x + f.w};
        const axis_map my{f.y_lo, f.y_hi, p.y.kind == scale::log, f.y + f.h, f.y};
        std::vector<device_series> dev;
        for (const auto& s : p.data) dev.push_back(to_device(s, mx, my));
        const rect area{f.x, f.y, f.w, f.h};
        const marker_choice chosen = choose_markers(th, p, dev, area);
        std::vector<marker_centres_of> panel_centres;
        for (std::size_t k = 0; k < p.data.size(); ++k) {
            marker_centres_of c;
            c.radius = th.marker_radius_pt * p.data[k].marker_scale;
            c.spaced = spaces_markers(p.data[k]);
            for (std::size_t j : chosen.kept[k]) {
                if (p.data[k].marker == marker_style::none) break;
                const double x = dev[k].x[j];
                const double y = dev[k].y[j];
                // Drawn where the centre is inside the axes (draw_series).
                if (x >= f.x && x <= f.x + f.w && y >= f.y && y <= f.y + f.h) c.centres.emplace_back(x, y);
            }
            panel_centres.push_back(std::move(c));
        }
        out.push_back(std::move(panel_centres));
    }
    return out;
}

namespace {

/// The series' points in data values as drawn: a curve's samples where its line is drawn.
drawn_points drawn_series(const series& s, const axis_map& mx, const axis_map& my, const rect& clip,
                          double tolerance) {
    drawn_points d;
    if (!s.curve || s.line == line_style::none) {
        const std::size_t n = std::min(s.x.size(), s.y.size());
        d.x.assign(s.x.begin(), s.x.begin() + static_cast<std::ptrdiff_t>(n));
        d.y.assign(s.y.begin(), s.y.begin() + static_cast<std::ptrdiff_t>(n));
        return d;
    }
    d.sampled = true;
    std::vector<double> dx;
    std::vector<double> dy;
    std::vector<double> u;
    sample_curve(*s.curve, mx, my, clip, tolerance, dx, dy, &u);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (std::size_t i = 0; i < u.size(); ++i) {
        // The function's own values at the vertices (a break stays a break).
        const auto [x, y] = std::isnan(dx[i]) ? std::pair{nan, nan} : curve_at(*s.curve, u[i]);
        d.x.push_back(x);
        d.y.push_back(y);
    }
    return d;
}

/// A panel's series as a drawing at `tolerance` in frame `f` draws them (drawn_series), the
/// curves followed a line's width past the frame as draw_panel follows them.
std::vector<drawn_points> drawn_panel(const panel& p, const panel_frame& f, const theme& th, double tolerance) {
    const axis_map mx{f.x_lo, f.x_hi, p.x.kind == scale::log, f.x, f.x + f.w};
    const axis_map my{f.y_lo, f.y_hi, p.y.kind == scale::log, f.y + f.h, f.y};
    const double reach = th.line_width_pt;
    const rect clip{f.x - reach, f.y - reach, f.w + 2 * reach, f.h + 2 * reach};
    std::vector<drawn_points> out;
    for (const auto& s : p.data) out.push_back(drawn_series(s, mx, my, clip, tolerance));
    return out;
}

}  // namespace

std::unordered_map<const curve*, std::vector<std::pair<double, double>>> drawn_curve_values(const figure& fig,
                                                                                             const drawing& drawn) {
    std::unordered_map<const curve*, std::vector<std::pair<double, double>>> out;
    if (!drawn.th || !laid_out_alike(fig, *drawn.th, drawn)) return out;
    const figure styled = with_theme_styles(*drawn.fig, *drawn.th);
    // As draw_figure samples on a vector page (one unit a point).
    const double tolerance = curve_tolerance(1.0, false);
    for (std::size_t i = 0; i < styled.panels.size() && i < drawn.frames.size(); ++i) {
        const panel& p = styled.panels[i];
        const std::vector<drawn_points> points = drawn_panel(p, drawn.frames[i], *drawn.th, tolerance);
        for (std::size_t k = 0; k < p.data.size(); ++k) {
            const series& s = p.data[k];
            if (!points[k].sampled || out.contains(s.curve.get())) continue;
            auto& values = out[s.curve.get()];
            for (std::size_t j = 0; j < points[k].x.size(); ++j) values.emplace_back(points[k].x[j], points[k].y[j]);
        }
    }
    return out;
}

std::vector<std::vector<drawn_points>> drawn_data(const figure& unstyled, const theme& th, double dpi,
                                                  std::vector<panel_frame>& frames) {
    const figure fig = with_theme_styles(unstyled, th);
    // Laid out as on a raster at the dpi (one pixel of it: nothing is kept), which samples
    // the curves as the PNG does: the samples below are those, from the curves' memos.
    const surface_ptr surface(cairo_image_surface_create(CAIRO_FORMAT_A8, 1, 1));
    check_cairo(cairo_surface_status(surface.get()), "an image surface");
    const context_ptr cr(cairo_create(surface.get()));
    check_cairo(cairo_status(cr.get()), "a drawing context");
    cairo_scale(cr.get(), dpi / 72.0, dpi / 72.0);
    draw_figure(cr.get(), fig, th, figure_size(fig, th), draw_pass::all, nullptr, false, &frames);
    const double tolerance = curve_tolerance(cr.get());
    std::vector<std::vector<drawn_points>> out;
    for (std::size_t i = 0; i < fig.panels.size() && i < frames.size(); ++i) {
        out.push_back(drawn_panel(fig.panels[i], frames[i], th, tolerance));
    }
    return out;
}

}  // namespace plot
