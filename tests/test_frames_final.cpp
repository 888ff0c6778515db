// SPDX-License-Identifier: GPL-3.0-or-later
// Where data meets the frame: a range the user set clips markers and lines cleanly at the
// frame in every format, with a note; tick marks stop short of curves as of markers, are
// not drawn as stubs, and close no box in a corner of the frame.
#include "figures/build_options.hpp"
#include "figures/catalog.hpp"
#include "figures/spec.hpp"
#include "figures/spec_build.hpp"
#include "figures/themes.hpp"
#include "plot/geometry.hpp"
#include "plot/render.hpp"
#include "plot/strokes.hpp"
#include "png_image.hpp"
#include "process.hpp"
#include "still_sweep.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using test_support::for_each_still_builtin;
using test_support::run_cli;
using test_support::run_command;
using test_support::still_case;
using test_support::temp_dir;

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

// ---- The tick rules at their boundaries ----

const plot::rect square{0, 0, 100, 100};
const plot::tick_clearance nothing{};

}  // namespace

// A tick mark a tick length from the perpendicular side is drawn; nearer, it would close a
// box in the corner and is not. On each side, at each end.
TEST(FramesTicks, CornerRuleBoundary) {
    const double L = 3.0;
    // Bottom side, pointing up: x is along the side.
    EXPECT_DOUBLE_EQ(plot::tick_mark_length(3.0, 100, 0, -1, L, nothing, 0.75, square, L), L);
    EXPECT_DOUBLE_EQ(plot::tick_mark_length(2.999, 100, 0, -1, L, nothing, 0.75, square, L), 0);
    EXPECT_DOUBLE_EQ(plot::tick_mark_length(97.0, 100, 0, -1, L, nothing, 0.75, square, L), L);
    EXPECT_DOUBLE_EQ(plot::tick_mark_length(97.001, 100, 0, -1, L, nothing, 0.75, square, L), 0);
    // Left side, pointing right: y is along the side.
    EXPECT_DOUBLE_EQ(plot::tick_mark_length(0, 3.0, 1, 0, L, nothing, 0.75, square, L), L);
    EXPECT_DOUBLE_EQ(plot::tick_mark_length(0, 2.999, 1, 0, L, nothing, 0.75, square, L), 0);
    EXPECT_DOUBLE_EQ(plot::tick_mark_length(100, 97.0, -1, 0, L, nothing, 0.75, square, L), L);
    EXPECT_DOUBLE_EQ(plot::tick_mark_length(100, 97.001, -1, 0, L, nothing, 0.75, square, L), 0);
    // On the side itself (a tick at the axis' limit): within a tick length too.
    EXPECT_DOUBLE_EQ(plot::tick_mark_length(0, 100, 0, -1, L, nothing, 0.75, square, L), 0);
}

// A tick mark shortened to half its length is drawn; shorter, it would be a stub, and is
// not. The curve is a horizontal line of half width 0.5 above the bottom side.
TEST(FramesTicks, StubRuleBoundary) {
    const double L = 3.0;
    const double gap = 0.5;  // with r, binary fractions: the boundary is exact
    const double r = 0.5;
    const auto at = [&](double clear) {
        plot::tick_clearance ink;
        const double y = 100 - clear - gap - r;  // the line's centre
        ink.segments.push_back({0, y, 100, y, r});
        return plot::tick_mark_length(50, 100, 0, -1, L, ink, gap, square, L);
    };
    EXPECT_DOUBLE_EQ(at(1.5), 1.5);  // exactly half: drawn
    EXPECT_DOUBLE_EQ(at(1.499), 0);  // below half: not drawn
    EXPECT_NEAR(at(2.0), 2.0, 1e-9);
    EXPECT_DOUBLE_EQ(at(3.5), L);  // clear of the line: whole
    EXPECT_DOUBLE_EQ(plot::min_tick_fraction, 0.5);
}

