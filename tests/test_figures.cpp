// SPDX-License-Identifier: GPL-3.0-or-later
// Tests of the figure catalog and of the render, list and data commands: the figures hold
// the right data, match the committed baseline images, and bad input touches no file.
#include "figures/batch.hpp"
#include "figures/catalog.hpp"
#include "figures/spec_build.hpp"
#include "pendulum/approximants.hpp"
#include "pendulum/exact.hpp"
#include "plot/output.hpp"
#include "figures/themes.hpp"
#include "plot/theme.hpp"
#include "png_image.hpp"
#include "process.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <filesystem>
#include <numbers>
#include <set>

using std::numbers::pi;
namespace fs = std::filesystem;
using test_support::files_in;
using test_support::run_cli;
using test_support::temp_dir;

namespace {

/// The built-in themes, from their style files.
plot::theme paper_theme() { return figures::load_theme("paper"); }
plot::theme slides_theme() { return figures::load_theme("slides"); }


}  // namespace

TEST(Catalog, EveryFigureOfThePaperAndItsAliases) {
    const auto& c = figures::catalog();
    ASSERT_EQ(c.size(), 16u);
    const char* ids[] = {"c1-lowest",         "trajectory-lowest", "coefficients-first", "trajectory-first",
                         "coefficients-second", "trajectory-second", "period",            "convergence",
                         "period-formulas",   "period-error",      "phase-portrait",     "spectrum",
                         "regimes",           "swing",             "separatrix",         "over-the-top"};
    for (std::size_t i = 0; i < c.size(); ++i) {
        EXPECT_EQ(c[i].id, ids[i]);
        if (i < 7) {
            EXPECT_EQ(&figures::find("fig" + std::to_string(i + 1)), &c[i]);
        }
    }
    EXPECT_THROW(figures::find("fig8"), std::invalid_argument);
    for (const auto& e : c) {
        const auto f = figures::build(e);
        EXPECT_EQ(f.panels.size(), e.spec.panels.size()) << e.id;
        EXPECT_LE(f.panels.size(), static_cast<std::size_t>(f.rows * f.cols));
        for (const auto& p : f.panels) {
            // Every plot has its axes labelled; a drawing of the pendulum has no axes.
            EXPECT_EQ(p.x.label.empty(), p.frameless) << e.id;
            EXPECT_EQ(p.y.label.empty(), p.frameless) << e.id;
            EXPECT_FALSE(p.data.empty());
        }
    }
}

TEST(Catalog, PanelsHaveThePapersSizes) {
    EXPECT_EQ(figures::build(figures::find("fig1")).panel_width_cm, 6.0);
    EXPECT_EQ(figures::build(figures::find("fig5")).panel_width_cm, 4.3);
    EXPECT_EQ(figures::build(figures::find("fig6")).panel_width_cm, 4.2);
    EXPECT_EQ(figures::find("fig2").spec.panels.back().paper_file, "Fig.Comparison.LowestD");
    EXPECT_EQ(figures::find("fig6").spec.panels.front().paper_file, "Fig.Lamb.4a");
}

TEST(Catalog, DataComeFromTheCore) {
    // Fig. 1: exact c1 by the paper's quadrature, lowest order c1 = theta0.
    const auto f1 = figures::build(figures::find("c1-lowest"));
    const auto& exact = f1.panels[0].data[0];
    ASSERT_FALSE(exact.x.empty());
    for (std::size_t i = 0; i < exact.x.size(); ++i) {
        EXPECT_NEAR(exact.y[i], pendulum::exact_solution(exact.x[i]).coefficient(0), 1e-12);
    }
    const auto& lowest = f1.panels[0].data[1];
    for (std::size_t i = 0; i < lowest.x.size(); ++i) EXPECT_EQ(lowest.y[i], lowest.x[i]);

    // Fig. 7(b): relative error in percent, -0.273 % for lowest order at pi/2.
    const auto f7 = figures::build(figures::find("period"));
    const auto& err = f7.panels[1].data[0];
    EXPECT_EQ(err.label.markup, "lowest order");
    double at_half_pi = 0;
    double closest = 10;
    for (std::size_t i = 0; i < err.x.size(); ++i) {
        if (std::fabs(err.x[i] - pi / 2) < closest) {
            closest = std::fabs(err.x[i] - pi / 2);
            at_half_pi = err.y[i];
        }
    }
    EXPECT_NEAR(at_half_pi, -0.273, 0.01);

    // Trajectories: the exact motion at t/T, and theta(0) = theta0 for every curve.
    const auto f2 = figures::build(figures::find("fig2"));
    ASSERT_EQ(f2.panels.size(), 4u);
    EXPECT_EQ(f2.rows, 2);
    EXPECT_EQ(f2.cols, 2);
    for (const auto& s : f2.panels[3].data) EXPECT_NEAR(s.y.front(), 9 * pi / 10, 1e-14);
    EXPECT_NE(f2.panels[3].label.markup.find("9<i>\u03c0</i>/10"), std::string::npos);
    // Amplitudes as the paper writes them.
    EXPECT_NE(figures::build(figures::find("fig6")).panels[1].label.markup.find("95<i>\u03c0</i>/100"), std::string::npos);
}

