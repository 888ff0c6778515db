// SPDX-License-Identifier: GPL-3.0-or-later
// Typography of labels: stacked fractions and radicals, placed by the layout and measured in
// the ink they draw, in the paper's and the slides' fonts.
#include "plot/handles.hpp"
#include "plot/math_layout.hpp"
#include "plot/tex_markup.hpp"
#include "plot/text.hpp"

#include "process.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

using namespace test_support;

namespace {

constexpr double px_per_pt = 20;
constexpr double label_pt = 10;
constexpr double em_px = px_per_pt * label_pt;  // pixels in an em of the label

const std::vector<std::string> families = {"CMU Serif, DejaVu Math TeX Gyre", "CMU Sans Serif, DejaVu Sans"};

/// A label drawn alone at label_pt, its baseline's left end at (4 pt, 16 pt), as an A8 image.
struct drawing {
    plot::surface_ptr surface;
    int w = 0, h = 0, stride = 0;
    const unsigned char* data = nullptr;
    bool inked(int x, int y) const { return data[y * stride + x] > 128; }
};

drawing draw(const std::string& tex, const std::string& family) {
    drawing d;
    d.w = 40 * static_cast<int>(px_per_pt);
    d.h = 30 * static_cast<int>(px_per_pt);
    d.surface.reset(cairo_image_surface_create(CAIRO_FORMAT_A8, d.w, d.h));
    plot::context_ptr cr(cairo_create(d.surface.get()));
    cairo_scale(cr.get(), px_per_pt, px_per_pt);
    const plot::text_engine engine(cr.get(), family);
    engine.draw_on_baseline(plot::tex_label(tex), label_pt, 4, 16);
    cairo_surface_flush(d.surface.get());
    d.data = cairo_image_surface_get_data(d.surface.get());
    d.stride = cairo_image_surface_get_stride(d.surface.get());
    return d;
}

/// A box of inked pixels (inclusive).
struct pixel_box {
    int x0 = 1 << 30, y0 = 1 << 30, x1 = -1, y1 = -1;
    bool empty() const { return x1 < 0; }
    double centre_x() const { return (x0 + x1 + 1) / 2.0; }
    void add(int x, int y) { x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y); }
};

/// The ink of rows y0..y1 (inclusive) and columns x0..x1.
pixel_box ink_in(const drawing& d, int y0, int y1, int x0 = 0, int x1 = 1 << 30) {
    pixel_box b;
    for (int y = std::max(y0, 0); y <= std::min(y1, d.h - 1); ++y) {
        for (int x = std::max(x0, 0); x <= std::min(x1, d.w - 1); ++x) {
            if (d.inked(x, y)) b.add(x, y);
        }
    }
    return b;
}

/// A horizontal rule: rows whose ink runs without a gap for at least `min_px` pixels.
struct rule_rows {
    int y0 = -1, y1 = -1, x0 = 0, x1 = 0;
    bool found() const { return y0 >= 0; }
    int thickness() const { return y1 - y0 + 1; }
};

/// The longest rule of rows y0..y1: the rows whose longest run of ink is within 2 pixels of
/// the longest of all of them (a fraction's rule is wider than any stroke of its parts).
rule_rows longest_rule(const drawing& d, int y0, int y1, int x_from = 0) {
    std::vector<rule_rows> rows;
    int best = 0;
    for (int y = std::max(y0, 0); y <= std::min(y1, d.h - 1); ++y) {
        int longest = 0, longest_x0 = 0, run = 0;
        for (int x = x_from; x < d.w; ++x) {
            run = d.inked(x, y) ? run + 1 : 0;
            if (run > longest) longest = run, longest_x0 = x - run + 1;
        }
        rows.push_back({y, y, longest_x0, longest_x0 + longest - 1});
        best = std::max(best, longest);
    }
    rule_rows r;
    for (const rule_rows& row : rows) {
        if (best == 0 || row.x1 - row.x0 + 1 < best - 2) continue;
        if (!r.found()) r = row;
        r.y1 = row.y1;
        r.x0 = std::min(r.x0, row.x0), r.x1 = std::max(r.x1, row.x1);
    }
    return r;
}

}  // namespace