// tick_length_clear against a line's pieces: across it, beside it, at its round end, and
// a line behind the tick; touching counts, as for markers.
TEST(FramesTicks, ClearOfALinesInk) {
    const double gap = 0.5;
    const auto clear = [&](plot::ink_segment s) {
        plot::tick_clearance ink;
        ink.segments.push_back(s);
        return plot::tick_length_clear(0, 0, 0, 1, 3, ink, gap);
    };
    // Across: a horizontal line at y = 2, half width 0.25, stops the tick at 2 - 0.75.
    EXPECT_NEAR(clear({-5, 2, 5, 2, 0.25}), 1.25, 1e-12);
    // Slanted at 45 degrees through (0, 2): the tick stops where its distance is 0.75.
    EXPECT_NEAR(clear({-5, 7, 5, -3, 0.25}), 2 - 0.75 * std::sqrt(2.0), 1e-12);
    // Beside, parallel: 0.76 away is clear, 0.74 away stops it where the line begins.
    EXPECT_DOUBLE_EQ(clear({0.76, 1, 0.76, 5, 0.25}), 3);
    EXPECT_NEAR(clear({0.74, 1, 0.74, 5, 0.25}), 1.0 - std::sqrt(0.75 * 0.75 - 0.74 * 0.74), 1e-12);
    // The round end of a line ending beside the tick's end.
    EXPECT_NEAR(clear({0.5, 3, 5, 3, 0.25}), 3 - std::sqrt(0.75 * 0.75 - 0.25), 1e-12);
    // Behind the frame, and starting within reach.
    EXPECT_DOUBLE_EQ(clear({-5, -2, 5, -2, 0.25}), 3);
    EXPECT_DOUBLE_EQ(clear({-5, -0.5, 5, -0.5, 0.25}), 0);
    // A degenerate piece (a dot) acts as its round end.
    EXPECT_NEAR(clear({0, 2, 0, 2, 0.25}), 1.25, 1e-12);
}

// Only the pieces that come within the band of the frame are kept, from the outside in; a
// NaN vertex breaks the line.
TEST(FramesTicks, InkNearTheFrameOnly) {
    std::vector<plot::ink_segment> out;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    // Deep inside: band 3.5, half width 0.5: 4 from the frame is outside the band.
    plot::add_ink_near_frame(out, {4.01, 50, 95.99}, {50, 4.01, 50}, 0.5, square, 3.5);
    EXPECT_TRUE(out.empty());
    plot::add_ink_near_frame(out, {4.0, 50}, {50, 50}, 0.5, square, 3.5);
    EXPECT_EQ(out.size(), 1u);
    out.clear();
    plot::add_ink_near_frame(out, {-10, 1, nan, 2, 50}, {50, 50, 50, 1, 1}, 0.5, square, 3.5);
    EXPECT_EQ(out.size(), 2u);  // (-10..1) across the left side, (2..50) along the top; none across the NaN
    out.clear();
    plot::add_ink_near_frame(out, {-200, -104.01}, {50, 50}, 0.5, square, 3.5);  // far outside
    EXPECT_TRUE(out.empty());
}

