// SPDX-License-Identifier: GPL-3.0-or-later
#include "figures/describe.hpp"

#include "figures/panel_support.hpp"
#include "figures/spec_build.hpp"
#include "figures/themes.hpp"
#include "plot/geometry.hpp"
#include "plot/render.hpp"

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
        std::snprintf(buf, sizeof buf, "%.3g", q);
        const std::string digits = buf;
        // Near a whole pi, said as pi ("1pi" reads badly).
        if (digits == "1" || digits == "-1") return (digits == "1" ? "" : "-") + std::string("pi");
        return digits + "pi";
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
        // About 512 values, shared with the drawing through the curve's memo (a costly
        // function, an error in MPFR, is evaluated once between them).
        out = plot::first_values(*s.curve, 512);
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
    if (s.data_slot >= 0) return s.errors.empty() ? "measured points" : "measured points with error bars";
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

/// An amplitude as its spec gives it: in degrees if it was given in degrees, else in pi.
std::string spoken_amplitude(const amplitude& a) {
    if (a.text.find("deg") != std::string::npos) return spoken(a.value * 180 / pi, plot::tick_kind::nice) + " degrees";
    return spoken(a.value, plot::tick_kind::multiples_of_pi);
}

/// What each start launched together does: "E = 2.6 goes over the top, round and round
/// (rotation)"; empty without starts.
std::string start_motions(const panel_spec& spec) {
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
    return motions.empty() ? "" : " Started together: " + join(motions) + ".";
}

/// The pendulum drawing: what is drawn, each pendulum's rod and bob, where they start.
std::string pendulum_drawing(const panel_spec& spec, bool animated) {
    static const char* const lines[] = {"solid", "solid", "dashed", "dotted", "dash-dot", "dash-dot-dot"};
    std::vector<std::string> who;
    for (std::size_t i = 0; i < spec.methods.size(); ++i) {
        const method_spec& m = spec.methods[i];
        const plot::line_style line = m.style.value_or(plot::line_style::solid);
        const plot::marker_style bob =
            m.marker.value_or(is_exact(m) ? plot::marker_style::filled_circle : plot::marker_style::open_circle);
        who.push_back(spoken_label(style_of(m, static_cast<int>(i)).label.markup) + " (" +
                      lines[static_cast<int>(line)] + " rod, " +
                      (bob == plot::marker_style::filled_circle ? "filled" : "open") + " bob)");
    }
    const std::size_t n = spec.methods.size() * std::max<std::size_t>(1, spec.starts.size());
    std::string out = " is a drawing, seen from the side, of " +
                      (n == 1 ? std::string("a pendulum") : std::to_string(n) + " pendulums of one length") +
                      " hanging from one pivot: " + join(who) + ".";
    if (!spec.theta0.empty()) {
        out += std::string(n == 1 ? " It is" : " They are") + " released from rest at theta0 = " +
               spoken_amplitude(spec.theta0.front()) +
               " from the vertical; dotted lines mark that angle on either side, and a faint circle the path of "
               "the bobs.";
    }
    if (spec.trail > 0) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%g", spec.trail);
        out += " Each bob leaves a fading trail of its last " + std::string(buf) + " periods.";
    }
    out += start_motions(spec);
    if (animated && spec.methods.size() > 1) {
        out += " They swing side by side, the approximations drifting from the exact pendulum.";
    }
    return out;
}

/// "+-A" for a range symmetric about zero, "from A to B" otherwise.
std::string extent(double lo, double hi, plot::tick_kind kind) {
    if (std::fabs(lo + hi) <= 1e-3 * (hi - lo)) return "+-" + spoken(hi, kind);
    return "from " + spoken(lo, kind) + " to " + spoken(hi, kind);
}

/// Each orbit of a phase plot: its shape and how far it reaches on both axes.
std::string phase_orbits(const plot::panel& p, const std::vector<const plot::series*>& shown, const std::string& x,
                         const std::string& y) {
    std::vector<std::string> closed, touching, open;
    for (const auto* s : shown) {
        auto points = dense(*s);
        if (points.empty()) continue;
        std::sort(points.begin(), points.end());
        double y0 = INFINITY, y1 = -INFINITY, peak_x = 0;
        for (const auto& [px, py] : points) {
            y0 = std::min(y0, py);
            if (py > y1) peak_x = px;
            y1 = std::max(y1, py);
        }
        const double x0 = points.front().first, x1 = points.back().first;
        const std::string name = spoken_label(s->label.markup);
        const double near = 1e-3 * std::max(std::fabs(y0), std::fabs(y1));
        if (y0 < -near && y1 > near) {
            closed.push_back(name + ": " + x + " " + extent(x0, x1, p.x.ticks) + ", " + y + " " +
                             extent(y0, y1, p.y.ticks));
        } else if (std::min(std::fabs(y0), std::fabs(y1)) <= near) {
            const bool above = y1 > near;
            touching.push_back(name + " meets " + y + " = 0 at " + x + " = " + spoken(x0, p.x.ticks) + " and " +
                               spoken(x1, p.x.ticks) + " and reaches " + spoken(above ? y1 : y0, p.y.ticks) + " at " +
                               x + " = " + spoken(above ? peak_x : x0, p.x.ticks) +
                               (name == "separatrix" ? ", with its mirror image below: the boundary between "
                                                       "swinging and going over the top"
                                                     : ""));
        } else {
            open.push_back(name + ": " + y + " " + extent(y0, y1, p.y.ticks) + ", " + (y0 > 0 ? "above" : "below") +
                           " the axis");
        }
    }
    std::string out;
    if (!closed.empty()) {
        out += std::string(closed.size() == 1 ? " A closed curve" : " Closed curves") + " around the origin (" +
               y + " is largest at " + x + " = 0 and zero at the turning points)" +
               (closed.size() == 1 ? ": " : ", nested by size: ") + join(closed) + ".";
    }
    if (!touching.empty()) {
        std::string who = join(touching);
        who[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(who[0])));
        out += " " + who + ".";
    }
    if (!open.empty()) {
        out += std::string(open.size() == 1 ? " A curve" : " Curves") + " across the whole width, never reaching " +
               y + " = 0 (rotations): " + join(open) + ".";
    }
    return out;
}

