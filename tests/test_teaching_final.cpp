// SPDX-License-Identifier: GPL-3.0-or-later
// Teaching, the last remainder: each start's own series ids, describe's words for each
// method's glyph as drawn, the clock's line and the drawing's room in every theme.
#include "figures/animation.hpp"
#include "figures/catalog.hpp"
#include "figures/describe.hpp"
#include "figures/spec.hpp"
#include "figures/spec_build.hpp"
#include "figures/themes.hpp"
#include "plot/errors.hpp"
#include "plot/frames.hpp"
#include "plot/render.hpp"
#include "animation_builtins.hpp"
#include "process.hpp"

#include <gtest/gtest.h>

#include <iostream>

#include <algorithm>
#include <filesystem>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <vector>

namespace {

using namespace test_support;

/// Frames worth checking: the first, one a third in, the last, and (under a cross-fade) the
/// first blended one.
std::vector<int> frames_to_check(const figures::animation_plan& plan) {
    std::set<int> out{0, plan.frames / 3, plan.frames - 1};
    for (int i = 0; i < plan.frames; ++i) {
        if (plan.fade_in(i) > 0) {
            out.insert(i);
            break;
        }
    }
    return {out.begin(), out.end()};
}

/// The ids of a panel's series given twice or not at all.
std::vector<std::string> repeated_ids(const plot::panel& p) {
    std::map<std::string, int> n;
    for (const auto& s : p.data) ++n[s.id];
    std::vector<std::string> out;
    for (const auto& [id, k] : n) {
        if (k > 1 || id.empty()) out.push_back("'" + id + "' x" + std::to_string(k));
    }
    return out;
}

}  // namespace

// 4. Each start's rod, bob, trail, streak, turning points and moving dots have ids of their
// own: no series id is given twice (or left empty) in any panel of a built-in animation's
// still figure or frames.
TEST(TeachingFinal, EverySeriesIdIsUniqueInEveryBuiltinAnimation) {
    const auto animations = builtin_animations();
    ASSERT_GE(animations.size(), 3U);
    for (const char* theme : {"paper", "slides"}) {
        const plot::theme th = figures::load_theme(theme);
        for (const auto* e : animations) {
            const auto still = figures::build(*e, figures::sized_by({}, th));
            for (const auto& p : still.panels) EXPECT_TRUE(repeated_ids(p).empty()) << e->id << " still: " << testing::PrintToString(repeated_ids(p));
            const auto options = animated_options(th);
            const auto plan = figures::plan_animation(*e, options);
            const auto base = figures::build(*e, options);
            for (int i : frames_to_check(plan)) {
                const auto frame = figures::planned_frame(*e, options, plan, base, i);
                for (const auto& p : frame.panels) {
                    EXPECT_TRUE(repeated_ids(p).empty())
                        << e->id << " frame " << i << " in " << theme << ": " << testing::PrintToString(repeated_ids(p));
                }
            }
        }
    }
}

// The same through the program: the SVG of a frame has each id once, and its alt text and
// legend name each start once.
TEST(TeachingFinal, SvgFrameIdsAndLegendEntriesAreUnique) {
    const auto dir = temp_dir("teaching-final-ids");
    for (const auto* e : builtin_animations()) {
        const auto r = run_cli("render " + e->id + " --at 0.3 -f svg --set svg_text=text", dir);
        ASSERT_EQ(r.status, 0) << r.err;
        const std::string svg = slurp(dir / (e->id + ".svg"));
        std::map<std::string, int> ids;
        const std::regex id(" id=\"([^\"]*)\"");
        for (std::sregex_iterator it(svg.begin(), svg.end(), id), end; it != end; ++it) ++ids[(*it)[1].str()];
        ASSERT_FALSE(ids.empty()) << e->id;
        for (const auto& [name, n] : ids) EXPECT_EQ(n, 1) << e->id << ": id " << name;
    }
    // over-the-top's words name each start's legend entry once.
    const std::string svg = slurp(dir / "over-the-top.svg");
    for (const char* start : {"E = 1.6 mgL, libration (", "E = 2 mgL, separatrix (", "E = 2.6 mgL, rotation ("}) {
        std::size_t n = 0;
        for (auto at = svg.find(start); at != std::string::npos; at = svg.find(start, at + 1)) ++n;
        EXPECT_EQ(n, 1U) << start;
    }
    // And each frame's legend has each label once.
    for (const auto* e : builtin_animations()) {
        const plot::theme th = figures::load_theme("slides");
        const auto options = animated_options(th);
        const auto plan = figures::plan_animation(*e, options);
        const auto frame = figures::planned_frame(*e, options, plan, figures::build(*e, options), plan.frames / 2);
        std::map<std::string, int> labels;
        for (const auto& p : frame.panels) {
            for (const auto& s : p.data) {
                if (!s.label.empty()) ++labels[s.label.markup];
            }
        }
        EXPECT_FALSE(labels.empty()) << e->id;
        for (const auto& [label, n] : labels) EXPECT_EQ(n, 1) << e->id << ": " << label;
    }
}