TEST(Catalog, AmplitudesCanBeReplaced) {
    figures::build_options o;
    o.amplitudes = {{"170deg", 170 * pi / 180}};
    const auto f = figures::build(figures::find("trajectory-first"), o);
    ASSERT_EQ(f.panels.size(), 1u);
    EXPECT_EQ(f.rows, 1);
    EXPECT_EQ(f.cols, 1);
    // As typed, and no "(a)" on a figure of one panel.
    EXPECT_EQ(f.panels[0].label.markup, "<i>\u03d1</i><sub>0</sub> = 170\u00b0");
    o.amplitudes = {{"0.5", 0.5}, {"1", 1}, {"1.5", 1.5}, {"2", 2}, {"2.5", 2.5}};
    const auto g = figures::build(figures::find("trajectory-second"), o);
    EXPECT_EQ(g.rows, 2);
    EXPECT_EQ(g.cols, 3);
}

TEST(Catalog, AmplitudeLabels) {
    EXPECT_EQ(figures::typeset_angle("pi/2"), "<i>\u03c0</i>/2");
    EXPECT_EQ(figures::typeset_angle("95pi/100"), "95<i>\u03c0</i>/100");
    EXPECT_EQ(figures::typeset_angle("0.999pi"), "0.999<i>\u03c0</i>");
    EXPECT_EQ(figures::typeset_angle("170deg"), "170\u00b0");
    EXPECT_EQ(figures::typeset_angle("pi-1e-6"), "<i>\u03c0</i> \u2212 10<sup>\u22126</sup>");
    EXPECT_EQ(figures::typeset_angle("pi - 2.5e-6"), "<i>\u03c0</i> \u2212 2.5\u00d710<sup>\u22126</sup>");
    EXPECT_EQ(figures::typeset_angle("9*pi/10"), "9<i>\u03c0</i>/10");
    EXPECT_EQ(figures::typeset_angle("-1.5"), "\u22121.5");
    EXPECT_EQ(figures::typeset_angle("1.2"), "1.2");
}

namespace {

/// RMS tolerance of the baseline comparison, in RGB values 0..255 (matplotlib's
/// compare_images); renders on one machine are identical, other library versions may
/// anti-alias edges a little differently.
constexpr double baseline_tolerance = 0.3;

/// Compares a render of the figure with the committed baseline in RGB; a render that
/// differs is written beside the build as NAME-failed.png with NAME-failed-diff.png.
test_support::comparison against_baseline(const plot::figure& f, const plot::theme& theme, double dpi,
                                          const std::string& id, const std::string& name) {
    const auto path = fs::path(PENDULUM_BASELINES) / theme.name / (id + ".png");
    const auto want = test_support::decode_rgb(test_support::slurp(path));
    const std::string png = plot::render(f, theme, "png", {dpi});
    const auto got = test_support::decode_rgb(png);
    const auto out = fs::current_path() / "baseline-failures";
    fs::create_directories(out);
    const auto c = test_support::compare_rgb(want, got, baseline_tolerance, (out / (name + "-failed-diff.png")).string());
    if (!c.same_size || c.rms > baseline_tolerance) test_support::write_png((out / (name + "-failed.png")).string(), got);
    return c;
}

}  // namespace

