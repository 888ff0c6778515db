// SPDX-License-Identifier: GPL-3.0-or-later
// The alt text's cost: a figure's words take the layout of the file being written (a PDF's,
// an SVG's) instead of laying the figure out a second time, where that drawing laid out what
// the words speak of (the paper theme's layout of the figure as built), and say the same
// words, byte for byte, whichever layout they took.
#include "figures/batch.hpp"
#include "figures/catalog.hpp"
#include "figures/describe.hpp"
#include "figures/themes.hpp"
#include "plot/figure.hpp"
#include "plot/output.hpp"
#include "plot/render.hpp"
#include "plot/theme.hpp"
#include "process.hpp"
#include "still_sweep.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

namespace {

using test_support::temp_dir;

const plot::theme& paper() {
    static const plot::theme th = figures::load_theme("paper", {});
    return th;
}

/// Fig. 7 as `render` builds it in the paper theme.
plot::figure fig7() { return figures::build(figures::find("period"), figures::sized_by({}, paper())); }

/// The layouts `work` does.
template <class Work>
std::size_t layouts_of(Work work) {
    const std::size_t before = plot::figure_layouts();
    work();
    return plot::figure_layouts() - before;
}

/// The words describe finds with a layout of its own (no drawing given).
plot::figure_words own_words(const figures::entry& e, const plot::figure& fig, const plot::theme& th) {
    const figures::figure_description d = figures::describe(e, fig, figures::sized_by({}, th));
    return {d.alt, d.text};
}

/// A vector drawing of `fig` in `th`, as a PDF's is: its frames as draw_figure records them.
plot::drawing vector_drawing(const plot::figure& fig, const plot::theme& th) {
    return plot::drawing{&fig, &th, false, plot::panel_frames(fig, th)};
}

TEST(AltTextCost, APdfLaysTheFigureOutOnceWordsIncluded) {
    const plot::figure fig = fig7();
    EXPECT_EQ(layouts_of([&] { (void)plot::render(fig, paper(), "pdf", {}); }), 1u);
    // The words are found once per figure: a second file takes them as found.
    EXPECT_EQ(layouts_of([&] { (void)plot::render(fig, paper(), "svg", {}); }), 1u);
    EXPECT_EQ(layouts_of([&] { (void)plot::render(fig, paper(), "png", {}); }), 1u);
}

TEST(AltTextCost, AnSvgFirstLaysTheFigureOutOnceWordsIncluded) {
    const plot::figure fig = fig7();
    EXPECT_EQ(layouts_of([&] { (void)plot::render(fig, paper(), "svg", {}); }), 1u);
    EXPECT_EQ(layouts_of([&] { (void)plot::render(fig, paper(), "pdf", {}); }), 1u);
}

TEST(AltTextCost, RenderOfFig7PngAndPdfIsTwoLayouts) {
    // As `render fig7 -f png,pdf --jobs 1` writes them: one layout per file, none for the words.
    const auto dir = temp_dir("alttext-render");
    const auto files = figures::files_for({&figures::find("period")}, {"png", "pdf"}, dir, false, {});
    plot::output_options out;
    out.jobs = 1;
    out.force = true;
    EXPECT_EQ(layouts_of([&] { figures::write_figures(files, {}, paper(), out); }), 2u);
    EXPECT_TRUE(std::filesystem::exists(dir / "period.pdf"));
    EXPECT_TRUE(std::filesystem::exists(dir / "period.png"));
    std::filesystem::remove_all(dir);
}

TEST(AltTextCost, ADrawingInAnotherThemeIsNotTheWordsLayout) {
    // The words speak of the paper theme's layout: a slides PDF leaves them to lay out their own.
    const plot::theme slides = figures::load_theme("slides", {});
    const plot::figure fig = figures::build(figures::find("period"), figures::sized_by({}, slides));
    EXPECT_EQ(layouts_of([&] { (void)plot::render(fig, slides, "pdf", {}); }), 2u);
    EXPECT_EQ(fig.words(nullptr).description, own_words(figures::find("period"), fig, slides).description);
}

TEST(AltTextCost, APanelFileIsNotTheWordsLayout) {
    // A paper file of one panel (with its peers) carries the whole figure's words.
    const plot::figure fig = fig7();
    const plot::figure one = figures::single_panel(fig, 1, fig.panel_width_cm);
    EXPECT_EQ(layouts_of([&] { (void)plot::render(one, paper(), "pdf", {}); }), 2u);
    EXPECT_EQ(one.words(nullptr).description, own_words(figures::find("period"), fig, paper()).description);
}

// The boundary of reuse: the same content and theme take the drawing's frames; one ulp in one
// value, one point of one text size, a raster or a missing frame lay the figure out again.
TEST(AltTextCost, FramesAreTakenOnlyFromTheSameLayout) {
    const plot::figure fig = fig7();
    const plot::drawing same = vector_drawing(fig, paper());
    std::vector<plot::panel_frame> taken;
    EXPECT_EQ(layouts_of([&] { taken = plot::panel_frames(fig, paper(), &same); }), 0u);
    ASSERT_EQ(taken.size(), same.frames.size());

    // The same content styled as the theme styles it (describe's figure) is the same layout.
    const plot::figure styled = plot::with_theme_styles(fig, paper());
    EXPECT_EQ(layouts_of([&] { (void)plot::panel_frames(styled, paper(), &same); }), 0u);

    plot::figure moved = fig;
    auto& y = moved.panels.at(1).data.at(1).y;
    ASSERT_FALSE(y.empty());
    y[0] = std::nextafter(y[0], std::numeric_limits<double>::infinity());
    EXPECT_EQ(layouts_of([&] { (void)plot::panel_frames(moved, paper(), &same); }), 1u);

    plot::theme larger = paper();
    larger.tick_font_pt += 1;
    EXPECT_EQ(layouts_of([&] { (void)plot::panel_frames(fig, larger, &same); }), 1u);

    plot::drawing raster = same;
    raster.raster = true;
    EXPECT_EQ(layouts_of([&] { (void)plot::panel_frames(fig, paper(), &raster); }), 1u);

    plot::drawing short_of_one = same;
    short_of_one.frames.pop_back();
    EXPECT_EQ(layouts_of([&] { (void)plot::panel_frames(fig, paper(), &short_of_one); }), 1u);

    const plot::drawing nothing{};
    EXPECT_EQ(layouts_of([&] { (void)plot::panel_frames(fig, paper(), &nothing); }), 1u);
}

// Hostile: a drawing of other content with the words of this figure (a caller that changed
// a copy) must not lend its frames: a limit moved by a spec's y range changes the words.
TEST(AltTextCost, AChangedCopyKeepsTheWordsOfTheFigure) {
    const figures::entry& e = figures::find("period");
    const plot::figure fig = fig7();
    plot::figure changed = fig;  // carries fig's words
    changed.panels.at(0).y.min = 0.0;
    changed.panels.at(0).y.max = 10.0;
    changed.panels.at(0).y.exact_range = true;
    (void)plot::render(changed, paper(), "pdf", {});
    const plot::figure_words found = fig.words(nullptr);
    const plot::figure_words own = own_words(e, fig, paper());
    EXPECT_EQ(found.alt, own.alt);
    EXPECT_EQ(found.description, own.description);
    EXPECT_NE(found.description.find("T/T0 from 1 to 3.72"), std::string::npos) << found.description;
}

// Byte for byte: every built-in still x theme x size (the theme's own, 8.6 cm, 17.8 cm): the
// words a PDF's drawing lent its layout to are describe's own, and the PDF is the one written
// with describe's own words; the paper theme at its own size lays the figure out once.
TEST(AltTextCost, EveryBuiltinSaysTheSameWordsWithOneLayout) {
    int reused = 0;
    const auto counts = test_support::for_each_still_builtin(
        {"", "figure_width_cm=8.6", "figure_width_cm=17.8"}, [&](const test_support::still_case& c) {
            const plot::figure_words own = own_words(c.entry, c.figure, c.theme);
            std::string pdf;
            const std::size_t layouts = layouts_of([&] { pdf = plot::render(c.figure, c.theme, "pdf", {}); });
            const plot::figure_words found = c.figure.words(nullptr);
            EXPECT_EQ(found.alt, own.alt) << c.where();
            EXPECT_EQ(found.description, own.description) << c.where();
            plot::figure told = c.figure;
            told.words = [own](const plot::drawing*) { return own; };
            EXPECT_EQ(plot::render(told, c.theme, "pdf", {}), pdf) << c.where();
            const bool paper_as_is = c.theme == paper();
            EXPECT_EQ(layouts, paper_as_is ? 1u : 2u) << c.where();
            reused += paper_as_is ? 1 : 0;
        });
    EXPECT_EQ(reused, 13) << "the built-in stills in the paper theme at its own size";
    EXPECT_GE(counts.checked, 13 * 3 * 2);
}

TEST(AltTextCost, SvgDescIsDescribesOwnInEveryBuiltinPaperFigure) {
    for (const auto& e : figures::catalog()) {
        if (e.spec.animation) continue;
        const plot::figure fig = figures::build(e, figures::sized_by({}, paper()));
        std::string svg;
        EXPECT_EQ(layouts_of([&] { svg = plot::render(fig, paper(), "svg", {}); }), 1u) << e.id;
        const plot::figure_words own = own_words(e, fig, paper());
        EXPECT_NE(svg.find("<desc>" + plot::escape_markup(own.description) + "</desc>"), std::string::npos) << e.id;
    }
}

}  // namespace