namespace {

/// "solid" for a line style, as describe speaks of it.
std::string line_word(plot::line_style l) {
    static const char* const words[] = {"none", "solid", "dashed", "dotted", "dash-dot", "dash-dot-dot"};
    return words[static_cast<int>(l)];
}

/// Each pendulum of a frame's drawing as drawn, in order: "(dotted rod, open bob)".
std::vector<std::string> drawn_glyphs(const plot::panel& p) {
    std::vector<std::string> out;
    for (const auto& rod : p.data) {
        if (!rod.id.starts_with("rod:")) continue;
        const std::string bob_id = "bob:" + rod.id.substr(4);
        const auto bob = std::find_if(p.data.begin(), p.data.end(), [&](const plot::series& s) { return s.id == bob_id; });
        EXPECT_NE(bob, p.data.end()) << bob_id;
        if (bob == p.data.end()) continue;
        out.push_back("(" + line_word(rod.line) + " rod, " +
                      (bob->marker == plot::marker_style::filled_circle ? "filled" : "open") + " bob)");
    }
    return out;
}

/// The "(X rod, Y bob)" of a description, in order.
std::vector<std::string> described_glyphs(const std::string& text) {
    std::vector<std::string> out;
    const std::regex glyph(R"(\([a-z-]+ rod, [a-z]+ bob\))");
    for (std::sregex_iterator it(text.begin(), text.end(), glyph), end; it != end; ++it) out.push_back(it->str());
    return out;
}

}  // namespace

// 3. describe's words for each pendulum are its glyph as drawn: rod line and bob, in every
// built-in animation and theme (the words go into the SVG and PDF of that theme).
TEST(TeachingFinal, DescribeSpeaksOfTheDrawnGlyphs) {
    for (const auto& row : figures::builtin_themes()) {
        const plot::theme th = figures::load_theme(row.name);
        const auto options = animated_options(th);
        for (const auto* e : builtin_animations()) {
            const auto plan = figures::plan_animation(*e, options);
            const auto base = figures::build(*e, options);
            const auto frame = plot::with_theme_styles(figures::planned_frame(*e, options, plan, base, 3), th);
            std::vector<std::string> drawn;
            for (const auto& p : frame.panels) {
                for (auto& g : drawn_glyphs(p)) drawn.push_back(std::move(g));
            }
            const auto d = figures::describe(*e, base, options);
            EXPECT_EQ(described_glyphs(d.text), drawn) << e->id << " in " << row.name << ":\n" << d.text;
        }
    }
    // The harmonic rod of swing: dotted in paper (its theme style), dashed in a theme whose
    // style makes it so (the words follow the theme, not the paper theme always).
    const auto& swing = figures::find("swing");
    const auto words = [&](const plot::theme& th) {
        return figures::describe(swing, figures::build(swing, {}), figures::sized_by({}, th)).text;
    };
    const auto paper = words(figures::load_theme("paper"));
    EXPECT_NE(paper.find("harmonic (dotted rod, open bob)"), std::string::npos) << paper;
    const auto dashed = words(figures::load_theme("slides", {"styles.harmonic={line=\"dashed\"}"}));
    EXPECT_NE(dashed.find("harmonic (dashed rod, open bob)"), std::string::npos) << dashed;
    // Several starts: each start's own line; several amplitudes all named.
    const auto over = figures::describe(figures::find("over-the-top"), figures::build(figures::find("over-the-top"), {}));
    EXPECT_NE(over.text.find("E = 1.6 mgL (solid rod, filled bob), E = 2 mgL (dashed rod, filled bob), and E = 2.6 mgL "
                             "(dotted rod, filled bob)"),
              std::string::npos)
        << over.text;
}

// The same through the program: a swing frame's SVG in slides and in paper says what it draws.
TEST(TeachingFinal, SvgWordsFollowTheTheme) {
    const auto dir = temp_dir("teaching-final-words");
    for (const char* theme : {"paper", "slides"}) {
        std::filesystem::create_directories(dir / theme);
        const auto r = run_cli(std::string("render swing --at 0.3 -f svg --theme ") + theme + " -o " + theme +
                                   (std::string(theme) == "slides" ? " --set 'styles.harmonic={line=\"dashed\"}'" : ""),
                               dir);
        ASSERT_EQ(r.status, 0) << r.err;
    }
    EXPECT_NE(slurp(dir / "paper" / "swing.svg").find("harmonic (dotted rod, open bob)"), std::string::npos);
    EXPECT_NE(slurp(dir / "slides" / "swing.svg").find("harmonic (dashed rod, open bob)"), std::string::npos);
}