namespace {

// ---- Tick marks against the drawn lines of every built-in ----

double point_segment(double px, double py, double x0, double y0, double x1, double y1) {
    const double dx = x1 - x0;
    const double dy = y1 - y0;
    const double l2 = dx * dx + dy * dy;
    const double u = l2 > 0 ? std::clamp(((px - x0) * dx + (py - y0) * dy) / l2, 0.0, 1.0) : 0.0;
    return std::hypot(x0 + u * dx - px, y0 + u * dy - py);
}

double cross(double ax, double ay, double bx, double by) { return ax * by - ay * bx; }

/// The distance between two segments (0 where they cross).
double segment_segment(const plot::tick_mark& t, double x0, double y0, double x1, double y1) {
    const double d1 = cross(t.x1 - t.x0, t.y1 - t.y0, x0 - t.x0, y0 - t.y0);
    const double d2 = cross(t.x1 - t.x0, t.y1 - t.y0, x1 - t.x0, y1 - t.y0);
    const double d3 = cross(x1 - x0, y1 - y0, t.x0 - x0, t.y0 - y0);
    const double d4 = cross(x1 - x0, y1 - y0, t.x1 - x0, t.y1 - y0);
    if (d1 * d2 < 0 && d3 * d4 < 0) return 0;
    return std::min({point_segment(t.x0, t.y0, x0, y0, x1, y1), point_segment(t.x1, t.y1, x0, y0, x1, y1),
                     point_segment(x0, y0, t.x0, t.y0, t.x1, t.y1), point_segment(x1, y1, t.x0, t.y0, t.x1, t.y1)});
}

/// A piece of a drawn line in points, and its ink's half width.
struct piece {
    double x0, y0, x1, y1, r;
};

/// What the sweep measured over its cases.
struct tick_survey {
    double least = inf;   // least distance from a tick mark's ink to a line's ink, points
    std::string where;    // the case of the least
    int near = 0;         // tick marks whose full length would have come within 0.5 pt of a line's ink
    int ticks = 0;        // tick marks drawn
    int corner = 0;       // tick marks within a tick length of the perpendicular side
    int stubs = 0;        // tick marks shorter than min_tick_fraction of their length
    std::string first_bad;
};

/// The frame a tick mark starts on.
const plot::panel_frame* frame_of(const plot::tick_mark& t, const std::vector<plot::panel_frame>& frames) {
    for (const auto& f : frames) {
        const bool on_x = std::abs(t.x0 - f.x) < 0.01 || std::abs(t.x0 - f.x - f.w) < 0.01;
        const bool on_y = std::abs(t.y0 - f.y) < 0.01 || std::abs(t.y0 - f.y - f.h) < 0.01;
        if ((on_x && t.y0 > f.y - 0.01 && t.y0 < f.y + f.h + 0.01) ||
            (on_y && t.x0 > f.x - 0.01 && t.x0 < f.x + f.w + 0.01)) {
            return &f;
        }
    }
    return nullptr;
}

/// The drawn lines of a case near its frames, in points, from drawn_data (the samples the
/// raster draws), with their ink's half width.
std::vector<piece> lines_near_frames(const plot::figure& styled, const plot::theme& th,
                                     const std::vector<std::vector<plot::drawn_points>>& data,
                                     const std::vector<plot::panel_frame>& frames) {
    std::vector<piece> out;
    const double band = th.tick_length_pt + 2 * th.line_width_pt + 2;
    for (std::size_t i = 0; i < data.size() && i < frames.size(); ++i) {
        const auto& f = frames[i];
        const plot::panel& p = styled.panels[i];
        const plot::axis_map mx{f.x_lo, f.x_hi, p.x.kind == plot::scale::log, f.x, f.x + f.w};
        const plot::axis_map my{f.y_lo, f.y_hi, p.y.kind == plot::scale::log, f.y + f.h, f.y};
        for (std::size_t k = 0; k < data[i].size() && k < p.data.size(); ++k) {
            const plot::series& s = p.data[k];
            if (s.line == plot::line_style::none || s.overlay) continue;
            const double r = 0.5 * plot::line_width(th, th.line_width_pt * s.width_scale);
            const auto& d = data[i][k];
            for (std::size_t j = 1; j < d.x.size(); ++j) {
                const double x0 = mx(d.x[j - 1]), y0 = my(d.y[j - 1]), x1 = mx(d.x[j]), y1 = my(d.y[j]);
                if (std::isnan(x0 + y0 + x1 + y1)) continue;
                const bool inside = std::min(x0, x1) > f.x + band && std::max(x0, x1) < f.x + f.w - band &&
                                    std::min(y0, y1) > f.y + band && std::max(y0, y1) < f.y + f.h - band;
                if (!inside) out.push_back({x0, y0, x1, y1, r});
            }
        }
    }
    return out;
}

/// Measures one case: every tick mark against the lines, the corners and the stub rule.
void survey(const still_case& c, tick_survey& out) {
    const plot::tick_marks_record record;
    std::vector<plot::panel_frame> frames;
    const auto data = plot::drawn_data(c.figure, c.theme, 300, frames);
    const plot::figure styled = plot::with_theme_styles(c.figure, c.theme);
    const auto lines = lines_near_frames(styled, c.theme, data, frames);
    const auto bad = [&](const std::string& what) {
        if (out.first_bad.empty()) out.first_bad = c.where() + ": " + what;
    };
    for (const auto& t : record.marks()) {
        ++out.ticks;
        const double length = std::hypot(t.x1 - t.x0, t.y1 - t.y0);
        if (length < plot::min_tick_fraction * t.full - 1e-9) {
            ++out.stubs;
            bad("a stub of " + std::to_string(length) + " pt");
        }
        if (const plot::panel_frame* f = frame_of(t, frames)) {
            const bool across_x = std::abs(t.x1 - t.x0) < std::abs(t.y1 - t.y0);
            const double along = across_x ? t.x0 : t.y0;
            const double lo = across_x ? f->x : f->y;
            const double hi = across_x ? f->x + f->w : f->y + f->h;
            // A tick length and the ticks' clearance (half their width and half a point).
            const double corner = c.theme.tick_length_pt + 0.5 * plot::line_width(c.theme, c.theme.frame_width_pt) + 0.5;
            if (std::min(along - lo, hi - along) < corner - 1e-9) {
                ++out.corner;
                bad("a tick mark " + std::to_string(std::min(along - lo, hi - along)) + " pt from a corner");
            }
        } else {
            bad("a tick mark on no frame");
        }
        // The tick mark at its full length, for `near`.
        plot::tick_mark whole = t;
        if (length > 0) {
            whole.x1 = t.x0 + (t.x1 - t.x0) / length * t.full;
            whole.y1 = t.y0 + (t.y1 - t.y0) / length * t.full;
        }
        bool near = false;
        for (const auto& l : lines) {
            const double d = segment_segment(t, l.x0, l.y0, l.x1, l.y1) - l.r - 0.5 * t.width;
            if (d < out.least) {
                out.least = d;
                out.where = c.where();
            }
            near = near || segment_segment(whole, l.x0, l.y0, l.x1, l.y1) - l.r - 0.5 * t.width < 0.5;
        }
        out.near += near;
    }
}

}  // namespace

