// SPDX-License-Identifier: GPL-3.0-or-later
// The renderer's geometry: axis maps, segment clipping and polyline simplification.
#include "plot/geometry.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace {

using namespace plot;

TEST(Geometry, AxisMapLinearAndLog) {
    const axis_map lin{0, 10, false, 100, 200};
    EXPECT_EQ(lin(0), 100);
    EXPECT_EQ(lin(10), 200);
    EXPECT_EQ(lin(2.5), 125);
    const axis_map down{-1, 1, false, 50, 0};  // y grows downwards on the page
    EXPECT_EQ(down(1), 0);
    EXPECT_EQ(down(0), 25);
    const axis_map log{1e-4, 1, true, 0, 400};
    EXPECT_DOUBLE_EQ(log(1e-2), 200);
    EXPECT_DOUBLE_EQ(log(1e-3), 100);
    EXPECT_TRUE(std::isnan(log(0)));
    EXPECT_TRUE(std::isnan(log(-1)));
}

TEST(Geometry, ClipSegmentToARectangle) {
    const rect r{0, 0, 10, 10};
    double x0 = -5, y0 = 5, x1 = 15, y1 = 5;  // through the middle
    ASSERT_TRUE(clip_segment(x0, y0, x1, y1, r));
    EXPECT_EQ(x0, 0);
    EXPECT_EQ(x1, 10);
    EXPECT_EQ(y0, 5);
    x0 = -5, y0 = -5, x1 = 5, y1 = 5;  // a diagonal entering at the corner
    ASSERT_TRUE(clip_segment(x0, y0, x1, y1, r));
    EXPECT_EQ(x0, 0);
    EXPECT_EQ(y0, 0);
    EXPECT_EQ(x1, 5);
    x0 = 2, y0 = 3, x1 = 4, y1 = 6;  // inside: unchanged
    ASSERT_TRUE(clip_segment(x0, y0, x1, y1, r));
    EXPECT_EQ(std::make_pair(x0, y0), std::make_pair(2.0, 3.0));
    EXPECT_EQ(std::make_pair(x1, y1), std::make_pair(4.0, 6.0));
    x0 = -5, y0 = -1, x1 = 15, y1 = -1;  // outside, parallel to an edge
    EXPECT_FALSE(clip_segment(x0, y0, x1, y1, r));
    x0 = 11, y0 = -20, x1 = 30, y1 = 5;  // outside, crossing neither edge
    EXPECT_FALSE(clip_segment(x0, y0, x1, y1, r));
    x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // a point on the edge
    EXPECT_TRUE(clip_segment(x0, y0, x1, y1, r));
}

TEST(Geometry, DistanceToSegment) {
    EXPECT_DOUBLE_EQ(distance_to_segment(5, 3, 0, 0, 10, 0), 3);
    EXPECT_DOUBLE_EQ(distance_to_segment(-3, 4, 0, 0, 10, 0), 5);  // past an end: to the end
    EXPECT_DOUBLE_EQ(distance_to_segment(1, 1, 2, 2, 2, 2), std::sqrt(2.0));  // degenerate segment
}

TEST(Geometry, SimplifyKeepsWhatShows) {
    // A straight line of many points becomes its two ends.
    std::vector<std::pair<double, double>> line;
    for (int i = 0; i <= 50; ++i) line.emplace_back(i, 2.0 * i);
    simplify(line, 0.05);
    ASSERT_EQ(line.size(), 2u);
    EXPECT_EQ(line.front(), std::make_pair(0.0, 0.0));
    EXPECT_EQ(line.back(), std::make_pair(50.0, 100.0));
    // A corner stays, and no dropped point is farther than the tolerance from the result.
    std::vector<std::pair<double, double>> corner;
    for (int i = 0; i <= 20; ++i) corner.emplace_back(i, 0);
    for (int i = 1; i <= 20; ++i) corner.emplace_back(20, i);
    const auto original = corner;
    simplify(corner, 0.05);
    EXPECT_EQ(corner.size(), 3u);
    for (const auto& [px, py] : original) {
        double best = 1e9;
        for (std::size_t i = 1; i < corner.size(); ++i) {
            best = std::min(best, distance_to_segment(px, py, corner[i - 1].first, corner[i - 1].second,
                                                      corner[i].first, corner[i].second));
        }
        EXPECT_LE(best, 0.05);
    }
    // A wiggle larger than the tolerance is kept.
    std::vector<std::pair<double, double>> wiggle = {{0, 0}, {1, 0.2}, {2, 0}};
    simplify(wiggle, 0.05);
    EXPECT_EQ(wiggle.size(), 3u);
}

