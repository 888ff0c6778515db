// SPDX-License-Identifier: GPL-3.0-or-later
// The TeX a physicist writes in a label: every macro of the one table in markup and LaTeX,
// \theta apart from \vartheta, nesting limits, hostile LaTeX, the man page's list; and SVGs
// whose ids are their own.
#include "figures/panel_support.hpp"
#include "pendulum/formula.hpp"
#include "pendulum/methods.hpp"
#include "plot/math_layout.hpp"
#include "plot/tex_markup.hpp"
#include "plot/text.hpp"

#include "process.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

using plot::macro_kind;
using plot::math_class;
using plot::tex_to_latex;
using plot::tex_to_markup;
using plot::tex_to_plain;
using test_support::run_cli;
using test_support::slurp;
using test_support::temp_dir;

namespace {

std::string escaped(std::string_view s) {
    std::string out;
    for (const char c : s) {
        if (c == '&') {
            out += "&amp;";
        } else {
            out += c;
        }
    }
    return out;
}

/// The message tex_to_markup throws for `tex`, or "" if it accepts it.
std::string refusal(const std::string& tex) {
    try {
        tex_to_markup(tex);
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "";
}

/// "$" + open n times + core + close n times + "$".
std::string nested(const std::string& open, const std::string& core, const std::string& close, int n) {
    std::string s = "$";
    for (int i = 0; i < n; ++i) s += open;
    s += core;
    for (int i = 0; i < n; ++i) s += close;
    return s + "$";
}

}  // namespace

TEST(Notation, EverySymbolAsMarkupAndLatex) {
    int symbols = 0;
    for (const auto& m : plot::tex_macros()) {
        if (m.kind != macro_kind::symbol) continue;
        ++symbols;
        const std::string tex = "$a \\" + std::string(m.name) + " b$";
        const std::string drawn = m.italic ? "<i>" + escaped(m.markup) + "</i>" : escaped(m.markup);
        // an operator name (a word: sin, log) is followed by TeX's thin space before its operand
        const bool word = m.markup.size() > 1 && std::all_of(m.markup.begin(), m.markup.end(), [](char c) {
                              return std::isalpha(static_cast<unsigned char>(c)) != 0;
                          });
        const std::string spaced = m.spacing != math_class::ordinary ? " " + drawn + " "
                                   : word                            ? drawn + "\u2009"
                                                                     : drawn;
        EXPECT_EQ(tex_to_markup(tex), "<i>a</i>" + spaced + "<i>b</i>") << m.name;
        EXPECT_EQ(tex_to_latex(tex), "$a" + std::string(m.latex) + "b$") << m.name;
    }
    EXPECT_GE(symbols, 100);
}

TEST(Notation, EveryAccentAndFaceAsMarkupAndLatex) {
    for (const auto& m : plot::tex_macros()) {
        const std::string name(m.name);
        if (m.kind == macro_kind::accent) {
            const std::string drawn = m.markup.empty() ? "<span overline=\"single\"><i>x</i></span>"
                                                       : "<i>x" + std::string(m.markup) + "</i>";
            EXPECT_EQ(tex_to_markup("$\\" + name + "{x}$"), drawn) << name;
            EXPECT_EQ(tex_to_latex("$\\" + name + "{x}$"), "$\\" + name + "{x}$") << name;
            EXPECT_EQ(tex_to_latex("$\\" + name + " x$"), "$\\" + name + "{x}$") << name;
        } else if (m.kind == macro_kind::font) {
            const std::string tag(m.markup);
            EXPECT_EQ(tex_to_markup("$\\" + name + "{d x}$"), tag.empty() ? "d x" : "<" + tag + ">d x</" + tag + ">") << name;
            const bool text = name == "text" || name == "textrm";
            EXPECT_EQ(tex_to_latex("$\\" + name + "{d x}$"), "$\\" + name + "{d" + (text ? " " : "\\ ") + "x}$") << name;
        }
    }
}

TEST(Notation, RootsFractionsAndDelimiters) {
    // \sqrt: the sign, and the radicand under a line; an index raised before it.
    EXPECT_EQ(tex_to_markup("$\\sqrt{x}$"), "\u221a<span overline=\"single\"><i>x</i></span>");
    EXPECT_EQ(tex_to_markup("$\\sqrt{1 - k^2}$"), "\u221a<span overline=\"single\">1 \u2212 <i>k</i><sup>2</sup></span>");
    EXPECT_EQ(tex_to_markup("$\\sqrt[3]{x}$"), "\u2009<sup>3</sup>\u221a<span overline=\"single\"><i>x</i></span>");
    EXPECT_EQ(tex_to_latex("$\\sqrt{x}$"), "$\\sqrt{x}$");
    EXPECT_EQ(tex_to_latex("$\\sqrt x$"), "$\\sqrt{x}$");
    EXPECT_EQ(tex_to_latex("$\\sqrt[3]{x}$"), "$\\sqrt[3]{x}$");
    EXPECT_EQ(tex_to_plain("$\\sqrt{g/L}$"), "\u221a(g/L)");
    // \frac: stacked by the layout; in line (alt text, plain text) a/b, a part in parentheses
    // only where it is a sum.
    EXPECT_EQ(tex_to_markup("$\\frac{T}{T_0}$"), "<frac><num><i>T</i></num><den><i>T</i><sub>0</sub></den></frac>");
    EXPECT_EQ(plot::inline_fractions(tex_to_markup("$\\frac{T}{T_0}$")), "<i>T</i>/<i>T</i><sub>0</sub>");
    EXPECT_EQ(plot::inline_fractions(tex_to_markup("$\\frac{a+b}{2}$")), "(<i>a</i> + <i>b</i>)/2");
    EXPECT_EQ(plot::inline_fractions(tex_to_markup("$\\frac{1}{a-b}$")), "1/(<i>a</i> \u2212 <i>b</i>)");
    EXPECT_EQ(plot::inline_fractions(tex_to_markup("$\\frac{2\\pi}{3}$")), "2<i>\u03c0</i>/3");
    EXPECT_EQ(plot::inline_fractions(tex_to_markup("$\\frac12$")), "1/2");
    // a quotient in a part is one too: 1/(x/2), never 1/x/2 (which reads (1/x)/2)
    EXPECT_EQ(plot::inline_fractions(tex_to_markup("$\\frac{1}{x/2}$")), "1/(<i>x</i>/2)");
    // what is inside written parentheses is not at the part's top
    EXPECT_EQ(plot::inline_fractions(tex_to_markup("$\\frac{\\sin(x/2)}{(a+b)}$")), "sin(<i>x</i>/2)/(<i>a</i> + <i>b</i>)");
    EXPECT_EQ(plot::inline_fractions(tex_to_markup("$\\frac{(a+b)c}{2}$")), "(<i>a</i> + <i>b</i>)<i>c</i>/2");
    EXPECT_EQ(plot::inline_fractions(tex_to_markup("$\\frac{a*b}{c}$")), "(<i>a</i>\u2217<i>b</i>)/<i>c</i>");
    // an operator name and its operand with TeX's thin space: sin x, sin² x; none before (
    EXPECT_EQ(plot::inline_fractions(tex_to_markup("$\\frac{\\sin x}{x/2}$")), "sin\u2009<i>x</i>/(<i>x</i>/2)");
    EXPECT_EQ(tex_to_markup("$\\sin^2 x$"), "sin<sup>2</sup>\u2009<i>x</i>");
    EXPECT_EQ(tex_to_markup("$\\cos(x)$"), "cos(<i>x</i>)");
    EXPECT_EQ(tex_to_markup("$\\log\\left(x\\right)$"), "log(<i>x</i>)");
    EXPECT_EQ(tex_to_latex("$\\sin x$"), "$\\sin x$");
    for (const std::string f : {"frac", "tfrac", "dfrac"}) {
        EXPECT_EQ(plot::inline_fractions(tex_to_markup("$\\" + f + "{\\pi}{2}$")), "<i>\u03c0</i>/2") << f;
        EXPECT_EQ(tex_to_latex("$\\" + f + "{\\pi}{2}$"), "$\\" + f + "{\\pi }{2}$") << f;
    }
    // \left and \right: the delimiters as written, at the text's size.
    EXPECT_EQ(tex_to_markup("$\\left( x \\right)$"), "(<i>x</i>)");
    EXPECT_EQ(tex_to_markup("$\\left[ x \\right]$"), "[<i>x</i>]");
    EXPECT_EQ(tex_to_markup("$\\left\\{ x \\right\\}$"), "{<i>x</i>}");
    EXPECT_EQ(tex_to_markup("$\\left| x \\right|$"), "|<i>x</i>|");
    EXPECT_EQ(tex_to_markup("$\\left. x \\right|$"), "<i>x</i>|");
    EXPECT_EQ(tex_to_latex("$\\left( x \\right)$"), "$\\left(x\\right)$");
    EXPECT_EQ(tex_to_latex("$\\left\\{ x \\right.$"), "$\\left\\{x\\right.$");
    EXPECT_EQ(refusal("$\\left( x$"), "label '$\\left( x$': \\left( without \\right");
    EXPECT_EQ(refusal("$x \\right)$"), "label '$x \\right)$': \\right without \\left");
    EXPECT_EQ(refusal("$\\left< x \\right>$"),
              "label '$\\left< x \\right>$': \\left and \\right take a delimiter: ( ) [ ] \\{ \\} | \\| or . (none)");
    EXPECT_EQ(refusal("$\\left( {x \\right)}$"), "label '$\\left( {x \\right)}$': \\right without \\left");
    // The two labels of the period figure's test.
    EXPECT_EQ(tex_to_markup("$T/T_0 \\approx 1/\\sqrt{\\cos(\\theta_0/2)}$"),
              "<i>T</i>/<i>T</i><sub>0</sub> \u2248 1/\u221a<span overline=\"single\">cos(<i>\u03b8</i><sub>0</sub>/2)</span>");
    EXPECT_EQ(plot::inline_fractions(tex_to_markup("$\\left(\\frac{T}{T_0}\\right)^2 \\le \\infty$")),
              "(<i>T</i>/<i>T</i><sub>0</sub>)<sup>2</sup> \u2264 \u221e");
    EXPECT_EQ(tex_to_latex("$\\left(\\frac{T}{T_0}\\right)^2 \\le \\infty$"),
              "$\\left(\\frac{T}{T_0}\\right)^2\\le \\infty $");
}

TEST(Notation, ThetaIsNotVartheta) {
    EXPECT_EQ(tex_to_markup("$\\theta$"), "<i>\u03b8</i>");
    EXPECT_EQ(tex_to_markup("$\\vartheta$"), "<i>\u03d1</i>");
    EXPECT_EQ(tex_to_latex("$\\theta$"), "$\\theta $");
    EXPECT_EQ(tex_to_latex("$\\vartheta$"), "$\\vartheta $");
    EXPECT_EQ(tex_to_plain("$\\theta \\vartheta$"), "\u03b8\u03d1");
    EXPECT_EQ(plot::markup_to_latex("<i>\u03b8</i>"), "$\\theta $");
    EXPECT_EQ(plot::markup_to_latex("<i>\u03d1</i>"), "$\\vartheta $");
    // Computer Modern Unicode draws both with one glyph: the serif's is ϑ, the sans's θ. The
    // letter whose shape is missing is drawn by its mathematical italic form.
    const auto forms = [](const std::string& family) {
        const plot::gobject_ptr<PangoContext> context(pango_font_map_create_context(plot::thread_font_map()));
        return plot::distinct_letter_forms(context.get(), family);
    };
    const auto serif = forms("CMU Serif");
    ASSERT_EQ(serif.size(), 1u);
    EXPECT_EQ(serif[0].letter, "\u03b8");
    EXPECT_EQ(plot::with_letter_forms("<i>\u03b8\u0307</i><i>\u03d1</i>", serif),
              "<i><span style=\"normal\">\U0001d703\u0307</span></i><i>\u03d1</i>");
    const auto sans = forms("CMU Sans Serif");
    ASSERT_EQ(sans.size(), 1u);
    EXPECT_EQ(sans[0].letter, "\u03d1");
    EXPECT_TRUE(forms("DejaVu Sans").empty());  // its own two glyphs
    // Drawn: the two labels give different pictures in both themes.
    const auto dir = temp_dir("notation-theta");
    for (const std::string theme : {"paper", "slides"}) {
        for (const std::string name : {"theta", "vartheta"}) {
            const auto r = run_cli("plot period --methods exact --theme " + theme + " --panel-title '$\\" + name +
                                       "_0$' -f png --dpi 150 --name " + theme + "-" + name,
                                   dir);
            ASSERT_EQ(r.status, 0) << r.err;
        }
        EXPECT_NE(slurp(dir / (theme + "-theta.png")), slurp(dir / (theme + "-vartheta.png"))) << theme;
    }
    std::filesystem::remove_all(dir);
}

TEST(Notation, UnknownMacroNamesTheNearestOne) {
    EXPECT_EQ(refusal("$\\lamda$"), "label '$\\lamda$': unknown macro \\lamda (did you mean \\lambda?)");
    EXPECT_EQ(refusal("$\\sqr{x}$"), "label '$\\sqr{x}$': unknown macro \\sqr (did you mean \\sqrt?)");
    EXPECT_EQ(refusal("$\\vartheat$"), "label '$\\vartheat$': unknown macro \\vartheat (did you mean \\vartheta?)");
    EXPECT_EQ(refusal("$\\foo$"), "label '$\\foo$': unknown macro \\foo");
    EXPECT_EQ(refusal("$\\input{x}$"), "label '$\\input{x}$': unknown macro \\input");
    const auto dir = temp_dir("notation-unknown");
    const auto r = run_cli("plot period --methods exact --panel-title '$\\omgea$' -f png", dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("unknown macro \\omgea (did you mean \\omega?)"), std::string::npos) << r.err;
    EXPECT_TRUE(test_support::files_in(dir).empty());
    std::filesystem::remove_all(dir);
}

TEST(Notation, NestingLimitsAcceptFiftyLevels) {
    const std::string too_deep = "nested too deeply (at most 50 levels of braces, scripts and accents)";
    struct construct {
        std::string open, core, close;
        int deepest;  // the most accepted: 50 levels
    };
    // Each construct's levels: a group is one, \sqrt{...} and \hat{...} two (the macro and its
    // group), \left( one, \frac{...}{x} two, a script's group one.
    const construct constructs[] = {{"{", "x", "}", 49},
                                    {"\\sqrt{", "x", "}", 24},
                                    {"\\hat{", "x", "}", 24},
                                    {"\\frac{", "x", "}{2}", 24},
                                    {"\\left(", "x", "\\right)", 49},
                                    {"x^{", "x", "}", 49}};
    for (const auto& c : constructs) {
        EXPECT_EQ(refusal(nested(c.open, c.core, c.close, c.deepest)), "") << c.open;
        const std::string tex = nested(c.open, c.core, c.close, c.deepest + 1);
        const std::string why = refusal(tex);
        EXPECT_NE(why.find(too_deep), std::string::npos) << c.open << ": " << why;
        EXPECT_THROW(tex_to_latex(tex), std::invalid_argument) << c.open;
    }
}

TEST(Notation, LatexHoldsOnlyTheTablesMacros) {
    // No row of the table is a TeX primitive or macro that reads, writes, runs or redefines.
    const std::set<std::string> dangerous = {"input", "include", "write", "openout", "openin", "read", "immediate",
                                             "csname", "endcsname", "catcode", "def", "edef", "gdef", "let",
                                             "newcommand", "renewcommand", "special", "directlua", "usepackage",
                                             "jobname", "expandafter", "string", "scantokens", "makeatletter"};
    std::set<std::string> allowed;
    for (const auto& m : plot::tex_macros()) {
        EXPECT_EQ(dangerous.count(std::string(m.name)), 0u) << m.name;
        allowed.insert(std::string(m.name));
    }
    // The escapes of characters in text and math.
    for (const std::string e : {"textbackslash", "textbar", "textless", "textgreater", "backslash", "^", "~", "prime"}) {
        allowed.insert(e);
    }
    const std::string hostile[] = {
        "$\\sqrt{\\input /etc/passwd}$",
        "$\\sqrt[\\write18{ls}]{x}$",
        "$\\frac{\\csname input\\endcsname}{2}$",
        "$\\left( \\catcode`\\^^M=13 \\right)$",
        "$\\left\\input x \\right)$",
        "$\\frac{\\mathrm{\\input x}}{\\text{\\write18 ls}}$",
        "$\\hat{\\mathbf{\\openout1=victim.tex}}$",
        "$\\overline{\\def\\x{}}$ ^^5cinput",
        "$\\sqrt[3]{\\left. \\frac{a}{b} \\right|}^{\\immediate}$",
        "$\\vec{\\input}$ \\input{x}",
        "$\\mathbf{}}\\input x{$",
        "$\\left(\\right)\\input$",
    };
    static const std::regex macro(R"(\\([A-Za-z]+|[^A-Za-z]))");
    for (const auto& tex : hostile) {
        std::string latex;
        try {
            latex = tex_to_latex(tex);
        } catch (const std::invalid_argument&) {
            continue;
        }
        for (auto it = std::sregex_iterator(latex.begin(), latex.end(), macro); it != std::sregex_iterator(); ++it) {
            EXPECT_EQ(allowed.count((*it)[1].str()), 1u) << tex << " -> " << latex;
        }
        EXPECT_EQ(latex.find("^^"), std::string::npos) << tex << " -> " << latex;
    }
    // A lone prime followed by primes or a superscript is one superscript, as LaTeX needs
    // (two were a "Double superscript" error that stopped the document).
    EXPECT_EQ(tex_to_latex("$\\infty ''x$"), "$\\infty {}^{\\prime\\prime}x$");
    EXPECT_EQ(tex_to_latex("$x '^2$"), "$x{}^{\\prime 2}$");
    EXPECT_EQ(tex_to_latex("$x '_1$"), "$x{}^{\\prime}_1$");
    // The text of a hostile label is kept as text.
    EXPECT_EQ(tex_to_latex("$\\sqrt{\\mathrm{\\input x}}$"), "$\\sqrt{\\mathrm{\\backslash input\\ x}}$");
    EXPECT_EQ(tex_to_latex("^^5c \\input"), "\\^{}\\^{}5c \\textbackslash{}input");
}

TEST(Notation, ManPageListsExactlyTheTable) {
    const std::string page = slurp(std::filesystem::path(PENDULUM_TEST_DATA) / "../../man/pendulum-figures-spec.5");
    const std::string begin = ".\\\" The macros: generated from plot::tex_macros_man(); keep in step.\n";
    const auto from = page.find(begin);
    ASSERT_NE(from, std::string::npos) << "no list of macros in the man page";
    const auto start = from + begin.size();
    const auto end = page.find(".TE\n", start);
    ASSERT_NE(end, std::string::npos);
    EXPECT_EQ(page.substr(start, end + 4 - start), plot::tex_macros_man())
        << "the man page's list of macros is not the table's; put this in its place:\n" << plot::tex_macros_man();
    // Every name once, as a row's first cell.
    std::set<std::string> rows;
    std::istringstream lines(plot::tex_macros_man());
    for (std::string line; std::getline(lines, line);) {
        if (line.starts_with("\\e") || line.starts_with("\\&\\e")) rows.insert(line.substr(0, line.find('\t')));
    }
    EXPECT_EQ(rows.size(), plot::tex_macros().size());
}

TEST(Notation, SvgIdsAreTheFiguresOwn) {
    const auto dir = temp_dir("notation-svg-ids");
    ASSERT_EQ(run_cli("plot period --methods exact -f svg --name a", dir).status, 0);
    ASSERT_EQ(run_cli("plot phase --theta0 pi/3 --methods exact -f svg --name b", dir).status, 0);
    ASSERT_EQ(run_cli("plot period --methods exact -f svg --name a2 --set svg_text=text", dir).status, 0);
    ASSERT_EQ(run_cli("plot period --methods exact -f svg --name again", dir).status, 0);
    const auto ids = [](const std::string& svg) {
        std::set<std::string> out;
        static const std::regex id(R"re( id="([^"]+)")re");
        for (auto it = std::sregex_iterator(svg.begin(), svg.end(), id); it != std::sregex_iterator(); ++it) {
            EXPECT_TRUE(out.insert((*it)[1].str()).second) << "id twice: " << (*it)[1].str();
        }
        return out;
    };
    std::set<std::string> prefixes;
    std::map<std::string, std::set<std::string>> of;
    for (const std::string name : {"a", "b", "a2"}) {
        const std::string svg = slurp(dir / (name + ".svg"));
        of[name] = ids(svg);
        ASSERT_FALSE(of[name].empty()) << name;
        // Every id has the file's prefix, f and 12 hex digits, and every reference resolves.
        static const std::regex prefixed(R"(f[0-9a-f]{12}-[a-z]+[0-9-]*)");
        for (const auto& i : of[name]) {
            EXPECT_TRUE(std::regex_match(i, prefixed)) << name << ": " << i;
            prefixes.insert(i.substr(0, 14));
        }
        static const std::regex reference(R"re((?:href="#|url\(#)([^")]+))re");
        int references = 0;
        for (auto it = std::sregex_iterator(svg.begin(), svg.end(), reference); it != std::sregex_iterator(); ++it) {
            ++references;
            EXPECT_EQ(of[name].count((*it)[1].str()), 1u) << name << ": #" << (*it)[1].str() << " is not defined";
        }
        if (name != "a2") {  // text as <text>: no glyphs to refer to
            EXPECT_GT(references, 0) << name;
        }
    }
    EXPECT_EQ(prefixes.size(), 3u);  // one prefix per file, a different one for each
    for (const auto& i : of["a"]) EXPECT_EQ(of["b"].count(i) + of["a2"].count(i), 0u) << i;
    // The same figure, the same bytes.
    EXPECT_EQ(slurp(dir / "a.svg"), slurp(dir / "again.svg"));
    std::filesystem::remove_all(dir);
}

// ---------------------------------------------------------------------------------------
// Accents placed by the layout, TeX's thin space after a comma, a formula's label as math,
// and the SVG text's overline.

namespace {

/// The inked pixels of a label drawn alone: their bounding box, in pixels of 20 a point.
struct pixel_box {
    int x0 = 1 << 30, y0 = 1 << 30, x1 = -1, y1 = -1;
    bool empty() const { return x1 < 0; }
    double centre_x() const { return (x0 + x1 + 1) / 2.0; }
};

constexpr double px_per_pt = 20;
constexpr double label_pt = 10;

/// Draws the TeX label in `family` at label_pt, its baseline's left end at (4 pt, 16 pt), and
/// returns the box of its ink in the rows from `from` to above `below` (all rows by default).
pixel_box drawn_ink(const std::string& tex, const std::string& family, int below = 1 << 30, int from = 0) {
    const int w = 40 * static_cast<int>(px_per_pt);
    const int h = 24 * static_cast<int>(px_per_pt);
    plot::surface_ptr s(cairo_image_surface_create(CAIRO_FORMAT_A8, w, h));
    plot::context_ptr cr(cairo_create(s.get()));
    cairo_scale(cr.get(), px_per_pt, px_per_pt);
    const plot::text_engine engine(cr.get(), family);
    engine.draw_on_baseline(plot::tex_label(tex), label_pt, 4, 16);
    cairo_surface_flush(s.get());
    const unsigned char* data = cairo_image_surface_get_data(s.get());
    const int stride = cairo_image_surface_get_stride(s.get());
    pixel_box b;
    for (int y = std::max(from, 0); y < std::min(h, below); ++y) {
        for (int x = 0; x < w; ++x) {
            if (data[y * stride + x] <= 64) continue;
            b.x0 = std::min(b.x0, x), b.x1 = std::max(b.x1, x);
            b.y0 = std::min(b.y0, y), b.y1 = std::max(b.y1, y);
        }
    }
    return b;
}

}  // namespace

TEST(Notation, EveryAccentSitsCentredAboveItsLetter) {
    // Every accent of the table drawn as a mark (the overline is a line over a run) over
    // Latin and Greek, italic and upright letters, in the paper's and the slides' fonts: its
    // ink is above the letter's ink, clear of it, and centred on its optical centre within 0.1 em (an
    // italic letter's accent stands right of the middle of its ink, along its slope).
    const std::vector<std::string> bases = {"\\theta", "\\vartheta", "\\psi", "\\phi", "\\omega", "i", "j", "l", "W",
                                            "x", "\\Theta", "\\mathrm{x}", "\\mathrm{W}"};
    int checked = 0;
    double worst = 0;
    for (const std::string family : {"CMU Serif, DejaVu Math TeX Gyre", "CMU Sans Serif, DejaVu Sans"}) {
        for (const auto& m : plot::tex_macros()) {
            if (m.kind != macro_kind::accent || m.markup.empty()) continue;
            for (const auto& base : bases) {
                // The letter without its accent: \imath for i and \jmath for j, as the accent draws them.
                const std::string bare = base == "i" ? "\\mathit{\u0131}" : base == "j" ? "\\mathit{\u0237}" : base;
                const pixel_box letter = drawn_ink("$" + bare + "$", family);
                ASSERT_FALSE(letter.empty()) << base;
                const std::string tex = "$\\" + std::string(m.name) + "{" + base + "}$";
                const pixel_box accent = drawn_ink(tex, family, letter.y0);
                const pixel_box whole = drawn_ink(tex, family);
                const std::string what = tex + " in " + family;
                ASSERT_FALSE(accent.empty()) << what << ": no ink above the letter (the accent is lost or inside it)";
                // Nothing of the accent reaches the letter's rows but what is above it.
                EXPECT_EQ(whole.y0, accent.y0) << what;
                EXPECT_LE(accent.y1, letter.y0 - 0.02 * label_pt * px_per_pt) << what << ": the accent touches the letter";
                // The letter's optical centre: the middle of the ink of its top part (the
                // stem of j, not its hook; the loop of ϑ).
                const int band = letter.y0 + static_cast<int>(0.3 * (letter.y1 - letter.y0 + 1));
                const pixel_box top = drawn_ink("$" + bare + "$", family, band + 1, letter.y0);
                EXPECT_NEAR(accent.centre_x(), top.centre_x(), 0.1 * label_pt * px_per_pt) << what;
                worst = std::max(worst, std::fabs(accent.centre_x() - top.centre_x()) / (label_pt * px_per_pt));
                EXPECT_LE(letter.y0 - accent.y1, 0.2 * label_pt * px_per_pt) << what << ": the accent floats off";
                ++checked;
            }
        }
    }
    EXPECT_EQ(checked, 2 * 6 * 13);
    std::printf("accents: farthest from the optical centre %.3f em\n", worst);
}

TEST(Notation, AccentsAreCutFromTheirRunsInTheirElements) {
    using plot::split_accents;
    auto pieces = split_accents("<i>a\u03b8\u0307b</i> c");
    ASSERT_EQ(pieces.size(), 3u);
    EXPECT_EQ(pieces[0].text, "<i>a</i>");
    EXPECT_EQ(pieces[0].mark, "");
    EXPECT_EQ(pieces[1].text, "<i>\u03b8</i>");
    EXPECT_EQ(pieces[1].mark, "\u0307");
    EXPECT_EQ(pieces[2].text, "<i>b</i> c");
    // Two marks on one letter stay together; a run of nothing but tags is left out.
    pieces = split_accents("<span overline=\"single\"><b>x\u0302\u0307</b></span>");
    ASSERT_EQ(pieces.size(), 1u);
    EXPECT_EQ(pieces[0].text, "<span overline=\"single\"><b>x</b></span>");
    EXPECT_EQ(pieces[0].mark, "\u0302\u0307");
    // An entity is one character; the vector arrow (U+20D7) is a mark too.
    pieces = split_accents("&amp;\u20d7");
    ASSERT_EQ(pieces.size(), 1u);
    EXPECT_EQ(pieces[0].text, "&amp;");
    EXPECT_EQ(pieces[0].mark, "\u20d7");
    EXPECT_EQ(split_accents("no accents").size(), 1u);
    // An accent on i or j drops its dot: TeX's \imath and \jmath.
    EXPECT_EQ(tex_to_markup("$\\dot i \\hat j$"), "<i>\u0131\u0307</i><i>\u0237\u0302</i>");
    EXPECT_EQ(tex_to_latex("$\\dot i$"), "$\\dot{i}$");
}

TEST(Notation, ThinSpaceAfterACommaInMath) {
    // TeX's punctuation class: a thin space after a comma in math, none in scripts.
    EXPECT_EQ(tex_to_markup("$f(a,b)$"), "<i>f</i>(<i>a</i>,\u2009<i>b</i>)");
    EXPECT_EQ(tex_to_markup("$f(a, b)$"), "<i>f</i>(<i>a</i>,\u2009<i>b</i>)");
    EXPECT_EQ(tex_to_markup("$x_{i,j}$"), "<i>x</i><sub><i>i</i>,<i>j</i></sub>");
    // Text keeps its commas as they are; LaTeX spaces the comma itself.
    EXPECT_EQ(tex_to_markup("a,b $a,b$"), "a,b <i>a</i>,\u2009<i>b</i>");
    EXPECT_EQ(tex_to_latex("$f(a,b)$"), "$f(a,b)$");
    EXPECT_EQ(tex_to_plain("$f(a,b)$"), "f(a,\u2009b)");
}

TEST(Notation, FormulaReadsAsMath) {
    const auto tex = [](const std::string& f) { return pendulum::formula_tex(pendulum::formula(f)); };
    const std::pair<std::string, std::string> cases[] = {
        {"sqrt(1/cos(theta0/2))", "\\sqrt{\\frac{1}{\\cos(\\frac{\\theta_0}{2})}}"},
        {"1 + theta0^2/16", "1 + \\frac{\\theta_0^{2}}{16}"},
        {"2*pi*sqrt(t)", "2\\,\\pi\\,\\sqrt{t}"},
        {"2pi", "2\\,\\pi"},
        {"2*3", "2 \\cdot 3"},
        {"\u03c0*\u03b80", "\\pi\\,\\theta_0"},
        {"(1+theta0)*(1-theta0)", "(1 + \\theta_0)\\,(1 - \\theta_0)"},
        {"1 - (theta0 - 1)", "1 - (\\theta_0 - 1)"},
        {"1 - theta0 - 1", "1 - \\theta_0 - 1"},
        {"-(theta0-1)^2", "-(\\theta_0 - 1)^{2}"},
        {"-2^2", "-2^{2}"},
        {"-(-t)", "-(-t)"},
        {"2^3^2", "2^{3^{2}}"},
        {"(2^3)^2", "(2^{3})^{2}"},
        {"(1/2)^t", "(\\frac{1}{2})^{t}"},
        {"1.5e-3*log(theta0)", "1.5 \\times 10^{-3}\\,\\ln(\\theta_0)"},
        {"2E+5", "2 \\times 10^{5}"},
        {"abs(sin(t))", "\\left|\\sin(t)\\right|"},
        {"exp(asin(t)) + acos(t)*atan(t)", "\\exp(\\arcsin(t)) + \\arccos(t)\\,\\arctan(t)"},
        {"tan(t) + sinh(t) + cosh(t) + tanh(t)", "\\tan(t) + \\sinh(t) + \\cosh(t) + \\tanh(t)"},
        {"agm(1, cos(theta0/2))", "\\mathrm{agm}(1, \\cos(\\frac{\\theta_0}{2}))"},
        {"besselj(-2, t)", "J_{-2}(t)"},
        {"ellipk(sin(theta0/2)^2) + ellipe(t)", "K(\\sin(\\frac{\\theta_0}{2})^{2}) + E(t)"},
    };
    for (const auto& [formula, expected] : cases) {
        EXPECT_EQ(tex(formula), expected) << formula;
        // The engine draws every one of them, and LaTeX gets the same math.
        EXPECT_NO_THROW(tex_to_markup("$" + expected + "$")) << formula;
        EXPECT_EQ(tex_to_latex("$" + expected + "$").substr(0, 1), "$") << formula;
    }
}

TEST(Notation, FormulasDefaultLegendLabelIsItsMath) {
    const auto label = [](const std::string& f) { return figures::method_label(pendulum::parse_method("formula:" + f)); };
    const plot::label l = label("sqrt(1/cos(theta0/2))");
    EXPECT_EQ(l.markup, tex_to_markup("$\\sqrt{\\frac{1}{\\cos(\\frac{\\theta_0}{2})}}$"));
    EXPECT_EQ(l.latex, tex_to_latex("$\\sqrt{\\frac{1}{\\cos(\\frac{\\theta_0}{2})}}$"));
    // The formula itself stays the formula.
    EXPECT_EQ(pendulum::parse_method("formula:sqrt(1/cos(theta0/2))").label(), "sqrt(1/cos(theta0/2))");
    // A label holds at most max_label_bytes: a formula whose TeX (with its dollars) has
    // 1000 bytes reads as math, one of 1001 as its text. 200 terms 1 + 1 + ... + 11...1:
    // 4 bytes a term and the last one's digits.
    const auto terms = [](std::size_t digits) {
        std::string f;
        for (int i = 0; i < 199; ++i) f += "1+";
        return f + std::string(digits, '1');
    };
    ASSERT_EQ(pendulum::formula_tex(pendulum::formula(terms(202))).size() + 2, plot::max_label_bytes);
    EXPECT_NE(label(terms(202)).markup.find("1 + 1"), std::string::npos) << "1000 bytes: math";
    EXPECT_EQ(label(terms(203)).markup, tex_to_markup(terms(203))) << "1001 bytes: the formula's text";
    EXPECT_EQ(label(terms(203)).markup.find("1 + 1"), std::string::npos);
}

TEST(Notation, FormulaLabelInARenderedLegend) {
    // The spec's formula, drawn: the legend's text (SVG text) is the math, not the formula.
    const auto dir = temp_dir("notation-formula-legend");
    std::ofstream(dir / "f.toml") << "[figure]\ncolumns = 1\n[[panel]]\nplot = \"period\"\n"
                                     "methods = [\"exact\", { formula = \"sqrt(1/cos(theta0/2))\" }]\n";
    const auto r = run_cli("render f.toml -f svg --set svg_text=text", dir);
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string svg = slurp(dir / "f.svg");
    std::string texts;
    static const std::regex text("<text[^>]*>(.*?)</text>");
    for (auto it = std::sregex_iterator(svg.begin(), svg.end(), text); it != std::sregex_iterator(); ++it) {
        texts += (*it)[1].str() + "\n";
    }
    EXPECT_EQ(texts.find("theta0"), std::string::npos) << texts;
    EXPECT_EQ(texts.find("sqrt"), std::string::npos) << texts;
    EXPECT_NE(texts.find("\u221a<tspan text-decoration=\"overline\">1/cos("), std::string::npos) << texts;
    std::filesystem::remove_all(dir);
}

TEST(Notation, SvgTextOverlineIsOneLineOverTheWholeRun) {
    // \overline{x_1} and \sqrt{1 - k^2}: one <tspan> carries the overline around the runs of
    // the letter and of its script, rather than each run its own at its own height.
    const auto dir = temp_dir("notation-svg-overline");
    std::ofstream(dir / "o.toml") << "[figure]\ncolumns = 1\ntitle = '$\\overline{x_1}$ and $\\sqrt{1 - k^2}$'\n"
                                     "[[panel]]\nplot = \"period\"\nmethods = [\"exact\"]\n";
    const auto r = run_cli("render o.toml -f svg --set svg_text=text", dir);
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string svg = slurp(dir / "o.svg");
    static const std::regex overlined("<tspan text-decoration=\"overline\">(.*?)</tspan></tspan>");
    std::vector<std::string> runs;
    for (auto it = std::sregex_iterator(svg.begin(), svg.end(), overlined); it != std::sregex_iterator(); ++it) {
        runs.push_back((*it)[1].str());
    }
    ASSERT_EQ(runs.size(), 2u) << svg;
    EXPECT_NE(runs[0].find(">x<"), std::string::npos) << runs[0];
    EXPECT_TRUE(runs[0].ends_with(">1")) << runs[0];
    EXPECT_NE(runs[1].find(">k<"), std::string::npos) << runs[1];
    EXPECT_TRUE(runs[1].ends_with(">2")) << runs[1];
    // No other element draws an overline of its own.
    std::size_t count = 0;
    for (std::size_t pos = 0; (pos = svg.find("text-decoration", pos)) != std::string::npos; ++pos) ++count;
    EXPECT_EQ(count, 2u);
    std::filesystem::remove_all(dir);
}

TEST(Notation, AccentCutsLeaveBadMarkupBad) {
    // The cuts close and reopen the elements around an accent, but an element the markup
    // leaves open stays open, and an end without a start stays: Pango refuses both.
    auto pieces = plot::split_accents("<i>x\u0302 unclosed");
    ASSERT_EQ(pieces.size(), 2u);
    EXPECT_EQ(pieces[0].text, "<i>x</i>");
    EXPECT_EQ(pieces[1].text, "<i> unclosed");
    pieces = plot::split_accents("a</i>");
    ASSERT_EQ(pieces.size(), 1u);
    EXPECT_EQ(pieces[0].text, "a</i>");
    plot::text_shaper shaper("CMU Serif");
    EXPECT_THROW(shaper.box("<i>x\u0302 unclosed", 10), std::invalid_argument);
    EXPECT_THROW(shaper.box("<i>unclosed", 10), std::invalid_argument);
}
