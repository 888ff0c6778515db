// SPDX-License-Identifier: GPL-3.0-or-later
#include "plot/preflight.hpp"

#include "plot/errors.hpp"
#include "plot/handles.hpp"
#include "plot/render.hpp"
#include "plot/tex_markup.hpp"
#include "plot/text.hpp"

#include <cairo.h>
#include <pango/pango.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <regex>
#include <memory>
#include <tuple>

namespace plot {

namespace {

// The rules as each journal writes them; see the style files in src/figures/journals for
// the sources at length. APS's widths are revtex4-2's reprint \columnwidth and \textwidth.
constexpr std::array<journal_rules, 3> journals{{
    {"aps", "APS (Physical Review)", 8.6, 17.8, 8, 6, 0.5,
     "APS author tips; revtex4-2 reprint: \\columnwidth 8.6 cm, \\textwidth 17.8 cm"},
    {"aip", "AIP Publishing (APL, JAP, JCP, ...)", 8.5, 17.0, 8, 6, 0.5,
     "AIP Publishing, \"Preparing graphics\": one column 3.37 in, two 6.69 in, lettering 8 pt, lines 0.5 pt"},
    {"ajp", "American Journal of Physics", 8.6, 17.0, 8, 6, 0.5,
     "AJP, \"Formatting Figures\": one column 3.4 in, two 6.7 in, smallest font 8 pt"},
}};

constexpr double pt_per_cm = 72.0 / 2.54;

/// A number as a message shows it: at most three decimals, no trailing zeros.
std::string shown(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3f", v);
    std::string s = buf;
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
    return s;
}

/// What a stroke callback needs: the context whose strokes it measures, and where they go.
struct stroke_log {
    cairo_t* cr = nullptr;
    struct stroke {
        double width_pt;
        double x;
        double y;
    };
    std::vector<stroke> strokes;
};

/// Called by the observer surface for every stroke, while the context still holds the path
/// and the line width it strokes with: the width in page units, and the path's centre.
void on_stroke(cairo_surface_t* /*observer*/, cairo_surface_t* /*target*/, void* data) {
    auto* log = static_cast<stroke_log*>(data);
    double dx = cairo_get_line_width(log->cr);
    double dy = 0;
    cairo_user_to_device_distance(log->cr, &dx, &dy);
    double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    cairo_path_extents(log->cr, &x0, &y0, &x1, &y1);
    if (x0 == x1 && y0 == y1 && !cairo_has_current_point(log->cr)) return;  // an empty path draws nothing
    double cx = 0.5 * (x0 + x1);
    double cy = 0.5 * (y0 + y1);
    cairo_user_to_device(log->cr, &cx, &cy);
    log->strokes.push_back({std::hypot(dx, dy), cx, cy});
}

/// The panel a point of the page belongs to: the one whose axes hold it, else the nearest.
std::string panel_at(const figure& fig, const std::vector<panel_frame>& frames, double x, double y) {
    if (fig.panels.size() < 2 || frames.empty()) return {};
    std::size_t best = 0;
    double best_d = INFINITY;
    for (std::size_t i = 0; i < frames.size() && i < fig.panels.size(); ++i) {
        const auto& f = frames[i];
        const double dx = std::max({f.x - x, 0.0, x - (f.x + f.w)});
        const double dy = std::max({f.y - y, 0.0, y - (f.y + f.h)});
        const double d = std::hypot(dx, dy);
        if (d < best_d) {
            best_d = d;
            best = i;
        }
    }
    const auto& label = fig.panels[best].label;
    return label.empty() ? "panel " + std::to_string(best + 1) : markup_text(label.markup);
}

/// The style key that sets a text of this size, for a message's advice.
std::string size_key(const theme& th, double size) {
    const std::pair<const char*, double> keys[] = {{"tick_font_pt", th.tick_font_pt},
                                                   {"legend_font_pt", th.legend_font_pt},
                                                   {"label_font_pt", th.label_font_pt},
                                                   {"title_font_pt", th.title_font_pt}};
    for (const auto& [key, pt] : keys) {
        if (std::fabs(pt - size) < 1e-9) return key;
    }
    return "the text's size";
}

/// The glyph runs Pango shaped for one placed text: each run's characters and font size.
void add_runs(figure_measure& m, const theme& th, const placed_text& placed, const std::string& where) {
    text_shaper& shaper = text_shaper::for_thread(th.font_family);
    const auto box = shaper.box(placed.text.markup, placed.size_pt);
    const std::string whole = markup_text(placed.text.markup);
    const std::string key = size_key(th, placed.size_pt);
    for (const auto& part : box->parts) {
        PangoLayout* layout = part.layout.get();
        const char* chars = pango_layout_get_text(layout);
        std::unique_ptr<PangoLayoutIter, void (*)(PangoLayoutIter*)> it(pango_layout_get_iter(layout),
                                                                         pango_layout_iter_free);
        do {
            PangoLayoutRun* run = pango_layout_iter_get_run_readonly(it.get());
            if (!run) continue;
            font_description_ptr d(pango_font_describe_with_absolute_size(run->item->analysis.font));
            const double size = pango_font_description_get_size(d.get()) / static_cast<double>(PANGO_SCALE);
            m.texts.push_back({std::string(chars + run->item->offset, static_cast<std::size_t>(run->item->length)),
                               whole, size, size < placed.size_pt - 1e-3, where, key});
        } while (pango_layout_iter_next_run(it.get()));
    }
}

/// A series' colour as drawn.
rgb color_of(const theme& th, const series& s) {
    if (s.rgb_color) return *s.rgb_color;
    if (th.palette.empty()) return th.foreground;
    return th.palette[static_cast<std::size_t>(s.color) % th.palette.size()];
}

/// Each panel's labelled series, with the theme's named styles applied as drawn.
void add_series(figure_measure& m, const figure& fig, const theme& th) {
    const figure styled = with_theme_styles(fig, th);
    for (std::size_t i = 0; i < styled.panels.size(); ++i) {
        const panel& p = styled.panels[i];
        const std::string where = styled.panels.size() < 2 ? std::string()
                                  : p.label.empty()       ? "panel " + std::to_string(i + 1)
                                                          : markup_text(p.label.markup);
        std::vector<set_series> shown;
        for (const auto& s : p.data) {
            if (s.label.empty()) continue;
            shown.push_back({markup_text(s.label.markup), color_of(th, s), s.line, s.marker, where});
        }
        m.series.push_back(std::move(shown));
    }
}

/// "where: " before a message, or nothing for a one-panel figure.
std::string at(const std::string& where) { return where.empty() ? std::string() : where + ": "; }

/// The figure's width against the column or columns asked for.
void width_problems(std::vector<std::string>& out, const figure_measure& m, const journal_check& c) {
    const journal_rules& j = *c.rules;
    const double w = m.width_cm;
    constexpr double eps = 1e-6;
    const std::string is = "the figure is " + shown(w) + " cm wide";
    if (c.span == column_span::one && w > j.column_cm + eps) {
        out.push_back(is + ", wider than " + std::string(j.name) + "'s one column (" + shown(j.column_cm) +
                      " cm): set figure_width_cm = " + shown(j.column_cm) +
                      " (or a smaller panel_width_cm), or check it as a two-column figure (--check " +
                      std::string(j.name) + ":2)");
    } else if (w > j.page_cm + eps) {
        out.push_back(is + ", wider than " + std::string(j.name) + "'s two columns (" + shown(j.page_cm) +
                      " cm): set figure_width_cm = " + shown(j.page_cm) + " or less (or a smaller panel_width_cm)");
    }
}

/// Texts below the journal's lettering, one line per panel, size and key.
void text_problems(std::vector<std::string>& out, const figure_measure& m, const journal_rules& j) {
    std::map<std::tuple<std::string, double, bool, std::string>, std::vector<std::string>> small;
    for (const auto& t : m.texts) {
        const double least = t.script ? j.min_script_pt : j.min_text_pt;
        if (t.size_pt >= least - 1e-9) continue;
        auto& texts = small[{t.where, t.size_pt, t.script, t.key}];
        const std::string shown_text = "\"" + (t.script ? t.text + "\" (in \"" + t.whole + "\")" : t.whole + "\"");
        if (std::find(texts.begin(), texts.end(), shown_text) == texts.end()) texts.push_back(shown_text);
    }
    for (const auto& [k, texts] : small) {
        const auto& [where, size, script, key] = k;
        std::string list;
        for (const auto& t : texts) list += (list.empty() ? "" : ", ") + t;
        const double least = script ? j.min_script_pt : j.min_text_pt;
        const std::string what = script ? "superscripts and subscripts" : "lettering";
        out.push_back(at(where) + (script ? "script " : "text ") + list + " set at " + shown(size) + " pt, below " +
                      std::string(j.name) + "'s smallest " + what + " (" + shown(least) + " pt): raise " + key +
                      (script ? " (scripts are set smaller than their text)" : "") + " to " +
                      (script ? "a size whose scripts reach " + shown(least) + " pt" : shown(least) + " pt or more"));
    }
}

/// Strokes thinner than the journal's thinnest line, one line per panel and width.
void stroke_problems(std::vector<std::string>& out, const figure_measure& m, const journal_rules& j) {
    std::map<std::pair<std::string, double>, int> thin;
    for (const auto& s : m.strokes) {
        if (s.width_pt < j.min_line_pt - 1e-9) ++thin[{s.where, s.width_pt}];
    }
    for (const auto& [k, count] : thin) {
        out.push_back(at(k.first) + std::to_string(count) + (count == 1 ? " line " : " lines ") + shown(k.second) +
                      " pt wide, thinner than " + std::string(j.name) + "'s thinnest line (" + shown(j.min_line_pt) +
                      " pt): set min_line_pt = " + shown(j.min_line_pt) +
                      " (every line at least that), or raise line_width_pt (series) or frame_width_pt (frame "
                      "and ticks)");
    }
}

/// Labelled series of a panel that print as the same grey with the same dash and marker.
void grey_problems(std::vector<std::string>& out, const figure_measure& m) {
    for (const auto& panel_series : m.series) {
        for (std::size_t a = 0; a < panel_series.size(); ++a) {
            for (std::size_t b = a + 1; b < panel_series.size(); ++b) {
                const set_series& s = panel_series[a];
                const set_series& t = panel_series[b];
                // Series of one colour are not told apart by colour: greyscale changes nothing.
                const bool same_color = s.color.r == t.color.r && s.color.g == t.color.g && s.color.b == t.color.b;
                if (s.label == t.label || same_color || s.line != t.line || s.marker != t.marker) continue;
                const double step = std::fabs(grey_of(s.color) - grey_of(t.color));
                if (step >= min_grey_step - 1e-9) continue;
                out.push_back(at(s.where) + "\"" + s.label + "\" and \"" + t.label + "\" have the same dash and marker " +
                              "and greys " + shown(step) + " apart (less than " + shown(min_grey_step) +
                              " of black to white): they merge in greyscale print; give one another dash or marker, "
                              "or colours further apart in grey");
            }
        }
    }
}

}  // namespace

std::span<const journal_rules> journal_table() { return journals; }

std::string journal_names() {
    std::string out;
    for (const auto& j : journals) out += (out.empty() ? "" : ", ") + std::string(j.name);
    return out;
}

journal_check find_journal(std::string_view text) {
    const auto colon = text.find(':');
    const std::string_view name = text.substr(0, colon);
    const std::string_view span = colon == std::string_view::npos ? std::string_view() : text.substr(colon + 1);
    const std::string shown_value = text_problem(text).empty() ? "'" + std::string(text) + "'" : "(the value)";
    const auto row = std::find_if(journals.begin(), journals.end(), [&](const auto& j) { return j.name == name; });
    if (row == journals.end()) {
        throw bad_input("--check " + shown_value + ": unknown journal; journals: " + journal_names() +
                        " (NAME:1 holds a figure to one column, NAME:2 to two)");
    }
    if (colon != std::string_view::npos && span != "1" && span != "2") {
        throw bad_input("--check " + shown_value + ": after the journal's name, :1 (one column) or :2 (two columns)");
    }
    const column_span s = span == "1" ? column_span::one : span == "2" ? column_span::two : column_span::either;
    return {&*row, s};
}

double grey_of(const rgb& c) { return 0.299 * c.r + 0.587 * c.g + 0.114 * c.b; }

figure_measure measure_figure(const figure& fig, const theme& th) {
    const page_size size = figure_size(fig, th);
    figure_measure m;
    m.width_cm = size.width_pt / pt_per_cm;
    m.height_cm = size.height_pt / pt_per_cm;
    const cairo_rectangle_t extents{0, 0, size.width_pt, size.height_pt};
    surface_ptr target(cairo_recording_surface_create(CAIRO_CONTENT_COLOR_ALPHA, &extents));
    surface_ptr observer(cairo_surface_create_observer(target.get(), CAIRO_SURFACE_OBSERVER_NORMAL));
    context_ptr cr(cairo_create(observer.get()));
    stroke_log log{cr.get(), {}};
    cairo_surface_observer_add_stroke_callback(observer.get(), on_stroke, &log);
    std::vector<placed_text> texts;
    std::vector<panel_frame> frames;
    // As a PDF draws it, with each text recorded where it is set rather than drawn.
    draw_figure(cr.get(), fig, th, size, draw_pass::all, &texts, true, &frames);
    cairo_surface_finish(observer.get());
    for (const auto& t : texts) add_runs(m, th, t, panel_at(fig, frames, t.x, t.y));
    for (const auto& s : log.strokes) m.strokes.push_back({s.width_pt, panel_at(fig, frames, s.x, s.y)});
    add_series(m, fig, th);
    return m;
}

std::string scaling_note(const figure_measure& m, const journal_check& check) {
    const journal_rules& j = *check.rules;
    constexpr double eps = 1e-6;
    if (check.span != column_span::either || m.width_cm <= j.column_cm + eps || m.width_cm > j.page_cm + eps ||
        m.texts.empty()) {
        return {};
    }
    double smallest = m.texts.front().size_pt;
    for (const auto& t : m.texts) {
        if (!t.script) smallest = std::min(smallest, t.size_pt);
    }
    const double scaled = std::floor(smallest * j.column_cm / m.width_cm * 10) / 10;  // rounded down: never kinder
    return "include it at its natural size (width " + shown(m.width_cm) + " cm): scaled to the " +
           shown(j.column_cm) + "-cm column, its smallest text would be " + shown(scaled) + " pt" +
           (scaled < j.min_text_pt - eps ? ", below " + shown(j.min_text_pt) : "");
}

std::vector<std::string> preflight_problems(const figure_measure& m, const journal_check& check) {
    std::vector<std::string> out;
    width_problems(out, m, check);
    text_problems(out, m, *check.rules);
    stroke_problems(out, m, *check.rules);
    grey_problems(out, m);
    return out;
}

namespace {

/// Every label of the figure's panels (its peers too: every file of a set decides alike)
/// and its title, as plain text.
std::vector<std::string> label_texts(const figure& fig) {
    std::vector<std::string> out;
    const auto add = [&](const label& l) {
        if (!l.empty()) out.push_back(markup_text(l.markup));
    };
    add(fig.title);
    for (const auto* panels : {&fig.panels, &fig.peers}) {
        for (const panel& p : *panels) {
            add(p.label);
            add(p.x.label);
            add(p.y.label);
            for (const series& s : p.data) add(s.label);
        }
    }
    return out;
}

}  // namespace

std::string angle_notation_problem(const figure& fig) {
    // A decimal multiple of pi (0.95π), and a fraction of it (9π/10, π/2).
    static const std::regex decimal("[0-9]*\\.[0-9]+\u03c0");
    static const std::regex fraction("[0-9]*\u03c0/[0-9]+");
    std::string a_decimal;
    std::string a_fraction;
    for (const std::string& text : label_texts(fig)) {
        std::smatch m;
        if (a_decimal.empty() && std::regex_search(text, m, decimal)) a_decimal = m.str();
        if (a_fraction.empty() && std::regex_search(text, m, fraction)) a_fraction = m.str();
    }
    if (a_decimal.empty() || a_fraction.empty()) return {};
    return "angles are written two ways in one figure, " + a_fraction + " (a fraction of \u03c0) and " + a_decimal +
           " (a decimal): write them one way in the spec, all as decimals (0.9pi) or all as fractions (99pi/100)";
}

}  // namespace plot
