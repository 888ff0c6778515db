// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Part of the plot layer's renderer; not a public interface.

#include "plot/errors.hpp"
#include "plot/figure.hpp"
#include "plot/handles.hpp"
#include "plot/math_layout.hpp"

#include <cairo.h>
#include <pango/pangocairo.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace plot {

/// This thread's Pango font map over the project's private font configuration (only the
/// fonts in /usr/share/fonts, no machine or user settings), so pictures are the same on
/// every machine. Font maps are not shared between threads.
PangoFontMap* thread_font_map();

/// This thread's Pango font map over the faces of the families `font_family` names and no
/// other font (thread_font_map() where none is installed): for a text they cover it picks
/// the faces thread_font_map() picks, after sorting a few faces instead of every font.
PangoFontMap* named_font_map(const std::string& font_family);

/// True if named_font_map(font_family) lays out `text` (with `attrs`, may be null) as
/// thread_font_map() does: a face of a named family covers each of its characters and no
/// attribute names a family of its own.
bool named_fonts_cover(const std::string& font_family, const char* text, PangoAttrList* attrs);

/// The font directories of that configuration, as fontconfig lists them: the machine's and
/// the user's font directories (read from their fontconfig files, not their settings).
std::vector<std::string> private_font_directories();

/// True if Pango, in `context`, loads the first family of the comma-separated
/// `font_family` as that very family (fontconfig substitutes another for a missing one).
bool first_family_resolves(PangoContext* context, const std::string& font_family);

/// A letter a font draws with another letter's glyph, and the markup that draws it apart.
struct letter_form {
    std::string letter;  ///< the UTF-8 letter, as a label's markup holds it
    std::string markup;  ///< what draws it instead
};

/// The letters the first family of `font_family` draws alike in italic (Computer Modern
/// Unicode draws θ as ϑ in its serif and ϑ as θ in its sans), each with the form that draws
/// it as itself: the Unicode mathematical italic letter (U+1D703 𝜃, U+1D717 𝜗), set upright
/// since its glyph leans already, from the family or a font fontconfig finds for it.
std::vector<letter_form> distinct_letter_forms(PangoContext* context, const std::string& font_family);

/// The primes (′ ″ ‴) as the first family of `font_family` draws them: where it has no
/// U+2032 but the modifier letter prime U+02B9 (Computer Modern Unicode), that, so that a
/// prime has the weight of the letters beside it and not a fallback font's; else none.
std::vector<letter_form> text_font_primes(PangoContext* context, const std::string& font_family);

/// Markup with each letter of `forms` replaced by its form.
std::string with_letter_forms(std::string markup, const std::vector<letter_form>& forms);

/// The text of Pango markup without its tags and entities, parsed by Pango (for metadata).
std::string markup_text(const std::string& markup);

/// The inked part of a text: a rectangle in points.
struct text_ink {
    double x = 0;  ///< left
    double y = 0;  ///< top (y down)
    double w = 0;  ///< width
    double h = 0;  ///< height
};

/// A text placed on the page but not drawn, for a LaTeX overlay: the left end of its
/// baseline, and the point of the baseline where `align` (0 left, 0.5 centre, 1 right) is.
struct placed_text {
    plot::label text;    ///< the text
    double size_pt = 0;  ///< its size
    double x = 0;        ///< the anchor, points from the left
    double y = 0;        ///< the anchor (on the baseline), points from the top
    double align = 0;    ///< which point of the text the anchor is: 0 left, 0.5 centre, 1 right
    bool rotate = false; ///< turned by 90 degrees (reading upwards)
};

/// Texts shaped with Pango in one font family, in points, and kept: a thread's shaper of a
/// family serves every figure and format the thread draws, so that the PNG, the PDF and the
/// words of a figure shape each of its texts once.
class text_shaper {
public:
    /// The calling thread's shaper of `family`; its first family must be installed.
    static text_shaper& for_thread(const std::string& family);

    /// A shaper of `family` in this thread's font map.
    explicit text_shaper(const std::string& family)
        : family_(family), context_(shaping_context(named_font_map(family))) {
        check_font_installed();
        forms_ = distinct_letter_forms(context_.get(), family_);
        for (letter_form& f : text_font_primes(context_.get(), family_)) forms_.push_back(std::move(f));
    }

