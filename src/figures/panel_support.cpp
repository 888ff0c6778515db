// SPDX-License-Identifier: GPL-3.0-or-later
#include "figures/panel_support.hpp"

#include "figures/errors.hpp"
#include "pendulum/angle.hpp"
#include "pendulum/formula.hpp"
#include "pendulum/phase.hpp"
#include "plot/tex_markup.hpp"
#include "pendulum/seconds.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace figures {

using plot::line_style;
using plot::marker_style;
using std::numbers::pi;

/// n + 1 evenly spaced values over [a, b], the last exactly b.
std::vector<double> grid(double a, double b, int n) {
    std::vector<double> v;
    v.reserve(static_cast<std::size_t>(n) + 1);
    for (int i = 0; i <= n; ++i) v.push_back(i == n ? b : a + (b - a) * i / n);
    return v;
}

void check_formula_finite(const pendulum::method_choice& m, const std::vector<double>& xs,
                          const std::function<double(double)>& value) {
    if (!m.user || xs.empty() || std::any_of(xs.begin(), xs.end(), [&](double x) { return std::isfinite(value(x)); })) return;
    throw bad_input("method " + m.text() + " = '" + m.user->text() + "' is not finite anywhere on the panel's axis (from " +
                    pendulum::format_double(xs.front()) + " to " + pendulum::format_double(xs.back()) +
                    "); check the formula, or the panel's range");
}

series_style style_of(const method_spec& m, int index) {
    series_style s{m.label.empty() ? method_label(m.method) : plot::tex_label(m.label), method_line(m.method),
                   m.method.is_exact() ? marker_style::open_circle : marker_style::none, index, ""};
    // The theme styles a method by name unless the spec says how it looks.
    // A user's formula keeps its own line (method_line): no theme style for all formulas alike.
    if (!m.style && !m.marker && !m.method.user) s.style_key = std::string(m.method.row->name);
    if (m.style) s.line = *m.style;
    if (m.marker) s.marker = *m.marker;
    s.rgb_color = m.color;
    s.id = m.method.text();
    return s;
}


/// An empty series in the style.
plot::series series_of(const series_style& st) {
    plot::series s;
    s.label = st.label;
    s.line = st.line;
    s.marker = st.marker;
    s.color = st.color;
    s.style_key = st.style_key;
    s.rgb_color = st.rgb_color;
    s.id = st.id;
    return s;
}

plot::series make_series(const series_style& st, std::vector<double> x, const std::function<double(double)>& f) {
    plot::series s = series_of(st);
    s.y.reserve(x.size());
    for (double v : x) s.y.push_back(f(v));
    s.x = std::move(x);
    return s;
}


bool is_exact(const method_spec& m) { return m.method.is_exact(); }

/// The amplitude axis over [lo, hi], in multiples of pi or in degrees.
plot::axis amplitude_axis(const panel_spec& p, double lo, double hi) {
    plot::axis a;
    a.label = theta0_markup;
    a.min = lo;
    a.max = hi;
    a.ticks = plot::tick_kind::multiples_of_pi;
    a.max_ticks = 5;
    if (p.degrees) {
        a.ticks = plot::tick_kind::degrees;
        a.min = lo * 180 / pi;
        a.max = hi * 180 / pi;
    }
    return a;
}

double to_axis_angle(const panel_spec& p, double theta) { return p.degrees ? theta * 180 / pi : theta; }


namespace {

/// The panel's amplitude range as drawn: an end at 0 or pi, where the approximants have no
/// value, moves in by a thousandth of the range; any range inside (0, pi) stays as asked.
std::pair<double, double> open_range(double lo, double hi) {
    const double inset = 1e-3 * (hi - lo);
    return {lo > 0 ? lo : lo + inset, hi < pi ? hi : hi - inset};
}

}  // namespace

/// Amplitudes where the exact values are marked: the multiples of pi/24 in the panel's
/// range, as in the paper, or nine even steps across a range that holds fewer than three.
std::vector<double> circle_amplitudes(double lo, double hi) {
    std::vector<double> a;
    for (int k = 1; k <= 23; ++k) {
        const double t = k * pi / 24;
        if (t >= lo && t <= hi) a.push_back(t);
    }
    if (a.size() >= 3) return a;
    const auto [from, to] = open_range(lo, hi);
    return grid(from, to, 8);
}

std::shared_ptr<const plot::curve> amplitude_curve(const panel_spec& p, double lo, double hi,
                                                   std::function<double(double)> f) {
    const double unit = to_axis_angle(p, 1.0);
    return plot::parametric_curve(lo, hi, [f = std::move(f), unit](double t) { return std::pair{unit * t, f(t)}; });
}

/// The fine grid for curves, inside the panel's range.
std::vector<double> curve_amplitudes(double lo, double hi) {
    const auto [from, to] = open_range(lo, hi);
    return grid(from, to, 400);
}

/// Seconds per unit of w0 t, for a spec with a [pendulum].
double seconds_per_radian(const figure_spec& spec) {
    return pendulum::seconds_per_radian(spec.pendulum->length_m, spec.pendulum->g);
}

