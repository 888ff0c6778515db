// SPDX-License-Identifier: GPL-3.0-or-later
// Journal rules, the rest: what the pdf_tex route shows against the PDF at every document
// size and theme, tick marks that stop short of markers, one notation for pi per figure.
#include "figures/catalog.hpp"
#include "figures/spec.hpp"
#include "figures/themes.hpp"
#include "plot/preflight.hpp"
#include "plot/render.hpp"
#include "plot/strokes.hpp"
#include "overlay_texts.hpp"
#include "process.hpp"
#include "still_sweep.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

using namespace test_support;
namespace fs = std::filesystem;

namespace {

/// The warning lines of stderr that name a file.
std::vector<std::string> warnings_of(const std::string& err, const std::string& file) {
    std::vector<std::string> out;
    std::istringstream in(err);
    for (std::string line; std::getline(in, line);) {
        if (line.starts_with("pendulum-figures: warning: " + file + ": ")) out.push_back(line);
    }
    return out;
}

}  // namespace

// The reproduction: the whole Fig. 7 at --tex-font-size 12 lost (b)'s y tick labels
// (-20 ... 0): (a)'s legend band moved the row down after (b)'s legend had been placed
// inside its axes, and at drawing (b)'s legend fell back to a band of its own that left its
// axes no height. Now (b)'s legend is decided in the cell where it ends.
TEST(JournalRoutes, WholeFig7At12KeepsItsTickLabels) {
    const fs::path dir = temp_dir("journal-fig7");
    for (const char* route : {"pdf", "tex12"}) {
        fs::create_directories(dir / route);
        const std::string options = std::string(route) == "pdf" ? "--tex-sizes absolute" : "--tex-font-size 12";
        const run_result r = run_cli("render fig7 -f pdf_tex " + options + " -o '" + (dir / route).string() + "'");
        ASSERT_EQ(r.status, 0) << r.err;
        EXPECT_EQ(r.err, "") << route;
    }
    const auto pdf = overlay_texts(dir / "pdf" / "period.pdf_tex");
    const auto tex12 = overlay_texts(dir / "tex12" / "period.pdf_tex");
    EXPECT_EQ(text_difference(pdf, tex12), "");
    for (const char* label : {"$-20$}}}%", "$-10$}}}%", "$0$}}}%", "second order}}}%"}) {
        EXPECT_GE(tex12.count(label), 1u) << label;
    }
    fs::remove_all(dir);
}

