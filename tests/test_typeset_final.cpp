// SPDX-License-Identifier: GPL-3.0-or-later
// Typesetting and drawing details from a 1200-dpi review: lines drawn from dense samples,
// the energy unit set one way in every route, one line for a theme below its minimum.
#include "figures/build_options.hpp"
#include "figures/catalog.hpp"
#include "figures/themes.hpp"
#include "plot/geometry.hpp"
#include "plot/output.hpp"
#include "plot/render.hpp"
#include "plot/ticks.hpp"
#include "process.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

using test_support::run_cli;
using test_support::slurp;
using test_support::temp_dir;

namespace {

using point = std::pair<double, double>;

/// The stroked polylines of an SVG (paths without fill and without Bezier pieces), in page points.
std::vector<std::vector<point>> stroked_polylines(const std::string& svg) {
    std::vector<std::vector<point>> out;
    const auto attribute = [](const std::string& attrs, const std::string& name) -> std::string {
        const auto at = attrs.find(" " + name + "=\"");
        if (at == std::string::npos) return {};
        const auto from = at + name.size() + 3;
        return attrs.substr(from, attrs.find('"', from) - from);
    };
    for (std::size_t at = svg.find("<path "); at != std::string::npos; at = svg.find("<path ", at + 1)) {
        const std::string attrs = svg.substr(at + 5, svg.find('>', at) - at - 5);
        if (attrs.find("fill:none") == std::string::npos) continue;
        const std::string d = attribute(attrs, "d");
        if (d.empty() || d.find('C') != std::string::npos) continue;
        double m[6] = {1, 0, 0, 1, 0, 0};
        if (const std::string tr = attribute(attrs, "transform"); !tr.empty()) {
            std::string text = tr.substr(tr.find('(') + 1);
            std::replace(text.begin(), text.end(), ',', ' ');
            std::istringstream in(text);
            for (double& v : m) in >> v;
        }
        std::istringstream in(d);
        std::string token;
        std::vector<std::vector<point>> here;
        while (in >> token) {
            if (std::isalpha(static_cast<unsigned char>(token[0]))) {
                if (token[0] == 'M') here.emplace_back();
                continue;
            }
            const double x = std::stod(token);
            double y = 0;
            in >> y;
            if (here.empty()) here.emplace_back();
            here.back().emplace_back(m[0] * x + m[2] * y + m[4], m[1] * x + m[3] * y + m[5]);
        }
        for (auto& s : here) {
            if (s.size() >= 2) out.push_back(std::move(s));
        }
    }
    return out;
}

/// A curve sampled on the page finely enough (vertices within 0.02 pt of each other) that
/// the distance to its nearest vertex is its distance to the curve within 0.01 pt, with a
/// grid of 1-pt cells to find the vertices near a point.
class dense_curve {
public:
    dense_curve(const plot::curve& c, const plot::axis_map& mx, const plot::axis_map& my) {
        const auto at = [&](double u) {
            const auto [x, y] = c.at(u);
            return point{mx(x), my(y)};
        };
        const int n = 4096;
        point prev = at(c.u0);
        add(prev);
        for (int i = 1; i <= n; ++i) {
            const double u0 = c.u0 + (c.u1 - c.u0) * (i - 1) / n;
            const double u1 = c.u0 + (c.u1 - c.u0) * i / n;
            const point next = at(u1);
            const double gap = std::hypot(next.first - prev.first, next.second - prev.second);
            const int steps = std::isfinite(gap) ? std::min(4000, static_cast<int>(std::ceil(gap / 0.02))) : 1;
            for (int j = 1; j <= steps; ++j) add(at(u0 + (u1 - u0) * j / steps));
            prev = next;
        }
    }

