// SPDX-License-Identifier: GPL-3.0-or-later
#include "plot/geometry.hpp"

#include <algorithm>
#include <array>
#include <mutex>
#include <unordered_map>

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

std::pair<double, double> error_span(const std::vector<double>& v, const std::vector<double>& lower,
                                     const std::vector<double>& upper, std::size_t i) {
    const double lo = i < lower.size() ? lower[i] : 0.0;
    const double hi = i < upper.size() ? upper[i] : 0.0;
    return {v[i] - lo, v[i] + hi};
}

namespace {

/// The error bars of a series' finite points, in device coordinates (a bar with an end off
/// a log axis is left out).
std::vector<device_bar> device_bars(const series& s, const axis_map& mx, const axis_map& my) {
    std::vector<device_bar> bars;
    const auto& e = s.errors;
    if (e.empty()) return bars;
    const std::size_t n = std::min(s.x.size(), s.y.size());
    for (std::size_t i = 0; i < n; ++i) {
        if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) continue;
        const double x = mx(s.x[i]);
        const double y = my(s.y[i]);
        if (!e.y_lower.empty() || !e.y_upper.empty()) {
            const auto [lo, hi] = error_span(s.y, e.y_lower, e.y_upper, i);
            const device_bar b{x, my(lo), x, my(hi), true};
            if (lo < hi && std::isfinite(b.y0) && std::isfinite(b.y1)) bars.push_back(b);
        }
        if (!e.x_lower.empty() || !e.x_upper.empty()) {
            const auto [lo, hi] = error_span(s.x, e.x_lower, e.x_upper, i);
            const device_bar b{mx(lo), y, mx(hi), y, false};
            if (lo < hi && std::isfinite(b.x0) && std::isfinite(b.x1)) bars.push_back(b);
        }
    }
    return bars;
}

}  // namespace

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
    d.bars = device_bars(s, mx, my);
    return d;
}

std::shared_ptr<const curve> parametric_curve(double u0, double u1, std::function<std::pair<double, double>(double)> at,
                                              int pieces) {
    auto c = std::make_shared<curve>();
    c->u0 = u0;
    c->u1 = u1;
    c->at = std::move(at);
    c->pieces = pieces;
    return c;
}

std::shared_ptr<const curve> function_curve(double x0, double x1, std::function<double(double)> f) {
    return parametric_curve(x0, x1, [f = std::move(f)](double x) { return std::pair{x, f(x)}; });
}

namespace {

// Values of a curve kept for another sampling, at most.
constexpr std::size_t max_values = std::size_t{1} << 16;

/// The curve at u, from `values` if it is there (kept there if there is room); `values`
/// may be null. The caller holds the memo's lock.
std::pair<double, double> remembered_at(const curve& c, curve_values* values,
                                        double u) {
    if (!values) return c.at(u);
    if (const auto known = values->find(u); known != values->end()) return known->second;
    const auto v = c.at(u);
    if (values->size() < max_values) values->emplace(u, v);
    return v;
}

/// The parameter of the i-th of `pieces` first pieces' ends, as the sampler cuts them.
double piece_end(const curve& c, int i, int pieces) {
    return i == pieces ? c.u1 : c.u0 + (c.u1 - c.u0) * i / pieces;
}

/// Recursive subdivision of a curve's parameter in device space.
class curve_sampler {
public:
    curve_sampler(const curve& c, const axis_map& mx, const axis_map& my, const rect& clip, double tolerance,
                  std::vector<double>& x, std::vector<double>& y, std::vector<double>& u,
                  curve_values* values)
        : c_(c), mx_(mx), my_(my), clip_(clip), tolerance_(tolerance), x_(x), y_(y), u_(u), values_(values) {}

