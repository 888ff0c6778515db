#include "plot/render.hpp"

#include "plot/handles.hpp"
#include "plot/ticks.hpp"

#include <fontconfig/fontconfig.h>
#include <pango/pangofc-fontmap.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
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
    if (th.fixed_width_cm > 0 && th.fixed_height_cm > 0) {
        return {th.fixed_width_cm * pt_per_cm, th.fixed_height_cm * pt_per_cm};
    }
    const double w = fig.panel_width_cm * pt_per_cm;
    return {w * fig.cols, w * fig.panel_aspect * fig.rows};
}

namespace {

/// A rectangle in device points, y down.
struct rect {
    double x = 0;
    double y = 0;
    double w = 0;
    double h = 0;
};

/// The fonts figures may use: the system's font directories with their caches, and none
/// of the machine's or the user's font configuration (substitutions, hinting, subpixel
/// order), which would otherwise change the pictures from one machine to the next.
FcConfig* private_font_config() {
    static FcConfig* const config = [] {
        FcConfig* c = FcConfigCreate();
        static const char* const xml =
            "<?xml version=\"1.0\"?><!DOCTYPE fontconfig SYSTEM \"urn:fontconfig:fonts.dtd\">"
            "<fontconfig><dir>/usr/share/fonts</dir><cachedir>/var/cache/fontconfig</cachedir>"
            "<cachedir prefix=\"xdg\">fontconfig</cachedir></fontconfig>";
        if (!c || !FcConfigParseAndLoadFromMemory(c, reinterpret_cast<const FcChar8*>(xml), FcTrue) ||
            !FcConfigBuildFonts(c)) {
            throw std::runtime_error("cannot set up the font configuration");
        }
        return c;
    }();
    return config;
}

/// This thread's Pango font map over private_font_config(). Font maps are not shared
/// between threads; one per thread keeps loaded fonts across figures.
PangoFontMap* thread_font_map() {
    thread_local const gobject_ptr<PangoFontMap> map = [] {
        gobject_ptr<PangoFontMap> m(pango_cairo_font_map_new_for_font_type(CAIRO_FONT_TYPE_FT));
        if (!m.get()) throw std::runtime_error("cannot create a Pango font map");
        pango_fc_font_map_set_config(PANGO_FC_FONT_MAP(m.get()), private_font_config());
        return m;
    }();
    return map.get();
}

/// Text set with Pango in one font family, measured and drawn in points.
class text_engine {
public:
    text_engine(cairo_t* cr, const std::string& family)
        : cr_(cr), family_(family), context_(pango_font_map_create_context(thread_font_map())) {
        pango_cairo_update_context(cr, context_.get());
        // Points as user units, and no hinting: the layout is the same in every format.
        pango_cairo_context_set_resolution(context_.get(), 72.0);
        font_options_ptr options(cairo_font_options_create());
        cairo_font_options_set_hint_style(options.get(), CAIRO_HINT_STYLE_NONE);
        cairo_font_options_set_hint_metrics(options.get(), CAIRO_HINT_METRICS_OFF);
        cairo_font_options_set_antialias(options.get(), CAIRO_ANTIALIAS_GRAY);
        pango_cairo_context_set_font_options(context_.get(), options.get());
        check_font_installed();
    }

    /// Logical width and height of the markup at `size` points.
    std::pair<double, double> measure(const std::string& markup, double size) const {
        PangoRectangle logical;
        pango_layout_get_extents(layout(markup, size), nullptr, &logical);
        return {logical.width / double(PANGO_SCALE), logical.height / double(PANGO_SCALE)};
    }

