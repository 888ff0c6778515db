// SPDX-License-Identifier: GPL-3.0-or-later
#include "figures/describe.hpp"

#include "figures/panel_support.hpp"
#include "figures/spec_build.hpp"

#include <algorithm>
#include <cmath>
#include <cctype>
#include <cstdio>
#include <numbers>
#include <optional>
#include <utility>
#include <vector>

namespace figures {

namespace {

using std::numbers::pi;

/// A number as a reader says it: three significant digits, an angle axis' in fractions of pi.
std::string spoken(double v, plot::tick_kind kind) {
    char buf[32];
    if (kind == plot::tick_kind::multiples_of_pi) {
        const double q = v / pi;
        // pi/6, pi/4, pi/3, pi/2 ... as fractions; others (0.99 pi) in decimals.
        for (int den : {1, 2, 3, 4, 6, 10, 12}) {
            const double num = std::round(q * den);
            if (std::fabs(q * den - num) > 1e-9) continue;
            if (num == 0) return "0";
            const long n = std::lround(num);
            std::string out = (n == 1 ? "" : n == -1 ? "-" : std::to_string(n)) + "pi";
            return den == 1 ? out : out + "/" + std::to_string(den);
        }
        std::snprintf(buf, sizeof buf, "%.3gpi", q);
        return buf;
    }
    std::snprintf(buf, sizeof buf, "%.3g", v);
    std::string out = buf;
    if (kind == plot::tick_kind::degrees) out += " degrees";
    return out;
}

/// A label as a screen reader should meet it: subscripts after the base (T0, T_N, c_(2k+1)),
/// Greek letters and primes spelt out, no markup.
std::string spoken_label(const std::string& markup) {
    std::string flat;
    for (std::size_t pos = 0; pos < markup.size();) {
        const bool sub = markup.compare(pos, 5, "<sub>") == 0;
        if (sub || markup.compare(pos, 5, "<sup>") == 0) {
            const std::size_t end = markup.find(sub ? "</sub>" : "</sup>", pos);
            if (end != std::string::npos) {
                const std::string inner = plain_text(markup.substr(pos + 5, end - pos - 5));
                const bool digits = inner.find_first_not_of("0123456789") == std::string::npos;
                const bool primes = inner.find_first_not_of("\u02b9\u2032'") == std::string::npos;
                if (sub && digits) {
                    flat += inner;
                } else if (primes) {
                    flat += inner;
                } else {
                    flat += std::string(sub ? "_" : "^") + (inner.size() > 1 ? "(" + inner + ")" : inner);
                }
                pos = end + 6;
                continue;
            }
        }
        flat += markup[pos++];
    }
    std::string out = plain_text(flat);
    const std::pair<const char*, const char*> words[] = {
        {"\u03d1", "theta"}, {"\u03b8", "theta"}, {"\u03c0", "pi"}, {"\u03c9", "omega"}, {"\u02b9", "'"},
        {"\u2032", "'"},     {"\u2212", "-"},     {"\u00b0", " degrees"}};
    for (const auto& [from, to] : words) {
        const std::string f = from;
        for (std::size_t pos = 0; (pos = out.find(f, pos)) != std::string::npos; pos += std::string(to).size()) {
            out.replace(pos, f.size(), to);
        }
    }
    return out;
}

/// Points along a series: its curve sampled finely where it has one, else its points.
std::vector<std::pair<double, double>> dense(const plot::series& s) {
    std::vector<std::pair<double, double>> out;
    if (s.curve) {
        constexpr int n = 2000;
        for (int i = 0; i <= n; ++i) {
            const double u = s.curve->u0 + (s.curve->u1 - s.curve->u0) * i / n;
            out.push_back(s.curve->at(u));
        }
    } else {
        for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) out.emplace_back(s.x[i], s.y[i]);
    }
    std::erase_if(out, [](const auto& p) { return !std::isfinite(p.first) || !std::isfinite(p.second); });
    return out;
}

/// y of a series at x, by linear interpolation between its points sorted by x; none outside them.
std::optional<double> value_at(const std::vector<std::pair<double, double>>& sorted, double x) {
    if (sorted.size() < 2 || x < sorted.front().first || x > sorted.back().first) return std::nullopt;
    const auto hi = std::lower_bound(sorted.begin(), sorted.end(), x,
                                     [](const auto& p, double v) { return p.first < v; });
    if (hi == sorted.begin()) return hi->second;
    const auto lo = hi - 1;
    if (hi->first == lo->first) return hi->second;
    return lo->second + (hi->second - lo->second) * (x - lo->first) / (hi->first - lo->first);
}

/// "from A to B" of the finite values of the panel's data on one axis (the axis' own
/// limits where it has them).
std::pair<double, double> data_range(const plot::panel& p, bool horizontal) {
    const plot::axis& a = horizontal ? p.x : p.y;
    double lo = INFINITY, hi = -INFINITY;
    for (const auto& s : p.data) {
        if (!s.autoscale || s.overlay) continue;
        for (const auto& [x, y] : dense(s)) {
            const double v = horizontal ? x : y;
            if (a.min && v < *a.min) continue;
            if (a.max && v > *a.max) continue;
            lo = std::min(lo, v);
            hi = std::max(hi, v);
        }
    }
    return {a.min.value_or(lo), a.max.value_or(hi)};
}

std::string how_drawn(const plot::series& s) {
    if (s.line == plot::line_style::none) {
        return s.marker == plot::marker_style::filled_circle ? "dots" : "circles";
    }
    static const char* const lines[] = {"", "solid line", "dashed line", "dotted line", "dash-dot line",
                                        "dash-dot-dot line"};
    return lines[static_cast<int>(s.line)];
}

std::string join(const std::vector<std::string>& items) {
    std::string out;
    for (std::size_t i = 0; i < items.size(); ++i) {
        out += i == 0 ? "" : i + 1 == items.size() ? (items.size() > 2 ? ", and " : " and ") : ", ";
        out += items[i];
    }
    return out;
}

std::string axis_name(const plot::axis& a, const char* fallback) {
    const std::string name = spoken_label(a.label.markup);
    return name.empty() ? fallback : name;
}

/// The panel's paragraph.
std::string describe_panel(const plot::panel& p, const panel_spec& spec, std::size_t index, std::size_t count) {
    // "Panel (a), theta0 = pi/3," or "Panel 2 (title)" or "The plot".
    const std::string title = spoken_label(p.label.markup);
    std::string out = count > 1 ? "Panel " + std::to_string(index + 1) : "The plot";
    if (title.starts_with("(")) {
        const auto close = title.find(')');
        const std::string rest = close == std::string::npos ? "" : title.substr(close + 1);
        out = "Panel " + title.substr(0, close + 1) +
              (rest.find_first_not_of(' ') == std::string::npos ? "" : "," + rest + ",");
    } else if (!title.empty()) {
        out += " (" + title + ")";
    }
    std::vector<const plot::series*> shown;
    for (const auto& s : p.data) {
        if (s.autoscale && !s.overlay && !s.label.empty()) shown.push_back(&s);
    }
    if (p.frameless) {
        std::vector<std::string> names;
        for (const auto* s : shown) names.push_back(spoken_label(s->label.markup));
        out += " is a drawing" + (names.empty() ? "" : ", with " + join(names)) + ".";
        // What each start launched from the bottom, or from a state, does.
        std::vector<std::string> motions;
        for (const auto& start : spec.starts) {
            const char* what = "swings between two turning points";
            if (start.motion.kind() == pendulum::regime::separatrix) {
                what = "creeps up towards the top and never quite reaches it";
            } else if (start.motion.kind() == pendulum::regime::rotation) {
                what = "goes over the top, round and round";
            }
            motions.push_back(spoken_label(start.label) + " " + what + " (" +
                              std::string(pendulum::row_of(start.motion.kind()).name) + ")");
        }
        if (!motions.empty()) out += " Started together: " + join(motions) + ".";
        return out;
    }
    const std::string x = axis_name(p.x, "x"), y = axis_name(p.y, "y");
    const auto [x0, x1] = data_range(p, true);
    auto [y0, y1] = data_range(p, false);
    // A limit a millionth of the range from zero is zero (a coefficient that vanishes at 0).
    if (p.y.kind == plot::scale::linear) {
        if (std::fabs(y0) < 1e-6 * (y1 - y0)) y0 = 0;
        if (std::fabs(y1) < 1e-6 * (y1 - y0)) y1 = 0;
    }
    out += " shows " + y + " against " + x + ", " + x + " from " + spoken(x0, p.x.ticks) + " to " +
           spoken(x1, p.x.ticks) + (p.x.kind == plot::scale::log ? " on a logarithmic scale" : "") + ", " + y +
           " from " + spoken(y0, p.y.ticks) + " to " + spoken(y1, p.y.ticks) +
           (p.y.kind == plot::scale::log ? " on a logarithmic scale" : "") + ".";
    if (!shown.empty()) {
        std::vector<std::string> items;
        for (const auto* s : shown) items.push_back(spoken_label(s->label.markup) + " (" + how_drawn(*s) + ")");
        out += std::string(shown.size() == 1 ? " One curve: " : " Curves: ") + join(items) + ".";
    }
    // Where each approximation leaves the exact curve by a visible amount.
    const plot::series* exact = nullptr;
    for (const auto* s : shown) {
        if (spoken_label(s->label.markup).starts_with("exact")) exact = s;
    }
    // An error axis in per cent has its exact curve at zero.
    std::optional<plot::series> zero;
    std::string reference_name = "the exact curve";
    if (!exact && spec.y == period_axis::error_percent) {
        zero.emplace();
        zero->x = {x0, x1};
        zero->y = {0, 0};
        exact = &*zero;
        reference_name = "zero";
    }
    if (exact && p.y.kind == plot::scale::linear && y1 > y0) {
        auto reference = dense(*exact);
        std::sort(reference.begin(), reference.end());
        const double visible = visible_fraction * (y1 - y0);
        std::vector<std::string> leaves, stays;
        for (const auto* s : shown) {
            if (s == exact) continue;
            std::optional<double> at;
            double covered_to = -INFINITY;
            auto points = dense(*s);
            std::sort(points.begin(), points.end());
            for (const auto& [px, py] : points) {
                const auto e = value_at(reference, px);
                if (!e) continue;
                covered_to = px;
                if (std::fabs(py - *e) > visible) {
                    at = px;
                    break;
                }
            }
            const std::string name = spoken_label(s->label.markup);
            if (at) {
                leaves.push_back(name + " at " + x + " = " + spoken(*at, p.x.ticks));
            } else if (std::isfinite(covered_to)) {
                stays.push_back(name);
            }
        }
        char pct[16];
        std::snprintf(pct, sizeof pct, "%g", visible_fraction * 100);
        if (!leaves.empty()) {
            out += " Leaving " + reference_name + " by more than " + std::string(pct) + " % of the " + y +
                   " axis: " + join(leaves) + ".";
        }
        if (!stays.empty()) {
            std::string who = join(stays);
            if (std::islower(static_cast<unsigned char>(who[0]))) who[0] = static_cast<char>(std::toupper(who[0]));
            out += " " + who + (stays.size() == 1 ? " stays" : " stay") + " on " + reference_name + " over " +
                   (leaves.empty() ? "the whole" : "its whole") + " range.";
        }
    }
    // On a logarithmic axis, the values in the middle of the x range tell the curves apart.
    if (p.y.kind == plot::scale::log && !shown.empty()) {
        const double mid = p.x.kind == plot::scale::log ? std::sqrt(x0 * x1) : (x0 + x1) / 2;
        std::vector<std::string> values;
        for (const auto* s : shown) {
            auto points = dense(*s);
            std::sort(points.begin(), points.end());
            if (const auto v = value_at(points, mid)) values.push_back(spoken_label(s->label.markup) + " " + spoken(*v, p.y.ticks));
        }
        if (!values.empty()) out += " At " + x + " = " + spoken(mid, p.x.ticks) + ": " + join(values) + ".";
    }
    if (spec.energy_axis && x0 < 2 && 2 < x1) {
        out += " A dotted vertical line marks the separatrix at E = 2, where the period diverges from both "
               "sides: the libration's period below it, the time of one revolution above it.";
    }
    // Reference lines, and where the curves cross them.
    for (const auto& line : spec.lines) {
        const std::string label = line.label.empty() ? "" : " (" + plot::tex_to_plain(line.label) + ")";
        if (line.y) {
            out += " A horizontal line at " + y + " = " + spoken(*line.y, p.y.ticks) + label;
            if (line.span) {
                out += " runs from " + x + " = " + spoken(to_axis_angle(spec, (*line.span)[0]), p.x.ticks) + " to " +
                       spoken(to_axis_angle(spec, (*line.span)[1]), p.x.ticks);
            }
            std::vector<std::string> crossings;
            for (const auto* s : shown) {
                auto points = dense(*s);
                std::sort(points.begin(), points.end());
                for (std::size_t i = 1; i < points.size(); ++i) {
                    const double a = points[i - 1].second - *line.y, b = points[i].second - *line.y;
                    if ((a < 0) != (b < 0)) {
                        crossings.push_back(spoken_label(s->label.markup) + " at " + x + " = " +
                                            spoken(points[i].first, p.x.ticks));
                        break;
                    }
                }
            }
            out += crossings.empty() ? "; no curve crosses it." : "; first crossed by " + join(crossings) + ".";
        } else if (line.x) {
            out += " A vertical line marks " + x + " = " + spoken(*line.x, p.x.ticks) + label + ".";
        }
    }
    return out;
}

}  // namespace

figure_description describe(const entry& e, const plot::figure& built, const build_options& options) {
    const auto panels = panels_with(e.spec, options);
    figure_description d;
    d.alt = e.description() + ".";
    if (built.panels.size() > 1) d.alt += " " + std::to_string(built.panels.size()) + " panels.";
    if (e.spec.animation) {
        const auto& a = *e.spec.animation;
        char buf[160];
        if (a.duration_s) {
            std::snprintf(buf, sizeof buf, "An animation of %g s at %g frames per second.", *a.duration_s, a.fps);
        } else {
            std::snprintf(buf, sizeof buf, "An animation over %g periods of the exact motion, at %g frames per second.",
                          a.periods.value_or(1.0), a.fps);
        }
        d.text += std::string(buf) + " Its first frame:\n";
    }
    const std::string title = spoken_label(built.title.markup);
    if (!title.empty()) d.text = "Title: " + title + ".\n" + d.text;
    for (std::size_t i = 0; i < built.panels.size() && i < panels.size(); ++i) {
        d.text += describe_panel(built.panels[i], panels[i], i, built.panels.size()) + "\n";
    }
    return d;
}

}  // namespace figures