    void run() {
        x_.clear();
        y_.clear();
        u_.clear();
        if (!c_.at || !(c_.u1 > c_.u0)) return;
        const int pieces = std::clamp(c_.pieces, 1, 1 << 16);
        point a = eval(c_.u0);
        emit(a);
        for (int i = 1; i <= pieces; ++i) {
            const double u = piece_end(c_, i, pieces);
            const point b = eval(u);
            piece_end_ = std::min(x_.size() + max_piece_points, max_points);
            refine(a, eval(0.5 * (a.u + u)), b, 0);
            a = b;
        }
    }

private:
    struct point {
        double u;
        double x;
        double y;
        bool ok;
    };

    // Halvings of a first piece at most: 2^-30 of it is below what a double resolves
    // in the parameter of a plotted curve.
    static constexpr int max_depth = 30;
    // Vertices at most, of a first piece and of the curve: more are spent only on a curve
    // that is not smooth at any scale (rounding noise, values that flicker between finite
    // and not), and what is left of it is drawn through the points at hand.
    static constexpr std::size_t max_piece_points = 4096;
    static constexpr std::size_t max_points = std::size_t{1} << 16;
    std::size_t piece_end_ = 0;  // the vertex count at which the current piece is spent

    point eval(double u) const {
        const auto [dx, dy] = remembered_at(c_, values_, u);
        const bool finite = std::isfinite(dx) && std::isfinite(dy);
        const double px = finite ? mx_(dx) : 0.0;
        const double py = finite ? my_(dy) : 0.0;
        return {u, px, py, finite && std::isfinite(px) && std::isfinite(py)};
    }

    void emit(const point& p) {
        const double nan = std::numeric_limits<double>::quiet_NaN();
        if (!p.ok && !x_.empty() && std::isnan(x_.back())) return;  // one break is enough
        x_.push_back(p.ok ? p.x : nan);
        y_.push_back(p.ok ? p.y : nan);
        u_.push_back(p.u);
    }

    /// Which sides of the clip rectangle the point is beyond, as bits.
    int beyond(const point& p) const {
        return (p.x < clip_.x ? 1 : 0) | (p.x > clip_.x + clip_.w ? 2 : 0) | (p.y < clip_.y ? 4 : 0) |
               (p.y > clip_.y + clip_.h ? 8 : 0);
    }

    double off_chord(const point& p, const point& a, const point& b) const {
        return distance_to_segment(p.x, p.y, a.x, a.y, b.x, b.y);
    }

    /// Emits the vertices after a up to b, m being the curve at the middle of [a.u, b.u].
    void refine(const point& a, const point& m, const point& b, int depth) {
        if (depth >= max_depth || x_.size() >= piece_end_) {
            emit(m);
            emit(b);
            return;
        }
        const point q1 = eval(0.5 * (a.u + m.u));
        const point q3 = eval(0.5 * (m.u + b.u));
        const std::array<const point*, 5> all{&a, &q1, &m, &q3, &b};
        const bool finite = std::all_of(all.begin(), all.end(), [](const point* p) { return p->ok; });
        if (finite) {
            // Beyond one side of the clip rectangle all along: the chord is clipped away.
            int side = 15;
            for (const point* p : all) side &= beyond(*p);
            // The chord stands for the curve when the quarter points are on it. The bound
            // has a margin for the deviation between them. A curve that runs much faster
            // through one half than the other is near a singularity (a log error at a zero,
            // a period at pi), where a sharp tip can hide between the quarter points: it is
            // cut until its quarters are alike or short.
            const double bound = 0.8 * tolerance_;
            double longest = 0;  // squared lengths of the quarters
            double shortest = HUGE_VAL;
            for (std::size_t i = 1; i < all.size(); ++i) {
                const double dx = all[i]->x - all[i - 1]->x;
                const double dy = all[i]->y - all[i - 1]->y;
                longest = std::max(longest, dx * dx + dy * dy);
                shortest = std::min(shortest, dx * dx + dy * dy);
            }
            const bool uneven = longest > 0.25 * 0.25 && longest > 4 * shortest;
            if (side != 0 || (!uneven && off_chord(q1, a, b) <= bound && off_chord(m, a, b) <= bound &&
                              off_chord(q3, a, b) <= bound)) {
                emit(b);
                return;
            }
        } else if (std::none_of(all.begin(), all.end(), [](const point* p) { return p->ok; })) {
            emit(b);  // a gap
            return;
        }
        refine(a, q1, m, depth + 1);
        refine(m, q3, b, depth + 1);
    }