    /// Draws markup with its box anchored at (x, y): ax, ay in {0, 0.5, 1} pick the
    /// anchor (left/centre/right, top/middle/bottom). `rotate` turns it by -90 degrees.
    void draw(const std::string& markup, double size, double x, double y, double ax, double ay,
              bool rotate = false) const {
        PangoLayout* shaped = layout(markup, size);
        PangoRectangle logical;
        pango_layout_get_extents(shaped, nullptr, &logical);
        const double w = logical.width / double(PANGO_SCALE);
        const double h = logical.height / double(PANGO_SCALE);
        cairo_save(cr_);
        cairo_translate(cr_, x, y);
        if (rotate) cairo_rotate(cr_, -M_PI / 2);
        cairo_move_to(cr_, -ax * w - logical.x / double(PANGO_SCALE), -ay * h - logical.y / double(PANGO_SCALE));
        // Metrics are unhinted, so the layout made for measuring draws unchanged here.
        pango_cairo_show_layout(cr_, shaped);
        cairo_restore(cr_);
    }

private:
    /// The shaped layout of markup at size; each text is shaped once per figure.
    PangoLayout* layout(const std::string& markup, double size) const {
        auto key = std::make_pair(markup, size);
        auto it = layouts_.find(key);
        if (it == layouts_.end()) it = layouts_.emplace(std::move(key), make(markup, size)).first;
        return it->second.get();
    }

    gobject_ptr<PangoLayout> make(const std::string& markup, double size) const {
        gobject_ptr<PangoLayout> layout(pango_layout_new(context_.get()));
        font_description_ptr font(pango_font_description_new());
        pango_font_description_set_family(font.get(), family_.c_str());
        pango_font_description_set_size(font.get(), static_cast<gint>(std::lround(size * PANGO_SCALE)));
        pango_layout_set_font_description(layout.get(), font.get());
        const std::string spans = scripts_as_spans(markup, size);
        // Checked first: Pango would only print a warning and show nothing.
        GError* error = nullptr;
        if (!pango_parse_markup(spans.c_str(), -1, 0, nullptr, nullptr, nullptr, &error)) {
            const std::string why = error ? error->message : "not valid";
            g_clear_error(&error);
            throw std::invalid_argument("invalid text markup '" + markup + "': " + why);
        }
        pango_layout_set_markup(layout.get(), spans.c_str(), -1);
        return layout;
    }

    /// Pango sizes <sub> and <sup> from the font's OS/2 script metrics, which some fonts
    /// (Computer Modern Unicode among them) set far too large; spell them out instead.
    static std::string scripts_as_spans(const std::string& markup, double size) {
        const auto units = [](double pt) { return std::to_string(std::lround(pt * PANGO_SCALE)); };
        const std::string small = units(0.7 * size);
        const std::pair<std::string, std::string> rules[] = {
            {"<sub>", "<span size=\"" + small + "\" rise=\"-" + units(0.22 * size) + "\">"},
            {"<sup>", "<span size=\"" + small + "\" rise=\"" + units(0.38 * size) + "\">"},
            {"</sub>", "</span>"},
            {"</sup>", "</span>"}};
        std::string out = markup;
        for (const auto& [from, to] : rules) {
            for (std::size_t pos = 0; (pos = out.find(from, pos)) != std::string::npos; pos += to.size()) {
                out.replace(pos, from.size(), to);
            }
        }
        return out;
    }

    /// The first family must be installed: without it every figure would change.
    void check_font_installed() const {
        const std::string first = family_.substr(0, family_.find(','));
        font_description_ptr font(pango_font_description_new());
        pango_font_description_set_family(font.get(), first.c_str());
        gobject_ptr<PangoFont> loaded(pango_context_load_font(context_.get(), font.get()));
        std::string got;
        if (loaded.get()) {
            font_description_ptr d(pango_font_describe(loaded.get()));
            if (const char* f = pango_font_description_get_family(d.get())) got = f;
        }
        if (got != first) {
            throw std::runtime_error("font '" + first + "' is not installed (Debian package fonts-cmu)");
        }
    }

    cairo_t* cr_;
    std::string family_;
    gobject_ptr<PangoContext> context_;
    mutable std::map<std::pair<std::string, double>, gobject_ptr<PangoLayout>> layouts_;
};

/// Maps data values of one axis to device coordinates.
struct axis_map {
    double lo = 0;
    double hi = 1;
    bool log = false;
    double d0 = 0;  // device coordinate of lo
    double d1 = 1;  // device coordinate of hi

    double operator()(double v) const {
        if (log) {
            if (!(v > 0)) return std::numeric_limits<double>::quiet_NaN();
            return d0 + (std::log10(v) - std::log10(lo)) / (std::log10(hi) - std::log10(lo)) * (d1 - d0);
        }
        return d0 + (v - lo) / (hi - lo) * (d1 - d0);
    }
};

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
    } else {
        t = linear_ticks(lo, hi, a.max_ticks, expand);
    }
    // A fixed limit stays where it was asked, even if expanding moved the other one.
    if (a.min) t.lo = *a.min;
    if (a.max) t.hi = *a.max;
    return t;
}