TEST(Baselines, RenderedFiguresMatchTheCommittedImages) {
    const std::pair<plot::theme, double> variants[] = {{paper_theme(), 100}, {slides_theme(), 50}};
    for (const auto& [theme, dpi] : variants) {
        for (const auto& e : figures::catalog()) {
            if (e.spec.animation) continue;  // animations: see test_animation
            const auto path = fs::path(PENDULUM_BASELINES) / theme.name / (e.id + ".png");
            ASSERT_TRUE(fs::exists(path)) << path << " (make update-baselines writes it)";
            figures::build_options o;
            o.panel_width_cm = theme.panel_width_cm;
            o.panel_aspect = theme.panel_aspect;
            const auto c = against_baseline(figures::build(e, o), theme, dpi, e.id, theme.name + "-" + e.id);
            ASSERT_TRUE(c.same_size) << theme.name << " " << e.id;
            EXPECT_LE(c.rms, baseline_tolerance) << theme.name << " " << e.id << ": see build/tests' baseline-failures";
        }
    }
}

TEST(Baselines, ComparisonCatchesSmallMutations) {
    // Each of these once passed a grey comparison with loose thresholds.
    const auto paper = paper_theme();
    const auto slides = slides_theme();
    const auto& e = figures::find("period");
    auto build = [&](const plot::theme& th) {
        figures::build_options o;
        o.panel_width_cm = th.panel_width_cm;
        o.panel_aspect = th.panel_aspect;
        return figures::build(e, o);
    };
    const auto same = against_baseline(build(paper), paper, 100, e.id, "unchanged");
    EXPECT_LE(same.rms, baseline_tolerance);

    auto typo = build(paper);
    for (auto& p : typo.panels) {
        for (auto& s : p.data) {
            if (s.label.markup == "second order") s.label = "second ordre";
        }
    }
    const auto a = against_baseline(typo, paper, 100, e.id, "mutation-legend-typo");
    EXPECT_GT(a.rms, baseline_tolerance) << "legend typo";

    auto dashed = build(paper);
    bool changed = false;
    for (auto& p : dashed.panels) {
        for (auto& s : p.data) {
            if (s.line == plot::line_style::dotted) {
                s.line = plot::line_style::dashed;
                changed = true;
            }
        }
    }
    ASSERT_TRUE(changed);
    const auto b = against_baseline(dashed, paper, 100, e.id, "mutation-dotted-dashed");
    EXPECT_GT(b.rms, baseline_tolerance) << "dotted -> dashed";

    auto swapped = slides;
    ASSERT_GE(swapped.palette.size(), 3u);
    std::swap(swapped.palette[1], swapped.palette[2]);
    const auto c = against_baseline(build(slides), swapped, 50, e.id, "mutation-colours-swapped");
    EXPECT_GT(c.rms, baseline_tolerance) << "two slide colours swapped";

    auto recoloured = slides;
    recoloured.palette[3].b = std::min(1.0, recoloured.palette[3].b + 0.15);  // a little bluer green
    const auto d = against_baseline(build(slides), recoloured, 50, e.id, "mutation-colour-changed");
    EXPECT_GT(d.rms, baseline_tolerance) << "one colour changed";
    std::printf("RMS against period.png: unchanged %.3f, legend typo %.3f, dotted->dashed %.3f, colours swapped %.3f, "
                "one colour changed %.3f (tolerance %.1f)\n",
                same.rms, a.rms, b.rms, c.rms, d.rms, baseline_tolerance);
}

TEST(RenderCommand, WritesEveryRequestedFile) {
    const auto dir = temp_dir("render");
    auto r = run_cli("render fig1 period -o '" + dir.string() + "' -f png,pdf,svg,eps --dpi 72");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(files_in(dir), (std::set<std::string>{"c1-lowest.eps", "c1-lowest.pdf", "c1-lowest.png", "c1-lowest.svg",
                                                    "period.eps", "period.pdf", "period.png", "period.svg"}));
    fs::remove_all(dir);
    fs::create_directories(dir);
    r = run_cli("render --all --paper-files -f eps -o '" + dir.string() + "'");
    ASSERT_EQ(r.status, 0) << r.err;
    std::set<std::string> expected;
    for (const auto& e : figures::catalog()) {
        for (const auto& p : e.spec.panels) {
            if (!p.paper_file.empty()) expected.insert(p.paper_file + ".eps");
        }
    }
    EXPECT_EQ(expected.size(), 19u);
    EXPECT_EQ(files_in(dir), expected);
    // Each panel at the width the LaTeX gives it: 4.2 cm for Fig.Lamb.4a.
    const std::string eps = test_support::slurp(dir / "Fig.Lamb.4a.eps");
    EXPECT_NE(eps.find("%%BoundingBox: 0 0 120 "), std::string::npos) << eps.substr(0, 300);
    fs::remove_all(dir);
}