// Every built-in still figure x theme x three panel sizes: no tick mark's ink within half
// a point of a drawn line's ink (the reproductions: Fig. 5(c)'s 0.2 tick, Fig. 7(a)'s 3.5
// tick, Fig. 7(b)'s -15 tick in slides, regimes (a)'s zero tick at the cusp), no tick mark
// within a tick length and half a point of the perpendicular side's tick marks (Fig. 6's
// corner boxes), none a stub.
TEST(FramesTicks, NoTickMarkOverALineNorInACornerNorAStub) {
    tick_survey s;
    const auto counts =
        for_each_still_builtin({"", "panel_width_cm=4.2", "panel_width_cm=12"}, [&](const still_case& c) { survey(c, s); });
    EXPECT_GT(counts.checked, 80);
    EXPECT_GT(s.ticks, 10000);
    EXPECT_GT(s.near, 50) << "the rule acts where tick marks met lines";
    EXPECT_GE(s.least, 0.5 - 1e-6) << s.where;
    EXPECT_EQ(s.corner, 0) << s.first_bad;
    EXPECT_EQ(s.stubs, 0) << s.first_bad;
    std::printf("tick marks %d, %d near a line; least tick-to-line ink %.4f pt (%s)\n", s.ticks, s.near, s.least,
                s.where.c_str());
}

// The reported figures one by one, in the themes the review saw them in: the rule acted
// (some tick mark met a line) and leaves half a point.
TEST(FramesTicks, TheReportedTickMarksStopShortOfTheCurves) {
    const struct {
        const char* id;
        const char* theme;
    } reported[] = {{"coefficients-second", "paper"}, {"period", "paper"}, {"period", "slides"}, {"regimes", "paper"}};
    for (const auto& r : reported) {
        const plot::theme th = figures::load_theme(r.theme, {});
        const auto& e = figures::find(r.id);
        const plot::figure fig = figures::build(e, figures::sized_by({}, th));
        tick_survey s;
        survey(still_case{e, r.theme, "", th, fig}, s);
        EXPECT_GT(s.near, 0) << r.id << " " << r.theme;
        EXPECT_GE(s.least, 0.5 - 1e-6) << r.id << " " << r.theme;
        EXPECT_EQ(s.corner + s.stubs, 0) << s.first_bad;
    }
}