/// Liang-Barsky: clips the segment to r; returns false if nothing is left.
bool clip_segment(double& x0, double& y0, double& x1, double& y1, const rect& r) {
    double t0 = 0.0;
    double t1 = 1.0;
    const double dx = x1 - x0;
    const double dy = y1 - y0;
    const double p[4] = {-dx, dx, -dy, dy};
    const double q[4] = {x0 - r.x, r.x + r.w - x0, y0 - r.y, r.y + r.h - y0};
    for (int i = 0; i < 4; ++i) {
        if (p[i] == 0.0) {
            if (q[i] < 0.0) return false;
        } else {
            const double t = q[i] / p[i];
            if (p[i] < 0.0) {
                if (t > t1) return false;
                t0 = std::max(t0, t);
            } else {
                if (t < t0) return false;
                t1 = std::min(t1, t);
            }
        }
    }
    const double nx0 = x0 + t0 * dx;
    const double ny0 = y0 + t0 * dy;
    x1 = x0 + t1 * dx;
    y1 = y0 + t1 * dy;
    x0 = nx0;
    y0 = ny0;
    return true;
}

/// Device coordinates of one series; non-finite points are NaN.
struct device_series {
    std::vector<double> x;
    std::vector<double> y;
};

device_series to_device(const series& s, const axis_map& mx, const axis_map& my) {
    device_series d;
    const std::size_t n = std::min(s.x.size(), s.y.size());
    d.x.reserve(n);
    d.y.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
        const bool ok = std::isfinite(s.x[i]) && std::isfinite(s.y[i]);
        d.x.push_back(ok ? mx(s.x[i]) : std::numeric_limits<double>::quiet_NaN());
        d.y.push_back(ok ? my(s.y[i]) : std::numeric_limits<double>::quiet_NaN());
    }
    return d;
}

/// How much of the data a box would cover: segments and markers that touch it.
int overlap(const rect& box, const std::vector<series>& data, const std::vector<device_series>& dev,
            double marker_radius) {
    int count = 0;
    for (std::size_t k = 0; k < data.size(); ++k) {
        const auto& d = dev[k];
        if (data[k].line != line_style::none) {
            for (std::size_t i = 1; i < d.x.size(); ++i) {
                double x0 = d.x[i - 1], y0 = d.y[i - 1], x1 = d.x[i], y1 = d.y[i];
                if (std::isnan(x0 + y0 + x1 + y1)) continue;
                if (clip_segment(x0, y0, x1, y1, box)) ++count;
            }
        }
        if (data[k].marker != marker_style::none) {
            const rect grown{box.x - marker_radius, box.y - marker_radius, box.w + 2 * marker_radius,
                             box.h + 2 * marker_radius};
            for (std::size_t i = 0; i < d.x.size(); ++i) {
                if (d.x[i] >= grown.x && d.x[i] <= grown.x + grown.w && d.y[i] >= grown.y &&
                    d.y[i] <= grown.y + grown.h) {
                    ++count;
                }
            }
        }
    }
    return count;
}

void set_foreground(cairo_t* cr, const theme& th) {
    cairo_set_source_rgb(cr, th.foreground.r, th.foreground.g, th.foreground.b);
}

void set_color(cairo_t* cr, const theme& th, int index) {
    const rgb& c = th.palette[static_cast<std::size_t>(index) % th.palette.size()];
    cairo_set_source_rgb(cr, c.r, c.g, c.b);
}

void set_line_style(cairo_t* cr, const theme& th, line_style style) {
    const double w = th.line_width_pt;
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
        default: cairo_set_dash(cr, nullptr, 0, 0);
    }
}

double distance_to_segment(double px, double py, double ax, double ay, double bx, double by) {
    const double dx = bx - ax;
    const double dy = by - ay;
    const double len2 = dx * dx + dy * dy;
    double t = len2 > 0 ? ((px - ax) * dx + (py - ay) * dy) / len2 : 0.0;
    t = std::clamp(t, 0.0, 1.0);
    return std::hypot(px - (ax + t * dx), py - (ay + t * dy));
}

