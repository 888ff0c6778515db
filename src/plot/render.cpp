// SPDX-License-Identifier: GPL-3.0-or-later
#include "plot/render.hpp"

#include "plot/geometry.hpp"
#include "plot/handles.hpp"
#include "plot/layout.hpp"
#include "plot/legend.hpp"
#include "plot/strokes.hpp"
#include "plot/text.hpp"
#include "plot/ticks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <stdexcept>
#include <string>

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

void draw_ticks(cairo_t* cr, const theme& th, const tick_set& t, const axis_map& m, const rect& area,
                bool horizontal) {
    auto tick = [&](double v, double len) {
        const double d = m(v);
        if (std::isnan(d)) return;
        if (horizontal) {
            if (d < area.x - 0.01 || d > area.x + area.w + 0.01) return;
            cairo_move_to(cr, d, area.y + area.h);
            cairo_line_to(cr, d, area.y + area.h - len);
            cairo_move_to(cr, d, area.y);
            cairo_line_to(cr, d, area.y + len);
        } else {
            if (d < area.y - 0.01 || d > area.y + area.h + 0.01) return;
            cairo_move_to(cr, area.x, d);
            cairo_line_to(cr, area.x + len, d);
            cairo_move_to(cr, area.x + area.w, d);
            cairo_line_to(cr, area.x + area.w - len, d);
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

/// Draws one panel; with show_legend, its legend goes inside the axes where it covers no
/// data, otherwise in a row of its own above them.
void draw_panel(cairo_t* cr, const text_engine& text, const theme& th, const panel& p, const panel_plan& plan,
                const rect& cell, bool show_legend, pass_gate& gate) {
    // Which series this pass draws.
    const auto drawn = [&gate](const series& s) { return gate.draws(s.overlay); };
    const double pad = th.padding_pt;
    const double tolerance = curve_tolerance(cr);
    // Curves are followed closely where their lines show: within a line width of the axes.
    const double reach = th.line_width_pt;
    panel_geometry g = place_panel(p, plan, panel_area(p, plan, cell), tolerance, reach);
    const legend_layout& lg = plan.legend;
    std::optional<rect> legend_box;
    std::optional<rect> legend_band;
    if (show_legend && !lg.entries.empty()) {
        legend_box = legend_inside(p, lg, g, th);
        if (!legend_box && p.legend == legend_place::automatic) {
            // A band at the top of the cell, above the panel label.
            const double band = legend_band_height(lg, th, cell.w - 2 * pad);
            rect area = g.area;
            area.y += band;
            area.h -= band;
            g = place_panel(p, plan, area, tolerance, reach);
            legend_band = rect{cell.x + pad, cell.y + 0.3 * pad, cell.w - 2 * pad, band};
        }
    }
    const rect& area = g.area;
    const axis_map& mx = g.mx;
    const axis_map& my = g.my;
    const auto& dev = g.dev;

    // Curves clipped to the axes; markers whole (matplotlib's clip_on=False), those whose
    // centre is inside.
    cairo_save(cr);
    cairo_rectangle(cr, area.x, area.y, area.w, area.h);
    cairo_clip(cr);
    const rect clip{area.x - reach, area.y - reach, area.w + 2 * reach, area.h + 2 * reach};
    for (std::size_t k = 0; k < p.data.size(); ++k) {
        const auto& s = p.data[k];
        if (s.line == line_style::none || !drawn(s)) continue;
        set_color(cr, th, s);
        set_line_style(cr, th, s.line, s.width_scale);
        stroke_polyline(cr, dev[k], clip);
    }
    // Error bars over the lines and under the markers, clipped to the axes as the lines are.
    for (std::size_t k = 0; k < p.data.size(); ++k) {
        if (dev[k].bars.empty() || !drawn(p.data[k])) continue;
        set_color(cr, th, p.data[k]);
        draw_error_bars(cr, th, p.data[k], dev[k].bars);
    }
    cairo_restore(cr);
    // draw_markers keeps markers whose centre is within a radius of the rect it is given.
    const double inward = th.marker_radius_pt - 1e-6 * (area.w + area.h);
    const rect centres{area.x + inward, area.y + inward, area.w - 2 * inward, area.h - 2 * inward};
    for (std::size_t k = 0; k < p.data.size(); ++k) {
        if (p.data[k].marker == marker_style::none || !drawn(p.data[k])) continue;
        set_color(cr, th, p.data[k]);
        draw_markers(cr, th, p.data[k], dev[k], centres);
    }

    if (!p.overlay_label.empty() && gate.draws(true)) {
        set_foreground(cr, th);
        // Inside the top left corner, which a drawing of the pendulum and a phase portrait leave free.
        text.draw(p.overlay_label, th.label_font_pt, area.x + pad, area.y + pad, 0.0, 0.0);
    }
    if (!gate.draws(false)) return;

    if (p.frameless) {
        // A drawing: only its title and legend.
        set_foreground(cr, th);
        if (!p.label.empty()) text.draw(p.label, th.label_font_pt, area.x, area.y - 0.4 * pad, 0.0, 1.0);
        if (legend_box) draw_legend(cr, text, th, p, lg, *legend_box);
        if (legend_band) draw_legend_band(cr, text, th, p, lg, *legend_band);
        return;
    }

    // Frame and ticks.
    set_foreground(cr, th);
    cairo_set_dash(cr, nullptr, 0, 0);
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_BUTT);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_MITER);
    cairo_set_line_width(cr, th.frame_width_pt);
    cairo_rectangle(cr, area.x, area.y, area.w, area.h);
    cairo_stroke(cr);
    draw_ticks(cr, th, plan.xt, mx, area, true);
    draw_ticks(cr, th, plan.yt, my, area, false);

    // Tick labels, all at tick_gap from the frame: x labels on one baseline below their
    // highest ink (and below the ink of y labels that hang under their baseline), y labels
    // with their ink ending there, centred on a digit's height.
    const double x_baseline = area.y + area.h + plan.xtick_gap + plan.xtick_up;
    for (std::size_t i = 0; i < plan.xt.major.size(); ++i) {
        const double d = mx(plan.xt.major[i]);
        if (d < area.x - 0.01 || d > area.x + area.w + 0.01) continue;
        const text_ink ink = text.ink(plan.xt.labels[i], th.tick_font_pt);
        text.draw_on_baseline(plan.xt.labels[i], th.tick_font_pt, d - ink.x - 0.5 * ink.w, x_baseline, false, 0.5);
    }
    for (std::size_t i = 0; i < plan.yt.major.size(); ++i) {
        const double d = my(plan.yt.major[i]);
        if (d < area.y - 0.01 || d > area.y + area.h + 0.01) continue;
        const text_ink ink = text.ink(plan.yt.labels[i], th.tick_font_pt);
        text.draw_on_baseline(plan.yt.labels[i], th.tick_font_pt, area.x - plan.tick_gap - ink.x - ink.w,
                              d + 0.5 * plan.digit_h, false, 1.0);
    }

    // Axis labels at label_gap from the tick labels (y labels of a column aligned, as the
    // widest tick labels of the figure set them), panel label above the top tick label.
    if (!p.x.label.empty()) {
        const text_ink ink = text.ink(p.x.label.markup, th.label_font_pt);
        const double top = x_baseline + plan.xtick_down + plan.label_gap;
        text.draw_on_baseline(p.x.label, th.label_font_pt, area.x + 0.5 * area.w - ink.x - 0.5 * ink.w, top - ink.y,
                              false, 0.5);
    }
    if (!p.y.label.empty()) {
        // Turned by -90 degrees: the text's down is the page's right.
        const text_ink ink = text.ink(p.y.label.markup, th.label_font_pt);
        const double right = area.x - plan.tick_gap - plan.column_ytick_w - plan.label_gap;
        text.draw_on_baseline(p.y.label, th.label_font_pt, right - (ink.y + ink.h),
                              area.y + 0.5 * area.h + ink.x + 0.5 * ink.w, true, 0.5);
    }
    if (!p.label.empty()) {
        const text_ink ink = text.ink(p.label.markup, th.label_font_pt);
        const double bottom = area.y - 0.5 * plan.digit_h - plan.label_gap;
        text.draw_on_baseline(p.label, th.label_font_pt, area.x - ink.x, bottom - (ink.y + ink.h));
    }
    if (legend_box) draw_legend(cr, text, th, p, lg, *legend_box);
    if (legend_band) draw_legend_band(cr, text, th, p, lg, *legend_band);
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

figure with_theme_styles(const figure& fig, const theme& th) {
    figure styled = fig;
    const auto style = [&](std::vector<panel>& panels) {
        for (auto& p : panels) {
            for (auto& s : p.data) {
                if (s.data_slot >= 0) apply_data_style(s, th);
                const auto it = s.style_key.empty() ? th.styles.end() : th.styles.find(s.style_key);
                if (it == th.styles.end()) continue;
                if (it->second.line) s.line = *it->second.line;
                if (it->second.marker) s.marker = *it->second.marker;
            }
        }
    };
    style(styled.panels);
    style(styled.peers);  // planned as their own files draw them
    return styled;
}

void draw_figure(cairo_t* cr, const figure& unstyled, const theme& th, page_size size, draw_pass pass,
                 std::vector<placed_text>* texts, bool vector, std::vector<panel_frame>* frames) {
    const auto keyed = [](const panel& p) {
        return std::any_of(p.data.begin(), p.data.end(),
                           [](const series& s) { return !s.style_key.empty() || s.data_slot >= 0; });
    };
    const bool any_key = std::any_of(unstyled.panels.begin(), unstyled.panels.end(), keyed) ||
                         std::any_of(unstyled.peers.begin(), unstyled.peers.end(), keyed);
    const figure styled = any_key ? with_theme_styles(unstyled, th) : figure{};
    const figure& fig = any_key ? styled : unstyled;
    if (fig.rows < 1 || fig.cols < 1 || fig.panels.size() > static_cast<std::size_t>(fig.rows * fig.cols)) {
        throw std::invalid_argument("figure grid is too small for its panels");
    }
    if (th.palette.empty()) throw bad_input("theme has no colours");
    text_engine text(cr, th.font_family);
    text.record_into(texts);
    pass_gate gate{pass};
    if ((!vector || th.opaque_vector_background) && gate.draws(false)) {
        cairo_set_source_rgb(cr, th.background.r, th.background.g, th.background.b);
        cairo_paint(cr);
    }

    // Shared margins keep the axes of neighbouring panels aligned, and those of panels drawn
    // alone in files of their own (the peers, each in a cell the size of this figure's):
    // a peer is planned as its own file plans it, crowded ticks thinned and all, so that
    // every file of the set reaches the same margins. Plans past the panels are the peers'.
    std::vector<panel> with_peers;
    if (!fig.peers.empty()) {
        with_peers = fig.panels;
        with_peers.insert(with_peers.end(), fig.peers.begin(), fig.peers.end());
    }
    const std::vector<panel>& planned = fig.peers.empty() ? fig.panels : with_peers;
    std::vector<panel_plan> plans;
    for (const auto& p : planned) plans.push_back(plan_panel(text, p, th));
    share_margins(plans, th, fig.cols);
    auto make_cells = [&](double top) {
        const double cw = size.width_pt / fig.cols;
        const double ch = (size.height_pt - top) / fig.rows;
        std::vector<rect> cells;
        for (std::size_t i = 0; i < fig.panels.size(); ++i) {
            cells.push_back(rect{static_cast<double>(i % fig.cols) * cw, top + static_cast<double>(i / fig.cols) * ch,
                                 cw, ch});
        }
        return cells;
    };
    // The title, centred above everything, at padding from the top.
    double title_h = 0;
    if (!fig.title.empty() && th.title_font_pt > 0) {
        const text_ink ink = text.ink(fig.title.markup, th.title_font_pt);
        title_h = th.padding_pt + ink.h + 0.5 * th.padding_pt;
        if (gate.draws(false)) {
            set_foreground(cr, th);
            text.draw_on_baseline(fig.title, th.title_font_pt, 0.5 * size.width_pt - ink.x - 0.5 * ink.w,
                                  th.padding_pt - ink.y, false, 0.5);
        }
    }
    std::vector<rect> cells = make_cells(title_h);
    // Every planned panel (the peers too) gets a cell the size of this figure's.
    const auto planned_cells_of = [&](const std::vector<rect>& own) {
        std::vector<rect> all = own;
        if (!all.empty()) all.resize(planned.size(), all.front());
        return all;
    };
    thin_crowded_ticks(text, planned, plans, planned_cells_of(cells), th, fig.cols);
    keep_data_off_frame(planned, plans, planned_cells_of(cells), th);
    // Axes too small to read are an error, not a figure.
    const double least = 3 * th.tick_font_pt;
    // Room for a band over files of one panel each: their axes keep three quarters of their
    // height (and room to read), or the band would squeeze the plots it names.
    const auto roomy = [&](const std::vector<rect>& these) {
        for (std::size_t i = 0; i < fig.panels.size(); ++i) {
            const rect area = axes_area(plans[i], these[i]);
            const rect before = axes_area(plans[i], cells[i]);
            if (area.w < least || area.h < std::max(least, 0.75 * before.h)) return false;
        }
        return true;
    };
    const auto check_room = [&] {
        for (std::size_t i = 0; i < fig.panels.size(); ++i) {
            const rect area = axes_area(plans[i], cells[i]);
            if (area.w >= least && area.h >= least) continue;
            constexpr double cm = 2.54 / 72;
            const auto number = [](const char* format, double value) {
                char buf[32];
                std::snprintf(buf, sizeof buf, format, value);
                return std::string(buf);
            };
            const auto cm_of = [&](double pt) { return number("%.1f", pt * cm); };
            const std::string what =
                "a figure of " + cm_of(size.width_pt) + " x " + cm_of(size.height_pt) + " cm leaves panel " +
                std::to_string(i + 1) + " of " + std::to_string(fig.panels.size()) + " axes of " +
                cm_of(std::max(area.w, 0.0)) + " x " + cm_of(std::max(area.h, 0.0)) + " cm, too small for " +
                number("%.3g", th.tick_font_pt) +
                " pt text: make the figure larger (figure_width_cm and figure_height_cm, or panel_width_cm) or its "
                "text smaller (tick_font_pt, label_font_pt, legend_font_pt)";
            throw layout_error(what);
        }
    };
    const auto record_frames = [&] {
        if (!frames) return;
        frames->clear();
        for (std::size_t i = 0; i < fig.panels.size(); ++i) {
            const rect a = panel_area(fig.panels[i], plans[i], cells[i]);
            frames->push_back(panel_frame{a.x, a.y, a.w, a.h, plans[i].xt.lo, plans[i].xt.hi, plans[i].yt.lo,
                                          plans[i].yt.hi, fig.panels[i].frameless, plans[i].xt.labels,
                                          plans[i].yt.labels});
        }
    };
    if (!fig.shared_legend || fig.panels.empty() || !same_legend_entries(planned)) {
        plans.resize(fig.panels.size());
        check_room();
        record_frames();
        for (std::size_t i = 0; i < fig.panels.size(); ++i) {
            draw_panel(cr, text, th, fig.panels[i], plans[i], cells[i], true, gate);
        }
        return;
    }
    // A shared legend goes to the first panel of the set with room for it inside the axes;
    // failing that, to a band across the top. The set is the figure's panels, or, for a file
    // of one panel of a figure (peers), the figure's panels in their order: every file of a
    // figure decides alike, so exactly one of them shows the legend, and all of them leave
    // room for a band, which keeps their frames in line; files too small for a band above
    // their axes (see roomy) have no legend: a caption names the lines. Every panel shows the same
    // series, so the first panel's entries stand for all.
    std::vector<std::size_t> set_order;  // indices into planned, in the set's order
    if (fig.peers.empty()) {
        for (std::size_t i = 0; i < fig.panels.size(); ++i) set_order.push_back(i);
    } else {
        const std::size_t own = std::min<std::size_t>(fig.place_in_set, fig.peers.size());
        for (std::size_t i = 0; i < own; ++i) set_order.push_back(1 + i);
        set_order.push_back(0);
        for (std::size_t i = own; i < fig.peers.size(); ++i) set_order.push_back(1 + i);
    }
    const legend_layout lg = plans[0].legend;
    std::optional<std::size_t> legend_panel;  // index into planned
    for (std::size_t i : set_order) {
        const rect cell = i < cells.size() ? cells[i] : cells.front();
        const auto g = place_panel(planned[i], plans[i], axes_area(plans[i], cell), curve_tolerance(cr),
                                   th.line_width_pt);
        if (legend_inside(planned[i], lg, g, th)) {
            legend_panel = i;
            break;
        }
    }
    const double band = lg.entries.empty() ? 0.0 : legend_band_height(lg, th, size.width_pt - 2 * th.padding_pt);
    if (!legend_panel && !lg.entries.empty() &&
        (fig.peers.empty() || roomy(make_cells(title_h + band + 0.3 * th.padding_pt)))) {
        if ((fig.peers.empty() || fig.place_in_set == 0) && gate.draws(false)) {
            draw_legend_band(cr, text, th, fig.panels[0], lg,
                             rect{th.padding_pt, title_h + 0.3 * th.padding_pt, size.width_pt - 2 * th.padding_pt, band});
        }
        cells = make_cells(title_h + band + 0.3 * th.padding_pt);
        keep_data_off_frame(planned, plans, planned_cells_of(cells), th);
    }
    plans.resize(fig.panels.size());
    check_room();
    record_frames();
    for (std::size_t i = 0; i < fig.panels.size(); ++i) {
        const bool here = legend_panel && i == *legend_panel;
        if (here) plans[i].legend = lg;
        draw_panel(cr, text, th, fig.panels[i], plans[i], cells[i], here, gate);
    }
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

}  // namespace

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
        const panel& p = fig.panels[i];
        const panel_frame& f = frames[i];
        const axis_map mx{f.x_lo, f.x_hi, p.x.kind == scale::log, f.x, f.x + f.w};
        const axis_map my{f.y_lo, f.y_hi, p.y.kind == scale::log, f.y + f.h, f.y};
        const double reach = th.line_width_pt;  // as draw_panel follows curves
        const rect clip{f.x - reach, f.y - reach, f.w + 2 * reach, f.h + 2 * reach};
        std::vector<drawn_points> panel_points;
        for (const auto& s : p.data) panel_points.push_back(drawn_series(s, mx, my, clip, tolerance));
        out.push_back(std::move(panel_points));
    }
    return out;
}

}  // namespace plot
