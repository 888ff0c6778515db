// SPDX-License-Identifier: GPL-3.0-or-later
// plot animates: a trajectory, phase or pendulum plot becomes an animation where a format
// holds moving pictures or an animation option is given; --apart gives each start its own
// panel; a plot that does not move refuses both with a word on what does.
#include <gtest/gtest.h>

#include "process.hpp"

#include <filesystem>
#include <string>

namespace fs = std::filesystem;
using namespace test_support;

namespace {

/// An image's property read back by Pillow: `expression` of the opened image `im`.
std::string pillow(const fs::path& image, const std::string& expression) {
    const auto r = run_command("/usr/bin/python3 -c \"from PIL import Image; im = Image.open('" + image.string() +
                               "'); print(" + expression + ")\"");
    EXPECT_EQ(r.status, 0) << r.err;
    return r.out;
}

/// The number of frames of a GIF.
int gif_frames(const fs::path& gif) { return std::stoi(pillow(gif, "im.n_frames")); }

/// The resolution a PNG says it has (its pHYs chunk).
double png_dpi(const fs::path& png) { return std::stod(pillow(png, "im.info['dpi'][0]")); }

}  // namespace

TEST(PlotAnimates, AGifOfAPendulumPlotMovesAndAVideoToo) {
    const auto dir = temp_dir("plot-animates");
    const auto r = run_cli("plot pendulum --theta0 10deg,170deg --methods exact --apart --fps 10 --periods 1 -f gif,mp4", dir);
    ASSERT_EQ(r.status, 0) << r.err;
    // One period of the first start (10 degrees: 1.0019 T0 = 2.0103 s for a 1 m pendulum) at 10 fps,
    // 21 frames; the 170-degree pendulum is then mid-swing, so the end cross-fades (5 frames,
    // half a second) into the start, and stderr says so.
    EXPECT_EQ(gif_frames(dir / "pendulum.gif"), 26);
    EXPECT_NE(r.err.find("cannot loop without a jump"), std::string::npos) << r.err;
    EXPECT_TRUE(fs::is_regular_file(dir / "pendulum.mp4"));
    fs::remove_all(dir);
}

TEST(PlotAnimates, PngWritesOneFilePerFrameOfAnAnimation) {
    const auto dir = temp_dir("plot-animates-png");
    const auto r = run_cli("plot trajectory --theta0 1 --methods exact,harmonic --fps 5 --periods 1 -f png", dir);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_TRUE(fs::is_regular_file(dir / "trajectory-0001.png"));
    EXPECT_FALSE(fs::exists(dir / "trajectory.png"));
    fs::remove_all(dir);
}

TEST(PlotAnimates, AStillPlotStaysStillInAGif) {
    const auto dir = temp_dir("plot-still-gif");
    const auto r = run_cli("plot period --methods exact -f gif", dir);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(gif_frames(dir / "period.gif"), 1);
    fs::remove_all(dir);
}

TEST(PlotAnimates, APlotThatDoesNotMoveRefusesVideoAndAnimationOptions) {
    const auto dir = temp_dir("plot-animates-refused");
    for (const std::string args : {"plot period --methods exact -f mp4", "plot spectrum --theta0 1 -f webm",
                                   "plot period --methods exact --fps 10 -f png", "plot coefficient --clock true"}) {
        const auto r = run_cli(args, dir);
        EXPECT_EQ(r.status, 2) << args;
        EXPECT_NE(r.err.find("does not move"), std::string::npos) << r.err;
        EXPECT_NE(r.err.find("the plots that animate are trajectory, phase and pendulum"), std::string::npos) << r.err;
    }
    EXPECT_TRUE(files_in(dir).empty());
    fs::remove_all(dir);
}

TEST(PlotAnimates, FpsLimitsAreTheSpecsAndTheGifsAtTheBoundary) {
    const auto dir = temp_dir("plot-animates-fps");
    const std::string start = "plot pendulum --theta0 1 --methods exact --periods 0.05 ";
    EXPECT_EQ(run_cli(start + "--fps 120 -f mp4", dir).status, 0);
    auto r = run_cli(start + "--fps 121 -f mp4", dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("fps"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("120"), std::string::npos) << r.err;
    EXPECT_EQ(run_cli(start + "--fps 50 -f gif", dir).status, 0);
    r = run_cli(start + "--fps 51 -f gif", dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("at most 50"), std::string::npos) << r.err;
    fs::remove_all(dir);
}

TEST(PlotApart, OnePanelPerStartAndListsThatDoNotPairAreRefused) {
    const auto dir = temp_dir("plot-apart");
    auto r = run_cli("plot phase --theta0 0.5,1,2 --methods exact --apart -f svg", dir);
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string svg = slurp(dir / "phase.svg");
    EXPECT_NE(svg.find("(c)"), std::string::npos) << "three panels are labelled (a) to (c)";
    r = run_cli("plot pendulum --theta0 10deg,170deg,20deg --omega0 0,1 --methods exact --apart -f png", dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("--apart: --omega0 has 2 items where another start list has 3"), std::string::npos) << r.err;
    r = run_cli("plot period --methods exact --apart -f png", dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("give --theta0, --energy or --omega0"), std::string::npos) << r.err;
    fs::remove_all(dir);
}

TEST(PlotLabels, AnEmptyPanelTitleIsAcceptedAsInASpec) {
    const auto dir = temp_dir("plot-empty-title");
    const auto r = run_cli("plot period --methods exact --panel-title '' -f png", dir);
    EXPECT_EQ(r.status, 0) << r.err;
    const auto v = run_cli("plot period --methods exact --range '' -f png", dir);
    EXPECT_EQ(v.status, 2) << "a value, unlike a label, may not be empty";
    fs::remove_all(dir);
}


// A slide is seen whole: at --size 1920x1080 the slides theme keeps its 25.4-cm page, so its
// text keeps its share of the frame (192 dpi, not 128); --dpi, when given, still wins, and a
// theme sized by its panels (paper) keeps its resolution.
TEST(SlideSize, TextKeepsItsShareOfTheFrameAtAnySize) {
    const auto dir = temp_dir("slide-size");
    const std::string plot = "plot trajectory --theta0 170deg --methods exact -f png ";
    ASSERT_EQ(run_cli(plot + "--theme slides --name s720", dir).status, 0);
    ASSERT_EQ(run_cli(plot + "--theme slides --size 1920x1080 --name s1080", dir).status, 0);
    ASSERT_EQ(run_cli(plot + "--theme slides --size 3840x2160 --name s2160", dir).status, 0);
    ASSERT_EQ(run_cli(plot + "--theme slides --size 1920x1080 --dpi 128 --name fixed", dir).status, 0);
    ASSERT_EQ(run_cli(plot + "--theme paper --size 1000x600 --name paper", dir).status, 0);
    EXPECT_NEAR(png_dpi(dir / "s720.png"), 128, 0.5);
    EXPECT_NEAR(png_dpi(dir / "s1080.png"), 192, 0.5);
    EXPECT_NEAR(png_dpi(dir / "s2160.png"), 384, 0.5);
    EXPECT_NEAR(png_dpi(dir / "fixed.png"), 128, 0.5);
    EXPECT_NEAR(png_dpi(dir / "paper.png"), 300, 0.5);
    fs::remove_all(dir);
}