/// Drops the points of a polyline that lie within `tolerance` of the line drawn without
/// them, as matplotlib's path simplification does: invisible, but it keeps vector files
/// small and fast to draw.
void simplify(std::vector<std::pair<double, double>>& run, double tolerance) {
    if (run.size() < 3) return;
    std::vector<std::pair<double, double>> out{run.front()};
    std::size_t first_pending = 1;  // run[first_pending .. i-1] are not yet emitted
    for (std::size_t i = 2; i < run.size(); ++i) {
        const auto [ax, ay] = out.back();
        const auto [bx, by] = run[i];
        bool fits = i - first_pending < 64;
        for (std::size_t j = first_pending; fits && j < i; ++j) {
            fits = distance_to_segment(run[j].first, run[j].second, ax, ay, bx, by) <= tolerance;
        }
        if (!fits) {
            out.push_back(run[i - 1]);
            first_pending = i;
        }
    }
    out.push_back(run.back());
    run = std::move(out);
}

void stroke_polyline(cairo_t* cr, const device_series& d, const rect& clip) {
    // Visible runs of the clipped polyline, each simplified, then stroked as one path.
    std::vector<std::vector<std::pair<double, double>>> runs;
    bool open = false;
    for (std::size_t i = 1; i < d.x.size(); ++i) {
        double x0 = d.x[i - 1], y0 = d.y[i - 1], x1 = d.x[i], y1 = d.y[i];
        if (std::isnan(x0 + y0 + x1 + y1) || !clip_segment(x0, y0, x1, y1, clip)) {
            open = false;
            continue;
        }
        if (!open || runs.back().back() != std::pair{x0, y0}) runs.push_back({{x0, y0}});
        runs.back().emplace_back(x1, y1);
        open = true;
    }
    for (auto& run : runs) {
        simplify(run, 0.05);
        cairo_move_to(cr, run.front().first, run.front().second);
        for (std::size_t i = 1; i < run.size(); ++i) cairo_line_to(cr, run[i].first, run[i].second);
    }
    cairo_stroke(cr);
}

void draw_markers(cairo_t* cr, const theme& th, const device_series& d, const rect& area) {
    const double r = th.marker_radius_pt;
    cairo_set_dash(cr, nullptr, 0, 0);
    cairo_set_line_width(cr, 0.75 * th.line_width_pt);
    for (std::size_t i = 0; i < d.x.size(); ++i) {
        if (std::isnan(d.x[i] + d.y[i])) continue;
        if (d.x[i] < area.x - r || d.x[i] > area.x + area.w + r || d.y[i] < area.y - r ||
            d.y[i] > area.y + area.h + r) {
            continue;
        }
        cairo_new_sub_path(cr);
        cairo_arc(cr, d.x[i], d.y[i], r, 0, 2 * M_PI);
    }
    cairo_stroke(cr);
}

/// Legend geometry: box size and the height of one entry.
struct legend_layout {
    std::vector<std::size_t> entries;  // indices of series with a label
    std::vector<double> text_ws;       // width of each entry's text
    double sample_w = 0;
    double text_w = 0;
    double row_h = 0;
    double w = 0;
    double h = 0;
};