TEST(Geometry, ToDeviceMarksNonFinitePoints) {
    series s;
    s.x = {0, 1, std::numeric_limits<double>::quiet_NaN(), 3};
    s.y = {0, 1, 2, std::numeric_limits<double>::infinity()};
    const auto d = to_device(s, axis_map{0, 3, false, 0, 30}, axis_map{0, 3, false, 30, 0});
    ASSERT_EQ(d.x.size(), 4u);
    EXPECT_EQ(d.x[1], 10);
    EXPECT_EQ(d.y[1], 20);
    EXPECT_TRUE(std::isnan(d.x[2]));
    EXPECT_TRUE(std::isnan(d.y[3]));
}

/// The largest distance from the curve, sampled finely, to the polyline (x, y).
double largest_gap(const curve& c, const axis_map& mx, const axis_map& my, const std::vector<double>& x,
                   const std::vector<double>& y) {
    double worst = 0;
    for (int i = 0; i <= 20000; ++i) {
        const auto [cx, cy] = c.at(c.u0 + (c.u1 - c.u0) * i / 20000);
        if (!std::isfinite(cx) || !std::isfinite(cy)) continue;
        double best = HUGE_VAL;
        for (std::size_t k = 1; k < x.size(); ++k) {
            if (std::isnan(x[k - 1] + x[k])) continue;
            best = std::min(best, distance_to_segment(mx(cx), my(cy), x[k - 1], y[k - 1], x[k], y[k]));
        }
        worst = std::max(worst, best);
    }
    return worst;
}

TEST(Geometry, SampledCurveStaysWithinTheTolerance) {
    const axis_map mx{0, 10, false, 0, 200};
    const axis_map my{-1.2, 1.2, false, 150, 0};
    const rect clip{0, 0, 200, 150};
    const auto c = function_curve(0, 10, [](double x) { return std::sin(3 * x) * std::exp(-0.1 * x); });
    for (double tolerance : {0.05, 0.005}) {
        std::vector<double> x;
        std::vector<double> y;
        sample_curve(*c, mx, my, clip, tolerance, x, y);
        EXPECT_LE(largest_gap(*c, mx, my, x, y), tolerance);
        // Few points for it: not a fixed fine grid.
        EXPECT_LT(x.size(), tolerance > 0.01 ? 400u : 1200u);
    }
    // On a log axis too.
    const axis_map log_y{1e-6, 1, true, 150, 0};
    const auto e = function_curve(0, 10, [](double x) { return std::exp(-x); });
    std::vector<double> x;
    std::vector<double> y;
    sample_curve(*e, mx, log_y, clip, 0.01, x, y);
    EXPECT_LE(largest_gap(*e, mx, log_y, x, y), 0.01);
}

TEST(Geometry, SampledCurveBreaksWhereItIsNotFinite) {
    const axis_map mx{0, 1, false, 0, 100};
    const axis_map my{0, 1, false, 100, 0};
    const auto c = function_curve(0, 1, [](double x) { return x < 0.3 || x > 0.6 ? x : std::nan(""); });
    std::vector<double> x;
    std::vector<double> y;
    sample_curve(*c, mx, my, rect{0, 0, 100, 100}, 0.01, x, y);
    const auto breaks = std::count_if(x.begin(), x.end(), [](double v) { return std::isnan(v); });
    EXPECT_EQ(breaks, 1);
    // The line goes up to where the curve stops, within the tolerance.
    double last_before = 0;
    for (std::size_t i = 0; i < x.size() && !std::isnan(x[i]); ++i) last_before = x[i];
    EXPECT_NEAR(last_before, 30, 0.01);
}

TEST(Geometry, SampledNoiseCostsABoundedNumberOfPoints) {
    // Values that are noise at every scale, and flicker between finite and not.
    const auto c = function_curve(0, 1, [](double x) {
        const double h = std::fmod(std::sin(x * 1e7) * 43758.5453, 1.0);
        return h > 0.5 ? std::nan("") : h;
    });
    std::vector<double> x;
    std::vector<double> y;
    sample_curve(*c, axis_map{0, 1, false, 0, 100}, axis_map{-1, 1, false, 100, 0}, rect{0, 0, 100, 100}, 0.01, x,
                 y);
    EXPECT_LE(x.size(), 70000u);
}

TEST(Geometry, SampledCurveOutsideTheClipIsCoarse) {
    // A curve far above the axes costs its first grid and no more.
    const auto c = function_curve(0, 1, [](double x) { return 10 + std::sin(40 * x); });
    std::vector<double> x;
    std::vector<double> y;
    sample_curve(*c, axis_map{0, 1, false, 0, 100}, axis_map{0, 1, false, 100, 0}, rect{0, 0, 100, 100}, 0.001, x, y);
    EXPECT_EQ(x.size(), 33u);
}

}  // namespace
