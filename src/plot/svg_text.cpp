// SPDX-License-Identifier: GPL-3.0-or-later
#include "plot/svg_text.hpp"

#include "plot/math_layout.hpp"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <utility>

namespace plot {

std::string svg_number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3f", v);
    std::string s = buf;
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
    return s == "-0" ? "0" : s;
}

namespace {

std::string hex_color(const rgb& c) {
    const auto byte = [](double v) { return static_cast<unsigned>(std::lround(std::clamp(v, 0.0, 1.0) * 255)); };
    char buf[8];
    std::snprintf(buf, sizeof buf, "#%02x%02x%02x", byte(c.r), byte(c.g), byte(c.b));
    return buf;
}

/// Pango's comma-separated families as a CSS font-family list, each quoted.
std::string css_families(const std::string& families) {
    std::string out;
    std::size_t from = 0;
    while (from <= families.size()) {
        auto comma = families.find(',', from);
        if (comma == std::string::npos) comma = families.size();
        std::string name = families.substr(from, comma - from);
        name.erase(0, name.find_first_not_of(' '));
        name.erase(name.find_last_not_of(' ') + 1);
        if (!name.empty()) {
            std::string quoted;
            for (const char c : name) {
                if (c != '\'' && c != '"' && c != '\\') quoted += c;
            }
            out += (out.empty() ? "'" : ", '") + escape_markup(quoted) + "'";
        }
        from = comma + 1;
    }
    return out;
}

/// A run of text in one style, as Pango parses markup.
struct run {
    std::string text;
    double pt = 0;       // size
    double rise = 0;     // baseline raised by, in points
    bool italic = false;
    bool bold = false;
    bool overline = false;  // \sqrt's and \overline's line
    std::string family;  // empty: the text element's
};

struct attr_list_deleter {
    void operator()(PangoAttrList* p) const { pango_attr_list_unref(p); }
    void operator()(PangoAttrIterator* p) const { pango_attr_iterator_destroy(p); }
};

/// Markup's runs at size pt; scripts nested in other elements (which split_scripts leaves)
/// at the drawing's script size and shifts.
std::vector<run> runs_of(const std::string& markup, double pt) {
    const script_metrics m;
    const auto units = [](double v) { return std::to_string(std::lround(v * PANGO_SCALE)); };
    const std::pair<std::string, std::string> rules[] = {
        {"<sub>", "<span size=\"" + units(m.size * pt) + "\" rise=\"-" + units(m.sub_shift * pt) + "\">"},
        {"<sup>", "<span size=\"" + units(m.size * pt) + "\" rise=\"" + units(m.sup_shift * pt) + "\">"},
        {"</sub>", "</span>"},
        {"</sup>", "</span>"}};
    std::string spans = markup;
    for (const auto& [from, to] : rules) {
        for (std::size_t pos = 0; (pos = spans.find(from, pos)) != std::string::npos; pos += to.size()) {
            spans.replace(pos, from.size(), to);
        }
    }
    PangoAttrList* list = nullptr;
    char* text = nullptr;
    GError* error = nullptr;
    if (!pango_parse_markup(spans.c_str(), -1, 0, &list, &text, nullptr, &error)) {
        const std::string why = error ? error->message : "not valid";
        g_clear_error(&error);
        throw bad_input("invalid text markup '" + markup + "': " + why);
    }
    const std::unique_ptr<char, decltype(&g_free)> owned_text(text, g_free);
    const std::unique_ptr<PangoAttrList, attr_list_deleter> owned_list(list);
    const std::unique_ptr<PangoAttrIterator, attr_list_deleter> it(pango_attr_list_get_iterator(list));
    const auto length = static_cast<gint>(std::strlen(text));
    std::vector<run> runs;
    do {
        gint start = 0;
        gint end = 0;
        pango_attr_iterator_range(it.get(), &start, &end);
        end = std::min(end, length);
        if (start >= end) continue;
        run r;
        r.text.assign(text + start, static_cast<std::size_t>(end - start));
        r.pt = pt;
        if (const auto* a = pango_attr_iterator_get(it.get(), PANGO_ATTR_SIZE)) {
            r.pt = reinterpret_cast<const PangoAttrSize*>(a)->size / double(PANGO_SCALE);
        }
        if (const auto* a = pango_attr_iterator_get(it.get(), PANGO_ATTR_SCALE)) {
            r.pt *= reinterpret_cast<const PangoAttrFloat*>(a)->value;
        }
        if (const auto* a = pango_attr_iterator_get(it.get(), PANGO_ATTR_RISE)) {
            r.rise = reinterpret_cast<const PangoAttrInt*>(a)->value / double(PANGO_SCALE);
        }
        if (const auto* a = pango_attr_iterator_get(it.get(), PANGO_ATTR_STYLE)) {
            r.italic = reinterpret_cast<const PangoAttrInt*>(a)->value != PANGO_STYLE_NORMAL;
        }
        if (const auto* a = pango_attr_iterator_get(it.get(), PANGO_ATTR_WEIGHT)) {
            r.bold = reinterpret_cast<const PangoAttrInt*>(a)->value >= PANGO_WEIGHT_SEMIBOLD;
        }
        if (const auto* a = pango_attr_iterator_get(it.get(), PANGO_ATTR_OVERLINE)) {
            r.overline = reinterpret_cast<const PangoAttrInt*>(a)->value != PANGO_OVERLINE_NONE;
        }
        if (const auto* a = pango_attr_iterator_get(it.get(), PANGO_ATTR_FAMILY)) {
            r.family = reinterpret_cast<const PangoAttrString*>(a)->value;
        }
        runs.push_back(std::move(r));
    } while (pango_attr_iterator_next(it.get()));
    return runs;
}

/// The <tspan>s of one text element, which tracks how far its baseline is raised.
class tspan_writer {
public:
    tspan_writer(const text_engine& engine, double size) : engine_(engine), size_(size) {}

