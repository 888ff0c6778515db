// SPDX-License-Identifier: GPL-3.0-or-later
// The LaTeX picture of pdf_tex and eps_tex: text sizes, relative and absolute, and where
// each text is put.
#include "plot/latex_overlay.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace {

plot::output_options relative_at(double document_pt) {
    plot::output_options o;
    o.tex_font_pt = document_pt;
    return o;
}

TEST(LatexOverlay, RelativeSizesAreTheClassFilesSizes) {
    const plot::theme th;  // ticks 7.5, labels 8.5, legends 7 pt: \footnotesize, \small, \scriptsize
    struct row {
        double document_pt, tick, label, legend;
    };
    // size10.clo, size11.clo, size12.clo; other sizes scale the 10 pt ones.
    for (const row& r : {row{10, 8, 9, 7}, row{11, 9, 10, 8}, row{10.95, 9, 10, 8}, row{12, 10, 10.95, 8},
                         row{9, 7.2, 8.1, 6.3}}) {
        const plot::theme sized = plot::latex_sized_theme(th, relative_at(r.document_pt));
        EXPECT_DOUBLE_EQ(sized.tick_font_pt, r.tick) << r.document_pt;
        EXPECT_DOUBLE_EQ(sized.label_font_pt, r.label) << r.document_pt;
        EXPECT_DOUBLE_EQ(sized.legend_font_pt, r.legend) << r.document_pt;
        EXPECT_EQ(plot::latex_size_command(sized.tick_font_pt, relative_at(r.document_pt)), "\\footnotesize");
        EXPECT_EQ(plot::latex_size_command(sized.label_font_pt, relative_at(r.document_pt)), "\\small");
        EXPECT_EQ(plot::latex_size_command(sized.legend_font_pt, relative_at(r.document_pt)), "\\scriptsize");
    }
    // Slides' sizes map as far as \huge.
    EXPECT_EQ(plot::latex_size_command(20.74, relative_at(10)), "\\huge");
    EXPECT_EQ(plot::latex_size_command(5, relative_at(10)), "\\tiny");
}

TEST(LatexOverlay, AbsoluteSizesAreTheThemes) {
    plot::theme th;
    th.label_font_pt = 8.25;
    plot::output_options o;
    o.tex_sizes = plot::tex_sizing::absolute;
    o.tex_font_pt = 12;  // no effect
    const plot::theme sized = plot::latex_sized_theme(th, o);
    EXPECT_EQ(sized.tick_font_pt, 7.5);
    EXPECT_EQ(sized.label_font_pt, 8.25);
    EXPECT_EQ(sized.legend_font_pt, 7.0);
    EXPECT_EQ(plot::latex_size_command(7.5, o), "\\fontsize{7.5}{9}\\selectfont");
    EXPECT_EQ(plot::latex_size_command(8.25, o), "\\fontsize{8.25}{9.9}\\selectfont");
    EXPECT_EQ(plot::latex_size_command(24, o), "\\fontsize{24}{28.8}\\selectfont");
}

TEST(LatexOverlay, SizingTable) {
    ASSERT_FALSE(plot::tex_sizing_table().empty());
    EXPECT_EQ(plot::tex_sizing_table().front().value, plot::output_options{}.tex_sizes);  // the default first
    EXPECT_EQ(plot::find_tex_sizing("absolute").value, plot::tex_sizing::absolute);
    try {
        plot::find_tex_sizing("big");
        FAIL() << "no error";
    } catch (const std::invalid_argument& e) {
        EXPECT_STREQ(e.what(), "unknown text sizing 'big'; sizings: relative, absolute");
    }
}

TEST(LatexOverlay, PicturePutsEachTextAtItsAnchor) {
    plot::theme th;
    const std::vector<plot::placed_text> texts = {
        {"<i>T</i>/<i>T</i><sub>0</sub>", 9, 50, 100, 0.5, true},  // a y label, turned
        {"0.25", 8, 200, 150, 1.0, false},                          // a tick label, right-aligned
        {"(a)", 9, 20, 10, 0.0, false},
    };
    const std::string tex = plot::latex_picture(texts, {400, 200}, th, "fig.pdf", relative_at(10));
    // The figure's own width, or \figurewidth; y measured up from the bottom, in widths.
    EXPECT_NE(tex.find("\\setlength{\\unitlength}{400.00000bp}"), std::string::npos) << tex;
    EXPECT_NE(tex.find("\\setlength{\\unitlength}{\\figurewidth}"), std::string::npos);
    EXPECT_NE(tex.find("\\begin{picture}(1,0.50000)%\n"
                       "  \\put(0,0){\\includegraphics[width=\\unitlength]{fig.pdf}}%\n"
                       "  \\put(0.12500,0.25000){\\rotatebox{90}{\\makebox(0,0)[c]{\\smash{\\small $T/T_{0}$}}}}%\n"
                       "  \\put(0.50000,0.12500){\\makebox(0,0)[r]{\\smash{\\footnotesize $0.25$}}}%\n"
                       "  \\put(0.05000,0.47500){\\makebox(0,0)[l]{\\smash{\\small (a)}}}%\n"
                       "\\end{picture}%\n"),
              std::string::npos)
        << tex;
    // Black text takes the document's colour; any other is set.
    EXPECT_EQ(tex.find("\\color[rgb]"), std::string::npos);
    th.foreground = {1, 1, 1};
    EXPECT_NE(plot::latex_picture(texts, {400, 200}, th, "fig.pdf", relative_at(10)).find("\\color[rgb]{1.0000,1.0000,1.0000}"),
              std::string::npos);
}

}  // namespace