namespace {

/// The height of each drawing (frameless panel) of a frame, in points, and the figure's.
struct drawing_room {
    double drawing = 0;
    double figure = 0;
};

std::vector<drawing_room> drawings_of(const plot::figure& frame, const plot::theme& th) {
    std::vector<drawing_room> out;
    const double figure_h = plot::pixel_size(frame, th, 72).second;
    for (const auto& f : plot::panel_frames(frame, th)) {
        if (f.frameless) out.push_back({f.h, figure_h});
    }
    return out;
}

}  // namespace

// 1, 2. The drawing keeps its room: with the clock on a line of its own above it and the
// legend band across the row where the band over its own cell would leave it less than 0.6
// of the cell, each built-in animation's drawing (2.4 rod lengths high) is at least 0.4 of
// the figure's height and 1.8 cm in every theme and size the theme lays out (paper at
// 300 dpi: swing 0.50, over-the-top 0.42 = 1.89 cm; they were 0.27 and 0.17 of it with the
// clock's line inside the drawing and the band over one cell).
TEST(TeachingFinal, DrawingKeepsItsShareOfThePanel) {
    for (const auto& row : figures::builtin_themes()) {
        for (const char* size : {"", "1920x1080", "640x360"}) {
            std::vector<std::string> sets;
            if (*size != '\0') sets.push_back(std::string("size_px=") + size);
            const plot::theme th = figures::load_theme(row.name, sets);
            const auto options = animated_options(th);
            for (const auto* e : builtin_animations()) {
                const auto plan = figures::plan_animation(*e, options);
                const auto frame = figures::planned_frame(*e, options, plan, figures::build(*e, options), 0);
                std::vector<drawing_room> drawn;
                try {
                    drawn = drawings_of(plot::with_theme_styles(frame, th), th);
                } catch (const plot::bad_input& refused) {  // paper at 640x360: too small for its text
                    std::cout << e->id << " in " << row.name << " " << size << ": refused: " << refused.what() << '\n';
                    continue;
                }
                // swing and over-the-top have a drawing; separatrix none.
                EXPECT_EQ(drawn.empty(), e->id == "separatrix") << e->id;
                for (const auto& d : drawn) {
                    std::cout << e->id << " in " << row.name << " " << size << ": drawing " << d.drawing << " pt of "
                              << d.figure << " pt (" << d.drawing / d.figure << ")\n";
                    EXPECT_GE(d.drawing / d.figure, 0.4) << e->id << " in " << row.name << " " << size;
                    EXPECT_GE(d.drawing, 1.8 / 2.54 * 72) << e->id << " in " << row.name << " " << size;
                }
            }
        }
    }
}

// A drawing of one start names it in its title, as a trajectory panel does, so that drawings
// side by side (plot --apart) say which is which; a drawing of several starts names them in
// its legend and keeps its letter alone; a title the spec gives wins.
TEST(TeachingFinal, ADrawingOfOneStartNamesIt) {
    const auto spec = figures::parse_spec("[[panel]]\nplot = \"pendulum\"\ntheta0 = \"10deg\"\nmethods = [\"exact\"]\n"
                                          "[[panel]]\nplot = \"pendulum\"\ntheta0 = \"170deg\"\nmethods = [\"exact\"]\n"
                                          "[[panel]]\nplot = \"pendulum\"\ntheta0 = [\"10deg\", \"170deg\"]\n"
                                          "methods = [\"exact\"]\n"
                                          "[[panel]]\nplot = \"pendulum\"\ntheta0 = \"20deg\"\nmethods = [\"exact\"]\n"
                                          "title = \"mine\"\n",
                                          "apart.toml");
    const plot::figure fig = figures::build_figure(spec, {});
    ASSERT_EQ(fig.panels.size(), 4u);
    EXPECT_EQ(fig.panels[0].label.markup, "(a) <i>\u03d1</i><sub>0</sub> = 10\u00b0");
    EXPECT_EQ(fig.panels[1].label.markup, "(b) <i>\u03d1</i><sub>0</sub> = 170\u00b0");
    EXPECT_EQ(fig.panels[2].label.markup, "(c)");
    EXPECT_EQ(fig.panels[3].label.markup, "mine");
}