TEST(Typography, FractionMarkupKeepsTheInlineFormForText) {
    // The markup stacks; plain text, metadata and the alt text read the fraction in line,
    // a part in parentheses where it is a sum, relation, quotient or product.
    EXPECT_EQ(plot::tex_to_markup("$\\frac{1}{x/2}$"), "<frac><num>1</num><pden><i>x</i>/2</pden></frac>");
    EXPECT_EQ(plot::tex_to_markup("$\\dfrac{a}{b}$"), "<dfrac><num><i>a</i></num><den><i>b</i></den></dfrac>");
    EXPECT_EQ(plot::tex_to_markup("$\\tfrac{a}{b}$"), "<frac><num><i>a</i></num><den><i>b</i></den></frac>");
    EXPECT_EQ(plot::markup_text(plot::tex_to_markup("$\\frac{1}{x/2}$")), "1/(x/2)");
    // A fraction in a part is a quotient too: \frac{1}{\frac{x}{2}} reads 1/(x/2), not 1/x/2.
    EXPECT_EQ(plot::markup_text(plot::tex_to_markup("$\\frac{a+b}{\\frac{1}{c}}$")), "(a + b)/(1/c)");
    EXPECT_EQ(plot::inline_fractions(plot::tex_to_markup("$\\frac{\\frac{1}{2}}{3}$")), "(1/2)/3");
    EXPECT_EQ(plot::tex_to_plain("$\\frac{1}{\\frac{x}{2}}$"), "1/(x/2)");
    EXPECT_EQ(plot::tex_to_plain("$\\sqrt{\\frac{1}{c}}$"), "\u221a(1/c)");
    EXPECT_EQ(plot::tex_to_plain("$\\frac{1}{x/2}$"), "1/(x/2)");
    // A program's markup with a fraction still has LaTeX: the inline form's.
    EXPECT_EQ(plot::markup_to_latex(plot::tex_to_markup("$\\frac{1}{x/2}$")), "$1/(x/2)$");
    // LaTeX is written as the TeX was, stacked by LaTeX itself.
    EXPECT_EQ(plot::tex_to_latex("$\\frac{1}{x/2}$"), "$\\frac{1}{x/2}$");
}

TEST(Typography, FractionStacksNumeratorOverRuleOverDenominator) {
    // In both themes' fonts: one rule; the numerator's ink above it and the denominator's
    // below, each clear of it and centred on it to 0.05 em; the rule TeX's 0.04 em thick.
    for (const auto& family : families) {
        for (const std::string tex : {"$\\frac{a}{b}$", "$\\tfrac{T}{T_0}$", "$\\dfrac{1}{2}$", "$\\frac{\\omega}{2\\pi}$",
                                      "$\\frac{\\theta_0^2}{16}$", "$\\frac{1}{x/2}$"}) {
            const std::string what = tex + " in " + family;
            const drawing d = draw(tex, family);
            const rule_rows r = longest_rule(d, 0, d.h - 1);
            ASSERT_TRUE(r.found()) << what;
            EXPECT_NEAR(r.thickness(), 0.04 * em_px, 2.5) << what;
            const pixel_box num = ink_in(d, 0, r.y0 - 1);
            const pixel_box den = ink_in(d, r.y1 + 1, d.h - 1);
            ASSERT_FALSE(num.empty()) << what;
            ASSERT_FALSE(den.empty()) << what;
            const double rule_centre = (r.x0 + r.x1 + 1) / 2.0;
            EXPECT_NEAR(num.centre_x(), rule_centre, 0.05 * em_px) << what;
            EXPECT_NEAR(den.centre_x(), rule_centre, 0.05 * em_px) << what;
            // Clear of the rule: nothing touches it from above or below.
            EXPECT_GE(r.y0 - num.y1, 0.5 * 0.04 * em_px) << what;
            EXPECT_GE(den.y0 - r.y1, 0.5 * 0.04 * em_px) << what;
            // The rule on the math axis, 0.25 em above the baseline (16 pt down).
            EXPECT_NEAR((r.y0 + r.y1 + 1) / 2.0, 16 * px_per_pt - 0.25 * em_px, 2.5) << what;
            // The rule spans both parts.
            EXPECT_LE(r.x0, std::min(num.x0, den.x0) + 1) << what;
            EXPECT_GE(r.x1, std::max(num.x1, den.x1) - 1) << what;
        }
    }
}