    /// The markup as this family draws it: letters it would draw alike kept apart.
    std::string drawn(const std::string& markup) const { return with_letter_forms(markup, forms_); }

    /// A label set as TeX sets math: runs of text on the baseline, and after them
    /// superscripts and subscripts at script size, stacked, each a Pango layout.
    struct text_box {
        struct part {
            gobject_ptr<PangoLayout> layout;
            double x = 0;         // left end of the part's baseline
            double y = 0;         // the part's baseline, below the box's (y down)
            double baseline = 0;  // the layout's own baseline below its top
            double stretch = 1;   // drawn stretched upright by this (a radical's sign)
        };
        /// A filled rectangle: a fraction's rule, a radical's line.
        struct rule {
            double x = 0, y = 0, w = 0, h = 0;
        };
        std::vector<part> parts;
        std::vector<rule> rules;
        double width = 0;
        double ascent = 0;   // logical, above the baseline
        double descent = 0;  // logical, below the baseline
        double ink_x0 = 0, ink_y0 = 0, ink_x1 = 0, ink_y1 = 0;
        bool inked = false;  // some part has ink
    };


    /// The shaped box of markup at size, shaped once while it is kept (the most recent
    /// `kept_boxes` texts are; an animation's changing clock does not grow the memory).
    std::shared_ptr<const text_box> box(const std::string& markup, double size) {
        auto key = std::make_pair(markup, size);
        auto it = boxes_.find(key);
        if (it != boxes_.end()) return it->second;
        auto made = std::make_shared<const text_box>(make_box(markup, size));
        if (boxes_.size() >= kept_boxes) boxes_.clear();
        boxes_.emplace(std::move(key), made);
        return made;
    }

    /// How many shaped texts are kept.
    std::size_t kept() const { return boxes_.size(); }

    /// The most texts kept at once.
    static constexpr std::size_t kept_boxes = 4096;

private:


    /// Where a math accent goes, in ems of the base's size: the gap between the base's ink
    /// and the accent's, and the slope an italic letter leans by (Computer Modern's is 1/4).
    static constexpr double accent_gap = 0.08;
    static constexpr double italic_slope = 0.25;

    /// Adds a part: markup at pt with the left end of its baseline at (x, y); returns its
    /// advance. The box's ascent grows by the part's logical extent, or (for an accent,
    /// `logical` false) by its ink alone.
    double add_part(text_box& b, const std::string& text, double pt, double x, double y, bool logical = true,
                    double stretch = 1) const {
        text_box::part p;
        p.layout = make(text, pt, text);
        p.x = x;
        p.y = y;
        p.stretch = stretch;
        p.baseline = pango_layout_get_baseline(p.layout.get()) / double(PANGO_SCALE);
        PangoRectangle ink, extent;
        pango_layout_get_extents(p.layout.get(), &ink, &extent);
        for (PangoRectangle* r : {&ink, &extent}) {
            const int baseline_units = pango_layout_get_baseline(p.layout.get());
            r->y = static_cast<int>(std::lround(baseline_units + (r->y - baseline_units) * stretch));
            r->height = static_cast<int>(std::lround(r->height * stretch));
        }
        const double top = y - p.baseline;
        if (logical) {
            b.ascent = std::max(b.ascent, -(top + extent.y / double(PANGO_SCALE)));
            b.descent = std::max(b.descent, top + (extent.y + extent.height) / double(PANGO_SCALE));
        }
        if (ink.width > 0 && ink.height > 0) {
            const double x0 = x + ink.x / double(PANGO_SCALE);
            const double y0 = top + ink.y / double(PANGO_SCALE);
            const double x1 = x0 + ink.width / double(PANGO_SCALE);
            const double y1 = y0 + ink.height / double(PANGO_SCALE);
            if (!logical) b.ascent = std::max(b.ascent, -y0);
            b.ink_x0 = b.inked ? std::min(b.ink_x0, x0) : x0;
            b.ink_y0 = b.inked ? std::min(b.ink_y0, y0) : y0;
            b.ink_x1 = b.inked ? std::max(b.ink_x1, x1) : x1;
            b.ink_y1 = b.inked ? std::max(b.ink_y1, y1) : y1;
            b.inked = true;
        }
        b.parts.push_back(std::move(p));
        return extent.width / double(PANGO_SCALE);
    }