namespace {

// ---- A range the user set: clipped cleanly, with a note ----

const char* const set_range_spec = "[[panel]]\nplot = \"period\"\nmethods = [\"exact\"]\ny_range = [1, 3]\n";

/// Rasterises a file of the given format to grey pixels at 300 dpi (as the program's own
/// PNG, or with poppler, librsvg or ghostscript); empty where the tool is missing.
test_support::grey_image rasterise(const fs::path& file, const std::string& format) {
    const fs::path png = file.string() + ".r.png";
    std::string cmd;
    if (format == "png") return test_support::decode(test_support::slurp(file));
    if (format == "pdf") cmd = "pdftoppm -r 300 -gray -png -singlefile '" + file.string() + "' '" + file.string() + ".r'";
    if (format == "svg") cmd = "rsvg-convert -d 300 -p 300 -b white -o '" + png.string() + "' '" + file.string() + "'";
    if (format == "eps") {
        cmd = "gs -q -dSAFER -dBATCH -dNOPAUSE -dEPSCrop -sDEVICE=pnggray -r300 -sOutputFile='" + png.string() + "' '" +
              file.string() + "'";
    }
    if (run_command(cmd).status != 0) return {};
    return test_support::decode(test_support::slurp(png));
}

/// Dark pixels in the strip just below the bottom frame, between its outer edge and the
/// tick labels, over the axes' width short of the corners: a marker's lower half hanging
/// out of the axes shows there.
int ink_below_frame(const test_support::grey_image& im) {
    const test_support::frame_box b = test_support::find_frame(im);
    int dark = 0;
    // At 300 dpi a point is 4.17 px: rows 0.5 to 1.5 pt below the frame's outer edge.
    for (int y = b.bottom + 2; y <= b.bottom + 6 && y < static_cast<int>(im.height); ++y) {
        for (int x = b.left + 25; x < b.right - 25; ++x) dark += im.at(static_cast<unsigned>(x), static_cast<unsigned>(y)) < 160;
    }
    return dark;
}

}  // namespace

// The reproduction: y_range = [1, 3] puts the exact circles at T/T0 = 1 on the bottom frame;
// their lower halves hung outside the axes. In every format they are cut at the frame, and
// stderr says how many and what to do (exit 0, the range kept).
TEST(FramesClip, ARangeSetClipsMarkersAtTheFrameInEveryFormat) {
    const auto dir = temp_dir("frames-clip");
    std::ofstream(dir / "set.toml") << set_range_spec;
    for (const std::string format : {"png", "pdf", "svg", "eps"}) {
        const auto r = run_cli("render set.toml --theme paper --dpi 300 -f " + format, dir);
        ASSERT_EQ(r.status, 0) << r.err;
        EXPECT_NE(r.err.find("set." + format + ": a panel: "), std::string::npos) << r.err;
        EXPECT_NE(r.err.find("the range set (y from 1 to 3) puts "), std::string::npos) << r.err;
        EXPECT_NE(r.err.find(" markers on the frame, cut there; widen the range to show them whole"), std::string::npos)
            << r.err;
        const auto im = rasterise(dir / ("set." + format), format);
        if (im.width == 0) {
            ADD_FAILURE() << "could not rasterise " << format;
            continue;
        }
        EXPECT_EQ(ink_below_frame(im), 0) << format;
    }
    fs::remove_all(dir);
}

// The same spec with room below the circles: nothing below the frame, and no note; the
// strip test sees the hanging halves when they are there (a spec that moves the bottom
// frame up through the circles' centres, lines and all, is clipped alike).
TEST(FramesClip, RoomLeavesNoNoteAndTheStripSeesInk) {
    const auto dir = temp_dir("frames-room");
    std::ofstream(dir / "room.toml") << "[[panel]]\nplot = \"period\"\nmethods = [\"exact\"]\ny_range = [0, 3]\n";
    const auto r = run_cli("render room.toml --theme paper --dpi 300 -f png", dir);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err.find("on the frame"), std::string::npos) << r.err;
    EXPECT_EQ(ink_below_frame(rasterise(dir / "room.png", "png")), 0);
    // The strip is where a hanging marker would be: a one-point-high frame of data (an
    // x axis drawn through circles) shows ink right under a frame drawn by hand.
    test_support::grey_image im;
    im.width = 200;
    im.height = 100;
    im.pixels.assign(200 * 100, 255);
    for (unsigned x = 0; x < 200; ++x) im.pixels[10 * 200 + x] = im.pixels[80 * 200 + x] = 0;
    for (unsigned y = 10; y <= 80; ++y) im.pixels[y * 200 + 5] = im.pixels[y * 200 + 190] = 0;
    EXPECT_EQ(ink_below_frame(im), 0);
    im.pixels[83 * 200 + 100] = 0;  // a marker's ink 3 px below the frame
    EXPECT_EQ(ink_below_frame(im), 1);
    fs::remove_all(dir);
}