    /// The distance from p to the nearest vertex within 1 pt (2 pt if none is that near).
    double distance(point p) const {
        double best = 2.0;
        const long cx = cell(p.first);
        const long cy = cell(p.second);
        for (long i = cx - 1; i <= cx + 1; ++i) {
            for (long j = cy - 1; j <= cy + 1; ++j) {
                const auto it = cells_.find({i, j});
                if (it == cells_.end()) continue;
                for (const point& q : it->second) best = std::min(best, std::hypot(q.first - p.first, q.second - p.second));
            }
        }
        return best;
    }

private:
    static long cell(double v) { return static_cast<long>(std::floor(v)); }
    void add(point p) {
        if (std::isfinite(p.first) && std::isfinite(p.second)) cells_[{cell(p.first), cell(p.second)}].push_back(p);
    }
    std::map<std::pair<long, long>, std::vector<point>> cells_;
};

/// The largest distance from the exact curve of a segment of a drawn polyline whose two
/// ends lie on that curve (within 0.01 pt) and that is longer than 0.3 pt: such a segment is
/// the curve drawn, and must stay within the README's 0.05 pt of it everywhere.
double worst_deviation(const std::vector<std::vector<point>>& lines, const dense_curve& exact) {
    double worst = 0;
    for (const auto& line : lines) {
        for (std::size_t i = 1; i < line.size(); ++i) {
            const point a = line[i - 1];
            const point b = line[i];
            if (std::hypot(b.first - a.first, b.second - a.second) < 0.3) continue;
            if (exact.distance(a) > 0.01 || exact.distance(b) > 0.01) continue;
            for (int j = 1; j < 16; ++j) {
                const double t = j / 16.0;
                worst = std::max(worst, exact.distance({a.first + t * (b.first - a.first), a.second + t * (b.second - a.second)}));
            }
        }
    }
    return worst;
}

}  // namespace

// Every line drawn along an exact curve (a method's line, or the thin line through markers
// that would crowd) stays within 0.05 pt of the curve: it comes from the curve sampler, not
// from straight segments between marker samples (regimes (b)-(d), Fig. 6 had kinks ~2.5 mm apart).
TEST(TypesetFinal, EveryDrawnLineAlongACurveStaysWithinTheTolerance) {
    for (const char* theme_name : {"paper", "slides"}) {
        const plot::theme th = figures::load_theme(theme_name);
        for (const auto& e : figures::catalog()) {
            if (e.spec.animation) continue;
            const plot::figure fig = figures::build(e, figures::sized_by({}, th));
            const std::string svg = plot::render(fig, th, "svg", {});
            const auto lines = stroked_polylines(svg);
            const plot::figure styled = plot::with_theme_styles(fig, th);
            const auto frames = plot::panel_frames(styled, th);
            for (std::size_t i = 0; i < styled.panels.size() && i < frames.size(); ++i) {
                const plot::panel& p = styled.panels[i];
                const plot::panel_frame& f = frames[i];
                // Linear axes only: a log axis' sharp dips (an error through zero) need a
                // finer reference than this even sampling (the curves test measures those).
                if (f.frameless || p.x.kind == plot::scale::log || p.y.kind == plot::scale::log) continue;
                const plot::axis_map mx{f.x_lo, f.x_hi, p.x.kind == plot::scale::log, f.x, f.x + f.w};
                const plot::axis_map my{f.y_lo, f.y_hi, p.y.kind == plot::scale::log, f.y + f.h, f.y};
                for (std::size_t k = 0; k < p.data.size(); ++k) {
                    if (!p.data[k].curve) continue;
                    const double worst = worst_deviation(lines, dense_curve(*p.data[k].curve, mx, my));
                    EXPECT_LE(worst, 0.05 + 0.01) <<  // 0.01: the dense sampling's own error
                         e.id << " " << theme_name << " panel " << i << " series " << k;
                }
            }
        }
    }
}

// The energy unit is set as TeX sets $E = 1\,mgL$ in every route: a thin space (U+2009)
// in the PDF and SVG text, \, in pdf_tex (in math mode, titles too), a space in the alt text.
TEST(TypesetFinal, TheEnergyUnitIsSetOneWayInEveryRoute) {
    const auto dir = temp_dir("typeset-energy");
    std::filesystem::create_directories(dir / "tex");
    const auto r = run_cli("render regimes -f svg -o '" + dir.string() + "'");
    ASSERT_EQ(r.status, 0) << r.err;
    const auto t = run_cli("render regimes -f pdf_tex -o '" + (dir / "tex").string() + "'");
    ASSERT_EQ(t.status, 0) << t.err;
    const std::string tex = slurp(dir / "tex" / "regimes.pdf_tex");
    for (const char* e : {"1", "2", "3"}) {
        const std::string n(e);
        EXPECT_NE(tex.find("$E = " + n + "\\,mgL,$"), std::string::npos) << tex;  // legends
        EXPECT_NE(tex.find("$E=" + n + "\\,mgL$"), std::string::npos) << tex;     // titles, "=" in math
        EXPECT_EQ(tex.find("$E$"), std::string::npos) << tex;
        EXPECT_EQ(tex.find(n + " mgL"), std::string::npos) << tex;
        EXPECT_EQ(tex.find(n + "mgL"), std::string::npos) << tex;
    }
    const std::string svg = slurp(dir / "regimes.svg");
    // The alt text (title, Subject) in plain words: one ASCII space.
    EXPECT_NE(svg.find("Panel (b), libration, E = 1 mgL, shows"), std::string::npos);
    EXPECT_NE(svg.find("Curves: E = 1 mgL, libration"), std::string::npos);
    EXPECT_EQ(svg.find("1\u2009mgL"), std::string::npos) << "a thin space in the alt text";
    std::filesystem::remove_all(dir);
}