/// The x value of a trajectory panel at t = s T, its unit per exact period, and its label.
std::pair<double, std::string> time_unit_of(const figure_spec& spec, const panel_spec& p,
                                            const pendulum::exact_solution& exact) {
    if (p.time == time_unit::small_period) return {exact.period_ratio(), "<i>t</i>/<i>T</i><sub>0</sub>"};
    if (p.time == time_unit::seconds) return {4 * exact.quarter_period() * seconds_per_radian(spec), "<i>t</i> (s)"};
    return {1.0, "<i>t</i>/<i>T</i>"};
}

/// Line styles for series that differ by amplitude, in order.
series_style amplitude_style(std::size_t i, const plot::label& label) {
    static const line_style cycle[] = {line_style::solid, line_style::dashed, line_style::dotted, line_style::dash_dot};
    return {label, cycle[i % 4], i == 4 ? marker_style::open_circle : marker_style::none, static_cast<int>(i), "",
            std::nullopt, "theta0:" + std::to_string(i + 1)};
}


plot::line_style method_line(const pendulum::method_choice& m) {
    if (m.is_exact()) return line_style::none;
    if (m.user) {
        // Users' formulas apart from each other in one colour too: formula:K takes the K-th style.
        static const line_style cycle[] = {line_style::dashed, line_style::dotted, line_style::dash_dot,
                                           line_style::dash_dot_dot, line_style::solid};
        return cycle[static_cast<std::size_t>(std::max(m.n - 1, 0)) % 5];
    }
    if (m.has_motion()) return line_style::solid;
    return line_style::dashed;
}

std::string typeset_angle(std::string_view text) {
    using kind = pendulum::angle_token::kind;
    const auto tokens = pendulum::angle_tokens(text);
    std::string out;
    for (std::size_t i = 0; i < tokens.size(); ++i) {
        const auto& t = tokens[i];
        switch (t.type) {
            case kind::number:
                // An exponent is set as a power of ten: 1e-6 -> 10^-6, 2.5e3 -> 2.5x10^3.
                if (t.exponent.empty()) {
                    out += t.mantissa;
                } else {
                    out += (t.mantissa == "1" ? std::string() : t.mantissa + "\u00d7") + "10<sup>" +
                           (t.negative_exponent ? "\u2212" : "") + t.exponent + "</sup>";
                }
                break;
            case kind::pi: out += "<i>\u03c0</i>"; break;
            case kind::degrees: out += "\u00b0"; break;
            case kind::radians: break;
            case kind::plus: out += " + "; break;
            case kind::minus: out += " \u2212 "; break;
            case kind::sign_plus: out += "+"; break;
            case kind::sign_minus: out += "\u2212"; break;
            // "9*pi/10" reads as 9π/10; before a number it is a product sign.
            case kind::times:
                if (i + 1 < tokens.size() && tokens[i + 1].type == kind::number) out += "\u00d7";
                break;
            case kind::divide: out += "/"; break;
            case kind::open: out += "("; break;
            case kind::close: out += ")"; break;
        }
    }
    return out;
}

std::string start_id(const std::string& id, std::size_t i, std::size_t n) {
    return n > 1 ? id + ":" + std::to_string(i + 1) : id;
}

plot::series moving_dot(const series_style& st, std::size_t i, std::size_t n) {
    plot::series dot = series_of(st);
    dot.id = "dot:" + start_id(st.id, i, n);
    dot.label.clear();
    dot.style_key.clear();
    dot.line = line_style::none;
    dot.marker = marker_style::filled_circle;
    dot.marker_scale = 1.8;
    dot.autoscale = false;
    return dot;
}

std::pair<double, double> state_at(const method_spec& m, const pendulum::exact_solution& exact, double w0_t) {
    const double period = 4 * exact.quarter_period();
    if (is_exact(m)) {
        return {exact.theta_at_fraction(w0_t / period), pendulum::velocity_at_fraction(exact, w0_t / period)};
    }
    if (m.method.user) {
        // A user's theta(t) = f(t, theta0); its velocity by a central difference.
        const double t0 = exact.amplitude();
        const double h = 1e-5 * std::max(1.0, std::fabs(w0_t));
        return {m.method.user->value(t0, w0_t), (m.method.user->value(t0, w0_t + h) - m.method.user->value(t0, w0_t - h)) / (2 * h)};
    }
    const auto sol = pendulum::method_solution(m.method, exact.amplitude());
    return {sol.theta(w0_t), pendulum::velocity(sol, w0_t)};
}

std::string plain_text(const std::string& markup) {
    std::string out;
    bool in_tag = false;
    for (char c : markup) {
        if (c == '<') {
            in_tag = true;
        } else if (c == '>') {
            in_tag = false;
        } else if (!in_tag) {
            out += c;
        }
    }
    const std::pair<std::string, std::string> entities[] = {
        {"&lt;", "<"}, {"&gt;", ">"}, {"&quot;", "\""}, {"&apos;", "'"}, {"&amp;", "&"},
        {"\u2009", " "}};  // a thin space (E = 1 mgL) is a space in plain words
    for (const auto& [from, to] : entities) {
        for (std::size_t pos = 0; (pos = out.find(from, pos)) != std::string::npos; pos += to.size()) {
            out.replace(pos, from.size(), to);
        }
    }
    return out;
}

}  // namespace figures