namespace {

/// How far the lowest drawn marker's ink stays above the bottom frame (negative: across it),
/// in points, for the set-range spec from `lo` to 3 in the paper theme.
double room_below(double lo) {
    char spec[160];
    std::snprintf(spec, sizeof spec, "[[panel]]\nplot = \"period\"\nmethods = [\"exact\"]\ny_range = [%.17g, 3]\n", lo);
    const plot::theme th = figures::load_theme("paper", {});
    const plot::figure fig = figures::build_figure(figures::parse_spec(spec, "lo.toml"), figures::sized_by({}, th));
    const auto frames = plot::panel_frames(fig, th);
    const auto markers = plot::marker_centres(fig, th);
    const double stroke = plot::line_width(th, 0.75 * th.line_width_pt);
    double room = inf;
    for (const auto& s : markers.at(0)) {
        for (const auto& [x, y] : s.centres) room = std::min(room, frames.at(0).y + frames.at(0).h - (y + s.radius + 0.5 * stroke));
    }
    return room;
}

}  // namespace

// The note's boundary: the lowest circle's ink 0.01 pt clear of the frame's centre line
// gives none; 0.01 pt across it, the note. Found by bisection of the range's lower end.
TEST(FramesClip, TheNoteBoundary) {
    double clear = 0.5;  // room_below > 0
    double across = 0.99;
    ASSERT_GT(room_below(clear), 0);
    ASSERT_LT(room_below(across), 0);
    for (int i = 0; i < 40; ++i) {
        const double mid = 0.5 * (clear + across);
        (room_below(mid) > 0 ? clear : across) = mid;
    }
    const auto dir = temp_dir("frames-note");
    for (const double lo : {clear, across}) {
        const double room = room_below(lo);
        ASSERT_LT(std::abs(room), 0.01) << lo;
        char spec[160];
        std::snprintf(spec, sizeof spec, "[[panel]]\nplot = \"period\"\nmethods = [\"exact\"]\ny_range = [%.17g, 3]\n", lo);
        std::ofstream(dir / "lo.toml") << spec;
        const auto r = run_cli("render lo.toml --theme paper -f pdf --force", dir);
        EXPECT_EQ(r.status, 0) << r.err;
        EXPECT_EQ(r.err.find("1 marker on the frame, cut there") != std::string::npos, room < 0) << lo << " " << r.err;
    }
    fs::remove_all(dir);
}

// The built-in period-formulas set no range that puts its circles on the frame, in any
// theme: no note; Fig. 7 --paper-files keeps the paper's range and says so.
TEST(FramesClip, BuiltInsLeaveRoomAndThePapersFilesSayWhy) {
    const auto dir = temp_dir("frames-builtin");
    for (const char* theme : {"paper", "slides", "slides-dark"}) {
        const auto r = run_cli(std::string("render period-formulas period --theme ") + theme + " -f pdf", dir);
        EXPECT_EQ(r.status, 0) << r.err;
        EXPECT_EQ(r.err.find("on the frame"), std::string::npos) << theme << ": " << r.err;
    }
    const plot::theme th = figures::load_theme("paper", {});
    const auto fig = figures::build(figures::find("period-formulas"), figures::sized_by({}, th));
    const auto frames = plot::panel_frames(fig, th);
    EXPECT_EQ(frames.at(0).y_lo, 0.0);
    EXPECT_EQ(frames.at(0).y_hi, 4.0);
    const auto p = run_cli("render period --paper-files -f pdf", dir);
    EXPECT_EQ(p.status, 0) << p.err;
    EXPECT_NE(p.err.find("Fig.Comparison.PeriodA.pdf: panel (a): the paper's range (y from 1 to 3) puts "),
              std::string::npos)
        << p.err;
    EXPECT_EQ(p.err.find("PeriodB.pdf: panel (b): the paper's range"), std::string::npos) << p.err;
    EXPECT_TRUE(fs::exists(dir / "Fig.Comparison.PeriodA.pdf"));
    fs::remove_all(dir);
}