// The figure's labels, as the plot layer draws them (PDF, PNG and SVG set the same markup):
// every energy with a thin space before mgL, in legends and titles alike.
TEST(TypesetFinal, TheEnergyUnitHasAThinSpaceInLegendsAndTitles) {
    const plot::theme th = figures::load_theme("paper");
    for (const char* id : {"regimes", "over-the-top"}) {
        const plot::figure fig = figures::build(figures::find(id), figures::sized_by({}, th));
        int energies = 0;
        for (const auto& p : fig.panels) {
            std::vector<std::string> texts{p.label.markup};
            for (const auto& s : p.data) texts.push_back(s.label.markup);
            for (const auto& text : texts) {
                if (text.find("mgL") == std::string::npos) continue;
                ++energies;
                EXPECT_NE(text.find("\u2009<i>mgL</i>"), std::string::npos) << id << ": " << text;
                EXPECT_EQ(text.find(" <i>mgL</i>"), std::string::npos) << id << ": " << text;
            }
        }
        EXPECT_GE(energies, 3) << id;
    }
}

// A theme below its minimum is one error line naming the key, the value and what to change.
TEST(TypesetFinal, AThemeBelowItsMinimumIsOneLine) {
    const auto dir = temp_dir("typeset-theme");
    const auto r = run_cli("render fig1 --set tick_font_pt=7 -o '" + dir.string() + "'");
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find("tick_font_pt = 7 is below the theme's min_text_pt = 8"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("raise tick_font_pt to 8 or more"), std::string::npos) << r.err;
    EXPECT_TRUE(std::filesystem::is_empty(dir));
    // The boundary of the tick labels' scripts (0.7 of the text, at least 6 pt): 8.58 is
    // accepted, 8.57 refused in one line.
    const auto ok = run_cli("render fig1 --set tick_font_pt=8.58 -f svg -o '" + dir.string() + "'");
    EXPECT_EQ(ok.status, 0) << ok.err;
    const auto below = run_cli("render fig1 --set tick_font_pt=8.57 -f svg -o '" + dir.string() + "'");
    EXPECT_EQ(below.status, 2);
    EXPECT_EQ(std::count(below.err.begin(), below.err.end(), '\n'), 1) << below.err;
    EXPECT_NE(below.err.find("raise tick_font_pt to 8.58 or more"), std::string::npos) << below.err;
    // A style file's problem: one line too, with the file and line.
    std::ofstream(dir / "small.toml") << "tick_font_pt = 7\n";
    const auto f = run_cli("render fig1 --theme '" + (dir / "small.toml").string() + "' -f svg -o '" + dir.string() + "'");
    EXPECT_EQ(f.status, 2);
    EXPECT_EQ(std::count(f.err.begin(), f.err.end(), '\n'), 1) << f.err;
    EXPECT_EQ(f.err.find("bad theme:\n"), std::string::npos) << f.err;
    std::filesystem::remove_all(dir);
}

namespace {

/// WCAG's relative luminance of an sRGB colour.
double luminance(const plot::rgb& c) {
    const auto lin = [](double v) { return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4); };
    return 0.2126 * lin(c.r) + 0.7152 * lin(c.g) + 0.0722 * lin(c.b);
}

/// WCAG's contrast ratio of two colours, 1 to 21.
double contrast(const plot::rgb& a, const plot::rgb& b) {
    const double la = luminance(a);
    const double lb = luminance(b);
    return (std::max(la, lb) + 0.05) / (std::min(la, lb) + 0.05);
}

/// A series' colour as drawn in the theme.
plot::rgb colour_of(const plot::series& s, const plot::theme& th) {
    return s.rgb_color ? *s.rgb_color : th.palette[static_cast<std::size_t>(s.color) % th.palette.size()];
}

