#pragma once
// Part of the plot layer's renderer; not a public interface.

#include "plot/handles.hpp"

#include <cairo.h>
#include <pango/pangocairo.h>

#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>

namespace plot {

/// This thread's Pango font map over the project's private font configuration (only the
/// fonts in /usr/share/fonts, no machine or user settings), so pictures are the same on
/// every machine. Font maps are not shared between threads.
PangoFontMap* thread_font_map();

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

}  // namespace plot