    /// Adds a run of markup, its accents placed as TeX places them and an italic letter
    /// after a slash no farther from it than TeX sets it; returns its advance.
    double add_run(text_box& b, const std::string& markup, double pt, double x, double y) const {
        const std::size_t cut = italic_after_slash(markup);
        if (cut == std::string::npos) return add_accented(b, markup, pt, x, y);
        const std::string left = markup.substr(0, cut);
        const std::string right = markup.substr(cut);
        const double advance = add_accented(b, left, pt, x, y);
        const text_ink l = ink_of(left, pt);
        const text_ink r = ink_of(right, pt);
        const double gap = advance + r.x - (l.x + l.w);
        const double pull = l.w > 0 && r.w > 0 ? std::max(0.0, gap - slash_gap * pt) : 0.0;
        return advance - pull + add_run(b, right, pt, x + advance - pull, y);
    }

    /// Adds a run of markup, its accents placed as TeX places them; returns its advance.
    double add_accented(text_box& b, const std::string& markup, double pt, double x, double y) const {
        const std::vector<accent_piece> pieces = split_accents(markup);
        // Nothing but tags, or nothing: one part all the same, which has the font's height.
        if (pieces.empty()) return add_part(b, markup, pt, x, y);
        double advance = 0;
        for (const accent_piece& piece : pieces) {
            const double w = add_part(b, piece.text, pt, x + advance, y);
            if (!piece.mark.empty()) add_accent(b, piece, pt, x + advance, y);
            advance += w;
        }
        return advance;
    }

    /// The accent of an accented character drawn at (x, y): its ink centred over the
    /// character's optical centre (the middle of the ink of its top part, moved along the
    /// slope of an italic letter up to the accent's middle), `accent_gap` above its ink.
    void add_accent(text_box& b, const accent_piece& piece, double pt, double x, double y) const {
        const text_ink base = ink_of(piece.text, pt);
        // On a no-break space, as Unicode shows a mark alone: a mark at the start of a text
        // is drawn on a dotted circle.
        const std::string alone = "\u00a0" + piece.mark;
        const text_ink mark = ink_of(alone, pt);
        if (base.h <= 0 || mark.h <= 0) return;
        const double gap = accent_gap * pt;
        const auto [left, right] = ink_span_in_band(piece.text, pt, base.y, base.y + 0.3 * base.h);
        double centre = std::isfinite(left) ? (left + right) / 2 : base.x + base.w / 2;
        // The top band's middle is 0.15 of the height under the top; the accent's, half its
        // height and the gap above it.
        if (leans(piece.text)) centre += italic_slope * (0.15 * base.h + gap + mark.h / 2);
        const double mark_y = y + base.y - gap - (mark.y + mark.h);
        add_part(b, alone, pt, x + centre - (mark.x + mark.w / 2), mark_y, false);
    }

    /// True if the markup's glyphs lean: italic, or a mathematical italic letter (U+1D434..).
    bool leans(const std::string& text) const {
        const std::string d = drawn(text);
        return d.find("<i>") != std::string::npos || d.find("\xf0\x9d") != std::string::npos;
    }

    text_box make_box(const std::string& markup, double size) const {
        text_box b;
        b.width = add_math(b, markup, size, script_metrics{}.size * script_metrics{}.size * size, 0, 0);
        return b;
    }

    /// Lays out markup at `size` with the left end of its baseline at (x, y): runs on the
    /// baseline, fractions and radicals stacked, and the scripts after them, at every level
    /// of scripts (none smaller than `least`); returns its advance.
    double add_math(text_box& b, const std::string& markup, double size, double least, double x, double y) const {
        double width = 0;
        for (const auto& piece : split_scripts(markup)) {
            const double start = width;
            std::string base_markup;
            if (!piece.base.empty() || (!piece.has_sup && !piece.has_sub)) {
                width += add_boxes(b, piece.base, size, least, x + start, y);
                base_markup = piece.base;
            }
            const script_place at{base_markup, size, least, x, y, start, width};
            width += add_scripts(b, piece, at);
        }
        return width;
    }

