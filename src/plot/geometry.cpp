// SPDX-License-Identifier: GPL-3.0-or-later
#include "plot/geometry.hpp"

#include <algorithm>

namespace plot {

bool clip_segment(double& x0, double& y0, double& x1, double& y1, const rect& r) {
    double t0 = 0.0;
    double t1 = 1.0;
    const double dx = x1 - x0;
    const double dy = y1 - y0;
    const double p[4] = {-dx, dx, -dy, dy};
    const double q[4] = {x0 - r.x, r.x + r.w - x0, y0 - r.y, r.y + r.h - y0};
    for (int i = 0; i < 4; ++i) {
        if (p[i] == 0.0) {
            if (q[i] < 0.0) return false;
        } else {
            const double t = q[i] / p[i];
            if (p[i] < 0.0) {
                if (t > t1) return false;
                t0 = std::max(t0, t);
            } else {
                if (t < t0) return false;
                t1 = std::min(t1, t);
            }
        }
    }
    const double nx0 = x0 + t0 * dx;
    const double ny0 = y0 + t0 * dy;
    x1 = x0 + t1 * dx;
    y1 = y0 + t1 * dy;
    x0 = nx0;
    y0 = ny0;
    return true;
}

device_series to_device(const series& s, const axis_map& mx, const axis_map& my) {
    device_series d;
    const std::size_t n = std::min(s.x.size(), s.y.size());
    d.x.reserve(n);
    d.y.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
        const bool ok = std::isfinite(s.x[i]) && std::isfinite(s.y[i]);
        d.x.push_back(ok ? mx(s.x[i]) : std::numeric_limits<double>::quiet_NaN());
        d.y.push_back(ok ? my(s.y[i]) : std::numeric_limits<double>::quiet_NaN());
    }
    return d;
}

double distance_to_segment(double px, double py, double ax, double ay, double bx, double by) {
    const double dx = bx - ax;
    const double dy = by - ay;
    const double len2 = dx * dx + dy * dy;
    double t = len2 > 0 ? ((px - ax) * dx + (py - ay) * dy) / len2 : 0.0;
    t = std::clamp(t, 0.0, 1.0);
    return std::hypot(px - (ax + t * dx), py - (ay + t * dy));
}

void simplify(std::vector<std::pair<double, double>>& run, double tolerance) {
    if (run.size() < 3) return;
    std::vector<std::pair<double, double>> out{run.front()};
    std::size_t first_pending = 1;  // run[first_pending .. i-1] are not yet emitted
    for (std::size_t i = 2; i < run.size(); ++i) {
        const auto [ax, ay] = out.back();
        const auto [bx, by] = run[i];
        bool fits = i - first_pending < 64;
        for (std::size_t j = first_pending; fits && j < i; ++j) {
            fits = distance_to_segment(run[j].first, run[j].second, ax, ay, bx, by) <= tolerance;
        }
        if (!fits) {
            out.push_back(run[i - 1]);
            first_pending = i;
        }
    }
    out.push_back(run.back());
    run = std::move(out);
}

}  // namespace plot