/// The curve's points on the page, at most 0.05 pt apart.
std::vector<point> page_points(const plot::curve& c, const plot::axis_map& mx, const plot::axis_map& my) {
    std::vector<point> out;
    const int n = 20000;
    for (int i = 0; i <= n; ++i) {
        const auto [x, y] = c.at(c.u0 + (c.u1 - c.u0) * i / n);
        if (std::isfinite(mx(x)) && std::isfinite(my(y))) out.emplace_back(mx(x), my(y));
    }
    return out;
}

/// The least distance between two point sets, by a grid of 2-pt cells.
double least_distance(const std::vector<point>& a, const std::vector<point>& b) {
    std::map<std::pair<long, long>, std::vector<point>> cells;
    for (const point& q : b) cells[{static_cast<long>(std::floor(q.first / 2)), static_cast<long>(std::floor(q.second / 2))}].push_back(q);
    double best = 4.0;
    for (const point& p : a) {
        const long cx = static_cast<long>(std::floor(p.first / 2));
        const long cy = static_cast<long>(std::floor(p.second / 2));
        for (long i = cx - 1; i <= cx + 1; ++i) {
            for (long j = cy - 1; j <= cy + 1; ++j) {
                const auto it = cells.find({i, j});
                if (it == cells.end()) continue;
                for (const point& q : it->second) best = std::min(best, std::hypot(q.first - p.first, q.second - p.second));
            }
        }
    }
    return best;
}

}  // namespace

// The separatrix stands 3:1 or more against the background in every built-in theme (WCAG's
// contrast, from the theme's colours; slides-dark's was 2.88:1), and apart from every
// orbit's colour.
TEST(TypesetFinal, TheSeparatrixContrastsWithTheBackgroundInEveryTheme) {
    for (const auto& t : figures::builtin_themes()) {
        const plot::theme th = figures::load_theme(t.name);
        const plot::figure fig = plot::with_theme_styles(figures::build(figures::find("phase-portrait"), figures::sized_by({}, th)), th);
        int separatrix = 0;
        for (const auto& s : fig.panels.front().data) {
            if (s.label.markup != "separatrix") continue;
            ++separatrix;
            EXPECT_GE(contrast(colour_of(s, th), th.background), 3.0) << t.name;
            for (const auto& o : fig.panels.front().data) {
                if (o.rgb_color || !o.curve) continue;  // the separatrix' own halves
                const plot::rgb a = colour_of(s, th);
                const plot::rgb b = colour_of(o, th);
                EXPECT_FALSE(a.r == b.r && a.g == b.g && a.b == b.b) << t.name << " " << o.label.markup;
                // In the paper theme (black orbits) distinct in greyscale too. The slides
                // palettes hold greys as light as it (their orbits are told apart by colour).
                if (std::string(t.name) == "paper") {
                    EXPECT_GE(contrast(a, b), 3.0) << o.label.markup;
                }
            }
        }
        EXPECT_EQ(separatrix, 1) << t.name;  // its upper half carries the label
    }
}

// No two inks of the phase portrait (orbits and separatrix) come closer than 0.2 mm, in
// every built-in theme at its size: the separatrix is not hidden by an orbit beside it.
TEST(TypesetFinal, NoTwoPhaseInksCloserThanAFifthOfAMillimetre) {
    constexpr double mm = 72 / 25.4;
    for (const auto& t : figures::builtin_themes()) {
        const plot::theme th = figures::load_theme(t.name);
        const plot::figure fig = plot::with_theme_styles(figures::build(figures::find("phase-portrait"), figures::sized_by({}, th)), th);
        const auto frames = plot::panel_frames(fig, th);
        const plot::panel& p = fig.panels.front();
        const plot::panel_frame& f = frames.front();
        const plot::axis_map mx{f.x_lo, f.x_hi, false, f.x, f.x + f.w};
        const plot::axis_map my{f.y_lo, f.y_hi, false, f.y + f.h, f.y};
        std::vector<std::vector<point>> inks;
        std::vector<const plot::series*> series;
        for (const auto& s : p.data) {
            if (!s.curve || s.line == plot::line_style::none) continue;
            inks.push_back(page_points(*s.curve, mx, my));
            series.push_back(&s);
        }
        ASSERT_GE(inks.size(), 6u) << t.name;
        double least = 1e9;
        for (std::size_t a = 0; a < inks.size(); ++a) {
            for (std::size_t b = a + 1; b < inks.size(); ++b) {
                // The separatrix' two halves meet at +-pi: one line.
                if (series[a]->rgb_color && series[b]->rgb_color) continue;
                const double half_widths = 0.5 * th.line_width_pt * (series[a]->width_scale + series[b]->width_scale);
                const double gap = least_distance(inks[a], inks[b]) - half_widths;
                least = std::min(least, gap);
                EXPECT_GE(gap, 0.2 * mm) << t.name << " series " << a << " and " << b;
            }
        }
        std::cout << t.name << ": least ink gap " << least / mm << " mm\n";
    }
}