TEST(Typography, FractionPartsAreScriptSizedAndSmallerInScripts) {
    // A text-size label's \frac is \tfrac's size (parts at 0.7), \dfrac's parts at the text's
    // size, and a \frac in a superscript smaller again.
    for (const auto& family : families) {
        // The base a of a^{...} ends where it ends alone: the rule is sought right of it.
        const drawing base = draw("$a$", family);
        const int base_end = ink_in(base, 0, base.h - 1).x1 + 1;
        const auto num_height = [&](const std::string& tex) {
            const drawing d = draw(tex, family);
            const rule_rows r = longest_rule(d, 0, d.h - 1, tex.starts_with("$a") ? base_end : 0);
            EXPECT_TRUE(r.found()) << tex;
            const pixel_box num = ink_in(d, 0, r.y0 - 1, r.x0, r.x1);
            return num.y1 - num.y0 + 1;
        };
        const int x_full = num_height("$\\dfrac{x}{x}$");
        const int x_frac = num_height("$\\frac{x}{x}$");
        const int x_tfrac = num_height("$\\tfrac{x}{x}$");
        const int x_script = num_height("$a^{\\frac{x}{x}}$");
        EXPECT_EQ(x_frac, x_tfrac) << family;
        EXPECT_NEAR(double(x_frac) / x_full, 0.7, 0.06) << family;
        EXPECT_NEAR(double(x_script) / x_full, 0.49, 0.06) << family;
    }
}

TEST(Typography, FractionsNestInFractionsAndRadicals) {
    for (const auto& family : families) {
        // \frac in \frac: two rules, the inner one in the numerator above the outer one.
        const drawing nested = draw("$\\frac{\\frac{1}{2}}{3}$", family);
        const rule_rows outer = longest_rule(nested, 0, nested.h - 1);
        ASSERT_TRUE(outer.found()) << family;
        const rule_rows inner = longest_rule(nested, 0, outer.y0 - 2);
        ASSERT_TRUE(inner.found()) << family;
        EXPECT_NEAR(inner.thickness(), outer.thickness(), 2) << family;
        const pixel_box one = ink_in(nested, 0, inner.y0 - 1);
        const pixel_box two = ink_in(nested, inner.y1 + 1, outer.y0 - 1);
        const pixel_box three = ink_in(nested, outer.y1 + 1, nested.h - 1);
        EXPECT_FALSE(one.empty() || two.empty() || three.empty()) << family;
        // \sqrt over \frac: the radical's line above the numerator's ink, the fraction's rule
        // under it, and the sign reaching down to the denominator's foot.
        const drawing root = draw("$\\sqrt{\\frac{1}{2}}$", family);
        const rule_rows line = longest_rule(root, 0, root.h - 1);
        ASSERT_TRUE(line.found()) << family;
        const rule_rows bar = longest_rule(root, line.y1 + 2, root.h - 1);
        ASSERT_TRUE(bar.found()) << family;
        const std::vector<rule_rows> lines = {line, bar};
        const pixel_box num = ink_in(root, lines[0].y1 + 1, lines[1].y0 - 1, lines[1].x0, lines[1].x1);
        ASSERT_FALSE(num.empty()) << family;
        EXPECT_GE(num.y0 - lines[0].y1, 1) << family << ": the numerator touches the radical's line";
        const pixel_box den = ink_in(root, lines[1].y1 + 1, root.h - 1, lines[1].x0, lines[1].x1);
        const pixel_box sign = ink_in(root, 0, root.h - 1, 0, lines[1].x0 - 1);
        ASSERT_FALSE(sign.empty()) << family;
        EXPECT_GE(sign.y1, den.y1 - 0.05 * em_px) << family << ": the sign stops above the denominator's foot";
        EXPECT_LE(sign.y0, lines[0].y1) << family << ": the sign does not reach its line";
    }
}

