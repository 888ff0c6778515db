// SPDX-License-Identifier: GPL-3.0-or-later
// Room around the data and the text of a figure: no marker or line end on the frame unless
// a range the user set puts it there, the paper's ranges kept in the paper's files, y labels
// by their own panel's tick labels, legend bands as wide as the axes; and the files: dark
// PNGs as small as light ones, dark vector pages painted.
#include "figures/batch.hpp"
#include "figures/build_options.hpp"
#include "figures/catalog.hpp"
#include "figures/errors.hpp"
#include "figures/spec.hpp"
#include "figures/spec_build.hpp"
#include "figures/themes.hpp"
#include "plot/render.hpp"
#include "png_image.hpp"
#include "process.hpp"
#include "still_sweep.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using test_support::run_cli;
using test_support::slurp;
using test_support::temp_dir;
using test_support::for_each_still_builtin;
using test_support::still_case;

namespace {

double to_unit(double v, bool log) { return log ? std::log10(v) : v; }

/// Distance in points from a value to the low and high edges of an axis mapped over `length`.
struct axis_room {
    double lo;
    double hi;
    bool log;
    double length;
    double from_lo(double v) const { return (to_unit(v, log) - to_unit(lo, log)) / (to_unit(hi, log) - to_unit(lo, log)) * length; }
    double from_hi(double v) const { return length - from_lo(v); }
};

/// How near the frame a point of a series may come, in points: a marker's radius and half
/// its stroke, or a line's half width.
double least_room(const plot::series& s, const plot::theme& th) {
    const double line = s.line == plot::line_style::none ? 0.0 : 0.5 * th.line_width_pt * s.width_scale;
    const double marker =
        s.marker == plot::marker_style::none ? 0.0 : th.marker_radius_pt * s.marker_scale + 0.5 * th.line_width_pt;
    return std::max(line, marker);
}

/// The number of points of the figure's data checked against the frame; failures reported.
int check_data_off_frame(const plot::figure& fig, const plot::theme& th, const std::string& where) {
    const auto frames = plot::panel_frames(fig, th);
    EXPECT_EQ(frames.size(), fig.panels.size()) << where;
    int checked = 0;
    for (std::size_t i = 0; i < fig.panels.size() && i < frames.size(); ++i) {
        const auto& p = fig.panels[i];
        const auto& f = frames[i];
        if (f.frameless) continue;
        const axis_room xr{f.x_lo, f.x_hi, p.x.kind == plot::scale::log, f.w};
        const axis_room yr{f.y_lo, f.y_hi, p.y.kind == plot::scale::log, f.h};
        for (const auto& s : p.data) {
            if (!s.autoscale || !s.sets_limits) continue;
            if (s.line == plot::line_style::none && s.marker == plot::marker_style::none) continue;
            const double d = least_room(s, th);
            const std::string at = where + " panel " + std::to_string(i + 1) + " '" + s.label.markup + "'";
            for (std::size_t k = 0; k < s.x.size() && k < s.y.size(); ++k) {
                const double x = s.x[k];
                const double y = s.y[k];
                if (!std::isfinite(x) || !std::isfinite(y) || (xr.log && !(x > 0)) || (yr.log && !(y > 0))) continue;
                // A range the user set (a spec's y_range) is kept exactly: the data may meet it.
                if (!p.x.exact_range) {
                    EXPECT_GE(xr.from_lo(x), d) << at << " x = " << x;
                    EXPECT_GE(xr.from_hi(x), d) << at << " x = " << x;
                }
                const bool y_inside = !p.y.exact_range;
                if (y_inside) {
                    EXPECT_GE(yr.from_lo(y), d) << at << " y = " << y;
                    EXPECT_GE(yr.from_hi(y), d) << at << " y = " << y;
                }
                ++checked;
            }
        }
    }
    return checked;
}

}  // namespace