    /// Where a piece's scripts go: after its base (`base`, from `start` to `end` along the
    /// baseline at (x, y)), set at `size`.
    struct script_place {
        const std::string& base;
        double size, least, x, y, start, end;
    };

    /// A script starts after the base's advance, or clear of the base's ink beside it if an
    /// italic letter leans out that far (the bowl of ϑ), as a math italic font's wider
    /// advance would; under an overhang above it (the arm of T) it tucks in.
    double script_x(const script_place& at, const std::string& script, double pt, double dy) const {
        if (at.base.empty() || has_boxes(script)) return at.end;
        // After a fraction or radical, the run that ends the base (none: the box's advance).
        std::string base = at.base;
        double start = at.start;
        if (has_boxes(base)) {
            const std::vector<box_piece> pieces = split_boxes(base);
            if (pieces.back().type != box_piece::kind::run) return at.end;
            base = pieces.back().text;
            PangoRectangle extent;
            pango_layout_get_extents(make(base, at.size, base).get(), nullptr, &extent);
            start = at.end - extent.width / double(PANGO_SCALE);
        }
        const text_ink j = ink_of(script, pt);
        const double right = ink_right_in_band(base, at.size, dy + j.y, dy + j.y + j.h);
        return std::max(at.end, start + right + 0.04 * at.size - j.x);
    }

    /// Adds a piece's superscript and subscript, stacked; returns their advance.
    double add_scripts(text_box& b, const math_piece& piece, const script_place& at) const {
        const script_metrics m;
        const double script_pt = std::max(m.size * at.size, at.least);
        double script_w = 0;
        if (piece.has_sup) {
            double pt = script_pt;
            double dy = -m.sup_shift * at.size;
            if (only_primes(piece.sup)) {
                // Sized and raised by its ink to where TeX's prime, standing on the
                // superscript's baseline, would be.
                const text_ink i = ink_of(piece.sup, pt);
                if (i.h > 0) pt *= m.prime_height * at.size / i.h;
                const text_ink j = ink_of(piece.sup, pt);
                dy -= j.y + j.h;
            }
            const double sx = script_x(at, piece.sup, pt, dy);
            script_w = std::max(script_w, add_math(b, piece.sup, pt, at.least, at.x + sx, at.y + dy) + sx - at.end);
        }
        if (piece.has_sub) {
            const double dy = (piece.has_sup ? m.sub_shift_with_sup : m.sub_shift) * at.size;
            const double sx = script_x(at, piece.sub, script_pt, dy);
            script_w = std::max(script_w, add_math(b, piece.sub, script_pt, at.least, at.x + sx, at.y + dy) + sx - at.end);
        }
        return script_w;
    }

    /// Adds a base: its runs, and its fractions and radicals laid out; returns its advance.
    double add_boxes(text_box& b, const std::string& markup, double size, double least, double x, double y) const {
        if (!has_boxes(markup)) return add_run(b, markup, size, x, y);
        double advance = 0;
        for (const box_piece& p : split_boxes(markup)) {
            switch (p.type) {
                case box_piece::kind::run: advance += add_run(b, p.text, size, x + advance, y); break;
                case box_piece::kind::fraction: advance += add_fraction(b, p, size, least, x + advance, y); break;
                case box_piece::kind::radical: advance += add_radical(b, p, size, least, x + advance, y); break;
            }
        }
        return advance;
    }

    /// Markup laid out on its own, its baseline's left end at (0, 0).
    text_box sub_box(const std::string& markup, double size, double least) const {
        text_box t;
        t.width = add_math(t, markup, size, least, 0, 0);
        return t;
    }