// Markers on evenly spaced data (the iteration's orders, a trajectory's time grid) stand at
// a whole step: every k-th point from the first, k constant per series (convergence had
// circles 1 and 2 orders apart by turns), and reach the last point where the data does
// (Fig. 6 had circles at t/T = 0 and none at 1).
TEST(TypesetFinal, MarkersOnEvenDataStandAtAWholeStep) {
    int strided = 0;
    for (const auto& t : figures::builtin_themes()) {
        const plot::theme th = figures::load_theme(t.name);
        for (const char* id : {"convergence", "trajectory-second", "trajectory-first"}) {
            const plot::figure fig = plot::with_theme_styles(figures::build(figures::find(id), figures::sized_by({}, th)), th);
            const auto frames = plot::panel_frames(fig, th);
            const auto centres = plot::marker_centres(fig, th);
            for (std::size_t i = 0; i < fig.panels.size(); ++i) {
                const plot::panel_frame& f = frames[i];
                for (std::size_t k = 0; k < fig.panels[i].data.size(); ++k) {
                    const plot::series& s = fig.panels[i].data[k];
                    const auto& m = centres[i][k];
                    if (!m.spaced || m.centres.size() < 2 || s.x.size() < 3) continue;
                    // Each drawn marker's index in the data, from its x on the page.
                    std::vector<long> index;
                    for (const auto& c : m.centres) {
                        const double x = f.x_lo + (c.first - f.x) / f.w * (f.x_hi - f.x_lo);
                        index.push_back(std::lround((x - s.x.front()) / (s.x[1] - s.x[0])));
                    }
                    const long step = index[1] - index[0];
                    for (std::size_t j = 1; j < index.size(); ++j) {
                        EXPECT_EQ(index[j] - index[j - 1], step) << id << " " << t.name << " panel " << i << " series " << k;
                    }
                    EXPECT_EQ(index.front(), 0) << id << " " << t.name;
                    if (std::string(id) != "convergence") {
                        EXPECT_EQ(index.back(), static_cast<long>(s.x.size()) - 1) << id << " " << t.name << " panel " << i;
                    }
                    ++strided;
                }
            }
        }
    }
    EXPECT_GE(strided, 12);
}

// A log axis with limits the spec fixes labels both its ends where a step up to twice the
// thinnest that fits divides its span: period-formulas (b), 1e-10 to 1, was labelled at
// 1e-10 and 1e-2 only (every 8 decades), the top 10^0 bare.
TEST(TypesetFinal, AFixedLogAxisLabelsBothEnds) {
    const plot::tick_set three = plot::log_ticks(1e-10, 1, 3, false);
    ASSERT_EQ(three.major.size(), 3u);
    EXPECT_DOUBLE_EQ(three.major.front(), 1e-10);
    EXPECT_DOUBLE_EQ(three.major[1], 1e-5);
    EXPECT_DOUBLE_EQ(three.major.back(), 1.0);
    EXPECT_EQ(three.labels.back(), "10<sup>0</sup>");
    const plot::tick_set two = plot::log_ticks(1e-10, 1, 2, false);
    ASSERT_EQ(two.major.size(), 2u);
    EXPECT_DOUBLE_EQ(two.major.back(), 1.0);
    // No divisor within twice the step: 11 decades (prime) keep the thinnest step.
    const plot::tick_set prime = plot::log_ticks(1e-11, 1, 3, false);
    EXPECT_DOUBLE_EQ(prime.major.front(), 1e-11);
    EXPECT_LE(prime.major.size(), 3u);
    // The built-in, as drawn: (b)'s labels end at 10^0.
    const plot::theme th = figures::load_theme("paper");
    const plot::figure fig = figures::build(figures::find("period-formulas"), figures::sized_by({}, th));
    const auto frames = plot::panel_frames(plot::with_theme_styles(fig, th), th);
    ASSERT_EQ(frames.size(), 2u);
    ASSERT_FALSE(frames[1].y_labels.empty());
    EXPECT_EQ(frames[1].y_labels.back(), "10<sup>0</sup>");
    EXPECT_EQ(frames[1].y_labels.front(), "10<sup>\u221210</sup>");
}