// 1. Every built-in still figure, in every theme and at two sizes: no marker centre or line
// end within its radius (half width) of the frame, unless the spec's range puts it there.
// Plot kinds' own domains (amplitudes over [0, pi], t/T over [0, 1], orders [0, 40]) move out.
TEST(FrameRoom, NoMarkerOrLineEndOnTheFrameInEveryThemeAndSize) {
    int checked = 0;
    for_each_still_builtin({"", "panel_width_cm=4.2"}, [&](const still_case& c) {
        checked += check_data_off_frame(c.figure, c.theme, c.where());  // too small for its text: refused
    });
    EXPECT_GT(checked, 5000);
}

// The reproductions: Fig. 7(a)'s circle at T/T0 = 1, the trajectories' circles at t/T = 0
// and 1, the convergence figure's N = 0 marker; each stood on the frame.
TEST(FrameRoom, TheReportedMarkersStandInsideTheFrame) {
    const plot::theme th = figures::load_theme("paper", {});
    for (const char* id : {"period", "trajectory-second", "trajectory-first", "convergence", "regimes"}) {
        const auto fig = figures::build(figures::find(id), figures::sized_by({}, th));
        EXPECT_GT(check_data_off_frame(fig, th, id), 0) << id;
    }
    const auto fig = figures::build(figures::find("period"), figures::sized_by({}, th));
    const auto frames = plot::panel_frames(fig, th);
    // Fig. 7(a) now follows its data (its circle at T/T0 = 1 clear of the bottom), x its domain.
    EXPECT_LT(frames.at(0).y_lo, 1.0);
    EXPECT_LT(frames.at(0).x_lo, 0.0);
    EXPECT_GT(frames.at(0).x_hi, 3.14159);
}

// A range the user set is kept exactly, in every theme; the data beyond it are clipped.
TEST(FrameRoom, ARangeTheUserSetIsKeptExactly) {
    const auto spec = figures::parse_spec(
        "[[panel]]\nplot = \"period\"\nmethods = [\"exact\"]\ny_range = [1, 3]\n", "range.toml");
    for (const auto& builtin : figures::builtin_themes()) {
        const plot::theme th = figures::load_theme(std::string(builtin.name), {});
        const auto fig = figures::build_figure(spec, figures::sized_by({}, th));
        ASSERT_TRUE(fig.panels.at(0).y.exact_range);
        const auto frames = plot::panel_frames(fig, th);
        EXPECT_EQ(frames.at(0).y_lo, 1.0) << builtin.name;
        EXPECT_EQ(frames.at(0).y_hi, 3.0) << builtin.name;
    }
}

// The paper's files keep the paper's ranges (paper_y_range): Fig. 7(a) from 1 to 3, (b)
// from -20 to 2, exactly; the figure outside them follows its data.
TEST(FrameRoom, PaperFilesKeepThePapersRange) {
    const plot::theme th = figures::load_theme("paper", {});
    const auto fig = figures::build(figures::find("period"), figures::sized_by({}, th));
    const std::pair<double, double> want[] = {{1, 3}, {-20, 2}};
    for (int i = 0; i < 2; ++i) {
        const auto one = figures::single_panel(fig, i, fig.panel_width_cm);
        const auto frames = plot::panel_frames(one, th);
        ASSERT_EQ(frames.size(), 1u);
        EXPECT_EQ(frames[0].y_lo, want[i].first) << i;
        EXPECT_EQ(frames[0].y_hi, want[i].second) << i;
    }
    const auto dir = temp_dir("frame-paper");
    const auto r = run_cli("render period --paper-files -f png --dpi 50 -o " + dir.string());
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_TRUE(fs::exists(dir / "Fig.Comparison.PeriodA.png"));
    // The choice of range is said: describe names the paper's range of (b) and the readable figure.
    const auto d = run_cli("list");
    EXPECT_NE(d.out.find("paper's -20 to +2 % range"), std::string::npos) << d.out;
    EXPECT_NE(d.out.find("period-error"), std::string::npos);
    fs::remove_all(dir);
}