    /// Moves a box laid out on its own into b, its baseline's left end at (x, y): each part
    /// is shaped once however deep fractions and radicals nest.
    static void add_box(text_box& b, text_box&& t, double x, double y) {
        for (auto& p : t.parts) {
            p.x += x;
            p.y += y;
            b.parts.push_back(std::move(p));
        }
        for (const auto& r : t.rules) b.rules.push_back({r.x + x, r.y + y, r.w, r.h});
        b.ascent = std::max(b.ascent, t.ascent - y);
        b.descent = std::max(b.descent, t.descent + y);
        if (!t.inked) return;
        b.ink_x0 = b.inked ? std::min(b.ink_x0, t.ink_x0 + x) : t.ink_x0 + x;
        b.ink_y0 = b.inked ? std::min(b.ink_y0, t.ink_y0 + y) : t.ink_y0 + y;
        b.ink_x1 = b.inked ? std::max(b.ink_x1, t.ink_x1 + x) : t.ink_x1 + x;
        b.ink_y1 = b.inked ? std::max(b.ink_y1, t.ink_y1 + y) : t.ink_y1 + y;
        b.inked = true;
    }

    /// Adds a filled rectangle (a fraction's rule, a radical's line) to the box.
    static void add_rule(text_box& b, double x, double y, double w, double h) {
        b.rules.push_back({x, y, w, h});
        b.ascent = std::max(b.ascent, -y);
        b.descent = std::max(b.descent, y + h);
        b.ink_x0 = b.inked ? std::min(b.ink_x0, x) : x;
        b.ink_y0 = b.inked ? std::min(b.ink_y0, y) : y;
        b.ink_x1 = b.inked ? std::max(b.ink_x1, x + w) : x + w;
        b.ink_y1 = b.inked ? std::max(b.ink_y1, y + h) : y + h;
        b.inked = true;
    }

    /// The left end at which a part's ink (or, without ink, its advance) is centred on cx.
    static double centred(const text_box& part, double cx) {
        return part.inked ? cx - (part.ink_x0 + part.ink_x1) / 2 : cx - part.width / 2;
    }

    /// A fraction as TeX stacks it in text style (\dfrac: display style): the numerator
    /// over a rule on the math axis over the denominator, each part centred on the rule,
    /// clear of it by the rule's thickness (three in display style); returns its advance.
    double add_fraction(text_box& b, const box_piece& p, double size, double least, double x, double y) const {
        const fraction_metrics f;
        const double pt = p.display ? size : std::max(script_metrics{}.size * size, least);
        text_box num = sub_box(p.num, pt, least);
        text_box den = sub_box(p.den, pt, least);
        const double theta = f.rule * size;
        const double clear = (p.display ? 3 : 1) * theta;
        const double axis = f.axis * size;
        double up = (p.display ? f.num_shift_display : f.num_shift) * size;
        double down = (p.display ? f.den_shift_display : f.den_shift) * size;
        if (num.inked) up += std::max(0.0, clear - (up - num.ink_y1 - axis - theta / 2));
        if (den.inked) down += std::max(0.0, clear - (down + den.ink_y0 + axis - theta / 2));
        const double w = std::max(num.width, den.width);
        const double side = f.side * size;
        const double cx = x + side + w / 2;
        const double num_x = centred(num, cx);
        const double den_x = centred(den, cx);
        add_box(b, std::move(num), num_x, y - up);
        add_box(b, std::move(den), den_x, y + down);
        add_rule(b, x + side, y - axis - theta / 2, w, theta);
        return w + 2 * side;
    }

    /// A radical (or \overline's line alone): the radicand at the text's size under a rule
    /// clear of its ink as TeX's is (1.25 rules' thickness; \overline: 3), the sign at its
    /// own size where it reaches the rule and the radicand's foot, else stretched to them.
    double add_radical(text_box& b, const box_piece& p, double size, double least, double x, double y) const {
        const fraction_metrics f;
        text_box body = sub_box(p.text, size, least);
        const double theta = f.rule * size;
        const double body_top = body.inked ? std::min(body.ink_y0, -0.43 * size) : -0.43 * size;
        double rule_top = body_top - (p.sign ? 1.25 : 3) * theta - theta;
        double advance = 0;
        double rule_x = x;
        if (p.sign) {
            const std::string sign = "\u221a";
            const text_ink s = ink_of(sign, size);
            const double foot = std::max(s.y + s.h, body.inked ? body.ink_y1 : 0.0);
            rule_top = std::min(rule_top, s.y);
            const double stretch = s.h > 0 ? (foot - rule_top) / s.h : 1;
            advance = add_part(b, sign, size, x, y + rule_top - stretch * s.y, true, stretch);
            rule_x = x + s.x + s.w - theta / 2;
        }
        const double width = body.width;
        add_box(b, std::move(body), x + advance, y);
        add_rule(b, rule_x, y + rule_top, x + advance + width - rule_x, theta);
        return advance + width;
    }