legend_layout measure_legend(const text_engine& text, const panel& p, const theme& th) {
    legend_layout l;
    if (p.legend == legend_place::none) return l;
    for (std::size_t k = 0; k < p.data.size(); ++k) {
        if (p.data[k].label.empty()) continue;
        l.entries.push_back(k);
        const auto [w, h] = text.measure(p.data[k].label, th.legend_font_pt);
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

void draw_legend_sample(cairo_t* cr, const theme& th, const series& s, double x, double y, double w) {
    set_color(cr, th, s.color);
    if (s.line != line_style::none) {
        set_line_style(cr, th, s.line);
        cairo_move_to(cr, x, y);
        cairo_line_to(cr, x + w, y);
        cairo_stroke(cr);
    }
    if (s.marker != marker_style::none) {
        device_series d{{x + 0.5 * w}, {y}};
        draw_markers(cr, th, d, rect{x, y - w, w, 2 * w});
    }
}

/// Draws the legend entries in a column inside box (no frame: the box is free of data).
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

/// Entries laid out side by side in lines no wider than max_w: the legend placed outside
/// the axes, when no spot inside is free of data.
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

/// Height of the band that legend_lines need.
double legend_band_height(const legend_layout& l, const theme& th, double max_w) {
    if (l.entries.empty()) return 0;
    return static_cast<double>(legend_lines(l, th, max_w).size()) * l.row_h + 0.5 * th.padding_pt;
}

/// Draws the entries in centred lines filling the band.
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

/// Everything needed to lay out one panel before it is drawn.
/// Space between the axis and the x tick labels: at least half a label's height, so the
/// lowest y tick label, centred on the bottom edge, never meets the first x tick label.
double x_tick_gap(double tick_h) { return 0.5 * tick_h + 0.5; }

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

/// Where a panel's data lands: the axes rectangle, the maps, the series in device points.
struct panel_geometry {
    rect area;
    axis_map mx;
    axis_map my;
    std::vector<device_series> dev;
};

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

/// The first candidate spot for the legend inside the axes that covers no data, if any.
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

/// Draws one panel; with show_legend, its legend goes inside the axes where it covers no
/// data, otherwise in a row of its own above them.
void draw_panel(cairo_t* cr, const text_engine& text, const theme& th, const panel& p, const panel_plan& plan,
                const rect& cell, bool show_legend) {
    const double pad = th.padding_pt;
    panel_geometry g = place_panel(p, plan, axes_area(plan, cell));
    const legend_layout& lg = plan.legend;
    std::optional<rect> legend_box;
    std::optional<rect> legend_band;
    if (show_legend && !lg.entries.empty()) {
        legend_box = legend_inside(p, lg, g, th);
        if (!legend_box) {
            // A band at the top of the cell, above the panel label.
            const double band = legend_band_height(lg, th, cell.w - 2 * pad);
            rect area = g.area;
            area.y += band;
            area.h -= band;
            g = place_panel(p, plan, area);
            legend_band = rect{cell.x + pad, cell.y + 0.3 * pad, cell.w - 2 * pad, band};
        }
    }
    const rect& area = g.area;
    const axis_map& mx = g.mx;
    const axis_map& my = g.my;
    const auto& dev = g.dev;

    // Data, clipped to the axes.
    cairo_save(cr);
    cairo_rectangle(cr, area.x, area.y, area.w, area.h);
    cairo_clip(cr);
    const rect clip{area.x - th.line_width_pt, area.y - th.line_width_pt, area.w + 2 * th.line_width_pt,
                    area.h + 2 * th.line_width_pt};
    for (std::size_t k = 0; k < p.data.size(); ++k) {
        const auto& s = p.data[k];
        set_color(cr, th, s.color);
        if (s.line != line_style::none) {
            set_line_style(cr, th, s.line);
            stroke_polyline(cr, dev[k], clip);
        }
        if (s.marker != marker_style::none) draw_markers(cr, th, dev[k], area);
    }
    cairo_restore(cr);

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

    // Tick labels.
    const double tick_gap = x_tick_gap(plan.tick_h);
    for (std::size_t i = 0; i < plan.xt.major.size(); ++i) {
        const double d = mx(plan.xt.major[i]);
        if (d < area.x - 0.01 || d > area.x + area.w + 0.01) continue;
        text.draw(plan.xt.labels[i], th.tick_font_pt, d, area.y + area.h + tick_gap, 0.5, 0.0);
    }
    for (std::size_t i = 0; i < plan.yt.major.size(); ++i) {
        const double d = my(plan.yt.major[i]);
        if (d < area.y - 0.01 || d > area.y + area.h + 0.01) continue;
        text.draw(plan.yt.labels[i], th.tick_font_pt, area.x - 0.6 * pad, d, 1.0, 0.5);
    }

    // Axis labels, panel label and legend.
    if (!p.x.label.empty()) {
        text.draw(p.x.label, th.label_font_pt, area.x + 0.5 * area.w, cell.y + cell.h - pad, 0.5, 1.0);
    }
    if (!p.y.label.empty()) {
        text.draw(p.y.label, th.label_font_pt, cell.x + pad, area.y + 0.5 * area.h, 0.5, 0.0, true);
    }
    if (!p.label.empty()) {
        text.draw(p.label, th.label_font_pt, area.x, area.y - 0.4 * pad, 0.0, 1.0);
    }
    if (legend_box) draw_legend(cr, text, th, p, lg, *legend_box);
    if (legend_band) draw_legend_band(cr, text, th, p, lg, *legend_band);
}


/// The figure with the theme's named styles applied to the series that carry a style key.
figure with_theme_styles(const figure& fig, const theme& th) {
    figure styled = fig;
    for (auto& p : styled.panels) {
        for (auto& s : p.data) {
            const auto it = s.style_key.empty() ? th.styles.end() : th.styles.find(s.style_key);
            if (it == th.styles.end()) continue;
            if (it->second.line) s.line = *it->second.line;
            if (it->second.marker) s.marker = *it->second.marker;
        }
    }
    return styled;
}

}  // namespace

void draw_figure(cairo_t* cr, const figure& unstyled, const theme& th, page_size size) {
    const bool any_key = std::any_of(unstyled.panels.begin(), unstyled.panels.end(), [](const panel& p) {
        return std::any_of(p.data.begin(), p.data.end(), [](const series& s) { return !s.style_key.empty(); });
    });
    const figure styled = any_key && !th.styles.empty() ? with_theme_styles(unstyled, th) : figure{};
    const figure& fig = any_key && !th.styles.empty() ? styled : unstyled;
    if (fig.rows < 1 || fig.cols < 1 || fig.panels.size() > static_cast<std::size_t>(fig.rows * fig.cols)) {
        throw std::invalid_argument("figure grid is too small for its panels");
    }
    if (th.palette.empty()) throw std::invalid_argument("theme has no colours");
    const text_engine text(cr, th.font_family);
    cairo_set_source_rgb(cr, th.background.r, th.background.g, th.background.b);
    cairo_paint(cr);

    // Shared margins keep the axes of neighbouring panels aligned.
    std::vector<panel_plan> plans;
    panel_plan shared;
    for (const auto& p : fig.panels) {
        plans.push_back(plan_panel(text, p, th));
        shared.left = std::max(shared.left, plans.back().left);
        shared.bottom = std::max(shared.bottom, plans.back().bottom);
        shared.top = std::max(shared.top, plans.back().top);
        shared.right = std::max(shared.right, plans.back().right);
    }
    for (auto& plan : plans) {
        plan.left = shared.left;
        plan.bottom = shared.bottom;
        plan.top = shared.top;
        plan.right = shared.right;
    }
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
    std::vector<rect> cells = make_cells(0);
    if (!fig.shared_legend || fig.panels.empty()) {
        for (std::size_t i = 0; i < fig.panels.size(); ++i) draw_panel(cr, text, th, fig.panels[i], plans[i], cells[i], true);
        return;
    }
    // A shared legend goes to the first panel with room for it inside the axes; failing
    // that, to a band across the top of the figure. Every panel shows the same series, so
    // the first panel's entries stand for all.
    const legend_layout& lg = plans[0].legend;
    std::optional<std::size_t> legend_panel;
    for (std::size_t i = 0; i < fig.panels.size() && !legend_panel; ++i) {
        const auto g = place_panel(fig.panels[i], plans[i], axes_area(plans[i], cells[i]));
        if (legend_inside(fig.panels[i], lg, g, th)) legend_panel = i;
    }
    if (!legend_panel && !lg.entries.empty()) {
        const double band = legend_band_height(lg, th, size.width_pt - 2 * th.padding_pt);
        draw_legend_band(cr, text, th, fig.panels[0], lg,
                         rect{th.padding_pt, 0.3 * th.padding_pt, size.width_pt - 2 * th.padding_pt, band});
        cells = make_cells(band + 0.3 * th.padding_pt);
    }
    for (std::size_t i = 0; i < fig.panels.size(); ++i) {
        if (legend_panel && i == *legend_panel) plans[i].legend = lg;
        draw_panel(cr, text, th, fig.panels[i], plans[i], cells[i], legend_panel && i == *legend_panel);
    }
}

}  // namespace plot
