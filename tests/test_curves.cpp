// SPDX-License-Identifier: GPL-3.0-or-later
// Curves drawn from functions stay on them at any zoom: the lines of every built-in figure,
// in every theme, and of curves near the separatrix, read back from the SVG that Cairo
// writes, are within 0.05 pt / 8 of the functions they are drawn from.
#include "figures/catalog.hpp"
#include "figures/themes.hpp"
#include "plot/geometry.hpp"
#include "plot/output.hpp"
#include "process.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <set>
#include <string>
#include <vector>

namespace {

using plot::axis_map;
using plot::rect;

/// What the observer saw of one sampling of a curve.
struct record {
    const plot::curve* c = nullptr;
    axis_map mx;
    axis_map my;
    rect clip;
    double tolerance = 0;
    std::vector<double> x;
    std::vector<double> y;
    std::vector<double> u;
};

/// A stroked sub-path of the SVG: its vertices in points.
struct subpath {
    std::vector<std::pair<double, double>> v;
};

/// The stroked, straight sub-paths of Cairo's SVG (fill:none; glyphs and markers, which
/// have curves or are filled, are left out), with a path's transform applied.
std::vector<subpath> stroked_lines(const std::string& svg) {
    std::vector<subpath> out;
    // Attribute values of Cairo's output hold no '>' (std::regex overflows the stack on
    // paths this long).
    const auto attribute = [](const std::string& attrs, const std::string& name) -> std::optional<std::string> {
        const auto at = attrs.find(" " + name + "=\"");
        if (at == std::string::npos) return std::nullopt;
        const auto from = at + name.size() + 3;
        return attrs.substr(from, attrs.find('"', from) - from);
    };
    for (std::size_t at = svg.find("<path "); at != std::string::npos; at = svg.find("<path ", at + 1)) {
        const std::string attrs = svg.substr(at + 5, svg.find('>', at) - at - 5);
        if (attrs.find("fill:none") == std::string::npos) continue;
        const auto d = attribute(attrs, "d");
        if (!d) continue;
        double m[6] = {1, 0, 0, 1, 0, 0};
        if (const auto tr = attribute(attrs, "transform")) {
            std::string text = tr->substr(tr->find('(') + 1);
            std::replace(text.begin(), text.end(), ',', ' ');
            std::istringstream in(text);
            for (double& v : m) in >> v;
        }
        std::istringstream in(*d);
        std::string token;
        std::vector<subpath> here;
        bool curved = false;
        char command = 0;
        while (in >> token) {
            if (std::isalpha(static_cast<unsigned char>(token[0]))) {
                command = token[0];
                if (command == 'Z') continue;
                if (command == 'M') here.emplace_back();
                if (command == 'C') curved = true;
                continue;
            }
            double x = std::stod(token);
            double y = 0;
            in >> y;
            if (command == 'C') {
                in >> x >> y >> x >> y;  // two control points, then the end
            }
            if (here.empty()) here.emplace_back();
            here.back().v.emplace_back(m[0] * x + m[2] * y + m[4], m[1] * x + m[3] * y + m[5]);
        }
        if (curved) continue;
        for (auto& s : here) {
            if (s.v.size() >= 2) out.push_back(std::move(s));
        }
    }
    return out;
}

double distance_to_segment(std::pair<double, double> p, std::pair<double, double> a, std::pair<double, double> b) {
    return plot::distance_to_segment(p.first, p.second, a.first, a.second, b.first, b.second);
}

/// The curve's point at u in device points.
std::pair<double, double> device_at(const record& r, double u) {
    const auto [x, y] = r.c->at(u);
    return {r.mx(x), r.my(y)};
}

bool same(std::pair<double, double> p, double x, double y) {
    // Cairo rounds path coordinates to 1/256 pt.
    return std::fabs(p.first - x) <= 0.5 / 256 + 1e-6 && std::fabs(p.second - y) <= 0.5 / 256 + 1e-6;
}

/// The largest distance between the drawn segment a-b, which stands for the curve from
/// parameter u0 to u1, and that piece of the curve, both ways; the curve counts only where
/// it shows (inside the clip rectangle), and only when `whole` (a-b not cut by clipping).
double deviation(const record& r, double u0, double u1, std::pair<double, double> a, std::pair<double, double> b,
                 bool whole) {
    constexpr int n = 64;
    std::vector<std::pair<double, double>> q;
    for (int i = 0; i <= n; ++i) q.push_back(device_at(r, u0 + (u1 - u0) * i / n));
    double worst = 0;
    if (whole) {
        // A curve that leaves the clip rectangle, as a log error does towards a zero, is cut
        // off there.
        const rect& c = r.clip;
        for (const auto& p : q) {
            const bool shows = p.first >= c.x && p.first <= c.x + c.w && p.second >= c.y && p.second <= c.y + c.h;
            if (shows) worst = std::max(worst, distance_to_segment(p, a, b));
        }
    }
    for (int i = 0; i <= 16; ++i) {
        const double t = i / 16.0;
        const std::pair<double, double> p{a.first + t * (b.first - a.first), a.second + t * (b.second - a.second)};
        double best = HUGE_VAL;
        for (std::size_t j = 1; j < q.size(); ++j) best = std::min(best, distance_to_segment(p, q[j - 1], q[j]));
        worst = std::max(worst, best);
    }
    return worst;
}

/// The largest deviation of the sub-path from the curve, if the sub-path is a run of the
/// recorded sampling: its vertices samples in order (Cairo drops one where the line goes on
/// straight), its ends possibly cut by clipping onto a chord of samples.
std::optional<double> measure(const record& r, const subpath& s) {
    if (s.v.size() < 3) return std::nullopt;  // a tick or a two-point line
    const std::size_t n = r.x.size();
    const auto sample = [&](std::size_t j) { return std::pair{r.x[j], r.y[j]}; };
    const auto on_chord = [&](std::pair<double, double> p, std::size_t j) {
        return j + 1 < n && !std::isnan(r.x[j] + r.x[j + 1]) && distance_to_segment(p, sample(j), sample(j + 1)) < 0.01;
    };
    // Where each vertex is: at a sample (u of that sample), or on a chord (clipped end).
    std::vector<std::size_t> at(s.v.size());
    std::size_t k = 0;
    while (k < n && !same(s.v[1], r.x[k], r.y[k])) ++k;
    if (k == 0 || k >= n) return std::nullopt;
    at[1] = k;
    for (std::size_t i = 2; i < s.v.size(); ++i) {
        std::size_t j = at[i - 1] + 1;
        while (j < n && !same(s.v[i], r.x[j], r.y[j])) ++j;
        if (j < n) {
            at[i] = j;
            continue;
        }
        if (i + 1 < s.v.size()) return std::nullopt;
        // The last vertex, cut: on a chord after the last sample matched.
        j = at[i - 1];
        while (j + 1 < n && !on_chord(s.v[i], j)) ++j;
        if (j + 1 >= n) return std::nullopt;
        at[i] = j + 1;
    }
    std::size_t j0 = k;
    bool first_cut = false;
    while (j0 > 0 && !same(s.v[0], r.x[j0 - 1], r.y[j0 - 1])) --j0;
    if (j0 == 0) {
        j0 = k;
        while (j0 > 0 && !on_chord(s.v[0], j0 - 1)) --j0;
        if (j0 == 0) return std::nullopt;
        first_cut = true;
    }
    at[0] = j0 - 1;
    const bool last_cut = !same(s.v.back(), r.x[at.back()], r.y[at.back()]);
    double worst = 0;
    for (std::size_t i = 1; i < s.v.size(); ++i) {
        const bool whole = !(i == 1 && first_cut) && !(i + 1 == s.v.size() && last_cut);
        const double dv = deviation(r, r.u[at[i - 1]], r.u[at[i]], s.v[i - 1], s.v[i], whole);
        if (dv > 0.05 / 8 && std::getenv("CURVES_DEBUG")) {
            std::printf("seg u %.17g %.17g  (%g,%g)-(%g,%g) whole %d dv %g\n", r.u[at[i - 1]], r.u[at[i]],
                        s.v[i - 1].first, s.v[i - 1].second, s.v[i].first, s.v[i].second, whole, dv);
        }
        worst = std::max(worst, dv);
    }
    return worst;
}

struct result {
    double worst = 0;       // the largest deviation, points
    std::size_t curves = 0;  // curves whose drawn line was found
    std::size_t vertices = 0;
};

/// Renders the figure as SVG and measures every drawn curve against its function.
result check_figure(const plot::figure& fig, const plot::theme& th, const std::string& what) {
    std::vector<record> records;
    plot::observe_sampled_curves([&](const plot::sampled_curve& s) {
        records.push_back(record{s.c, s.mx, s.my, s.clip, s.tolerance, s.x, s.y, s.u});
    });
    const std::string svg = plot::render(fig, th, "svg", {});
    plot::observe_sampled_curves({});
    const auto lines = stroked_lines(svg);
    result res;
    std::set<const plot::curve*> sampled;
    std::set<const plot::curve*> found;
    for (const auto& r : records) {
        EXPECT_LE(r.tolerance, 0.05 / 8) << what;
        // A curve with a visible segment must be found in the drawing.
        for (std::size_t i = 1; i < r.x.size(); ++i) {
            const bool inside = r.x[i] > r.clip.x + 1 && r.x[i] < r.clip.x + r.clip.w - 1 &&
                                r.y[i] > r.clip.y + 1 && r.y[i] < r.clip.y + r.clip.h - 1 &&
                                r.x[i - 1] > r.clip.x + 1 && r.x[i - 1] < r.clip.x + r.clip.w - 1 &&
                                r.y[i - 1] > r.clip.y + 1 && r.y[i - 1] < r.clip.y + r.clip.h - 1;
            if (inside) {
                sampled.insert(r.c);
                break;
            }
        }
        for (const auto& s : lines) {
            const auto d = measure(r, s);
            if (!d) continue;
            found.insert(r.c);
            res.worst = std::max(res.worst, *d);
            res.vertices += s.v.size();
            EXPECT_LE(*d, 0.05 / 8) << what;
        }
    }
    for (const auto* c : sampled) EXPECT_TRUE(found.count(c)) << what << ": a curve is not in the SVG";
    res.curves = found.size();
    return res;
}

}  // namespace

