// SPDX-License-Identifier: GPL-3.0-or-later
#include "plot/legend.hpp"

#include "plot/render.hpp"
#include "plot/strokes.hpp"

#include <algorithm>
#include <string>

namespace plot {

namespace {

/// How many of a series' line segments and error bars touch the box.
int segments_touching(const rect& box, const series& s, const device_series& d) {
    int count = 0;
    if (s.line != line_style::none) {
        const auto& lx = d.line_x();
        const auto& ly = d.line_y();
        for (std::size_t i = 1; i < lx.size(); ++i) {
            double x0 = lx[i - 1], y0 = ly[i - 1], x1 = lx[i], y1 = ly[i];
            if (std::isnan(x0 + y0 + x1 + y1)) continue;
            if (clip_segment(x0, y0, x1, y1, box)) ++count;
        }
    }
    for (const auto& b : d.bars) {
        double x0 = b.x0, y0 = b.y0, x1 = b.x1, y1 = b.y1;
        if (clip_segment(x0, y0, x1, y1, box)) ++count;
    }
    return count;
}

/// How many of a series' markers touch the box: their centres within a radius of it.
int markers_touching(const rect& box, const series& s, const device_series& d, double marker_radius) {
    if (s.marker == marker_style::none) return 0;
    const rect grown{box.x - marker_radius, box.y - marker_radius, box.w + 2 * marker_radius,
                     box.h + 2 * marker_radius};
    int count = 0;
    for (std::size_t i = 0; i < d.x.size(); ++i) {
        if (d.x[i] >= grown.x && d.x[i] <= grown.x + grown.w && d.y[i] >= grown.y && d.y[i] <= grown.y + grown.h) {
            ++count;
        }
    }
    return count;
}

}  // namespace

int overlap(const rect& box, const std::vector<series>& data, const std::vector<device_series>& dev,
            double marker_radius) {
    int count = 0;
    for (std::size_t k = 0; k < data.size(); ++k) {
        // What moves in an animation must not move the legend from frame to frame.
        if (data[k].overlay) continue;
        count += segments_touching(box, data[k], dev[k]) + markers_touching(box, data[k], dev[k], marker_radius);
    }
    return count;
}

legend_layout measure_legend(const text_engine& text, const panel& p, const theme& th) {
    legend_layout l;
    if (p.legend == legend_place::none) return l;
    for (std::size_t k = 0; k < p.data.size(); ++k) {
        if (p.data[k].label.empty()) continue;
        l.entries.push_back(k);
        const auto [w, h] = text.measure(p.data[k].label.markup, th.legend_font_pt);
        l.text_ws.push_back(w);
        l.text_w = std::max(l.text_w, w);
        l.row_h = std::max(l.row_h, h);
    }
    if (l.entries.empty()) return l;
    l.sample_w = 2.6 * th.legend_font_pt;
    const double pad = 0.5 * th.padding_pt;
    l.w = pad + l.sample_w + th.padding_pt + l.text_w + pad;
    l.h = pad + l.row_h * l.entries.size() + pad;
    return l;
}

bool same_legend_entry(const series& a, const series& b) {
    const std::string& x = a.label.markup;
    const std::string& y = b.label.markup;
    const bool same_label = x == y || y.starts_with(x + ", ") || x.starts_with(y + ", ");
    const bool same_colour = a.color == b.color && a.rgb_color.has_value() == b.rgb_color.has_value() &&
                             (!a.rgb_color || (a.rgb_color->r == b.rgb_color->r && a.rgb_color->g == b.rgb_color->g &&
                                               a.rgb_color->b == b.rgb_color->b));
    return same_label && same_colour && a.line == b.line && a.marker == b.marker && a.style_key == b.style_key;
}

void one_legend(const std::vector<panel*>& panels) {
    std::vector<series*> shown;
    for (panel* p : panels) {
        for (auto& s : p->data) {
            if (s.label.empty()) continue;
            const auto same =
                std::find_if(shown.begin(), shown.end(), [&](const series* k) { return same_legend_entry(*k, s); });
            if (same == shown.end()) {
                shown.push_back(&s);
                continue;
            }
            if (s.label.markup.size() > (*same)->label.markup.size()) (*same)->label = s.label;
            s.label = {};
        }
    }
}

glyph_log& current_glyph_log() {
    thread_local glyph_log log;
    return log;
}

void draw_legend_sample(cairo_t* cr, const theme& th, const series& s, double x, double y, double w) {
    if (glyph_log& log = current_glyph_log(); log.out) {
        log.out->legend.push_back(glyph{s.label.markup, log.at, s.line, s.width_scale, s.marker, s.color, s.rgb_color});
    }
    set_color(cr, th, s);
    if (s.line != line_style::none) {
        set_line_style(cr, th, s.line, s.width_scale);
        cairo_move_to(cr, x, y);
        cairo_line_to(cr, x + w, y);
        cairo_stroke(cr);
    }
    device_series d{{x + 0.5 * w}, {y}};
    if (!s.errors.y_lower.empty() || !s.errors.y_upper.empty()) {
        // A data series: its marker on a bar with caps, as in the panel.
        const double half = 0.55 * th.legend_font_pt;
        d.bars.push_back({x + 0.5 * w, y - half, x + 0.5 * w, y + half, true});
        draw_error_bars(cr, th, s, d.bars);
    } else if (!s.errors.empty()) {
        const double half = 0.3 * w;
        d.bars.push_back({x + 0.5 * w - half, y, x + 0.5 * w + half, y, false});
        draw_error_bars(cr, th, s, d.bars);
    }
    if (s.marker != marker_style::none) {
        draw_markers(cr, th, s, d, rect{x, y - w, w, 2 * w});
    }
}

void draw_legend(cairo_t* cr, const text_engine& text, const theme& th, const panel& p,
                 const legend_layout& l, const rect& box) {
    const double pad = 0.5 * th.padding_pt;
    for (std::size_t i = 0; i < l.entries.size(); ++i) {
        const series& s = p.data[l.entries[i]];
        const double cy = box.y + pad + (i + 0.5) * l.row_h;
        draw_legend_sample(cr, th, s, box.x + pad, cy, l.sample_w);
        set_foreground(cr, th);
        text.draw(s.label, th.legend_font_pt, box.x + pad + l.sample_w + th.padding_pt, cy, 0.0, 0.5);
    }
}

std::vector<std::vector<std::size_t>> legend_lines(const legend_layout& l, const theme& th, double max_w) {
    std::vector<std::vector<std::size_t>> lines;
    double used = 0;
    for (std::size_t i = 0; i < l.entries.size(); ++i) {
        const double w = l.sample_w + th.padding_pt + l.text_ws[i];
        const double gap = 2 * th.padding_pt;
        if (lines.empty() || used + gap + w > max_w) {
            lines.push_back({i});
            used = w;
        } else {
            lines.back().push_back(i);
            used += gap + w;
        }
    }
    return lines;
}

double legend_band_height(const legend_layout& l, const theme& th, double max_w) {
    if (l.entries.empty()) return 0;
    return static_cast<double>(legend_lines(l, th, max_w).size()) * l.row_h + 0.5 * th.padding_pt;
}

void draw_legend_band(cairo_t* cr, const text_engine& text, const theme& th, const panel& p,
                      const legend_layout& l, const rect& band) {
    const auto lines = legend_lines(l, th, band.w);
    for (std::size_t r = 0; r < lines.size(); ++r) {
        double width = 0;
        for (std::size_t i : lines[r]) width += l.sample_w + th.padding_pt + l.text_ws[i] + 2 * th.padding_pt;
        width -= 2 * th.padding_pt;
        double x = band.x + 0.5 * (band.w - width);
        const double cy = band.y + (r + 0.5) * l.row_h;
        for (std::size_t i : lines[r]) {
            const series& s = p.data[l.entries[i]];
            draw_legend_sample(cr, th, s, x, cy, l.sample_w);
            set_foreground(cr, th);
            text.draw(s.label, th.legend_font_pt, x + l.sample_w + th.padding_pt, cy, 0.0, 0.5);
            x += l.sample_w + th.padding_pt + l.text_ws[i] + 2 * th.padding_pt;
        }
    }
}

}  // namespace plot
