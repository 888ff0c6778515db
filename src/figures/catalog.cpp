#include "figures/catalog.hpp"

#include "pendulum/approximants.hpp"
#include "pendulum/exact.hpp"

#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>
#include <stdexcept>

namespace figures {

using std::numbers::pi;
using plot::line_style;
using plot::marker_style;

namespace {

const char* const theta0_label = "<i>\u03d1</i><sub>0</sub>";

/// n + 1 evenly spaced values over [a, b].
std::vector<double> grid(double a, double b, int n) {
    std::vector<double> v;
    for (int i = 0; i <= n; ++i) v.push_back(i == n ? b : a + (b - a) * i / n);
    return v;
}

plot::series make_series(std::string label, const std::vector<double>& x, const std::function<double(double)>& f,
                         line_style line, marker_style marker, int color) {
    plot::series s;
    s.label = std::move(label);
    s.x = x;
    for (double v : x) s.y.push_back(f(v));
    s.line = line;
    s.marker = marker;
    s.color = color;
    return s;
}

std::string panel_letter(std::size_t i) { return std::string("(") + static_cast<char>('a' + i) + ")"; }

/// Amplitude axis on [0, pi] in multiples of pi.
plot::axis amplitude_axis() {
    plot::axis a;
    a.label = theta0_label;
    a.min = 0.0;
    a.max = pi;
    a.ticks = plot::tick_kind::multiples_of_pi;
    a.max_ticks = 5;
    return a;
}

// Amplitudes where the exact values are marked, and the fine grid for curves. The
// approximants are defined on (0, pi); the curves stop just short of pi.
const std::vector<double>& circle_amplitudes() {
    static const std::vector<double> v = [] {
        std::vector<double> a;
        for (int k = 1; k <= 23; ++k) a.push_back(k * pi / 24);
        return a;
    }();
    return v;
}

const std::vector<double>& curve_amplitudes() {
    static const std::vector<double> v = grid(1e-3, pi - 1e-3, 400);
    return v;
}

/// One coefficient panel: exact (circles, by the paper's quadrature), an approximant (solid)
/// and the polynomial approximant (dotted).
plot::panel coefficient_panel(int n, const std::string& order_name, const std::string& y_label,
                              const std::function<pendulum::fourier_solution(double)>& approximant) {
    plot::panel p;
    p.x = amplitude_axis();
    p.y.label = y_label;
    p.data.push_back(make_series(
        "exact", circle_amplitudes(),
        [n](double t) { return pendulum::exact_solution(t).coefficient_by_quadrature(n); }, line_style::none,
        marker_style::open_circle, 0));
    p.data.push_back(make_series(
        order_name, curve_amplitudes(), [&](double t) { return approximant(t).coefficients.at(n); },
        line_style::solid, marker_style::none, 1));
    p.data.push_back(make_series(
        "polynomial", curve_amplitudes(), [n](double t) { return pendulum::polynomial(t).coefficients.at(n); },
        line_style::dotted, marker_style::none, 2));
    return p;
}

std::string coefficient_label(int harmonic, int primes) {
    // Computer Modern Unicode has no prime: the glyph comes from the fallback font, whose
    // wide advance is pulled in so that the subscript sits under the primes as in TeX.
    const std::string prime_marks[] = {"", "\u2032", "\u2033"};
    const std::string primes_markup =
        primes == 0 ? "" : "<span letter_spacing=\"-" + std::to_string(primes == 1 ? 1500 : 1600) + "\">" + prime_marks[primes] + "</span>";
    return "<i>c</i>" + std::string(primes == 1 ? "\u200a" : "") + primes_markup + "<sub>" + std::to_string(harmonic) + "</sub>";
}

/// An approximant as the figures show it: legend text, line style and how to compute it.
struct method {
    std::string label;
    line_style style;
    pendulum::fourier_solution (*solve)(double theta0);
};

/// A grid of trajectory panels, one per amplitude, each comparing the exact motion (circles)
/// with approximants at the same physical time, over one exact period.
plot::figure trajectory_figure(const std::vector<double>& amplitudes, int max_cols, double width_cm,
                               const std::vector<method>& methods) {
    plot::figure f;
    f.cols = std::min<int>(max_cols, static_cast<int>(amplitudes.size()));
    f.rows = (static_cast<int>(amplitudes.size()) + f.cols - 1) / f.cols;
    f.panel_width_cm = width_cm;
    f.panel_aspect = 0.75;
    f.shared_legend = true;
    for (std::size_t i = 0; i < amplitudes.size(); ++i) {
        const double theta0 = amplitudes[i];
        const pendulum::exact_solution exact(theta0);
        const double period = 4 * exact.quarter_period();
        plot::panel p;
        p.label = panel_letter(i) + " " + theta0_label + " = " + amplitude_label(theta0);
        p.x.label = "<i>t</i>/<i>T</i>";
        p.x.min = 0.0;
        p.x.max = 1.0;
        p.x.max_ticks = width_cm < 5 ? 3 : 5;
        p.y.label = "<i>\u03d1</i>";
        p.y.ticks = plot::tick_kind::multiples_of_pi;
        p.y.max_ticks = 7;
        p.y.round_limits = true;
        p.y.margin = 0.002;  // just enough to keep the curve off the frame at a tick
        p.data.push_back(make_series("exact", grid(0, 1, 24),
                                     [&](double s) { return exact.theta_at_fraction(s); }, line_style::none,
                                     marker_style::open_circle, 0));
        int color = 1;
        for (const auto& m : methods) {
            const auto solution = m.solve(theta0);
            p.data.push_back(make_series(m.label, grid(0, 1, 300),
                                         [&](double s) { return solution.theta(s * period); }, m.style,
                                         marker_style::none, color++));
        }
        f.panels.push_back(std::move(p));
    }
    return f;
}

/// Coefficient panels c1, c3, ... of one approximant against the exact values, one panel
/// per harmonic, labelled (a), (b), ... when there is more than one.
plot::figure coefficient_figure(int harmonics, int primes, const std::string& order_name,
                                const std::function<pendulum::fourier_solution(double)>& approximant,
                                double width_cm, double aspect) {
    plot::figure f;
    f.cols = harmonics;
    f.panel_width_cm = width_cm;
    f.panel_aspect = aspect;
    f.shared_legend = true;
    for (int n = 0; n < harmonics; ++n) {
        auto p = coefficient_panel(n, order_name, coefficient_label(2 * n + 1, primes), approximant);
        if (harmonics > 1) p.label = panel_letter(n);
        if (width_cm < 5) p.x.max_ticks = 3;
        f.panels.push_back(std::move(p));
    }
    return f;
}

plot::figure period() {
    plot::figure f;
    f.cols = 2;
    const method methods[] = {{"lowest order", line_style::dashed, pendulum::lowest_order},
                              {"first order", line_style::dotted, pendulum::first_order},
                              {"second order", line_style::solid, pendulum::second_order}};
    plot::panel a;
    a.label = panel_letter(0);
    a.x = amplitude_axis();
    a.y.label = "<i>T</i>/<i>T</i><sub>0</sub>";
    a.y.min = 1.0;
    a.y.max = 3.0;
    a.data.push_back(make_series("exact", circle_amplitudes(), [](double t) { return pendulum::period_ratio(t); },
                                 line_style::none, marker_style::open_circle, 0));
    plot::panel b;
    b.label = panel_letter(1);
    b.x = amplitude_axis();
    b.y.label = "relative error (%)";
    // Near pi every approximant's error grows without bound; show the range that tells them apart.
    b.y.min = -20.0;
    b.y.max = 2.0;
    // Each period is computed once and shown twice: as T/T0 in (a), as an error in (b).
    const auto& t = curve_amplitudes();
    std::vector<double> exact;
    for (double x : t) exact.push_back(pendulum::period_ratio(x));
    int color = 1;
    for (const auto& m : methods) {
        plot::series ratio{m.label, t, {}, m.style, marker_style::none, color++};
        plot::series error = ratio;
        error.y.clear();
        for (std::size_t i = 0; i < t.size(); ++i) {
            ratio.y.push_back(m.solve(t[i]).period_ratio());
            error.y.push_back(100 * (ratio.y[i] / exact[i] - 1));
        }
        a.data.push_back(std::move(ratio));
        b.data.push_back(std::move(error));
    }
    f.panels = {std::move(a), std::move(b)};
    return f;
}

plot::figure convergence() {
    plot::figure f;
    f.panel_width_cm = 8.0;
    f.panel_aspect = 0.7;
    plot::panel p;
    p.x.label = "order <i>N</i> of the iteration";
    p.x.min = 0.0;
    p.x.max = 40.0;
    p.y.label = "|<i>T</i><sub><i>N</i></sub>/<i>T</i> \u2212 1|";
    p.y.kind = plot::scale::log;
    p.y.min = 1e-16;
    p.y.max = 1.0;
    p.y.max_ticks = 9;
    const std::pair<double, line_style> curves[] = {{pi / 2, line_style::solid},
                                                    {3 * pi / 4, line_style::dashed},
                                                    {9 * pi / 10, line_style::dotted},
                                                    {0.95 * pi, line_style::dash_dot},
                                                    {0.99 * pi, line_style::solid}};
    int color = 0;
    for (const auto& [theta0, style] : curves) {
        const double exact = pendulum::period_ratio(theta0);
        const auto levels = pendulum::iterated_sequence(theta0, 40);
        plot::series s;
        s.label = std::string(theta0_label) + " = " + amplitude_label(theta0);
        for (std::size_t n = 0; n < levels.size(); ++n) {
            const double err = std::fabs(levels[n].period_ratio() / exact - 1);
            s.x.push_back(static_cast<double>(n));
            // Below 1e-16 the difference is rounding: leave it out of a log plot.
            s.y.push_back(err > 1e-16 ? err : std::nan(""));
        }
        s.line = style;
        s.marker = color == 4 ? marker_style::open_circle : marker_style::none;
        s.color = color++;
        p.data.push_back(std::move(s));
    }
    f.panels.push_back(std::move(p));
    return f;
}

std::vector<double> or_default(const std::vector<double>& given, std::vector<double> fallback) {
    return given.empty() ? fallback : given;
}

}  // namespace

std::string amplitude_label(double theta0) {
    for (int den = 1; den <= 100; ++den) {
        const double num = theta0 / pi * den;
        const double r = std::round(num);
        if (r >= 1 && std::fabs(num - r) < 1e-12 * den) {
            // Smallest denominator first, so the fraction is already reduced.
            const long n = std::lround(r);
            return (n == 1 ? std::string() : std::to_string(n)) + "\u03c0" + (den == 1 ? "" : "/" + std::to_string(den));
        }
    }
    const double deg = theta0 * 180 / pi;
    if (std::fabs(deg - std::round(deg)) < 1e-9) return std::to_string(std::lround(deg)) + "\u00b0";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4g", theta0);
    return buf;
}

const std::vector<entry>& catalog() {
    static const std::vector<entry> entries = {
        {"c1-lowest", "fig1", "Fig. 1", "c1 against the amplitude: exact, lowest order, polynomial",
         {"Fig.C1.Lowest"}, 6.0, false},
        {"trajectory-lowest", "fig2", "Fig. 2",
         "theta(t) for pi/3, pi/2, 3pi/4, 9pi/10: exact, lowest order, harmonic",
         {"Fig.Comparison.LowestA", "Fig.Comparison.LowestB", "Fig.Comparison.LowestC", "Fig.Comparison.LowestD"},
         6.0, true},
        {"coefficients-first", "fig3", "Fig. 3", "c1' and c3' against the amplitude: exact, first order, polynomial",
         {"Fig.C1.First", "Fig.C3.First"}, 6.0, false},
        {"trajectory-first", "fig4", "Fig. 4", "theta(t) for pi/3, pi/2, 3pi/4, 9pi/10: exact, first order, harmonic",
         {"Fig.Comparison.FirstA", "Fig.Comparison.FirstB", "Fig.Comparison.FirstC", "Fig.Comparison.FirstD"}, 6.0,
         true},
        {"coefficients-second", "fig5", "Fig. 5",
         "c1'', c3'', c5'' against the amplitude: exact, second order, polynomial",
         {"Fig.C1.Second", "Fig.C3.Second", "Fig.C5.Second"}, 4.3, false},
        {"trajectory-second", "fig6", "Fig. 6", "theta(t) for 9pi/10, 95pi/100, 99pi/100: exact, second order",
         {"Fig.Lamb.4a", "Fig.Lamb.4b", "Fig.Lamb.4c"}, 4.2, true},
        {"period", "fig7", "Fig. 7", "T/T0 against the amplitude and its relative error: exact, lowest, first, second",
         {"Fig.Comparison.PeriodA", "Fig.Comparison.PeriodB"}, 6.0, false},
        {"convergence", "", "new", "|T_N/T - 1| against the order N of the iteration, for five amplitudes", {}, 8.0,
         false},
    };
    return entries;
}

const entry& find(std::string_view id) {
    for (const auto& e : catalog()) {
        if (e.id == id || (!e.alias.empty() && e.alias == id)) return e;
    }
    std::string ids;
    for (const auto& e : catalog()) ids += (ids.empty() ? "" : ", ") + e.id;
    throw std::invalid_argument("unknown figure '" + std::string(id) + "'; figures: " + ids + " (or fig1 ... fig7)");
}

plot::figure build(const entry& e, const build_options& options) {
    const auto& amps = options.amplitudes;
    if (e.id == "c1-lowest") {
        return coefficient_figure(1, 0, "lowest order", [](double t) { return pendulum::lowest_order(t); }, 6.0, 0.75);
    }
    if (e.id == "trajectory-lowest" || e.id == "trajectory-first") {
        const method order = e.id == "trajectory-lowest"
                                 ? method{"lowest order", line_style::solid, pendulum::lowest_order}
                                 : method{"first order", line_style::solid, pendulum::first_order};
        return trajectory_figure(or_default(amps, {pi / 3, pi / 2, 3 * pi / 4, 9 * pi / 10}), 2, 6.0,
                                 {order, {"harmonic", line_style::dotted, pendulum::harmonic}});
    }
    if (e.id == "coefficients-first") {
        return coefficient_figure(2, 1, "first order", [](double t) { return pendulum::first_order(t); }, 6.0, 0.75);
    }
    if (e.id == "coefficients-second") {
        return coefficient_figure(3, 2, "second order", [](double t) { return pendulum::second_order(t); }, 4.3, 0.85);
    }
    if (e.id == "trajectory-second") {
        auto f = trajectory_figure(or_default(amps, {9 * pi / 10, 95 * pi / 100, 99 * pi / 100}), 3, 4.2,
                                   {{"second order", line_style::solid, pendulum::second_order}});
        f.panel_aspect = 0.85;
        return f;
    }
    if (e.id == "period") return period();
    if (e.id == "convergence") return convergence();
    throw std::logic_error("figure '" + e.id + "' has no builder");
}

}  // namespace figures