TEST(RenderCommand, TeacherAmplitude) {
    const auto dir = temp_dir("teacher");
    const auto r = run_cli("render fig2 --theta0 170deg --theme slides -f png --dpi 40 -o '" + dir.string() + "'");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(files_in(dir), (std::set<std::string>{"trajectory-lowest.png"}));
    fs::remove_all(dir);
}

TEST(RenderCommand, BadInputTouchesNoFile) {
    const auto dir = temp_dir("bad");
    // A previous good figure that a failed run must leave alone.
    ASSERT_EQ(run_cli("render fig1 -f png --dpi 30 -o '" + dir.string() + "'").status, 0);
    const std::string before = test_support::slurp(dir / "c1-lowest.png");
    const std::string d = " -o '" + dir.string() + "'";
    const std::string cases[] = {
        "render nosuch" + d,
        "render fig1 nosuch" + d,
        "render fig1 -f png,bmp" + d,
        "render fig1 -f ''" + d,
        "render fig1 --theme dark" + d,
        "render fig1 --dpi 0" + d,
        "render fig1 --dpi 5000" + d,
        "render fig1 --dpi abc" + d,
        "render fig1 --theta0 pi" + d,
        "render fig1 --theta0 abc" + d,
        "render fig1 -o '" + (dir / "missing").string() + "'",
        "render fig1 -o '" + (dir / "c1-lowest.png").string() + "'",
        "render" + d,
        "render --all nosuch" + d,
        "render convergence --paper-files" + d,
        "render fig1 period --theta0 1" + d,
        "data nosuch",
        "data fig1 --theta0 1",
        "data fig2 --theta0 0",
    };
    for (const auto& args : cases) {
        const auto r = run_cli(args);
        EXPECT_EQ(r.status, 2) << args;  // bad input: 2, as --help says
        EXPECT_EQ(r.out, "") << args;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << ": " << r.err;
        EXPECT_EQ(r.err.rfind("pendulum-figures: error: ", 0), 0u) << r.err;
    }
    EXPECT_EQ(files_in(dir), (std::set<std::string>{"c1-lowest.png"}));
    EXPECT_EQ(test_support::slurp(dir / "c1-lowest.png"), before);
    const auto missing = run_cli("render fig1 -o '" + (dir / "missing").string() + "'");
    EXPECT_NE(missing.err.find((dir / "missing").string()), std::string::npos);
    fs::remove_all(dir);
}

TEST(ListAndData, ListEveryFigure) {
    const auto r = run_cli("list");
    ASSERT_EQ(r.status, 0);
    for (const auto& e : figures::catalog()) EXPECT_NE(r.out.find(e.id), std::string::npos);
    EXPECT_NE(r.out.find("Fig. 7"), std::string::npos);
}

TEST(ListAndData, DataIsCsvOfEverySeries) {
    const auto r = run_cli("data fig6");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.out.rfind("panel,series,x,y,id\n", 0), 0u);
    EXPECT_NE(r.out.find("\na,exact,0,2.827433388230814,exact\n"), std::string::npos);
    EXPECT_NE(r.out.find("\nc,second order,"), std::string::npos);
    const auto dir = temp_dir("data");
    const auto w = run_cli("data period -o '" + (dir / "p.csv").string() + "'");
    ASSERT_EQ(w.status, 0) << w.err;
    EXPECT_EQ(w.out, "");
    EXPECT_EQ(test_support::slurp(dir / "p.csv").rfind("panel,series,x,y,id\n", 0), 0u);
    fs::remove_all(dir);
}

TEST(RenderCommand, SameBytesAloneOrInABatch) {
    // Nothing in a file depends on what else the process drew, or on which core drew it.
    const auto all = temp_dir("batch-all");
    const auto one = temp_dir("batch-one");
    ASSERT_EQ(run_cli("render --all -f png,pdf,svg,eps --dpi 60 -o '" + all.string() + "'").status, 0);
    for (const char* id : {"period", "convergence"}) {
        ASSERT_EQ(run_cli(std::string("render ") + id + " -f png,pdf,svg,eps --dpi 60 -o '" + one.string() + "'").status, 0);
    }
    std::size_t compared = 0;
    for (const auto& name : files_in(one)) {
        EXPECT_EQ(test_support::slurp(one / name), test_support::slurp(all / name)) << name;
        ++compared;
    }
    EXPECT_EQ(compared, 8u);
    fs::remove_all(all);
    fs::remove_all(one);
}