/// The panel's paragraph.
std::string describe_panel(const plot::panel& p, const panel_spec& spec, std::size_t index, std::size_t count,
                           const plot::panel_frame* frame, bool animated) {
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
    if (p.frameless && spec.plot->name == "pendulum") return out + pendulum_drawing(spec, animated);
    if (p.frameless) {
        std::vector<std::string> names;
        for (const auto* s : shown) names.push_back(spoken_label(s->label.markup));
        out += " is a drawing" + (names.empty() ? "" : ", with " + join(names)) + ".";
        return out + start_motions(spec);
    }
    const std::string x = axis_name(p.x, "x"), y = axis_name(p.y, "y");
    // The data as far as the axes show it (a curve that leaves them is cut at their
    // limits), and the axes' own limits where they reach well past the data.
    auto [x0, x1] = data_range(p, true);
    auto [y0, y1] = data_range(p, false);
    std::string x_axis, y_axis;
    if (frame) {
        const auto visible = [](double& lo, double& hi, double axis_lo, double axis_hi, plot::tick_kind kind,
                                std::string& axis) {
            if (!(axis_hi > axis_lo)) return;
            if (!(lo >= axis_lo)) lo = axis_lo;
            if (!(hi <= axis_hi)) hi = axis_hi;
            const double room = 0.15 * (axis_hi - axis_lo);
            if (lo - axis_lo > room || axis_hi - hi > room) {
                axis = " (its axis from " + spoken(axis_lo, kind) + " to " + spoken(axis_hi, kind) + ")";
            }
        };
        if (p.x.kind == plot::scale::linear) visible(x0, x1, frame->x_lo, frame->x_hi, p.x.ticks, x_axis);
        if (p.y.kind == plot::scale::linear) visible(y0, y1, frame->y_lo, frame->y_hi, p.y.ticks, y_axis);
    }
    // A limit a millionth of the range from zero is zero (a coefficient that vanishes at 0).
    if (p.y.kind == plot::scale::linear) {
        if (std::fabs(y0) < 1e-6 * (y1 - y0)) y0 = 0;
        if (std::fabs(y1) < 1e-6 * (y1 - y0)) y1 = 0;
    }
    out += " shows " + y + " against " + x + ", " + x + " from " + spoken(x0, p.x.ticks) + " to " +
           spoken(x1, p.x.ticks) + (p.x.kind == plot::scale::log ? " on a logarithmic scale" : "") + x_axis + ", " +
           y + " from " + spoken(y0, p.y.ticks) + " to " + spoken(y1, p.y.ticks) +
           (p.y.kind == plot::scale::log ? " on a logarithmic scale" : "") + y_axis + ".";
    if (!shown.empty()) {
        std::vector<std::string> items;
        for (const auto* s : shown) items.push_back(spoken_label(s->label.markup) + " (" + how_drawn(*s) + ")");
        out += std::string(shown.size() == 1 ? " One curve: " : " Curves: ") + join(items) + ".";
    }
    if (spec.plot->name == "phase") out += phase_orbits(p, shown, x, y);
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

/// The panels' axes as the paper theme lays the figure out (the limits a reader sees);
/// none if it cannot be laid out so.
std::vector<plot::panel_frame> drawn_frames(const plot::figure& built) {
    try {
        static const plot::theme paper = load_theme("paper", {});
        return plot::panel_frames(built, paper);
    } catch (const std::exception&) {
        return {};
    }
}

}  // namespace

figure_description describe(const entry& e, const plot::figure& built, const build_options& options) {
    return describe(e.spec, built, options);
}

figure_description describe(const figure_spec& spec, const plot::figure& unstyled, const build_options& options) {
    // The lines as the default theme draws them (its named styles: harmonic dotted), as
    // the limits are the ones it lays out.
    static const plot::theme paper = load_theme("paper", {});
    const plot::figure built = plot::with_theme_styles(unstyled, paper);
    const auto panels = panels_with(spec, options);
    figure_description d;
    d.alt = (spec.description.empty() ? plot::tex_to_plain(spec.title) : spec.description) + ".";
    if (built.panels.size() > 1) d.alt += " " + std::to_string(built.panels.size()) + " panels.";
    if (spec.animation) {
        const auto& a = *spec.animation;
        char buf[160];
        if (a.duration_s) {
            std::snprintf(buf, sizeof buf, "An animation of %g s at %g frames per second.", *a.duration_s, a.fps);
        } else {
            const double periods = a.periods.value_or(1.0);
            std::snprintf(buf, sizeof buf, "An animation over %g period%s of the exact motion, at %g frames per second.",
                          periods, periods == 1 ? "" : "s", a.fps);
        }
        d.text += std::string(buf) + " Its first frame:\n";
    }
    const std::string title = spoken_label(built.title.markup);
    if (!title.empty()) d.text = "Title: " + title + ".\n" + d.text;
    const std::vector<plot::panel_frame> frames = drawn_frames(built);
    for (std::size_t i = 0; i < built.panels.size() && i < panels.size(); ++i) {
        d.text += describe_panel(built.panels[i], panels[i], i, built.panels.size(),
                                 i < frames.size() ? &frames[i] : nullptr, spec.animation.has_value()) +
                  "\n";
    }
    return d;
}

}  // namespace figures