    /// The label's markup, its scripts placed as the drawing places them.
    void write(const std::string& markup) {
        const script_metrics m;
        for (const auto& piece : split_scripts(engine_.drawn(inline_fractions(markup)))) {
            if (!piece.base.empty() || (!piece.has_sup && !piece.has_sub)) add(piece.base, size_, 0);
            double sup_width = 0;
            if (piece.has_sup) {
                if (only_primes(piece.sup)) {
                    // A prime's glyph is drawn raised already: on the baseline, full size.
                    add(piece.sup, size_, 0);
                    sup_width = engine_.measure(piece.sup, size_).first;
                } else {
                    add(piece.sup, m.size * size_, m.sup_shift * size_);
                    sup_width = engine_.measure(piece.sup, m.size * size_).first;
                }
            }
            if (piece.has_sub) {
                // Under the superscript: back by its width, then on by what it leaves.
                dx_ = -sup_width;
                const double shift = (piece.has_sup ? m.sub_shift_with_sup : m.sub_shift) * size_;
                add(piece.sub, m.size * size_, -shift);
                const double sub_width = engine_.measure(piece.sub, m.size * size_).first;
                if (sup_width > sub_width) dx_ = sup_width - sub_width;
            }
        }
    }

    /// What was written, an overline open at its end closed.
    std::string text() const { return overlined_ ? out_ + "</tspan>" : out_; }

private:
    void add(const std::string& markup, double pt, double rise) {
        for (const run& r : runs_of(markup, pt)) {
            const double up = rise + r.rise;
            std::string attributes;
            if (std::fabs(up - raised_) > 1e-9) attributes += " dy=\"" + svg_number(raised_ - up) + "\"";
            if (dx_ != 0) attributes += " dx=\"" + svg_number(dx_) + "\"";
            if (std::fabs(r.pt - size_) > 1e-9) attributes += " font-size=\"" + svg_number(r.pt) + "\"";
            if (r.italic) attributes += " font-style=\"italic\"";
            if (r.bold) attributes += " font-weight=\"bold\"";
            if (!r.family.empty()) attributes += " font-family=\"" + css_families(r.family) + "\"";
            raised_ = up;
            dx_ = 0;
            overline(r.overline);
            out_ += attributes.empty() ? escape_markup(r.text)
                                       : "<tspan" + attributes + ">" + escape_markup(r.text) + "</tspan>";
        }
    }

    /// One <tspan> with the overline around every run under it (\sqrt's and \overline's
    /// line), so that it is one line over the whole, not one per run at each run's height.
    void overline(bool on) {
        if (on == overlined_) return;
        out_ += on ? "<tspan text-decoration=\"overline\">" : "</tspan>";
        overlined_ = on;
    }

    const text_engine& engine_;
    double size_;
    bool overlined_ = false;  // an overline's <tspan> is open
    double raised_ = 0;  // the current baseline above the text's
    double dx_ = 0;      // a move along the baseline owed to the next run
    std::string out_;
};

}  // namespace

std::string svg_text_elements(const std::vector<placed_text>& texts, const theme& th) {
    if (texts.empty()) return {};
    // Only measures (scripts' widths): drawn nowhere.
    surface_ptr surface(cairo_image_surface_create(CAIRO_FORMAT_A8, 1, 1));
    context_ptr cr(cairo_create(surface.get()));
    const text_engine engine(cr.get(), th.font_family);
    std::string out = "<g fill=\"" + hex_color(th.foreground) + "\" font-family=\"" + css_families(th.font_family) +
                      "\" xml:space=\"preserve\">\n";
    for (const placed_text& t : texts) {
        tspan_writer spans(engine, t.size_pt);
        spans.write(t.text.markup);
        const std::string x = svg_number(t.x);
        const std::string y = svg_number(t.y);
        out += "<text x=\"" + x + "\" y=\"" + y + "\" font-size=\"" + svg_number(t.size_pt) + "\"";
        if (t.align > 0.75) {
            out += " text-anchor=\"end\"";
        } else if (t.align >= 0.25) {
            out += " text-anchor=\"middle\"";
        }
        if (t.rotate) out += " transform=\"rotate(-90 " + x + " " + y + ")\"";
        out += ">" + spans.text() + "</text>\n";
    }
    return out + "</g>\n";
}

}  // namespace plot