TEST(Typography, AFractionFitsItsLogicalBox) {
    // What a legend's row and a title's band are measured by: the logical box holds the ink.
    const plot::surface_ptr s(cairo_image_surface_create(CAIRO_FORMAT_A8, 1, 1));
    const plot::context_ptr cr(cairo_create(s.get()));
    for (const auto& family : families) {
        const plot::text_engine engine(cr.get(), family);
        for (const std::string tex : {"$\\frac{a}{b}$", "$\\dfrac{\\theta_0^2}{T_N}$", "$\\sqrt{\\frac{1}{\\cos(\\frac{\\theta_0}{2})}}$"}) {
            const std::string markup = plot::tex_to_markup(tex);
            const auto [w, h] = engine.measure(markup, label_pt);
            const plot::text_ink ink = engine.ink(markup, label_pt);
            const auto [w_x, h_x] = engine.measure("<i>x</i>", label_pt);
            EXPECT_GT(h, h_x) << tex;
            EXPECT_GE(h + 1e-9, ink.h) << tex << " in " << family;
            EXPECT_GE(w + 1e-9, ink.x + ink.w) << tex << " in " << family;
        }
    }
}

TEST(Typography, FractionLabelsRenderInEveryFormat) {
    // A legend entry and a title with stacked fractions, in every drawn format and with the
    // SVG's text as text; the SVG's <title> reads the title's fraction in line.
    const auto dir = temp_dir("typography-formats");
    std::filesystem::create_directories(dir / "out");
    std::filesystem::create_directories(dir / "text");
    std::ofstream(dir / "f.toml") << "[figure]\ncolumns = 1\ntitle = '$\\frac{1}{x/2}$'\n\n[[panel]]\nplot = \"period\"\n"
                                     "methods = [\"exact\", { formula = \"1/sqrt(cos(theta0/2))\", "
                                     "label = '$\\dfrac{1}{\\sqrt{\\cos\\frac{\\theta_0}{2}}}$' }]\n";
    const auto r = run_cli("render '" + (dir / "f.toml").string() + "' -o '" + (dir / "out").string() + "' -f png,pdf,svg,eps");
    ASSERT_EQ(r.status, 0) << r.err;
    const auto files = files_in(dir / "out");
    ASSERT_EQ(files.size(), 4u);
    for (const std::string& f : files) {
        if (!f.ends_with(".svg")) continue;
        const std::string svg = slurp(dir / "out" / f);
        EXPECT_NE(svg.find("<title>1/(x/2)</title>"), std::string::npos) << svg.substr(0, 400);
    }
    const auto t = run_cli("render '" + (dir / "f.toml").string() + "' -o '" + (dir / "text").string() +
                           "' -f svg --set svg_text=text");
    ASSERT_EQ(t.status, 0) << t.err;
}

namespace {

/// The gaps between the runs of inked columns of a drawing, in ems, left to right.
std::vector<double> column_gaps(const drawing& d) {
    std::vector<bool> inked(static_cast<std::size_t>(d.w), false);
    for (int y = 0; y < d.h; ++y) {
        for (int x = 0; x < d.w; ++x) {
            if (d.inked(x, y)) inked[static_cast<std::size_t>(x)] = true;
        }
    }
    std::vector<double> gaps;
    int last = -1;
    for (int x = 0; x < d.w; ++x) {
        if (!inked[static_cast<std::size_t>(x)]) continue;
        if (last >= 0 && x > last + 1) gaps.push_back((x - last - 1) / em_px);
        last = x;
    }
    return gaps;
}

}  // namespace

TEST(Typography, SlashSpacingIsTeXs) {
    // pdfTeX sets $t/T$ and $T_N/T$ in Computer Modern with 0.08 em of ink between the slash
    // and the T (tests/data/typography/slash.tex, measured by slash_gaps.py there). The text
    // italic T of Computer Modern Unicode stands 0.175 em into its advance, where the math
    // italic one stands at 0.03: unmended, the gap was 0.23 em. Now within 0.02 em of TeX's.
    for (const auto& family : families) {
        for (const std::string tex : {"$t/T$", "$T_N/T$", "$\\theta/T$"}) {
            const std::vector<double> gaps = column_gaps(draw(tex, family));
            ASSERT_FALSE(gaps.empty()) << tex;
            std::printf("%s in %s: %.3f em from the slash to the T\n", tex.c_str(), family.c_str(), gaps.back());
            EXPECT_NEAR(gaps.back(), plot::slash_gap, 0.02) << tex << " in " << family;
        }
        // A digit after the slash is set as the font sets it (TeX's gap already): π/4 unchanged.
        const std::vector<double> digits = column_gaps(draw("$\\pi/4$", family));
        ASSERT_FALSE(digits.empty()) << family;
        EXPECT_GT(digits.back(), 0.04) << family;
        EXPECT_LT(digits.back(), 0.14) << family;
    }
}