    const curve& c_;
    const axis_map& mx_;
    const axis_map& my_;
    rect clip_;
    double tolerance_;
    std::vector<double>& x_;
    std::vector<double>& y_;
    std::vector<double>& u_;
    curve_values* values_;
};

std::function<void(const sampled_curve&)>& observer() {
    static std::function<void(const sampled_curve&)> f;
    return f;
}

}  // namespace

void sample_curve(const curve& c, const axis_map& mx, const axis_map& my, const rect& clip, double tolerance,
                  std::vector<double>& x, std::vector<double>& y, std::vector<double>* vertex_u, bool observed) {
    const std::vector<double> key{mx.lo, mx.hi, mx.log ? 1.0 : 0.0, mx.d0, mx.d1, my.lo, my.hi, my.log ? 1.0 : 0.0,
                                  my.d0, my.d1, clip.x, clip.y, clip.w, clip.h, tolerance};
    std::vector<double> u;
    if (c.last) {
        // Held while sampling: another thread sampling this curve finds its values.
        const std::lock_guard<std::mutex> hold(c.last->lock);
        auto& last = c.last->last;
        const auto same = std::find_if(last.begin(), last.end(), [&](const auto& m) { return m.key == key; });
        if (same != last.end()) {
            x = same->x;
            y = same->y;
            u = same->u;
        } else {
            curve_sampler(c, mx, my, clip, tolerance, x, y, u, &c.last->values).run();
            constexpr std::size_t kept = 4;
            if (last.size() >= kept) last.erase(last.begin());
            last.push_back({key, x, y, u});
        }
    } else {
        curve_sampler(c, mx, my, clip, tolerance, x, y, u, nullptr).run();
    }
    if (observed && observer()) observer()(sampled_curve{&c, mx, my, clip, tolerance, x, y, u});
    if (vertex_u) *vertex_u = std::move(u);
}

std::pair<double, double> curve_at(const curve& c, double u) {
    if (!c.last) return c.at(u);
    const std::lock_guard<std::mutex> hold(c.last->lock);
    return remembered_at(c, &c.last->values, u);
}

std::vector<std::pair<double, double>> first_values(const curve& c, int at_least) {
    std::vector<std::pair<double, double>> out;
    if (!c.at || !(c.u1 > c.u0)) return out;
    const int pieces = std::clamp(c.pieces, 1, 1 << 16);
    int halvings = 0;
    while ((pieces << halvings) < at_least && halvings < 12) ++halvings;
    std::vector<double> us;
    const auto halve = [&](auto&& self, double a, double b, int depth) -> void {
        if (depth == 0) return;
        const double m = 0.5 * (a + b);  // as the sampler halves
        self(self, a, m, depth - 1);
        us.push_back(m);
        self(self, m, b, depth - 1);
    };
    us.push_back(c.u0);
    for (int i = 1; i <= pieces; ++i) {
        halve(halve, us.back(), piece_end(c, i, pieces), halvings);
        us.push_back(piece_end(c, i, pieces));
    }
    std::unique_lock<std::mutex> hold;
    if (c.last) hold = std::unique_lock<std::mutex>(c.last->lock);
    out.reserve(us.size());
    for (const double u : us) out.push_back(remembered_at(c, c.last ? &c.last->values : nullptr, u));
    return out;
}

void observe_sampled_curves(std::function<void(const sampled_curve&)> f) { observer() = std::move(f); }

device_series to_device(const series& s, const axis_map& mx, const axis_map& my, const rect& clip,
                        double tolerance) {
    device_series d = to_device(s, mx, my);
    if (s.curve && s.line != line_style::none) {
        d.sampled = true;
        sample_curve(*s.curve, mx, my, clip, tolerance, d.lx, d.ly);
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