    /// The rightmost ink of plain markup between heights y0 and y1 (relative to its
    /// baseline, y down), found by drawing it; -infinity if there is none.
    double ink_right_in_band(const std::string& text, double pt, double y0, double y1) const {
        return ink_span_in_band(text, pt, y0, y1).second;
    }

    /// The leftmost and rightmost ink of plain markup between heights y0 and y1 (relative
    /// to its baseline, y down), found by drawing it; infinities if there is none.
    std::pair<double, double> ink_span_in_band(const std::string& text, double pt, double y0, double y1) const {
        const gobject_ptr<PangoLayout> l = make(text, pt, text);
        PangoRectangle ink;
        pango_layout_get_extents(l.get(), &ink, nullptr);
        const double baseline = pango_layout_get_baseline(l.get()) / double(PANGO_SCALE);
        const double scale = 400.0 / pt;  // pixels per point: 400 across an em
        const double x1 = (ink.x + ink.width) / double(PANGO_SCALE);
        const int w = static_cast<int>(std::ceil(std::max(x1, 0.0) * scale)) + 2;
        const int top = static_cast<int>(std::floor((baseline + y0) * scale));
        const int h = static_cast<int>(std::ceil((y1 - y0) * scale)) + 1;
        if (w <= 2 || h <= 0) return {INFINITY, -INFINITY};
        surface_ptr surface(cairo_image_surface_create(CAIRO_FORMAT_A8, w, h));
        check_cairo(cairo_surface_status(surface.get()), "measure text");
        context_ptr cr(cairo_create(surface.get()));
        cairo_scale(cr.get(), scale, scale);
        cairo_translate(cr.get(), 0, -top / scale);
        pango_cairo_show_layout(cr.get(), l.get());
        cairo_surface_flush(surface.get());
        return inked_columns(surface.get(), scale);
    }

    /// The left end of the first column and the right end of the last column of an A8
    /// surface with ink (above a quarter's coverage), in points at `scale` pixels a point.
    static std::pair<double, double> inked_columns(cairo_surface_t* surface, double scale) {
        const unsigned char* data = cairo_image_surface_get_data(surface);
        const int stride = cairo_image_surface_get_stride(surface);
        const int w = cairo_image_surface_get_width(surface);
        const int h = cairo_image_surface_get_height(surface);
        const auto inked = [&](int x) {
            for (int y = 0; y < h; ++y) {
                if (data[y * stride + x] > 64) return true;
            }
            return false;
        };
        int first = 0;
        while (first < w && !inked(first)) ++first;
        if (first == w) return {INFINITY, -INFINITY};
        int last = w - 1;
        while (!inked(last)) --last;
        return {first / scale, (last + 1) / scale};
    }

    /// Ink of plain markup (no scripts) relative to its baseline.
    text_ink ink_of(const std::string& text, double pt) const {
        const gobject_ptr<PangoLayout> l = make(text, pt, text);
        PangoRectangle ink;
        pango_layout_get_extents(l.get(), &ink, nullptr);
        const double baseline = pango_layout_get_baseline(l.get()) / double(PANGO_SCALE);
        return {ink.x / double(PANGO_SCALE), ink.y / double(PANGO_SCALE) - baseline, ink.width / double(PANGO_SCALE),
                ink.height / double(PANGO_SCALE)};
    }

