// SPDX-License-Identifier: GPL-3.0-or-later
#include "figures/render_cost.hpp"

#include "figures/plots.hpp"
#include "figures/spec_build.hpp"
#include "pendulum/amplitude.hpp"
#include "pendulum/formula.hpp"
#include "pendulum/seconds.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <span>
#include <string_view>

namespace figures {

namespace {

/// A measured cost: seconds of one call at N (an order, or a number of levels).
struct measured {
    double n;
    double seconds;
};

/// Seconds at n between the measured points, linearly; beyond the last, in proportion to n.
double at(std::span<const measured> table, double n) {
    if (n <= table.front().n) return table.front().seconds;
    for (std::size_t i = 1; i < table.size(); ++i) {
        if (n <= table[i].n) {
            const auto& a = table[i - 1];
            const auto& b = table[i];
            return a.seconds + (b.seconds - a.seconds) * (n - a.n) / (b.n - a.n);
        }
    }
    return table.back().seconds * n / table.back().n;
}

// The unit costs, in seconds of one core, from bench/calibrate_costs (see
// bench/calibrate_costs.md for the run and the machine). Close to pi is below 0.02 from pi,
// where the iteration works with MPFR (pendulum::detail::iteration_mp_below): there the
// worst of d = 0.01, 1e-6 and 1e-300 is taken.
constexpr double mp_below = 0.02;

/// method_period of order:N, mean over the 400 amplitudes of an axis in (0, pi).
constexpr measured order_period[] = {{0, 1.5e-6},  {1, 2.4e-6},  {2, 2.0e-5},  {5, 6.9e-5},   {10, 1.6e-4},
                                     {20, 3.8e-4}, {40, 1.5e-3}, {80, 1.9e-3}, {120, 4.6e-3}, {200, 1.9e-2}};
/// method_period_error of order:N, the same way.
constexpr measured order_error[] = {{0, 1.1e-4},  {1, 2.1e-4},  {2, 4.7e-4},  {5, 1.5e-3}, {10, 3.1e-3},
                                    {20, 1.4e-2}, {40, 7.3e-2}, {80, 5.1e-1}, {120, 1.64}, {200, 8.1}};
/// method_solution of order:N on the axis (a coefficient panel), the same way.
constexpr measured order_solution_axis[] = {{0, 1.4e-6},  {1, 2.3e-6},  {2, 2.0e-5},  {5, 6.4e-5},   {10, 1.6e-4},
                                            {20, 4.2e-4}, {40, 1.5e-3}, {80, 1.9e-3}, {120, 5.0e-3}, {200, 1.7e-2}};
/// method_solution of order:N at one amplitude at least mp_below from pi.
constexpr measured order_solution_far[] = {{10, 6.8e-5}, {40, 5.3e-4}, {100, 3.1e-3}, {200, 1.6e-2}};
/// method_solution of order:N at one amplitude closer to pi.
constexpr measured order_solution_near[] = {{10, 4.3e-2}, {40, 6.8e-1}, {100, 4.7}, {200, 27.7}};
/// iterated_period_errors(theta0, N, 1e-300) (a convergence panel's amplitude) far from pi
/// (the worse of d = 0.5 and 0.01: its MPFR levels do not grow closer to pi).
constexpr measured convergence_far[] = {{10, 3.2e-3}, {40, 4.8e-2}, {100, 9.1e-1}, {200, 11.5}};
/// The same, close to pi.
constexpr measured convergence_near[] = {{10, 1.5e-2}, {40, 2.2e-1}, {100, 1.49}, {200, 11.5}};

/// A method without N (or agm:N and series:N at their largest N): one call of each.
struct fixed_method {
    std::string_view name;
    double period;    ///< method_period, mean over the axis
    double error;     ///< method_period_error, the same way
    double solution;  ///< method_solution (0: none)
};

constexpr fixed_method fixed_methods[] = {
    {"exact", 9.1e-7, 0, 0},
    {"harmonic", 7.8e-7, 2.1e-6, 8.8e-7},
    {"lowest", 9.8e-7, 3.6e-6, 9.9e-7},
    {"first", 1.2e-6, 1.9e-6, 1.2e-6},
    {"second", 1.9e-6, 5.6e-6, 1.7e-6},
    {"polynomial", 7.4e-7, 6.2e-6, 8.3e-7},
    {"kidd-fogg", 8.8e-7, 4.9e-6, 0},
    {"lima-arun", 8.1e-7, 8.7e-6, 0},
    {"ganley", 7.9e-7, 7.8e-6, 0},
    {"agm", 8.6e-7, 1.4e-4, 0},
    {"denman", 8.0e-7, 8.1e-6, 0},
    {"series", 8.6e-7, 4.3e-5, 0},
    {"log-asymptote", 7.9e-7, 3.3e-6, 0},
};

/// The exact solution: one fourier_coefficients(theta0, 100), one exact_solution with one theta.
constexpr double exact_coefficients_seconds = 1.1e-5;
constexpr double exact_solution_seconds = 1.4e-6;
/// One value theta(t) of a Fourier solution, per harmonic; one of the exact solution.
constexpr double harmonic_term_seconds = 2e-8;
constexpr double exact_theta_seconds = 5e-7;

/// The values a series of an amplitude axis takes per file (its grid and the curve's
/// samplings): the seconds of a one-method panel in png and pdf over the seconds of one
/// call (bench/calibrate_costs.sh: period 9500, coefficient 8200, period error 1700).
constexpr double axis_values_per_file = 5000;
constexpr double error_axis_values_per_file = 1000;
/// The points a series of a motion (trajectory, phase, pendulum) takes per period drawn:
/// the grid of 300 and the curve's samplings.
constexpr double motion_values_per_period = 1200;
/// The values a moving dot, streak and trail take per frame.
constexpr double frame_values = 120;

/// Drawing: per file (or frame), per point of a series in it (12 series of 100 periods in
/// png and pdf: 0.83 s, 60 MB).
constexpr double file_seconds = 2e-2;
constexpr double point_seconds = 3e-7;

/// Seconds per pixel of a raster file or frame, by format: drawing and encoding (a video's
/// encoder on its threads). 60 frames of swing at 1080p and 4K: gif 1.3 and 3.7 s, mp4 5.4
/// and 17 s, webm 14 and 38 s; a PNG of 10000 x 10000: 2.0 s.
double pixel_seconds(std::string_view format) {
    if (format == "mp4") return 6e-8;
    if (format == "webm") return 1.5e-7;
    if (format == "png" || format == "gif") return 2e-8;
    return 0;  // a vector format: its points
}

/// Memory per point of a series (its values, samplings and curves kept for the files).
constexpr double bytes_per_point = 50;

/// One call of the method's period, or of its error, on an amplitude axis.
double axis_call(const pendulum::method_choice& m, bool error) {
    // A user's formula: its nodes in doubles, or its bounded work in MPFR.
    if (m.user) return error ? pendulum::formula_error_seconds(*m.user) : 1e-8 * static_cast<double>(m.user->nodes().size());
    if (m.row->role == pendulum::method_role::iterated) return at(error ? order_error : order_period, m.n);
    for (const auto& f : fixed_methods) {
        if (f.name == m.row->name) return error ? f.error : f.period;
    }
    return error ? 1e-3 : 1e-4;  // a method added since the calibration: as the dearest closed forms
}

/// One method_solution of the method on an amplitude axis (a coefficient panel).
double axis_solution_call(const pendulum::method_choice& m) {
    if (m.row->role == pendulum::method_role::iterated) return at(order_solution_axis, m.n);
    for (const auto& f : fixed_methods) {
        if (f.name == m.row->name) return f.solution;
    }
    return 1e-3;
}

/// One method_solution of the method at an amplitude d from pi (the exact solution: its
/// coefficients).
double solution_call(const pendulum::method_choice& m, double d) {
    if (m.is_exact()) return exact_coefficients_seconds;
    if (m.row->role == pendulum::method_role::iterated) {
        return at(d < mp_below ? order_solution_near : order_solution_far, m.n);
    }
    for (const auto& f : fixed_methods) {
        if (f.name == m.row->name) return f.solution;
    }
    return 1e-3;
}

/// One value theta(t) of the method's solution.
double theta_call(const pendulum::method_choice& m) {
    if (m.is_exact()) return exact_theta_seconds;
    const double harmonics = m.row->role == pendulum::method_role::iterated ? m.n + 1 : 3;
    return harmonic_term_seconds * harmonics;
}

/// A panel's costs: once, per frame of an animation, and its points.
struct panel_costs {
    double once = 0;       ///< seconds of building it (its curves sampled for every file)
    double per_frame = 0;  ///< seconds of what moves, per frame
    double points = 0;     ///< points of its series
    std::string key;       ///< what to reduce in it
};

/// "3 methods (up to order:200)".
std::string methods_text(const panel_spec& p) {
    int most = -1;
    std::string dearest;
    for (const auto& m : p.methods) {
        if (m.method.n > most) {
            most = m.method.n;
            dearest = m.method.text();
        }
    }
    std::string text = "methods (" + std::to_string(p.methods.size());
    if (most >= 0) text += ", up to " + dearest;
    return text + ")";
}

/// The amplitudes of a panel (theta0, or its starts' amplitudes) as distances from pi.
std::vector<double> distances(const panel_spec& p) {
    std::vector<double> d;
    for (const auto& a : p.theta0) d.push_back(a.theta0().from_pi());
    for (const auto& s : p.starts) {
        // A rotation or the separatrix has no amplitude: the iteration's worst.
        try {
            d.push_back(s.motion.amplitude().from_pi());
        } catch (const std::exception&) {
            d.push_back(0);
        }
    }
    return d;
}

/// "theta0 (4, 2 close to pi)".
std::string amplitudes_text(const std::vector<double>& d) {
    const auto near = std::count_if(d.begin(), d.end(), [](double v) { return v < mp_below; });
    return "theta0 (" + std::to_string(d.size()) + (near ? ", " + std::to_string(near) + " close to pi" : "") + ")";
}

/// The periods a motion panel draws (its range, or one).
double periods_drawn(const figure_spec& spec, const panel_spec& p) {
    if (!p.range || p.plot->range != range_kind::times) return 1;
    double span = std::fabs((*p.range)[1] - (*p.range)[0]);
    if (p.time == time_unit::seconds && spec.pendulum) {
        span /= pendulum::small_period_seconds(spec.pendulum->length_m, spec.pendulum->g);
    }
    return std::max(1.0, span + p.trail);
}

panel_costs axis_panel(const panel_spec& p, std::string_view kind, double files) {
    panel_costs c;
    const bool error = kind == "period" && p.y != period_axis::value;
    for (const auto& m : p.methods) {
        if (error && m.method.is_exact()) continue;
        const double call = kind == "coefficient" && !m.method.is_exact() ? axis_solution_call(m.method)
                             : kind == "coefficient" || p.energy_axis   ? exact_solution_seconds
                                                                        : axis_call(m.method, error);
        const double values = error ? error_axis_values_per_file : axis_values_per_file;
        c.once += values * files * call;
        c.points += values;
    }
    c.key = methods_text(p);
    return c;
}

panel_costs convergence_panel_costs(const panel_spec& p) {
    panel_costs c;
    const auto d = distances(p);
    for (const double v : d) c.once += at(v < mp_below ? convergence_near : convergence_far, p.orders[1]);
    c.points = static_cast<double>(d.size()) * (p.orders[1] - p.orders[0] + 1);
    c.key = "orders (up to " + std::to_string(p.orders[1]) + ") and " + amplitudes_text(d);
    return c;
}

panel_costs spectrum_panel_costs(const panel_spec& p) {
    panel_costs c;
    const auto d = distances(p);
    for (const double v : d) {
        for (const auto& m : p.methods) c.once += solution_call(m.method, v);
    }
    c.points = static_cast<double>(d.size() * p.methods.size()) * p.harmonics;
    c.key = methods_text(p) + " and " + amplitudes_text(d);
    return c;
}

panel_costs motion_panel(const figure_spec& spec, const panel_spec& p) {
    panel_costs c;
    const auto d = distances(p);
    const double periods = periods_drawn(spec, p);
    for (const double v : d) {
        for (const auto& m : p.methods) {
            const double solve = m.method.is_exact() ? exact_solution_seconds : solution_call(m.method, v);
            c.once += solve + motion_values_per_period * periods * theta_call(m.method);
            c.points += motion_values_per_period * periods;
            c.per_frame += solve + frame_values * theta_call(m.method);
        }
    }
    c.key = methods_text(p) + " and " + amplitudes_text(d);
    if (periods > 10) c.key += ", over " + pendulum::format_double(std::round(periods)) + " periods (range)";
    return c;
}

panel_costs costs_of(const figure_spec& spec, const panel_spec& p, double files) {
    const std::string_view kind = p.plot->name;
    if (kind == "period" || kind == "coefficient") return axis_panel(p, kind, files);
    if (kind == "convergence") return convergence_panel_costs(p);
    if (kind == "spectrum") return spectrum_panel_costs(p);
    return motion_panel(spec, p);
}

/// "12 s", "4.5 min", "3.2 h".
std::string duration(double s) {
    char text[32];
    if (s < 120) {
        std::snprintf(text, sizeof text, "%.0f s", std::ceil(s));
    } else if (s < 7200) {
        std::snprintf(text, sizeof text, "%.1f min", std::ceil(s / 6) / 10);
    } else {
        std::snprintf(text, sizeof text, "%.1f h", std::ceil(s / 360) / 10);
    }
    return text;
}

std::string mebibytes(double bytes) {
    char text[32];
    std::snprintf(text, sizeof text, "%.0f MiB", std::ceil(bytes / 1048576));
    return text;
}

/// What one figure costs, its largest panel named.
struct figure_costs {
    double seconds = 0;
    double bytes = 0;
    cost_part largest;
};

/// The seconds of drawing the files (or frames) of a figure in its formats, beyond its points.
double files_seconds(const costed_figure& f) {
    const double draws = f.frames > 0 ? f.frames : 1;
    double seconds = 0;
    for (const auto& format : f.formats) seconds += draws * (file_seconds + f.raster_pixels * pixel_seconds(format));
    return seconds;
}

figure_costs cost_of(const costed_figure& f, const build_options& options) {
    figure_costs out;
    const auto panels = panels_of(*f.figure, options);
    const double frames = f.frames;
    // Still: the series once, drawn in each file. Animated: the frames' moving parts too,
    // and every series drawn in every frame of every file.
    const double draws = (frames > 0 ? frames : 1) * static_cast<double>(std::max<std::size_t>(1, f.formats.size()));
    double points = 0;
    for (std::size_t i = 0; i < panels.size(); ++i) {
        const panel_costs c = costs_of(f.figure->spec, panels[i], static_cast<double>(f.formats.size()));
        const double seconds = c.once + frames * c.per_frame + draws * c.points * point_seconds;
        points += c.points;
        out.seconds += seconds;
        if (seconds > out.largest.seconds) {
            std::string key = c.key;
            if (frames > 0 && frames * c.per_frame + draws * c.points * point_seconds > c.once) {
                key += ", in each of " + pendulum::format_double(frames) + " frames ([animation] fps, periods or "
                       "duration_s, or --frames)";
            }
            out.largest = {"figure '" + f.figure->id + "' panel " + std::to_string(i + 1) + " (" +
                               std::string(panels[i].plot->name) + ")",
                           key, seconds};
        }
    }
    const double drawing = files_seconds(f);
    out.seconds += drawing;
    if (drawing > out.largest.seconds) {
        out.largest = {"figure '" + f.figure->id + "'",
                       pendulum::format_double(draws) + " files or frames of " + pendulum::format_double(f.raster_pixels) +
                           " pixels (--dpi, size_px, the formats, or the frames)",
                       drawing};
    }
    out.bytes = points * bytes_per_point;
    return out;
}

}  // namespace

cost_estimate estimate_cost(const std::vector<costed_figure>& figures, const build_options& options) {
    cost_estimate e;
    for (const auto& f : figures) {
        const figure_costs c = cost_of(f, options);
        e.seconds += c.seconds;
        if (c.largest.seconds > e.largest.seconds) e.largest = c.largest;
        // Figures are built a few at a time: the largest is what is held at once.
        if (c.bytes > e.series_bytes) {
            e.series_bytes = c.bytes;
            e.largest_memory = {"figure '" + f.figure->id + "'", "", c.bytes};
        }
    }
    return e;
}

void check_cost(const std::vector<costed_figure>& figures, const build_options& options) {
    const cost_estimate e = estimate_cost(figures, options);
    if (e.seconds > max_render_seconds) {
        throw bad_input("this render would take about " + duration(e.seconds) + " of computing (estimated from the " +
                        "specs before any work); a render takes at most " + duration(max_render_seconds) +
                        ". Most of it is " + e.largest.where + ": reduce its " + e.largest.key + " (about " +
                        duration(e.largest.seconds) + " there), or render fewer figures or panels");
    }
    if (e.series_bytes > max_render_series_bytes) {
        throw bad_input("the curves of " + e.largest_memory.where + " would take about " + mebibytes(e.series_bytes) +
                        " of memory (estimated from the spec before any work); a render takes at most " +
                        mebibytes(max_render_series_bytes) +
                        ": draw fewer periods (range), methods or amplitudes, or fewer panels");
    }
}

}  // namespace figures