// Every built-in, every theme, every document size from 8 to 12 pt: the pdf_tex overlay
// shows the texts of the PDF route (the same tick labels and legends), or stderr names the
// file and says what changed. Nothing differs silently; every run exits 0.
TEST(JournalRoutes, EveryThemeAndDocumentSizeAgreesOrSaysSo) {
    const fs::path dir = temp_dir("journal-sweep");
    int compared = 0;
    int said = 0;
    int refused = 0;
    int too_small = 0;
    for (const auto& b : figures::builtin_themes()) {
        const std::string theme = std::string(b.name);
        const fs::path pdf_dir = dir / theme / "pdf";
        fs::create_directories(pdf_dir);
        const run_result pdf = run_cli("render --all -f pdf_tex --tex-sizes absolute --theme " + theme + " -o '" +
                                       pdf_dir.string() + "'");
        ASSERT_EQ(pdf.status, 0) << theme << ": " << pdf.err;
        for (const int pt : {8, 9, 10, 11, 12}) {
            const fs::path out = dir / theme / std::to_string(pt);
            fs::create_directories(out);
            const run_result r = run_cli("render --all -f pdf_tex --tex-font-size " + std::to_string(pt) +
                                         " --theme " + theme + " -o '" + out.string() + "'");
            // A document whose text the theme refuses (below its min_text_pt or
            // min_script_pt: the paper theme in an 8 or 9 pt document) is refused whole.
            if (r.status == 2 && r.err.find("below the theme's min_") != std::string::npos) {
                ++refused;
                EXPECT_TRUE(files_in(out).empty()) << theme << " " << pt;
                continue;
            }
            // A figure whose axes the document's text leaves too small is refused by name,
            // with what to change, and nothing of it is written (the four panels of regimes,
            // a slide, in a 12-pt document: 17.28-pt text).
            if (r.status == 2) {
                ++too_small;
                EXPECT_NE(r.err.find("regimes.pdf_tex: a figure of"), std::string::npos) << theme << " " << pt << ": " << r.err;
                EXPECT_NE(r.err.find("make the figure larger"), std::string::npos) << r.err;
                EXPECT_FALSE(fs::exists(out / "regimes.pdf_tex") || fs::exists(out / "regimes.pdf")) << theme << " " << pt;
            } else {
                ASSERT_EQ(r.status, 0) << theme << " " << pt << ": " << r.err;
            }
            for (const auto& file : files_in(pdf_dir)) {
                if (!file.ends_with(".pdf_tex") || !fs::exists(out / file)) continue;
                ++compared;
                const std::string difference =
                    text_difference(overlay_texts(pdf_dir / file), overlay_texts(out / file));
                if (difference.empty()) continue;
                ++said;
                EXPECT_FALSE(warnings_of(r.err, file).empty())
                    << theme << " at " << pt << " pt, " << file << " differs silently:" << difference;
            }
        }
    }
    EXPECT_GE(compared, 3 * 3 * 13);
    EXPECT_LE(refused, 2) << "only the paper theme's 8 and 9 pt documents";
    EXPECT_LE(too_small, 2) << "only regimes on a slide in a 12-pt document";
    std::cout << compared << " overlays compared, " << said << " differ and say so, " << refused
              << " sizes refused\n";
    fs::remove_all(dir);
}

// The paper theme decides at the sizes of a 12 pt document (tex_agree_pt = 12): at 10 to 12
// pt (below, its text is refused) its overlays have nothing to say about ticks.
TEST(JournalRoutes, PaperAgreesAt8To12WithoutTickNotes) {
    const fs::path dir = temp_dir("journal-paper");
    for (const int pt : {10, 11, 12}) {
        fs::create_directories(dir / std::to_string(pt));
        const run_result r = run_cli("render --all -f pdf_tex --tex-font-size " + std::to_string(pt) + " -o '" +
                                     (dir / std::to_string(pt)).string() + "'");
        ASSERT_EQ(r.status, 0) << r.err;
        EXPECT_EQ(r.err.find("tick labels"), std::string::npos) << pt << ": " << r.err;
    }
    fs::remove_all(dir);
}

// A note names the changed axis, both label lists and what to do: slides' text at 12 pt
// (tex_agree_pt = 0 decides at the overlay's own sizes).
TEST(JournalRoutes, ATickNoteNamesBothLists) {
    const fs::path dir = temp_dir("journal-note");
    const run_result r = run_cli("render --all -f pdf_tex --theme slides --tex-font-size 12 -o '" + dir.string() + "'");
    // regimes' four panels are too small for 17.28-pt text on a slide, and say so.
    ASSERT_EQ(r.status, 2) << r.err;
    EXPECT_NE(r.err.find("regimes.pdf_tex: a figure of"), std::string::npos) << r.err;
    std::istringstream in(r.err);
    for (std::string line; std::getline(in, line);) {
        if (line.find("tick labels") == std::string::npos) continue;
        EXPECT_NE(line.find(", not "), std::string::npos) << line;
        EXPECT_NE(line.find("as the PDF shows"), std::string::npos) << line;
        EXPECT_NE(line.find("tex_agree_pt"), std::string::npos) << line;
    }
    fs::remove_all(dir);
}

// ---- Tick marks and markers ----