// paper_y_range is read as y_range is: two increasing finite numbers; others refused, named.
TEST(FrameRoom, PaperRangeIsCheckedAsTheYRange) {
    const std::string head = "[[panel]]\nplot = \"period\"\nmethods = [\"exact\"]\n";
    EXPECT_NO_THROW(figures::parse_spec(head + "paper_y_range = [1, 3]\n", "ok.toml"));
    // The least span that can be labelled, 1e-9 of the largest magnitude, accepted; below it refused.
    EXPECT_NO_THROW(figures::parse_spec(head + "paper_y_range = [1, 1.000000001]\n", "ok.toml"));
    for (const char* bad : {"[3, 1]", "[1, 1]", "[1]", "[\"a\", 2]", "[1, 1.0000000009]"}) {
        try {
            figures::parse_spec(head + "paper_y_range = " + bad + "\n", "bad.toml");
            ADD_FAILURE() << bad << " accepted";
        } catch (const figures::bad_input& e) {
            EXPECT_NE(std::string(e.what()).find("'paper_y_range'"), std::string::npos) << e.what();
        }
    }
}

// 2. A y label stands by its own panel's tick labels (label_gap from their ink), not by the
// widest panel's, while the frames of a figure's files stay in line: Fig. 7(a)'s narrow
// tick labels ("1.0") beside (b)'s wide ones ("-20").
TEST(FrameRoom, AYLabelStandsByItsOwnPanelsTickLabels) {
    const auto dir = temp_dir("frame-ylabel");
    const auto r = run_cli("render period --paper-files -f png --dpi 600 -o " + dir.string());
    ASSERT_EQ(r.status, 0) << r.err;
    const double px_per_pt = 600.0 / 72.0;
    const plot::theme th = figures::load_theme("paper", {});
    int lefts[2] = {0, 0};
    int i = 0;
    for (const char* name : {"Fig.Comparison.PeriodA.png", "Fig.Comparison.PeriodB.png"}) {
        const auto im = test_support::decode(slurp(dir / name));
        ASSERT_GT(im.width, 0u) << name;
        const auto frame = test_support::find_frame(im);
        lefts[i++] = frame.left;
        // Columns left of the frame, over its height: ink of the tick labels next to the
        // frame, a gap, the y label's ink.
        auto inked = [&](int x) {
            for (int y = frame.top; y <= frame.bottom; ++y) {
                if (im.at(static_cast<unsigned>(x), static_cast<unsigned>(y)) < 128) return true;
            }
            return false;
        };
        // From the page's left edge: blank, the y label (turned, its ink one run of columns),
        // the gap, the tick labels.
        int x = 0;
        while (x < frame.left && !inked(x)) ++x;
        while (x < frame.left && inked(x)) ++x;
        const int label_right = x;
        while (x < frame.left && !inked(x)) ++x;
        ASSERT_LT(x, frame.left) << name;
        const double gap_pt = (x - label_right) / px_per_pt;
        EXPECT_NEAR(gap_pt, 0.8 * th.padding_pt, 0.6) << name;
    }
    EXPECT_NEAR(lefts[0], lefts[1], 1) << "the files' frames stay in line";
    fs::remove_all(dir);
}

