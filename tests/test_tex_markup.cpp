// SPDX-License-Identifier: GPL-3.0-or-later
// TeX math in labels, turned into Pango markup and plain text.
#include "plot/tex_markup.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

namespace {

using plot::tex_to_markup;
using plot::tex_to_plain;

TEST(TexMarkup, TheCatalogsLabels) {
    EXPECT_EQ(tex_to_markup("$\\vartheta_0$"), "<i>\u03d1</i><sub>0</sub>");
    EXPECT_EQ(tex_to_markup("$\\vartheta$"), "<i>\u03d1</i>");
    EXPECT_EQ(tex_to_markup("$t/T$"), "<i>t</i>/<i>T</i>");
    EXPECT_EQ(tex_to_markup("$T/T_0$"), "<i>T</i>/<i>T</i><sub>0</sub>");
    EXPECT_EQ(tex_to_markup("$c_1$"), "<i>c</i><sub>1</sub>");
    EXPECT_EQ(tex_to_markup("$c'_3$"), "<i>c</i><sup>\u02b9</sup><sub>3</sub>");
    EXPECT_EQ(tex_to_markup("$c''_5$"), "<i>c</i><sup>\u02b9\u02b9</sup><sub>5</sub>");
    EXPECT_EQ(tex_to_markup("$|T_N/T - 1|$"), "|<i>T</i><sub><i>N</i></sub>/<i>T</i> \u2212 1|");
    EXPECT_EQ(tex_to_markup("order $N$ of the iteration"), "order <i>N</i> of the iteration");
    EXPECT_EQ(tex_to_markup("relative error (%)"), "relative error (%)");
}

TEST(TexMarkup, ScriptsGroupsAndSymbols) {
    EXPECT_EQ(tex_to_markup("$x^{2k+1}$"), "<i>x</i><sup>2<i>k</i>+1</sup>");
    EXPECT_EQ(tex_to_markup("$c_{2k+1}$"), "<i>c</i><sub>2<i>k</i>+1</sub>");
    EXPECT_EQ(tex_to_markup("$a_1^2$"), "<i>a</i><sup>2</sup><sub>1</sub>");
    EXPECT_EQ(tex_to_markup("$95\\pi/100$"), "95<i>\u03c0</i>/100");
    EXPECT_EQ(tex_to_markup("$170^\\circ$"), "170\u00b0");
    EXPECT_EQ(tex_to_markup("$\\dot\\vartheta/\\omega_0$"), "<i>\u03d1\u0307</i>/<i>\u03c9</i><sub>0</sub>");
    EXPECT_EQ(tex_to_markup("$-x + -1 = y$"), "\u2212<i>x</i> + \u22121 = <i>y</i>");
    EXPECT_EQ(tex_to_markup("$T\\,\\mathrm{(s)}$"), "<i>T</i>\u2009(s)");
    EXPECT_EQ(tex_to_markup("$\\Omega \\omega$"), "\u03a9<i>\u03c9</i>");
    EXPECT_EQ(tex_to_markup("a < b & c"), "a &lt; b &amp; c");
    EXPECT_EQ(tex_to_markup("costs \\$5"), "costs $5");
}

TEST(TexMarkup, PlainText) {
    EXPECT_EQ(tex_to_plain("$\\vartheta_0 = 95\\pi/100$"), "\u03d10 = 95\u03c0/100");
    EXPECT_EQ(tex_to_plain("$c''_5$"), "c\u20335");
    EXPECT_EQ(tex_to_plain("a < b"), "a < b");
}

TEST(TexMarkup, BadLabelsAreErrorsNamingThem) {
    const auto why = [](const std::string& tex) {
        try {
            tex_to_markup(tex);
        } catch (const std::invalid_argument& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    EXPECT_EQ(why("$x"), "label '$x': unbalanced $");
    EXPECT_EQ(why("$x_{1$"), "label '$x_{1$': unbalanced $");
    EXPECT_EQ(why("$x}$"), "label '$x}$': unbalanced }");
    EXPECT_EQ(why("$\\foo$"), "label '$\\foo$': unknown macro \\foo");
    EXPECT_EQ(why("$x_$"), "label '$x_$': script without an argument");
    EXPECT_EQ(why("$x_1_2$"), "label '$x_1_2$': double script");
    EXPECT_EQ(why("$\\"), "label '$\\': lone backslash");
}

}  // namespace

TEST(TexMarkup, MarkupAsLatexForOverlays) {
    using plot::markup_to_latex;
    // What the program makes itself: tick labels, legends, axis labels.
    EXPECT_EQ(markup_to_latex("\u22120.5"), "$-0.5$");
    EXPECT_EQ(markup_to_latex("3\u03c0/4"), "$3\\pi /4$");
    EXPECT_EQ(markup_to_latex("10<sup>\u22124</sup>"), "$10^{-4}$");
    EXPECT_EQ(markup_to_latex("90\u00b0"), "$90^{\\circ}$");
    EXPECT_EQ(markup_to_latex("<i>\u03d1</i><sub>0</sub> = 95\u03c0/100"), "$\\vartheta _{0} = 95\\pi /100$");
    EXPECT_EQ(markup_to_latex("|<i>T</i><sub><i>N</i></sub>/<i>T</i> \u2212 1|"), "$|T_{N}/T - 1|$");
    EXPECT_EQ(markup_to_latex("<i>c</i><sup>\u02b9\u02b9</sup><sub>1</sub>"), "$c^{\\prime \\prime }_{1}$");
    EXPECT_EQ(markup_to_latex("order <i>N</i> of the iteration"), "order $N$ of the iteration");
    EXPECT_EQ(markup_to_latex("relative error (%)"), "relative error $(\\%)$");
    EXPECT_EQ(markup_to_latex("Kidd\u2013Fogg"), "Kidd--Fogg");
    EXPECT_EQ(markup_to_latex("<i>T</i> (s)"), "$T$ (s)");
    EXPECT_EQ(markup_to_latex("R&amp;D 100%"), "R\\&D $100\\%$");
    // A spec's label is written from its parse: the same TeX, every character escaped.
    using plot::tex_to_latex;
    EXPECT_EQ(tex_to_latex("$c''_1$"), "$c''_1$");
    EXPECT_EQ(tex_to_latex("the paper's 0.1 % bound, $\\vartheta_0 \\le \\pi/2$"),
              "the paper's 0.1 \\% bound, $\\vartheta _0\\le \\pi /2$");
    EXPECT_EQ(tex_to_latex("$\\vartheta$ (\u00b0)"), "$\\vartheta $ ($^{\\circ}$)");
    // A lone backslash at the end of text is a literal one, not the start of a macro.
    EXPECT_EQ(tex_to_latex("a\\"), "a\\textbackslash{}");
    EXPECT_EQ(tex_to_latex("50% & #1 a_b {c} ^ ~ | < >"),
              "50\\% \\& \\#1 a\\_b \\{c\\} \\^{} \\~{} \\textbar{} \\textless{} \\textgreater{}");
    // Nothing LaTeX cannot set slips through.
    EXPECT_THROW(markup_to_latex("\u263a"), std::invalid_argument);
}