TEST(Curves, EveryBuiltInFigureInEveryThemeFollowsItsFunctions) {
    for (const auto& t : figures::builtin_themes()) {
        const plot::theme th = figures::load_theme(t.name);
        for (const auto& e : figures::catalog()) {
            figures::build_options options;
            options.panel_width_cm = th.panel_width_cm;
            options.panel_aspect = th.panel_aspect;
            const plot::figure fig = figures::build(e, options);
            const std::string what = e.id + " (" + std::string(t.name) + ")";
            const result r = check_figure(fig, th, what);
            const bool has_curves = e.id != "convergence" && e.id != "spectrum";
            if (has_curves) {
                EXPECT_GT(r.curves, 0u) << what;
            }
            std::printf("%-22s %-12s %2zu curves %6zu vertices, largest deviation %.2e pt\n", e.id.c_str(),
                        std::string(t.name).c_str(), r.curves, r.vertices, r.worst);
        }
    }
}

TEST(Curves, NearTheSeparatrixTheLinesFollowTheirFunctions) {
    const auto dir = test_support::temp_dir("curves");
    const auto spec = dir / "near-pi.toml";
    std::ofstream(spec) << R"(
[figure]
title = "near pi"
columns = 2
legend = "each"

[[panel]]
plot = "trajectory"
theta0 = "pi-1e-6"
methods = [{ method = "exact", style = "solid", marker = "none" }, "harmonic", "lowest", "second"]
range = [0, 3]

[[panel]]
plot = "trajectory"
theta0 = "170deg"
methods = [{ method = "exact", style = "solid", marker = "none" }, "harmonic", "order:6"]
range = [0, 3]
angle_unit = "deg"

[[panel]]
plot = "phase"
theta0 = ["pi-1e-6", "170deg", "0.999pi"]
methods = ["exact", "lowest"]
separatrix = true

[[panel]]
plot = "period"
y = "error-log"
methods = ["lowest", "kidd-fogg"]
range = ["pi/2", "pi-1e-6"]
)";
    const auto e = figures::load(spec.string());
    for (const auto& t : figures::builtin_themes()) {
        const plot::theme th = figures::load_theme(t.name);
        const result r = check_figure(figures::build(e), th, "near pi (" + std::string(t.name) + ")");
        EXPECT_GE(r.curves, 11u);
        std::printf("near pi %-12s %2zu curves %6zu vertices, largest deviation %.2e pt\n",
                    std::string(t.name).c_str(), r.curves, r.vertices, r.worst);
    }
    std::filesystem::remove_all(dir);
}