// A legend band above the axes starts at the axes' left edge, not the page's: the
// period-error figure's band no longer starts at the figure's edge.
TEST(FrameRoom, ALegendBandIsAsWideAsTheAxes) {
    const auto dir = temp_dir("frame-band");
    int bands = 0;
    for (const char* theme : {"paper", "slides"}) {
        const auto r = run_cli(std::string("render period-error convergence -f png --dpi 300 --theme ") + theme +
                               " -o " + dir.string());
        ASSERT_EQ(r.status, 0) << r.err;
        for (const char* name : {"period-error.png", "convergence.png"}) {
            const auto im = test_support::decode(slurp(dir / name));
            ASSERT_GT(im.width, 0u);
            const auto frame = test_support::find_frame(im);
            // The band: every row above the frame by more than the tick labels' size (the
            // top tick label sits half above it).
            const int above = static_cast<int>(std::ceil(figures::load_theme(theme, {}).tick_font_pt * 300 / 72));
            int first = static_cast<int>(im.width), last = -1;
            for (int y = 0; y < frame.top - above; ++y) {
                for (int x = 0; x < static_cast<int>(im.width); ++x) {
                    if (im.at(static_cast<unsigned>(x), static_cast<unsigned>(y)) < 128) {
                        first = std::min(first, x);
                        last = std::max(last, x);
                    }
                }
            }
            if (last < 0) continue;  // the legend found room inside the axes: no band
            ++bands;
            EXPECT_GE(first, frame.left - 2) << theme << " " << name;
            // On the right, the axes leave half their last tick label: the band may use it.
            EXPECT_LE(last, frame.right + above) << theme << " " << name;
        }
    }
    EXPECT_GE(bands, 2);  // the paper theme's two figures have bands
    fs::remove_all(dir);
}

// 3. A dark theme's PNG compresses like a light one's: slides-dark within 1.5 times the
// slides theme's bytes for every built-in still figure (they were 7 to 9 times: a dark
// background's RGB pixels are no runs of one byte for run-length deflate without a filter).
TEST(FrameRoom, DarkPngsAreAsSmallAsLightOnes) {
    const auto dir = temp_dir("frame-png");
    for (const char* theme : {"slides", "slides-dark"}) {
        fs::create_directories(dir / theme);
        const auto r = run_cli(std::string("render --all -f png --dpi 150 --theme ") + theme + " -o " +
                               (dir / theme).string());
        ASSERT_EQ(r.status, 0) << r.err;
    }
    int compared = 0;
    for (const auto& f : fs::directory_iterator(dir / "slides")) {
        const auto dark = dir / "slides-dark" / f.path().filename();
        ASSERT_TRUE(fs::exists(dark)) << dark;
        const auto light_bytes = fs::file_size(f.path());
        const auto dark_bytes = fs::file_size(dark);
        EXPECT_LE(static_cast<double>(dark_bytes), 1.5 * static_cast<double>(light_bytes))
            << f.path().filename() << ": " << dark_bytes << " bytes dark, " << light_bytes << " light";
        ++compared;
    }
    EXPECT_GT(compared, 10);
    fs::remove_all(dir);
}

// Dark themes paint their vector pages (light text on a transparent page vanishes on a
// white one); paper and slides keep transparent pages; a style file may still choose.
TEST(FrameRoom, DarkVectorPagesArePainted) {
    EXPECT_TRUE(figures::load_theme("slides-dark", {}).opaque_vector_background);
    EXPECT_FALSE(figures::load_theme("paper", {}).opaque_vector_background);
    EXPECT_FALSE(figures::load_theme("slides", {}).opaque_vector_background);
    EXPECT_FALSE(figures::load_theme("slides-dark", {"opaque_vector_background=false"}).opaque_vector_background);
    const auto dir = temp_dir("frame-vector");
    const auto r = run_cli("render period --theme slides-dark -f svg,pdf -o " + dir.string());
    ASSERT_EQ(r.status, 0) << r.err;
    // Cairo writes the background, #1e1e28, as percentages.
    const std::string svg = slurp(dir / "period.svg");
    EXPECT_NE(svg.find("rgb(11.764706%,11.764706%,15.686275%)"), std::string::npos) << svg.substr(0, 600);
    // The PDF's page, drawn by poppler on white, has the dark background at its corner.
    const auto png = run_cli("render period --theme slides-dark -f pdf -o " + dir.string() +
                             " && pdftoppm -r 20 -png -singlefile " + (dir / "period.pdf").string() + " " +
                             (dir / "page").string());
    ASSERT_EQ(png.status, 0) << png.err;
    const auto page = test_support::decode(slurp(dir / "page.png"));
    ASSERT_GT(page.width, 0u);
    EXPECT_LT(page.at(0, 0), 64);
    fs::remove_all(dir);
}