// tick_length_clear at its boundaries: a disc whose ink is exactly `gap` beyond the tick's
// full length leaves it whole; nearer, the tick stops `gap` short of it; a tick that
// starts within a disc is not drawn; a disc behind or beside the tick changes nothing.
TEST(JournalTicks, TickLengthClearBoundaries) {
    const double gap = 0.75;
    // Along +y from (0, 0), length 3; a disc of radius 2 on the axis at y = 3 + 0.75 + 2.
    std::vector<plot::keep_out> discs = {{0, 5.75, 2}};
    EXPECT_DOUBLE_EQ(plot::tick_length_clear(0, 0, 0, 1, 3, discs, gap), 3);
    discs[0].y = 5.74;
    EXPECT_NEAR(plot::tick_length_clear(0, 0, 0, 1, 3, discs, gap), 2.99, 1e-12);
    discs[0].y = 2.75;  // the tick starts on the disc's grown edge
    EXPECT_DOUBLE_EQ(plot::tick_length_clear(0, 0, 0, 1, 3, discs, gap), 0);
    discs[0].y = 2.0;
    EXPECT_DOUBLE_EQ(plot::tick_length_clear(0, 0, 0, 1, 3, discs, gap), 0);
    discs[0] = {0, -4, 2};  // behind
    EXPECT_DOUBLE_EQ(plot::tick_length_clear(0, 0, 0, 1, 3, discs, gap), 3);
    discs[0] = {2.75, 1.5, 2};  // beside, its grown edge touching the tick's line
    EXPECT_NEAR(plot::tick_length_clear(0, 0, 0, 1, 3, discs, gap), 1.5, 1e-6);
    discs[0] = {2.76, 1.5, 2};  // beside, clear
    EXPECT_DOUBLE_EQ(plot::tick_length_clear(0, 0, 0, 1, 3, discs, gap), 3);
}

namespace {

/// The distance from (px, py) to the segment of a tick mark.
double distance_to(const plot::tick_mark& t, double px, double py) {
    const double dx = t.x1 - t.x0;
    const double dy = t.y1 - t.y0;
    const double l2 = dx * dx + dy * dy;
    const double u = l2 > 0 ? std::clamp(((px - t.x0) * dx + (py - t.y0) * dy) / l2, 0.0, 1.0) : 0.0;
    return std::hypot(t.x0 + u * dx - px, t.y0 + u * dy - py);
}

/// The least distance between the ink of any tick mark and of any marker of the figure, in
/// points (negative where they overlap), as draw_figure draws them, and how many tick marks
/// were within a tick's length and a marker's reach of a marker (where the rule acts).
struct tick_marker_gap {
    double least = std::numeric_limits<double>::infinity();
    int near = 0;
    int ticks = 0;
};

tick_marker_gap measure_ticks(const plot::figure& fig, const plot::theme& th) {
    tick_marker_gap out;
    const plot::tick_marks_record record;
    (void)plot::panel_frames(fig, th);
    const auto panels = plot::marker_centres(fig, th);
    const double marker_stroke = std::max(0.75 * th.line_width_pt, th.min_line_pt);
    out.ticks = static_cast<int>(record.marks().size());
    for (const auto& t : record.marks()) {
        bool near = false;
        for (const auto& panel : panels) {
            for (const auto& s : panel) {
                for (const auto& [x, y] : s.centres) {
                    // A circle's ink reaches its radius and half its stroke (the built-ins'
                    // methods' markers are circles; squares reach further, tested alike by
                    // marker_reach in draw_figure).
                    const double ink = s.radius + 0.5 * marker_stroke;
                    const double d = distance_to(t, x, y) - ink - 0.5 * t.width;
                    out.least = std::min(out.least, d);
                    near = near || std::hypot(t.x0 - x, t.y0 - y) < th.tick_length_pt + ink;
                }
            }
        }
        out.near += near;
    }
    return out;
}

}  // namespace

