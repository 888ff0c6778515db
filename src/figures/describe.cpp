// SPDX-License-Identifier: GPL-3.0-or-later
#include "figures/describe.hpp"

#include "figures/describe_support.hpp"

#include "figures/panel_support.hpp"
#include "figures/spec_build.hpp"
#include "figures/themes.hpp"
#include "plot/math_layout.hpp"
#include "plot/geometry.hpp"
#include "plot/render.hpp"

#include <algorithm>
#include <cmath>
#include <cctype>
#include <cstdio>
#include <numbers>
#include <optional>
#include <tuple>
#include <unordered_map>
#include <utility>
#include <vector>

namespace figures {

using std::numbers::pi;

namespace {

/// A multiple of pi as a reader says it: pi/6, pi/4, pi/3, pi/2 ... as fractions; others
/// (0.99 pi) in decimals.
std::string spoken_pi(double v) {
    const double q = v / pi;
    for (int den : {1, 2, 3, 4, 6, 10, 12}) {
        const double num = std::round(q * den);
        if (std::fabs(q * den - num) > 1e-9) continue;
        if (num == 0) return "0";
        const long n = std::lround(num);
        std::string out = (n == 1 ? "" : n == -1 ? "-" : std::to_string(n)) + "pi";
        return den == 1 ? out : out + "/" + std::to_string(den);
    }
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3g", q);
    const std::string digits = buf;
    // Near a whole pi, said as pi ("1pi" reads badly).
    if (digits == "1" || digits == "-1") return (digits == "1" ? "" : "-") + std::string("pi");
    return digits + "pi";
}

/// A <sub> or <sup> element's text as a reader meets it after its base: digits and primes
/// as they are, others after _ or ^ (in parentheses when longer than one character).
std::string spoken_script(const std::string& inner, bool sub) {
    const bool digits = inner.find_first_not_of("0123456789") == std::string::npos;
    const bool primes = inner.find_first_not_of("\u02b9\u2032'") == std::string::npos;
    if ((sub && digits) || primes) return inner;
    return std::string(sub ? "_" : "^") + (inner.size() > 1 ? "(" + inner + ")" : inner);
}

/// The markup with its subscripts and superscripts written after their base.
std::string flat_scripts(const std::string& markup) {
    std::string flat;
    for (std::size_t pos = 0; pos < markup.size();) {
        const bool sub = markup.compare(pos, 5, "<sub>") == 0;
        if (sub || markup.compare(pos, 5, "<sup>") == 0) {
            const std::size_t end = markup.find(sub ? "</sub>" : "</sup>", pos);
            if (end != std::string::npos) {
                flat += spoken_script(plain_text(markup.substr(pos + 5, end - pos - 5)), sub);
                pos = end + 6;
                continue;
            }
        }
        flat += markup[pos++];
    }
    return flat;
}

}  // namespace

std::string spoken(double v, plot::tick_kind kind) {
    if (kind == plot::tick_kind::multiples_of_pi) return spoken_pi(v);
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3g", v);
    std::string out = buf;
    if (kind == plot::tick_kind::degrees) out += " degrees";
    return out;
}

std::string spoken_label(const std::string& markup) {
    std::string out = plain_text(flat_scripts(plot::inline_fractions(markup)));
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

namespace {

/// Points along a series, in its order.
using points = std::vector<std::pair<double, double>>;

/// What the describe call on this thread knows: each curve's finite points found so far (the
/// words read them a few times over), from the start those a file's drawing drew.
struct describing {
    std::unordered_map<const plot::curve*, points> curves{};  ///< each curve's points
};

/// Points without their non-finite ones.
points finite(points p) {
    std::erase_if(p, [](const auto& v) { return !std::isfinite(v.first) || !std::isfinite(v.second); });
    return p;
}

/// This thread's describe call, if any.
thread_local describing* current = nullptr;

/// A describe call on this thread while it lives.
class describing_scope {
public:
    /// The words of `built`, drawn by `drawn` (null: not drawn).
    describing_scope(const plot::figure& built, const plot::drawing* drawn) : outer_(current) {
        // The curves the file drew, at the vertices it drew (their values are in the curves'
        // memos: nothing is evaluated, and the words are the file's whatever else drew the
        // figure first).
        if (drawn) {
            for (auto& [c, values] : plot::drawn_curve_values(built, *drawn)) {
                if (!values.empty()) now_.curves.emplace(c, finite(std::move(values)));
            }
        }
        current = &now_;
    }
    ~describing_scope() { current = outer_; }
    describing_scope(const describing_scope&) = delete;
    describing_scope& operator=(const describing_scope&) = delete;

private:
    describing now_;
    describing* outer_;
};

/// A curve's finite points where the file did not draw it: about 512 values shared with a
/// later drawing through the curve's memo (a costly function, an error in MPFR, is evaluated
/// once between them).
points curve_points(const plot::curve& c) { return finite(plot::first_values(c, 512)); }

/// A series' points: its curve's (found once per describe call), else its own finite points.
points points_of(const plot::series& s) {
    if (s.curve) {
        if (!current) return curve_points(*s.curve);
        const auto known = current->curves.find(s.curve.get());
        if (known != current->curves.end()) return known->second;
        return current->curves.emplace(s.curve.get(), curve_points(*s.curve)).first->second;
    }
    points out;
    for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) out.emplace_back(s.x[i], s.y[i]);
    return finite(std::move(out));
}

/// points_of, sorted by x.
points sorted_points(const plot::series& s) {
    points out = points_of(s);
    std::sort(out.begin(), out.end());
    return out;
}

}  // namespace

/// Points along a series: its curve sampled finely where it has one, else its points.
std::vector<std::pair<double, double>> dense(const plot::series& s) { return points_of(s); }

namespace {

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

}  // namespace

std::string join(const std::vector<std::string>& items) {
    std::string out;
    for (std::size_t i = 0; i < items.size(); ++i) {
        out += i == 0 ? "" : i + 1 == items.size() ? (items.size() > 2 ? ", and " : " and ") : ", ";
        out += items[i];
    }
    return out;
}

namespace {

std::string axis_name(const plot::axis& a, const char* fallback) {
    const std::string name = spoken_label(a.label.markup);
    return name.empty() ? fallback : name;
}

}  // namespace

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

/// "+-A" for a range symmetric about zero, "from A to B" otherwise.
std::string extent(double lo, double hi, plot::tick_kind kind) {
    if (std::fabs(lo + hi) <= 1e-3 * (hi - lo)) return "+-" + spoken(hi, kind);
    return "from " + spoken(lo, kind) + " to " + spoken(hi, kind);
}

namespace {

/// A panel being described: its data, spec, curves, axis names and the ranges shown.
struct panel_words {
    const plot::panel& p;                       ///< the built panel
    const panel_spec& spec;                     ///< its spec
    std::vector<const plot::series*> shown;     ///< its curves with a legend label
    std::string x, y;                           ///< the axes' names as spoken
    double x0 = 0, x1 = 0, y0 = 0, y1 = 0;      ///< the data's ranges as the axes show them
    double axis_y0 = 0, axis_y1 = 0;            ///< the y axis' limits (the data's range without a layout)
};

/// "Panel (a), theta0 = pi/3," or "Panel 2 (title)" or "The plot".
std::string panel_opening(const plot::panel& p, std::size_t index, std::size_t count) {
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
    return out;
}

/// A drawing's description: the kind's own (its glyphs in theme `th`), or what it shows and its starts.
std::string drawing_words(const panel_words& w, bool animated, const plot::theme& th) {
    if (w.spec.plot->describe_drawing) return w.spec.plot->describe_drawing(w.spec, animated, th);
    std::vector<std::string> names;
    for (const auto* s : w.shown) names.push_back(spoken_label(s->label.markup));
    return " is a drawing" + (names.empty() ? "" : ", with " + join(names)) + "." + start_motions(w.spec);
}

/// Cuts the data's range [lo, hi] to the axis' limits, noting the axis' limits in `axis`
/// where they reach well past the data.
void clip_to_axis(double& lo, double& hi, double axis_lo, double axis_hi, plot::tick_kind kind, std::string& axis) {
    if (!(axis_hi > axis_lo)) return;
    if (!(lo >= axis_lo)) lo = axis_lo;
    if (!(hi <= axis_hi)) hi = axis_hi;
    const double room = 0.15 * (axis_hi - axis_lo);
    if (lo - axis_lo > room || axis_hi - hi > room) {
        axis = " (its axis from " + spoken(axis_lo, kind) + " to " + spoken(axis_hi, kind) + ")";
    }
}

/// The axes' sentence: "shows y against x, x from A to B, y from C to D.", setting the ranges
/// of `w` as the axes show the data (a curve that leaves them is cut at their limits).
std::string axes_words(panel_words& w, const plot::panel_frame* frame) {
    const plot::panel& p = w.p;
    std::tie(w.x0, w.x1) = data_range(p, true);
    std::tie(w.y0, w.y1) = data_range(p, false);
    std::string x_axis, y_axis;
    if (frame && p.x.kind == plot::scale::linear) clip_to_axis(w.x0, w.x1, frame->x_lo, frame->x_hi, p.x.ticks, x_axis);
    if (frame && p.y.kind == plot::scale::linear) clip_to_axis(w.y0, w.y1, frame->y_lo, frame->y_hi, p.y.ticks, y_axis);
    // A limit a millionth of the range from zero is zero (a coefficient that vanishes at 0).
    if (p.y.kind == plot::scale::linear) {
        if (std::fabs(w.y0) < 1e-6 * (w.y1 - w.y0)) w.y0 = 0;
        if (std::fabs(w.y1) < 1e-6 * (w.y1 - w.y0)) w.y1 = 0;
    }
    w.axis_y0 = frame ? frame->y_lo : w.y0;
    w.axis_y1 = frame ? frame->y_hi : w.y1;
    const std::string& x = w.x;
    const std::string& y = w.y;
    return " shows " + y + " against " + x + ", " + x + " from " + spoken(w.x0, p.x.ticks) + " to " +
           spoken(w.x1, p.x.ticks) + (p.x.kind == plot::scale::log ? " on a logarithmic scale" : "") + x_axis + ", " +
           y + " from " + spoken(w.y0, p.y.ticks) + " to " + spoken(w.y1, p.y.ticks) +
           (p.y.kind == plot::scale::log ? " on a logarithmic scale" : "") + y_axis + ".";
}

/// "Curves: exact (solid line), ...".
std::string curves_words(const panel_words& w) {
    if (w.shown.empty()) return {};
    std::vector<std::string> items;
    for (const auto* s : w.shown) items.push_back(spoken_label(s->label.markup) + " (" + how_drawn(*s) + ")");
    return std::string(w.shown.size() == 1 ? " One curve: " : " Curves: ") + join(items) + ".";
}

/// y of a series at x: its function's value where it is a function y = f(x) defined at x,
/// else between its points (sorted by x); none outside them.
std::optional<double> y_of(const plot::series& s, const points& sorted, double x) {
    if (s.curve && x >= s.curve->u0 && x <= s.curve->u1) {
        const auto [cx, cy] = plot::curve_at(*s.curve, x);  // through the memo: dense() and the drawing evaluated most
        if (cx == x && std::isfinite(cy)) return cy;
    }
    return value_at(sorted, x);
}

/// Where series s first leaves the reference by more than `visible` (none if it never does):
/// the first of its points past it, then the crossing between it and the point before, by
/// bisection on the functions where both curves are functions of x. `covered`: whether any
/// point of s lies within the reference's x range.
std::optional<double> departure(const plot::series& reference, const points& sorted, const plot::series& s,
                                double visible, bool& covered) {
    const points along = sorted_points(s);
    covered = false;
    const auto gap = [&](double x) -> std::optional<double> {
        const auto e = y_of(reference, sorted, x);
        const auto y = y_of(s, along, x);
        if (!e || !y) return std::nullopt;
        return std::fabs(*y - *e);
    };
    std::optional<double> inside;
    for (const auto& [px, py] : along) {
        const auto g = gap(px);
        if (!g) continue;
        covered = true;
        if (*g <= visible) {
            inside = px;
            continue;
        }
        if (!inside) return px;
        double lo = *inside, hi = px;
        for (int k = 0; k < 80 && hi - lo > 1e-15 * std::fabs(hi); ++k) {
            const double mid = lo + (hi - lo) / 2;
            const auto gm = gap(mid);
            (gm && *gm > visible ? hi : lo) = mid;
        }
        return hi;
    }
    return std::nullopt;
}

/// The sentences of the curves leaving the reference, and of those staying on it.
std::string departures_words(const panel_words& w, const plot::series& exact, const std::string& reference_name) {
    const points reference = sorted_points(exact);
    // A fraction of the axis, as the sentence says (the axis reaches past the data).
    const double visible = visible_fraction * (w.axis_y1 - w.axis_y0);
    std::vector<std::string> leaves, stays;
    for (const auto* s : w.shown) {
        if (s == &exact) continue;
        bool covered = false;
        const auto at = departure(exact, reference, *s, visible, covered);
        const std::string name = spoken_label(s->label.markup);
        if (at) {
            leaves.push_back(name + " at " + w.x + " = " + spoken(*at, w.p.x.ticks));
        } else if (covered) {
            stays.push_back(name);
        }
    }
    std::string out;
    char pct[16];
    std::snprintf(pct, sizeof pct, "%g", visible_fraction * 100);
    if (!leaves.empty()) {
        out += " Leaving " + reference_name + " by more than " + std::string(pct) + " % of the " + w.y +
               " axis: " + join(leaves) + ".";
    }
    if (!stays.empty()) {
        std::string who = join(stays);
        if (std::islower(static_cast<unsigned char>(who[0]))) who[0] = static_cast<char>(std::toupper(who[0]));
        out += " " + who + (stays.size() == 1 ? " stays" : " stay") + " on " + reference_name + " over " +
               (leaves.empty() ? "the whole" : "its whole") + " range.";
    }
    return out;
}

/// Where each approximation leaves the exact curve by a visible amount (on an error axis in
/// per cent, the exact curve is zero).
std::string exact_words(const panel_words& w) {
    const plot::series* exact = nullptr;
    for (const auto* s : w.shown) {
        if (spoken_label(s->label.markup).starts_with("exact")) exact = s;
    }
    std::optional<plot::series> zero;
    std::string reference_name = "the exact curve";
    if (!exact && w.spec.y == period_axis::error_percent) {
        zero.emplace();
        zero->x = {w.x0, w.x1};
        zero->y = {0, 0};
        exact = &*zero;
        reference_name = "zero";
    }
    if (!exact || w.p.y.kind != plot::scale::linear || !(w.y1 > w.y0)) return {};
    return departures_words(w, *exact, reference_name);
}

/// On a logarithmic axis, the values in the middle of the x range tell the curves apart.
std::string middle_words(const panel_words& w) {
    const plot::panel& p = w.p;
    if (p.y.kind != plot::scale::log || w.shown.empty()) return {};
    const double mid = p.x.kind == plot::scale::log ? std::sqrt(w.x0 * w.x1) : (w.x0 + w.x1) / 2;
    std::vector<std::string> values;
    for (const auto* s : w.shown) {
        auto points = dense(*s);
        std::sort(points.begin(), points.end());
        if (const auto v = value_at(points, mid)) values.push_back(spoken_label(s->label.markup) + " " + spoken(*v, p.y.ticks));
    }
    if (values.empty()) return {};
    return " At " + w.x + " = " + spoken(mid, p.x.ticks) + ": " + join(values) + ".";
}

/// Where the segment from p to q, whose ends lie on either side of the horizontal line at y,
/// meets it, as the axes draw the segment: straight in a logarithmic y axis' logarithms.
double crossing_x(const plot::panel& panel, const std::pair<double, double>& p, const std::pair<double, double>& q,
                  double y) {
    const bool log_y = panel.y.kind == plot::scale::log && p.second > 0 && q.second > 0 && y > 0;
    const auto in_y = [&](double v) { return log_y ? std::log10(v) : v; };
    const double a = in_y(p.second) - in_y(y);
    const double b = in_y(q.second) - in_y(y);
    return p.first + (q.first - p.first) * (a / (a - b));
}

/// Where the curves first cross a horizontal line at y: between the first two of their
/// points (sorted by x) on either side of it.
std::string crossings_words(const panel_words& w, double y) {
    std::vector<std::string> crossings;
    for (const auto* s : w.shown) {
        auto points = dense(*s);
        std::sort(points.begin(), points.end());
        for (std::size_t i = 1; i < points.size(); ++i) {
            const double a = points[i - 1].second - y, b = points[i].second - y;
            if ((a < 0) != (b < 0)) {
                crossings.push_back(spoken_label(s->label.markup) + " at " + w.x + " = " +
                                    spoken(crossing_x(w.p, points[i - 1], points[i], y), w.p.x.ticks));
                break;
            }
        }
    }
    return crossings.empty() ? "; no curve crosses it." : "; first crossed by " + join(crossings) + ".";
}

/// A reference line, and where the curves cross it.
std::string line_words(const panel_words& w, const reference_line& line) {
    const plot::panel& p = w.p;
    const std::string label = line.label.empty() ? "" : " (" + plot::tex_to_plain(line.label) + ")";
    if (line.x && !line.y) return " A vertical line marks " + w.x + " = " + spoken(*line.x, p.x.ticks) + label + ".";
    if (!line.y) return {};
    std::string out = " A horizontal line at " + w.y + " = " + spoken(*line.y, p.y.ticks) + label;
    if (line.span) {
        out += " runs from " + w.x + " = " + spoken(to_axis_angle(w.spec, (*line.span)[0]), p.x.ticks) + " to " +
               spoken(to_axis_angle(w.spec, (*line.span)[1]), p.x.ticks);
    }
    return out + crossings_words(w, *line.y);
}

/// The panel's paragraph.
std::string describe_panel(const plot::panel& p, const panel_spec& spec, std::size_t index, std::size_t count,
                           const plot::panel_frame* frame, bool animated, const plot::theme& th) {
    panel_words w{p, spec, {}, axis_name(p.x, "x"), axis_name(p.y, "y")};
    for (const auto& s : p.data) {
        if (s.autoscale && !s.overlay && !s.label.empty()) w.shown.push_back(&s);
    }
    std::string out = panel_opening(p, index, count);
    if (p.frameless) return out + drawing_words(w, animated, th);
    out += axes_words(w, frame);
    out += curves_words(w);
    if (spec.plot->describe_curves) out += spec.plot->describe_curves({p, w.shown, w.x, w.y});
    out += exact_words(w);
    out += middle_words(w);
    if (spec.energy_axis && w.x0 < 2 && 2 < w.x1) {
        out += " A dotted vertical line marks the separatrix at E = 2, where the period diverges from both "
               "sides: the libration's period below it, the time of one revolution above it.";
    }
    for (const auto& line : spec.lines) out += line_words(w, line);
    return out;
}

/// The paper theme, read once.
const plot::theme& paper_theme() {
    static const plot::theme paper = load_theme("paper", {});
    return paper;
}

/// The panels' axes as the paper theme lays the figure out (the limits a reader sees),
/// from `drawn` where it laid them out; none if it cannot be laid out so.
std::vector<plot::panel_frame> drawn_frames(const plot::figure& built, const plot::drawing* drawn) {
    try {
        return plot::panel_frames(built, paper_theme(), drawn);
    } catch (const std::exception&) {
        return {};
    }
}

}  // namespace

figure_description describe(const entry& e, const plot::figure& built, const build_options& options,
                            const plot::drawing* drawn) {
    return describe(e.spec, built, options, drawn);
}

figure_description describe(const figure_spec& spec, const plot::figure& unstyled, const build_options& options,
                            const plot::drawing* drawn) {
    // The lines as the theme it is drawn in draws them (the paper theme's named styles:
    // harmonic dotted; the paper theme's unless the options say), as the limits are the
    // ones the paper theme lays out.
    const plot::theme& th = options.theme ? *options.theme : paper_theme();
    const plot::figure built = plot::with_theme_styles(unstyled, th);
    const auto panels = panels_with(spec, options);
    figure_description d;
    d.alt = (spec.description.empty() ? plot::tex_to_plain(spec.title) : spec.description) + ".";
    if (built.panels.size() > 1) d.alt += " " + std::to_string(built.panels.size()) + " panels.";
    if (spec.animation) {
        const auto& a = *spec.animation;
        char buf[160];
        if (a.duration_s) {
            std::snprintf(buf, sizeof buf, "An animation of %g s at %g frames per second.", *a.duration_s, a.fps);
        } else if (!a.periods) {
            std::snprintf(buf, sizeof buf,
                          "An animation over whole periods of every drawn motion where they meet, at %g frames per second.",
                          a.fps);
        } else {
            const double periods = *a.periods;
            std::snprintf(buf, sizeof buf, "An animation over %g period%s of the exact motion, at %g frames per second.",
                          periods, periods == 1 ? "" : "s", a.fps);
        }
        d.text += std::string(buf) + " Its first frame:\n";
    }
    const std::string title = spoken_label(built.title.markup);
    if (!title.empty()) d.text = "Title: " + title + ".\n" + d.text;
    const std::vector<plot::panel_frame> frames = drawn_frames(built, drawn);
    const describing_scope describing_now(built, drawn);
    for (std::size_t i = 0; i < built.panels.size() && i < panels.size(); ++i) {
        d.text += describe_panel(built.panels[i], panels[i], i, built.panels.size(),
                                 i < frames.size() ? &frames[i] : nullptr, spec.animation.has_value(), th) +
                  "\n";
    }
    return d;
}

}  // namespace figures