TEST(ListAndData, CsvQuotesAndPlainText) {
    plot::figure f;
    plot::panel p;
    p.data.push_back(plot::series{.label = "<i>a</i>, &amp; \"b\"", .x = {1, 2}, .y = {0.5, 0.25}});
    p.data.push_back(plot::series{.label = "c", .x = {3}, .y = {std::nan("")}});
    f.panels = {p, p};
    EXPECT_EQ(figures::figure_csv(f),
              "panel,series,x,y,id\n"
              "a,\"a, & \"\"b\"\"\",1,0.5,series:1\na,\"a, & \"\"b\"\"\",2,0.25,series:1\na,c,3,nan,series:2\n"
              "b,\"a, & \"\"b\"\"\",1,0.5,series:1\nb,\"a, & \"\"b\"\"\",2,0.25,series:1\nb,c,3,nan,series:2\n");
}

TEST(ListAndData, FilesForPaperNames) {
    const std::vector<const figures::entry*> chosen = {&figures::find("fig7"), &figures::find("convergence")};
    // Only some panels with paper files (more amplitudes than paper panels) is an error, before any work.
    figures::build_options five;
    for (int i = 1; i <= 5; ++i) five.amplitudes.push_back({std::to_string(i * 0.5), i * 0.5});
    EXPECT_THROW(figures::files_for({&figures::find("fig2")}, {"pdf"}, "out", true, five), std::invalid_argument);
    const auto files = figures::files_for(chosen, {"eps", "pdf"}, "out", true);
    ASSERT_EQ(files.size(), 4u);
    EXPECT_EQ(files[0].path, fs::path("out/Fig.Comparison.PeriodA.eps"));
    EXPECT_EQ(files[3].path, fs::path("out/Fig.Comparison.PeriodB.pdf"));
    EXPECT_EQ(files[3].panel, 1);
    const auto whole = figures::files_for(chosen, {"png"}, "out", false);
    ASSERT_EQ(whole.size(), 2u);
    EXPECT_EQ(whole[1].path, fs::path("out/convergence.png"));
    EXPECT_EQ(whole[1].panel, -1);
}

TEST(PaperFiles, PanelsOfOneFigureShareOneFrameBox) {
    // The paper sets the panel files of a figure side by side: their frames must line up.
    const auto dir = temp_dir("frames");
    const auto r = run_cli("render --all --paper-files -f png --dpi 300 -o '" + dir.string() + "'");
    ASSERT_EQ(r.status, 0) << r.err;
    std::vector<const figures::entry*> all;
    for (const auto& e : figures::catalog()) {
        if (!e.spec.animation) all.push_back(&e);
    }
    const double mm_per_px = 25.4 / 300;
    std::map<const figures::entry*, std::vector<std::pair<std::string, test_support::frame_box>>> boxes;
    for (const auto& f : figures::files_for(all, {"png"}, dir, true)) {
        const auto im = test_support::decode(test_support::slurp(f.path));
        ASSERT_GT(im.width, 0u) << f.path;
        boxes[f.figure].emplace_back(f.path.filename().string(), test_support::find_frame(im));
    }
    EXPECT_EQ(boxes.size(), 7u);
    for (const auto& [e, list] : boxes) {
        int spread[4] = {0, 0, 0, 0};
        for (const auto& [name, b] : list) {
            const auto& a = list.front().second;
            EXPECT_GT(b.right - b.left, 200) << name;
            spread[0] = std::max(spread[0], std::abs(b.left - a.left));
            spread[1] = std::max(spread[1], std::abs(b.top - a.top));
            spread[2] = std::max(spread[2], std::abs(b.right - a.right));
            spread[3] = std::max(spread[3], std::abs(b.bottom - a.bottom));
        }
        const int worst = *std::max_element(spread, spread + 4);
        std::printf("%-20s frame spread left %d top %d right %d bottom %d px: %.2f mm\n", e->id.c_str(), spread[0],
                    spread[1], spread[2], spread[3], worst * mm_per_px);
        EXPECT_LE(worst * mm_per_px, 0.3) << e->id;
    }
    fs::remove_all(dir);
}