TEST(Typography, ApostrophesAndQuotesInTextAreTypographic) {
    EXPECT_EQ(plot::tex_to_markup("the paper's period"), "the paper\u2019s period");
    EXPECT_EQ(plot::tex_to_markup("`a' and ``b''"), "\u2018a\u2019 and \u201cb\u201d");
    // In math ' is still a prime; LaTeX gets the text as written, and sets the same quotes.
    EXPECT_EQ(plot::tex_to_markup("$x'$"), "<i>x</i><sup>\u02b9</sup>");
    EXPECT_EQ(plot::tex_to_latex("the paper's"), "the paper's");
    // Plain text (CSV headers, file names' words) keeps ASCII.
    EXPECT_EQ(plot::tex_to_plain("the paper's"), "the paper's");
}

namespace {

/// The widest unbroken run of ink across the rows of the middle half of a drawing's ink: a
/// stroke's width (across a slanted stroke, its horizontal cut), in pixels.
int stem_width(const drawing& d) {
    pixel_box all = ink_in(d, 0, d.h - 1);
    int widest = 0;
    const int q = (all.y1 - all.y0) / 4;
    for (int y = all.y0 + q; y <= all.y1 - q; ++y) {
        int run = 0;
        for (int x = all.x0; x <= all.x1; ++x) {
            run = d.inked(x, y) ? run + 1 : 0;
            widest = std::max(widest, run);
        }
    }
    return widest;
}

}  // namespace

TEST(Typography, PrimesHaveTheWeightOfTheLetters) {
    // Computer Modern Unicode has no U+2032 but has the modifier letter prime U+02B9: every
    // prime (x', \prime, a typed ′) is drawn with it, from the letters' own font, and its
    // stroke is within 1.5 times the stem of CMU's l.
    const std::string family = families[0];
    const double stem = stem_width(draw("$\\mathrm{l}$", family));
    ASSERT_GT(stem, 0);
    for (const std::string tex : {"$\\prime$", "$\u2032$", "$x'$"}) {
        const drawing d = draw(tex, family);
        const double prime = tex == "$x'$" ? 0 : stem_width(d);
        if (prime > 0) {
            EXPECT_LT(prime / stem, 1.5) << tex;
        }
    }
    // The fallback's prime, for the record (its horizontal cut; its weight shows in its size).
    const double fallback = stem_width(draw("$\\prime$", "DejaVu Math TeX Gyre"));
    const double ours = stem_width(draw("$\\prime$", family));
    std::printf("prime's widest cut / stem of l: CMU's U+02B9 %.2f, DejaVu Math's U+2032 %.2f\n", ours / stem, fallback / stem);
    const plot::surface_ptr s(cairo_image_surface_create(CAIRO_FORMAT_A8, 1, 1));
    const plot::context_ptr cr(cairo_create(s.get()));
    const plot::text_engine engine(cr.get(), family);
    EXPECT_EQ(engine.drawn("<i>f</i>\u2032\u2033"), "<i>f</i>\u02b9\u02b9\u02b9");
    // A font with its own U+2032 keeps it.
    const plot::text_engine sans(cr.get(), "DejaVu Sans");
    EXPECT_EQ(sans.drawn("\u2032"), "\u2032");
}