// The reproduction: at 1200 dpi the inside tick mark at t = 0 of Fig. 2 crossed the first
// circle (theta = theta0 at t = 0, kept just off the frame). Every built-in, theme and two
// panel sizes: no tick mark's ink comes within half a point of a marker's ink.
TEST(JournalTicks, NoTickMarkUnderAMarker) {
    int near = 0;
    const sweep_counts counts = for_each_still_builtin({"panel_width_cm=4.2", "panel_width_cm=12"}, [&](const still_case& c) {
        const tick_marker_gap g = measure_ticks(c.figure, c.theme);  // too small for its text: refused
        near += g.near;
        EXPECT_GT(g.ticks, 0) << c.where();
        EXPECT_GE(g.least, 0.5 - 1e-9) << c.where();
    });
    EXPECT_GE(counts.checked, 60);
    EXPECT_GT(near, 0) << "no tick mark met a marker: the rule was not exercised";
}

// Fig. 2 in the paper theme: its first circles sit by the ticks at t = 0, where the rule acts.
TEST(JournalTicks, Fig2FirstCircleClearOfItsTick) {
    const plot::theme th = figures::load_theme("paper");
    const plot::figure fig = figures::build(figures::find("trajectory-lowest"), figures::sized_by({}, th));
    const tick_marker_gap g = measure_ticks(fig, th);
    EXPECT_GT(g.near, 0);
    EXPECT_GE(g.least, 0.5 - 1e-9);
}

// ---- One notation for pi ----

namespace {

/// stderr of rendering a one-panel spectrum spec with these amplitudes to a PNG.
std::string render_amplitudes(const std::string& theta0, int* status) {
    const fs::path dir = temp_dir("journal-notation");
    const fs::path spec = dir / "mixed.toml";
    std::ofstream(spec) << "[[panel]]\nplot = \"spectrum\"\ntheta0 = " << theta0
                        << "\nmethods = [\"exact\"]\nharmonics = 9\n";
    const run_result r = run_cli("render '" + spec.string() + "' -f png -o '" + dir.string() + "'");
    *status = r.status;
    const bool written = fs::exists(dir / "mixed.png");
    fs::remove_all(dir);
    return written ? r.err : "not written: " + r.err;
}

}  // namespace

// The reproduction: a spec that mixes 9pi/10 and 0.95pi in its labels still mixed them,
// silently. Now the figure is drawn (exit 0) and stderr names one angle of each way.
TEST(JournalNotation, MixedAnglesSaySo) {
    int status = -1;
    const std::string err = render_amplitudes("[\"9pi/10\", \"0.95pi\"]", &status);
    EXPECT_EQ(status, 0);
    EXPECT_NE(err.find("pendulum-figures: warning: mixed.png: angles are written two ways in one figure, "
                       "9\u03c0/10 (a fraction of \u03c0) and 0.95\u03c0 (a decimal)"),
              std::string::npos)
        << err;
}

// One way, either way, says nothing: decimals, fractions, and a whole multiple with either.
TEST(JournalNotation, OneWayIsQuiet) {
    for (const char* theta0 : {"[\"0.9pi\", \"0.95pi\"]", "[\"9pi/10\", \"19pi/20\"]", "[\"pi/2\", \"2pi/3\"]",
                               "[\"1.2\", \"pi/3\"]"}) {
        int status = -1;
        const std::string err = render_amplitudes(theta0, &status);
        EXPECT_EQ(status, 0) << theta0;
        EXPECT_EQ(err, "") << theta0;
    }
}

// Every built-in writes its angles one way (the rule holds for what ships).
TEST(JournalNotation, EveryBuiltinWritesPiOneWay) {
    const plot::theme th = figures::load_theme("paper");
    for (const auto& e : figures::catalog()) {
        const plot::figure fig = figures::build(e, figures::sized_by({}, th));
        EXPECT_EQ(plot::angle_notation_problem(fig), "") << e.id;
    }
}