    /// A context that shapes text in points alone, never in the target's pixels: the
    /// identity matrix whatever cr's scale (a PNG at any dpi, a PDF), glyph positions not
    /// rounded to device units, and no hinting, so that every format and every resolution
    /// get the same layout.
    static gobject_ptr<PangoContext> shaping_context(PangoFontMap* map) {
        gobject_ptr<PangoContext> context(pango_font_map_create_context(map));
        pango_context_set_matrix(context.get(), nullptr);
        pango_context_set_round_glyph_positions(context.get(), FALSE);
        pango_cairo_context_set_resolution(context.get(), 72.0);
        font_options_ptr options(cairo_font_options_create());
        cairo_font_options_set_hint_style(options.get(), CAIRO_HINT_STYLE_NONE);
        cairo_font_options_set_hint_metrics(options.get(), CAIRO_HINT_METRICS_OFF);
        cairo_font_options_set_antialias(options.get(), CAIRO_ANTIALIAS_GRAY);
        pango_cairo_context_set_font_options(context.get(), options.get());
        return context;
    }

    /// The context for markup whose text and attributes Pango parsed: the named faces'
    /// where they lay it out as all fonts do, else all fonts' (made when first needed).
    PangoContext* context_for(const char* text, PangoAttrList* attrs) const {
        if (named_fonts_cover(family_, text, attrs)) return context_.get();
        if (!all_fonts_.get()) all_fonts_ = shaping_context(thread_font_map());
        return all_fonts_.get();
    }

    /// A layout of markup (a piece of `whole`, named in errors) at size.
    gobject_ptr<PangoLayout> make(const std::string& markup, double size, const std::string& whole) const {
        const std::string spans = scripts_as_spans(drawn(inline_fractions(markup)), size);
        // Checked first: Pango would only print a warning and show nothing.
        GError* error = nullptr;
        PangoAttrList* attrs = nullptr;
        char* text = nullptr;
        if (!pango_parse_markup(spans.c_str(), -1, 0, &attrs, &text, nullptr, &error)) {
            const std::string why = error ? error->message : "not valid";
            g_clear_error(&error);
            throw bad_input("invalid text markup '" + whole + "': " + why);
        }
        const std::unique_ptr<PangoAttrList, decltype(&pango_attr_list_unref)> own_attrs(attrs, &pango_attr_list_unref);
        const std::unique_ptr<char, decltype(&g_free)> own_text(text, &g_free);
        gobject_ptr<PangoLayout> layout(pango_layout_new(context_for(text, attrs)));
        font_description_ptr font(pango_font_description_new());
        pango_font_description_set_family(font.get(), family_.c_str());
        pango_font_description_set_size(font.get(), static_cast<gint>(std::lround(size * PANGO_SCALE)));
        pango_layout_set_font_description(layout.get(), font.get());
        pango_layout_set_markup(layout.get(), spans.c_str(), -1);
        return layout;
    }

    /// Scripts nested in other elements, which split_scripts leaves in place: Pango sizes
    /// <sub> and <sup> from the font's OS/2 script metrics, which some fonts (Computer
    /// Modern Unicode among them) set far too large; spell them out instead.
    static std::string scripts_as_spans(const std::string& markup, double size) {
        const script_metrics m;
        const auto units = [](double pt) { return std::to_string(std::lround(pt * PANGO_SCALE)); };
        const std::string small = units(m.size * size);
        const std::pair<std::string, std::string> rules[] = {
            {"<sub>", "<span size=\"" + small + "\" rise=\"-" + units(m.sub_shift * size) + "\">"},
            {"<sup>", "<span size=\"" + small + "\" rise=\"" + units(m.sup_shift * size) + "\">"},
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
        if (!first_family_resolves(context_.get(), family_)) {
            const std::string first = family_.substr(0, family_.find(','));
            throw std::runtime_error("font '" + first + "' is not installed (fc-list : family lists the installed ones)");
        }
    }

    std::string family_;
    gobject_ptr<PangoContext> context_;          // over the named faces
    mutable gobject_ptr<PangoContext> all_fonts_;  // over every font, for the texts they do not cover
    std::vector<letter_form> forms_;
    std::map<std::pair<std::string, double>, std::shared_ptr<const text_box>> boxes_;
};

/// Text set with Pango in one font family, measured and drawn in points.
class text_engine {
public:
    /// An engine drawing into `cr` with this thread's shaper of `family`.
    text_engine(cairo_t* cr, const std::string& family) : cr_(cr), shaper_(&text_shaper::for_thread(family)) {}

