// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Part of the plot layer's renderer; not a public interface.

#include "plot/figure.hpp"

#include <cmath>
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

/// Device coordinates of one series; non-finite points are NaN.
struct device_series {
    std::vector<double> x;
    std::vector<double> y;
};

/// Liang-Barsky: clips the segment to r; returns false if nothing is left.
bool clip_segment(double& x0, double& y0, double& x1, double& y1, const rect& r);

/// The series in device coordinates; points with a non-finite coordinate are NaN.
device_series to_device(const series& s, const axis_map& mx, const axis_map& my);

/// Distance from the point (px, py) to the segment from (ax, ay) to (bx, by).
double distance_to_segment(double px, double py, double ax, double ay, double bx, double by);

/// Drops the points of a polyline that lie within `tolerance` of the line drawn without
/// them, as matplotlib's path simplification does: invisible, but it keeps vector files
/// small and fast to draw.
void simplify(std::vector<std::pair<double, double>>& run, double tolerance);

}  // namespace plot
