// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Part of the plot layer's renderer; not a public interface.

#include "plot/figure.hpp"

#include <cmath>
#include <functional>
#include <limits>
#include <utility>
#include <vector>

namespace plot {

/// A rectangle in device points, y down.
struct rect {
    double x = 0;
    double y = 0;
    double w = 0;
    double h = 0;
};

/// Maps data values of one axis to device coordinates.
struct axis_map {
    double lo = 0;
    double hi = 1;
    bool log = false;
    double d0 = 0;  // device coordinate of lo
    double d1 = 1;  // device coordinate of hi

    double operator()(double v) const {
        if (log) {
            if (!(v > 0)) return std::numeric_limits<double>::quiet_NaN();
            return d0 + (std::log10(v) - std::log10(lo)) / (std::log10(hi) - std::log10(lo)) * (d1 - d0);
        }
        return d0 + (v - lo) / (hi - lo) * (d1 - d0);
    }
};

/// One error bar in device coordinates, from (x0, y0) to (x1, y1), with a cap at each end
/// across it.
struct device_bar {
    double x0, y0, x1, y1;
    bool vertical;  // a y error: caps are horizontal
};

/// Device coordinates of one series; non-finite points are NaN.
struct device_series {
    std::vector<double> x{};  // the points: markers, and the line of a series without a curve
    std::vector<double> y{};
    bool sampled = false;      // the line is the series' curve, sampled into lx, ly
    std::vector<double> lx{};
    std::vector<double> ly{};
    std::vector<device_bar> bars{};  // the error bars of its points

    /// The vertices of the drawn line.
    const std::vector<double>& line_x() const { return sampled ? lx : x; }
    const std::vector<double>& line_y() const { return sampled ? ly : y; }
};

/// Liang-Barsky: clips the segment to r; returns false if nothing is left.
bool clip_segment(double& x0, double& y0, double& x1, double& y1, const rect& r);

/// The series in device coordinates; points with a non-finite coordinate are NaN.
device_series to_device(const series& s, const axis_map& mx, const axis_map& my);

/// The curve in device coordinates: a polyline whose segments stay within `tolerance` of
/// the curve wherever it passes through `clip` (elsewhere it is sampled coarsely), by
/// recursive subdivision of the parameter; NaN where the curve is not finite. The last
/// sampling of a curve is remembered, so that drawing it again with the same maps costs
/// nothing (the frames of an animation).
/// With `u`, the parameter of each vertex goes there. `observed` false keeps the sampling
/// from observe_sampled_curves (a crowded series' thin line, drawn in some layouts tried).
void sample_curve(const curve& c, const axis_map& mx, const axis_map& my, const rect& clip, double tolerance,
                  std::vector<double>& x, std::vector<double>& y, std::vector<double>* u = nullptr,
                  bool observed = true);

/// The curve at parameter u, through its memo: the value its sampling drew.
std::pair<double, double> curve_at(const curve& c, double u);

/// The curve at the parameters sample_curve takes first (its pieces, then halves of them,
/// at least `at_least` in all), through the curve's memo: another reader of the curve (a
/// description) and its drawing evaluate a costly function once between them.
std::vector<std::pair<double, double>> first_values(const curve& c, int at_least);

/// A curve as sample_curve sampled it: the parameter of each vertex too.
struct sampled_curve {
    const curve* c;
    axis_map mx;
    axis_map my;
    rect clip;
    double tolerance;
    const std::vector<double>& x;
    const std::vector<double>& y;
    const std::vector<double>& u;
};

/// For tests: f sees every curve sample_curve samples (or none, with an empty f). Not
/// for use while other threads draw.
void observe_sampled_curves(std::function<void(const sampled_curve&)> f);

/// The series in device coordinates, its curve (if any) sampled as sample_curve does.
device_series to_device(const series& s, const axis_map& mx, const axis_map& my, const rect& clip,
                        double tolerance);

/// Distance from the point (px, py) to the segment from (ax, ay) to (bx, by).
double distance_to_segment(double px, double py, double ax, double ay, double bx, double by);

/// Drops the points of a polyline that lie within `tolerance` of the line drawn without
/// them, as matplotlib's path simplification does: invisible, but it keeps vector files
/// small and fast to draw.
void simplify(std::vector<std::pair<double, double>>& run, double tolerance);

}  // namespace plot