    /// Logical width and height of the markup at `size` points.
    std::pair<double, double> measure(const std::string& markup, double size) const {
        const auto b = shaper_->box(markup, size);
        return {b->width, b->ascent + b->descent};
    }

    /// The inked part of the markup at `size` points, relative to the left end of its
    /// baseline (y down): x, y of the top left corner, width and height.
    text_ink ink(const std::string& markup, double size) const {
        const auto b = shaper_->box(markup, size);
        return {b->ink_x0, b->ink_y0, b->ink_x1 - b->ink_x0, b->ink_y1 - b->ink_y0};
    }

    /// The markup as the engine's font draws it (letters it would draw alike kept apart).
    std::string drawn(const std::string& markup) const { return shaper_->drawn(markup); }

    /// Draws markup with its box anchored at (x, y): ax, ay in {0, 0.5, 1} pick the
    /// anchor (left/centre/right, top/middle/bottom). `rotate` turns it by -90 degrees.
    void draw(const label& text, double size, double x, double y, double ax, double ay,
              bool rotate = false) const {
        const auto b = shaper_->box(text.markup, size);
        if (sink_) {
            // The anchor on the baseline; LaTeX aligns the text about it by its own width.
            const double down = -ay * (b->ascent + b->descent) + b->ascent;
            sink_->push_back({text, size, rotate ? x + down : x, rotate ? y : y + down, ax, rotate});
            return;
        }
        cairo_save(cr_);
        cairo_translate(cr_, x, y);
        if (rotate) cairo_rotate(cr_, -M_PI / 2);
        show(*b, -ax * b->width, -ay * (b->ascent + b->descent) + b->ascent);
        cairo_restore(cr_);
    }

    /// Draws markup with the left end of its baseline at (x, y), turned by -90 degrees
    /// about that point with `rotate`.
    void draw_on_baseline(const label& text, double size, double x, double y, bool rotate = false,
                          double align = 0) const {
        const std::string& markup = text.markup;
        if (sink_) {
            // The ink's left end, centre or right end as the anchor, so that LaTeX's own
            // width is what is aligned.
            const text_ink i = ink(markup, size);
            const double along = i.x + align * i.w;
            sink_->push_back({text, size, rotate ? x : x + along, rotate ? y - along : y, align, rotate});
            return;
        }
        cairo_save(cr_);
        cairo_translate(cr_, x, y);
        if (rotate) cairo_rotate(cr_, -M_PI / 2);
        show(*shaper_->box(markup, size), 0, 0);
        cairo_restore(cr_);
    }

    /// Texts are recorded in `sink` instead of drawn (null: drawn).
    void record_into(std::vector<placed_text>* sink) { sink_ = sink; }

private:
    using text_box = text_shaper::text_box;

    void show(const text_box& b, double x, double y) const {
        for (const auto& p : b.parts) {
            if (p.stretch != 1) {
                cairo_save(cr_);
                cairo_translate(cr_, x + p.x, y + p.y);
                cairo_scale(cr_, 1, p.stretch);
                cairo_move_to(cr_, 0, -p.baseline);
                pango_cairo_show_layout(cr_, p.layout.get());
                cairo_restore(cr_);
                continue;
            }
            cairo_move_to(cr_, x + p.x, y + p.y - p.baseline);
            // Metrics are unhinted, so the layout made for measuring draws unchanged here.
            pango_cairo_show_layout(cr_, p.layout.get());
        }
        if (!b.rules.empty()) cairo_new_path(cr_);
        for (const auto& r : b.rules) cairo_rectangle(cr_, x + r.x, y + r.y, r.w, r.h);
        if (!b.rules.empty()) cairo_fill(cr_);
    }

    cairo_t* cr_;
    std::vector<placed_text>* sink_ = nullptr;
    text_shaper* shaper_;
};

}  // namespace plot