TEST(Typography, AccentsInScriptsOfScriptsArePlacedByTheLayout) {
    // \dot{z} in a subscript of a subscript: the dot (the ink the accented label has and the
    // plain one has not) sits above the z's ink, clear of it, centred on it to 0.05 em of
    // the label, as at the first level; Pango's combining mark was left of the letter.
    for (const auto& family : families) {
        for (const std::string accent : {"\\dot", "\\hat", "\\bar"}) {
            // The last run of inked columns is the accented z: its rows from the top down to
            // the first empty row are the mark, the rest the letter.
            const drawing marked = draw("$e_{a_{" + accent + "{z}}}$", family);
            const pixel_box all = ink_in(marked, 0, marked.h - 1);
            int x0 = all.x1;
            while (x0 > all.x0 && !ink_in(marked, 0, marked.h - 1, x0 - 1, x0 - 1).empty()) --x0;
            const pixel_box whole = ink_in(marked, 0, marked.h - 1, x0, all.x1);
            int gap = whole.y0;
            while (gap <= whole.y1 && !ink_in(marked, gap, gap, x0, all.x1).empty()) ++gap;
            ASSERT_LT(gap, whole.y1) << accent << " in " << family << ": the mark touches the letter";
            const pixel_box mark = ink_in(marked, whole.y0, gap - 1, x0, all.x1);
            const pixel_box z = ink_in(marked, gap, whole.y1, x0, all.x1);
            ASSERT_FALSE(z.empty());
            EXPECT_LT(mark.y1, z.y0) << accent << " in " << family;
            EXPECT_NEAR(mark.centre_x(), z.centre_x(), 0.05 * em_px) << accent << " in " << family;
        }
    }
}

TEST(Typography, AScriptAfterAFractionClearsItsLetterAsAlone) {
    // x^2 after a fraction in the same math: the 2 clear of the leaning x by as much as in
    // x^2 alone (the base's last run is measured, not the fraction).
    for (const auto& family : families) {
        const std::vector<double> alone = column_gaps(draw("$x^2$", family));
        const std::vector<double> after = column_gaps(draw("$\\frac{1}{2} x^2$", family));
        ASSERT_FALSE(alone.empty()) << family;
        ASSERT_FALSE(after.empty()) << family;
        EXPECT_NEAR(after.back(), alone.back(), 0.01) << family;
    }
}

TEST(Typography, FractionsNestedToTheLimitAreShapedOnce) {
    // \frac{\frac{...}{2}}{2} 24 deep (the nesting limit's): each part is shaped once, not
    // once to measure and again to place (2^24 shapings).
    std::string tex = "x";
    for (int i = 0; i < 24; ++i) tex = "\\frac{" + tex + "}{2}";
    const auto start = std::chrono::steady_clock::now();
    const drawing d = draw("$" + tex + "$", families[0]);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_FALSE(ink_in(d, 0, d.h - 1).empty());
    EXPECT_LT(seconds, 5.0);
}

TEST(Typography, TheFractionElementCannotBeWrittenByALabel) {
    // Text and math escape < and >: a label that spells the element out gets its characters.
    for (const std::string tex : {"<frac><num>1</num><den>2</den></frac>", "$\\mathrm{<frac><num>1</num><den>2</den></frac>}$",
                                  "$<frac>$", "\u221a<span overline=\"single\">x</span>"}) {
        const std::string markup = plot::tex_to_markup(tex);
        EXPECT_EQ(markup.find("<frac>"), std::string::npos) << markup;
        EXPECT_EQ(markup.find("<span"), std::string::npos) << markup;
        for (const auto& p : plot::split_boxes(markup)) EXPECT_EQ(p.type, plot::box_piece::kind::run) << tex;
    }
}

TEST(Typography, DescriptionsReadAFractionInLineWithItsParentheses) {
    // A title \frac{1}{\frac{x}{2}} and a formula 1/(theta0/2): the SVG's <title>, the alt
    // text and the description read 1/(x/2) and 1/(theta0/2), never 1/x/2 nor 1x2.
    const auto dir = temp_dir("typography-alt");
    std::ofstream(dir / "alt.toml") << "[figure]\ncolumns = 1\ntitle = '$\\frac{1}{\\frac{x}{2}}$'\n\n[[panel]]\n"
                                       "plot = \"period\"\nmethods = [\"exact\", { formula = \"1/(theta0/2)\" }]\n";
    const auto d = run_cli("describe alt.toml", dir);
    ASSERT_EQ(d.status, 0) << d.err;
    EXPECT_EQ(d.out.rfind("1/(x/2).\n", 0), 0u) << d.out;
    EXPECT_NE(d.out.find("Title: 1/(x/2)."), std::string::npos) << d.out;
    EXPECT_NE(d.out.find("1/(theta0/2) (dashed line)"), std::string::npos) << d.out;
    const auto r = run_cli("render alt.toml -f svg", dir);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(slurp(dir / "alt.svg").find("<title>1/(x/2)</title>"), std::string::npos);
}
