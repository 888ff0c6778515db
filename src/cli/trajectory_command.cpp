// SPDX-License-Identifier: GPL-3.0-or-later
// trajectory: theta(t) of one start (amplitude, state or energy), exact or approximate.
#include "cli/commands.hpp"
#include "cli/options.hpp"
#include "cli/report.hpp"
#include "cli/table.hpp"
#include "figures/figure_data.hpp"
#include "pendulum/approximants.hpp"
#include "pendulum/exact.hpp"
#include "pendulum/formula.hpp"
#include "pendulum/methods.hpp"
#include "pendulum/motion.hpp"
#include "pendulum/phase.hpp"
#include "pendulum/seconds.hpp"
#include "pendulum/time_reduction.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <deque>
#include <iostream>
#include <memory>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

namespace pendulum::cli {

namespace {

constexpr int max_samples = 10'000'000;
constexpr double max_periods = 1e6;

struct trajectory_options {
    std::string theta0;
    std::string omega0;
    std::string energy;
    std::string time;
    std::optional<double> length;  // metres, for --time t/s
    double g = 9.80665;
    std::string method = "exact";
    std::string order;
    std::string at;
    int samples = 0;
    double periods = 1.0;
    std::string format = "csv";
};

/// A unit of time for --time: its name, its column and w0 t per unit.
struct time_unit_row {
    std::string_view name;         ///< as --time takes it
    std::string_view column;       ///< the table's first column
    std::string_view description;  ///< for --help
    /// w0 t per unit of time for a motion (w0 in radians per second given, 0 without --length).
    long double (*scale)(const motion& m, long double w0);
};

constexpr time_unit_row time_units[] = {
    {"t/T", "t_over_T", "periods T of the exact motion (T_rev for a rotation; none at the separatrix)",
     [](const motion& m, long double) { return static_cast<long double>(m.period()); }},
    {"t/T0", "t_over_T0", "small-amplitude periods T0 = 2 pi/w0", [](const motion&, long double) { return 2 * std::numbers::pi_v<long double>; }},
    {"t/s", "t_s", "seconds, for a pendulum of --length L (and --g)",
     [](const motion&, long double w0) { return w0; }},
};

const time_unit_row& parse_time_unit(const std::string& text) {
    std::string names;
    for (const auto& row : time_units) {
        if (row.name == text) return row;
        names += (names.empty() ? "" : ", ") + std::string(row.name);
    }
    throw usage_error("--time '" + shown_text(text) + "': the units of time are " + names);
}

/// The most methods of one --method list.
constexpr std::size_t max_methods = 8;

/// The methods of --method, a comma-separated list (order with --order N), each once, each
/// with a law of motion that applies to the start.
std::vector<method_choice> trajectory_methods(const trajectory_options& o, bool order_given, const start_option& start) {
    // split_list keeps a comma inside parentheses in its item: formula:besselj(1, t) is one.
    const auto items = split_list(o.method);
    if (items.size() > max_methods) {
        throw usage_error("--method '" + shown_text(o.method) + "': " + std::to_string(items.size()) +
                          " methods; at most " + std::to_string(max_methods) + " in one table");
    }
    const bool order_listed = std::find(items.begin(), items.end(), "order") != items.end();
    if (order_given && !order_listed) {
        throw usage_error("--order is only used with --method order, not --method " + o.method);
    }
    std::vector<method_choice> methods;
    for (const auto& item : items) {
        std::string text = item;
        if (item == "order") {
            if (!order_given) throw usage_error("--method order needs --order N (or write --method order:N)");
            text = "order:" + std::to_string(parse_order(o.order));
        }
        const method_choice method = parse_method_option("--method", text);
        if (!method.has_motion()) {
            throw usage_error("--method " + method.text() + " gives a period only, not a law of motion; see 'list'");
        }
        if (std::any_of(methods.begin(), methods.end(), [&](const method_choice& m) { return m.text() == method.text(); })) {
            throw usage_error("--method '" + shown_text(o.method) + "': " + method.text() + " is listed twice");
        }
        if (method.user && items.size() > 1) {
            throw usage_error("--method '" + shown_text(o.method) + "': a formula goes alone (its table is t and "
                              "theta); give the other methods in a run of their own");
        }
        check_method_applies(method, start);
        methods.push_back(method);
    }
    return methods;
}

/// True where --at gives a time in seconds (10s) or --omega0 a velocity in rad/s: values
/// that the pendulum's --length (and --g) convert.
bool physical_values(const trajectory_options& o) {
    if (!o.at.empty()) {
        for (const auto& item : split_list(o.at)) {
            if (parse_time("--at", item).seconds) return true;
        }
    }
    if (o.omega0.empty() || o.omega0 == "-" || o.omega0.starts_with("@")) return false;
    const auto items = split_list(o.omega0);
    return std::any_of(items.begin(), items.end(), [](const std::string& item) { return item.ends_with("rad/s"); });
}

/// The times of --at, in the unit of --time, each finite: an item in seconds (10s) is
/// converted with w0 (from --length and --g) and the unit's scale.
std::vector<double> times_at(const trajectory_options& o, const time_unit_row& unit, bool periods_given, long double w0,
                             long double scale) {
    std::vector<double> times;
    if (o.at.empty()) return times;
    if (periods_given) throw usage_error("--periods goes with --samples, not with --at");
    for (const auto& item : split_list(o.at)) {
        const given_time t = parse_time("--at", item);
        times.push_back(t.seconds && unit.name != "t/s" ? static_cast<double>(t.value * w0 / scale) : t.value);
        // Any finite time: it is reduced modulo the period exactly.
        if (!std::isfinite(times.back())) {
            throw usage_error("--at '" + item + "': a time " + std::string(unit.name) + " must be finite");
        }
    }
    return times;
}

/// w0 per second for --time t/s, --at in seconds or --omega0 in rad/s (--length and --g
/// checked), 0 otherwise.
long double checked_w0(const trajectory_options& o, const time_unit_row& unit) {
    const bool physical = physical_values(o);
    if (unit.name != "t/s" && !physical) {
        if (o.length) {
            throw usage_error("--length goes with --time t/s, --at in seconds (10s) or --omega0 in rad/s, not --time " +
                              std::string(unit.name));
        }
        return 0;
    }
    if (!o.length) {
        throw usage_error(unit.name == "t/s"
                              ? "--time t/s needs the pendulum's --length L in metres (and --g, default 9.80665)"
                              : "--at in seconds (10s) needs the pendulum's --length L in metres (and --g, default "
                                "9.80665); or give the times in the unit of --time (" + std::string(unit.name) + ")");
    }
    if (!(*o.length > 0 && *o.length <= 1e6)) {
        throw usage_error("--length " + format_double(*o.length) + ": a length in metres above 0 and at most 1e6");
    }
    if (!(o.g > 0 && o.g <= 1e4)) throw usage_error("--g " + format_double(o.g) + ": above 0 and at most 1e4");
    return angular_frequency(*o.length, o.g);
}

/// What every method's values at a time share: the start, the table's kind, the clock.
struct trajectory_context {
    const motion& m;
    bool state;        // a state or energy: omega too, theta unwrapped
    bool paper_table;  // an amplitude in t/T: the paper's table
    long double scale; // w0 t per unit of time
    bool fractions;    // a libration in t/T: times as fractions of its period
};

/// One method's run: its approximant (none for the exact solution), clock and phase.
struct method_run {
    explicit method_run(const method_choice& m) : method(m) {}
    method_choice method;
    fourier_solution approx{};
    std::optional<time_reducer> reduce{};
    double phase_at_start = 0;
};

/// Sets up r (its approximant, clock and phase); an iteration without a period is bad input.
void prepare_run(method_run& r, const trajectory_context& c, const start_option& start, const trajectory_options& o,
                 const time_unit_row& unit, const std::vector<double>& times) {
    const motion& m = c.m;
    const method_choice& method = r.method;
    const bool is_exact = method.is_exact();
    const amplitude theta0 = m.kind() == regime::libration ? m.amplitude() : amplitude(1.0);
    if (!is_exact) r.approx = method_solution(method, theta0);
    if (!is_exact && !r.approx.exists()) {
        throw usage_error(start.text + ": the iteration has no period at order " + std::to_string(method.n) +
                          " there (lambda = (w/w0)^2 < 0: the scheme itself breaks down near pi); choose another order, "
                          "or an amplitude further from pi");
    }
    // The times of a motion with a period are reduced modulo that period exactly (from the
    // exact amplitude or energy), and an approximant's phase (w/w0) w0 t modulo 2 pi with its
    // own frequency ratio: any finite time loses nothing. The separatrix has no period: far
    // out it is at the top to the last bit.
    if (m.has_period()) {
        double largest = o.periods;
        if (!o.at.empty()) {
            largest = 0;
            for (double s : times) largest = std::max(largest, std::fabs(s));
        }
        time_scale ts;
        if (unit.name == "t/T0") ts.what = time_scale::unit::small_periods;
        if (unit.name == "t/s") ts = {time_scale::unit::seconds, *o.length, o.g};
        // An approximant's phase with its own w/w0 from the exact amplitude (its exact source),
        // to the precision the largest time needs: not its double w/w0 taken as exact.
        if (is_exact) r.reduce.emplace(m, ts, largest, 0.0);
        else r.reduce.emplace(m, ts, largest, r.approx);
    }
    // A libration from a state runs its approximant on its own clock: the phase at time 0.
    if (is_exact || c.paper_table) r.phase_at_start = 0.0;
    else r.phase_at_start = r.reduce ? r.reduce->start_phase(m) : start_phase(m, r.approx);
}

/// Appends theta (and omega for a state) of the run at time s to the row.
void append_values(const trajectory_context& c, const method_run& r, double s, std::vector<double>& row) {
    const motion& m = c.m;
    if (!r.method.is_exact()) {
        const double x = r.reduce->phase(s);
        if (c.paper_table) {
            row.push_back(r.approx.theta_at_phase(x));
            return;
        }
        row.push_back(m.libration_center() + r.approx.theta_at_phase(x + r.phase_at_start));
        if (c.state) row.push_back(velocity_at_phase(r.approx, x + r.phase_at_start));
        return;
    }
    if (c.paper_table) {
        // The amplitude's own table, reduced by the exact period's symmetries.
        row.push_back(m.libration().theta_at_fraction(s));
        return;
    }
    if (c.fractions && m.exact_at_fraction(s)) {
        // A libration's state in periods T: its turning points and crossings (from a quarter
        // start), and its start and mirror image at every half period, land exactly.
        row.push_back(m.theta_at_fraction(s));
        if (c.state) row.push_back(m.velocity_at_fraction(s));
        return;
    }
    if (r.reduce) {
        // The time reduced exactly as a double-double; a rotation's revolutions added back exactly.
        const motion_point p = point_at(m, *r.reduce, s);
        row.push_back(p.theta);
        if (c.state) row.push_back(p.omega);
        return;
    }
    const long double far = 1e300L;
    const double t = static_cast<double>(std::clamp(s * c.scale, -far, far));
    row.push_back(m.theta(t));
    if (c.state) row.push_back(m.velocity(t));
}

/// The columns after time: theta (and omega) for one method, theta:ID (omega:ID) for each of several.
std::vector<std::string> value_columns(const std::vector<method_choice>& methods, bool state) {
    std::vector<std::string> columns;
    for (const auto& method : methods) {
        const std::string suffix = methods.size() == 1 ? "" : ":" + method.text();
        columns.push_back("theta" + suffix);
        if (state) columns.push_back("omega" + suffix);
    }
    return columns;
}

/// The head of the JSON of several methods: the start, the time's unit and each method's
/// columns, period and units; the rows follow as "rows".
std::string json_head(const start_option& start, const std::string& theta0_text, const time_unit_row& unit,
                      const std::vector<method_choice>& methods, bool state) {
    const motion& m = start.motion;
    const bool libration = m.kind() == regime::libration;
    std::string out = "{\"start\": " + figures::json_string(start.text) + ",\n \"theta0\": ";
    // The amplitude as written where it is given, and in radians for any libration.
    const std::string text = theta0_text.empty() ? "" : "\"text\": " + figures::json_string(theta0_text) + ", ";
    out += libration ? "{" + text + "\"radians\": " + figures::json_number(m.amplitude().radians()) + "}"
                     : std::string("null");
    out += ",\n \"time\": {\"column\": " + figures::json_string(std::string(unit.column)) + ", \"unit\": " +
           figures::json_string(std::string(unit.name)) + "},\n \"methods\": [";
    for (std::size_t i = 0; i < methods.size(); ++i) {
        const auto& method = methods[i];
        std::optional<double> period;
        if (libration) period = method_period(method, m.amplitude());
        out += std::string(i ? "," : "") + "\n  {\"id\": " + figures::json_string(method.text()) + ", \"method\": " +
               figures::json_string(method.text()) + ", \"theta_column\": " + figures::json_string("theta:" + method.text());
        if (state) out += ", \"omega_column\": " + figures::json_string("omega:" + method.text());
        out += ", \"period\": " + (period ? "{\"T_over_T0\": " + figures::json_number(*period) + "}" : std::string("null"));
        out += ", \"units\": {\"theta\": \"rad\"" + std::string(state ? ", \"omega\": \"theta'/w0\"" : "") + "}}";
    }
    return out + "\n ],\n \"rows\": ";
}

/// Says on standard error, per column, how many of its fields were left empty, where the
/// first was, and why (`reason`): no field is empty without a word.
void warn_empty_fields(const table_writer& writer, const std::vector<std::string>& columns, const std::string& reason) {
    for (std::size_t i = 1; i < columns.size(); ++i) {
        const std::size_t count = writer.empty_fields(i);
        if (count == 0) continue;
        std::cerr << "pendulum-figures: warning: " << count << (count == 1 ? " field" : " fields") << " of column "
                  << columns[i] << " left empty (null in JSON), the first at " << columns.front() << " = "
                  << format_double(writer.first_empty_at(i)) << ": " << reason << "\n";
    }
}

/// Why a value of an exact or approximate trajectory is empty: only a number beyond a double.
constexpr const char* beyond_double =
    "the value is beyond the largest double, 1.7976931348623157e308 (a rotation's unwrapped angle far out, "
    "or the time w0 t itself); omega, periodic, keeps every digit";

/// The table of a user's theta(t) = f(t, theta0), t = w0 t, at the times asked for; refused
/// for a state or an energy (the formula starts at rest at its amplitude) and where it is
/// finite at none of them.
void write_formula_trajectory(std::ostream& out, table_format format, const method_choice& method,
                              const start_option& start, bool state, const time_unit_row& unit, long double w0,
                              const trajectory_options& o, const std::vector<double>& times) {
    if (state) {
        throw usage_error("--method " + method.text() + " (a formula theta(t) = f(t, theta0)) starts at rest at its "
                          "amplitude: give --theta0 alone, not " + start.text);
    }
    const double theta0 = start.motion.amplitude().radians();
    const long double scale = unit.scale(start.motion, w0);
    const auto time_at = [&](std::size_t i) {
        return o.at.empty() ? o.periods * static_cast<double>(i) / (o.samples - 1) : times[i];
    };
    const std::size_t count = o.at.empty() ? static_cast<std::size_t>(o.samples) : times.size();
    const auto theta = [&](double s) { return method.user->value(theta0, static_cast<double>(s * scale)); };
    bool finite = false;
    for (std::size_t i = 0; i < count && !finite; ++i) finite = std::isfinite(theta(time_at(i)));
    if (!finite) {
        throw usage_error("--method " + method.text() + " = '" + method.user->text() +
                          "' is not finite at any of the times asked for; check the formula");
    }
    const std::vector<std::string> columns{std::string(unit.column), "theta"};
    table_writer writer(out, columns, format);
    for (std::size_t i = 0; i < count; ++i) writer.row({time_at(i), theta(time_at(i))});
    writer.finish();
    warn_empty_fields(writer, columns, "the formula '" + method.user->text() + "' is not finite there");
}

/// Refuses --samples and --periods outside their ranges (with --samples).
void check_sampling(const trajectory_options& o) {
    if (o.at.empty() == (o.samples == 0)) {
        throw usage_error("give either --at LIST or --samples N (with --periods P)");
    }
    if (!o.at.empty()) return;
    if (o.samples < 2 || o.samples > max_samples) {
        throw usage_error("--samples " + std::to_string(o.samples) + ": must be between 2 and " +
                          std::to_string(max_samples));
    }
    if (!(o.periods > 0.0) || !(o.periods <= max_periods)) {
        throw usage_error("--periods " + format_double(o.periods) + ": must be greater than 0 and at most " +
                          format_double(max_periods));
    }
}

/// |d ln T / d ln x| of a libration, x being whichever of theta0 and pi - theta0 its amplitude holds.
double period_sensitivity(const amplitude& a) {
    constexpr double h = 1e-6;
    const amplitude b = a.near_pi() ? amplitude::from_pi(a.from_pi() * (1 + h)) : amplitude(a.radians() * (1 + h));
    return std::fabs(std::log(exact_solution(b).period_ratio() / exact_solution(a).period_ratio())) / h;
}

/// Says on standard error how many digits of theta remain where an amplitude rounded from its
/// expression (9pi/10, not 3) meets a time of many periods: the phase is off by about
/// 2 pi (t/T) |d ln T/d ln theta0| 2^-53, however exactly the time itself is reduced.
void warn_conditioning(const start_option& start, const trajectory_options& o, const std::vector<double>& times,
                       long double scale) {
    const motion& m = start.motion;
    if (m.given_as() != motion::origin::amplitude || m.amplitude().exact()) return;
    double largest = o.periods;
    if (!o.at.empty()) {
        largest = 0;
        for (double s : times) largest = std::max(largest, std::fabs(s));
    }
    const double periods = largest * static_cast<double>(scale / m.period());
    const double error = 2 * std::numbers::pi * periods * period_sensitivity(m.amplitude()) * 0x1p-53;
    if (!(error > 1e-15)) return;
    const int digits = std::max(0, static_cast<int>(std::floor(-std::log10(error))));
    std::cerr << "pendulum-figures: warning: " << start.text << " is not a double as written, and its rounding "
              << "(half an ulp) shifts the phase by about " << format_double(error) << " rad at " << format_double(periods)
              << " periods: about " << digits << " digits of theta remain there; write the amplitude as a number "
              << "(a double is taken exactly) for every digit\n";
}

/// Writes the rows: --samples times computed as they are written (ten million need no
/// memory), or the times of --at.
void write_rows(table_writer& writer, const trajectory_context& c, const std::deque<method_run>& runs,
                const trajectory_options& o, const std::vector<double>& times) {
    std::vector<double> row;
    const auto write = [&](double s) {
        row.assign(1, s);
        for (const auto& r : runs) append_values(c, r, s, row);
        writer.row(row);
    };
    if (o.at.empty()) {
        for (int i = 0; i < o.samples; ++i) write(o.periods * i / (o.samples - 1));
    } else {
        for (double s : times) write(s);
    }
}

/// The one start of trajectory and its time unit, checked.
const start_option& single_start(const std::vector<start_option>& starts, const time_unit_row& unit) {
    if (starts.size() != 1) throw usage_error("trajectory takes one start: one --theta0 (and --omega0) or --energy");
    const start_option& start = starts.front();
    if (!start.motion.has_period() && unit.name == "t/T") {
        throw usage_error(start.text + " is on the separatrix (E = 2): it has no period T; give --time t/T0 or --time t/s");
    }
    return start;
}

/// Writes trajectory's table row by row; every input is checked before the first row.
void trajectory_stream(std::ostream& out, const trajectory_options& given, bool order_given, bool periods_given) {
    // --omega0 from @FILE or -: its items, as if typed, so that rad/s there counts as on the line.
    trajectory_options o = given;
    o.omega0 = listed_items(given.omega0, "--omega0");
    const auto format = parse_table_format(o.format);
    const auto starts = parse_starts(o.theta0, omega0_in_w0(o.omega0, o.length, o.g), o.energy);
    const time_unit_row& unit = parse_time_unit(o.time.empty() ? "t/T" : o.time);
    const start_option& start = single_start(starts, unit);
    const motion& m = start.motion;
    // An amplitude alone keeps the paper's table: t/T and theta; a state also prints theta'/w0.
    const bool state = !o.omega0.empty() || !o.energy.empty();
    const long double w0 = checked_w0(o, unit);
    const std::vector<method_choice> methods = trajectory_methods(o, order_given, start);
    check_sampling(o);
    const std::vector<double> times = times_at(o, unit, periods_given, w0, unit.scale(m, w0));
    if (methods.front().user) return write_formula_trajectory(out, format, methods.front(), start, state, unit, w0, o, times);
    const bool paper_table = !state && unit.name == "t/T";
    const trajectory_context c{m, state, paper_table, unit.scale(m, w0),
                               !paper_table && unit.name == "t/T" && m.kind() == regime::libration};
    std::deque<method_run> runs;  // in place: a time reducer stays where it is made
    for (const auto& method : methods) prepare_run(runs.emplace_back(method), c, start, o, unit, times);
    warn_conditioning(start, o, times, c.scale);

    std::vector<std::string> columns{std::string(unit.column)};
    for (auto& name : value_columns(methods, state)) columns.push_back(std::move(name));
    const bool several_json = methods.size() > 1 && format == table_format::json;
    if (several_json) out << json_head(start, state ? "" : o.theta0, unit, methods, state);
    table_writer writer(out, columns, format);
    write_rows(writer, c, runs, o, times);
    writer.finish();
    if (several_json) out << "}\n";
    warn_empty_fields(writer, columns, beyond_double);
}

}  // namespace

command add_trajectory_command(CLI::App& app) {
    auto tr = std::make_shared<trajectory_options>();
    auto* cmd = app.add_subcommand(
        "trajectory", "Print theta(t) for one start (amplitude, state or energy), exact or approximate.");
    cmd->add_option("--theta0", tr->theta0, "Amplitude, one angle; with --omega0 the start angle of a state")
        ->type_name("ANGLE")->check(non_empty);
    cmd->add_option("--omega0", tr->omega0,
                    "Launch velocity theta'(0) of a state started at --theta0 (any sign), in units of w0 = "
                    "sqrt(g/L); in rad/s with --length (2.5rad/s)")
        ->type_name("W")->check(non_empty);
    cmd->add_option("--energy", tr->energy, "Energy E/(m g L) of a launch from the bottom (2 is the separatrix)")
        ->type_name("E")->check(non_empty);
    std::string units;
    for (const auto& row : time_units) {
        units += (units.empty() ? "" : "; ") + std::string(row.name) + ": " + std::string(row.description);
    }
    cmd->add_option("--time", tr->time, "Unit of the times of --at, --samples and --periods (default t/T): " + units)
        ->type_name("t/T|t/T0|t/s");
    cmd->add_option("--length", tr->length, "Pendulum length in metres, for --time t/s")->type_name("L");
    cmd->add_option("--g", tr->g, "Gravity in m/s^2 for --length (default 9.80665)")->type_name("G");
    cmd->add_option("--method", tr->method,
                     "Methods with a law of motion, a comma-separated LIST of up to " +
                         std::to_string(max_methods) + ": exact (default), harmonic, lowest, first, second, "
                         "polynomial, or order:N (or order with --order N); see 'list'; or alone a formula "
                         "'formula:theta0*cos(t)', theta(t) in t = w0 t and theta0")
        ->type_name("METHOD");
    auto* order_opt = cmd->add_option("--order", tr->order, "Order N of --method order (0.." +
                                                                std::to_string(max_order) + ")")
                          ->type_name("N");
    cmd->add_option("--at", tr->at,
                    "Times in the unit of --time (default t/T, T the exact period), or in seconds with --length "
                    "(10s), a comma-separated list")
        ->type_name("LIST")->check(non_empty);
    cmd->add_option("--samples", tr->samples, "Number of equally spaced times from 0 to --periods")
        ->type_name("N");
    auto* periods_opt =
        cmd->add_option("--periods", tr->periods, "Time span in the unit of --time (default 1 period T)")
            ->type_name("P");
    cmd->add_option("--format", tr->format, "Output format: csv (default) or json")
        ->type_name("csv|json");
    cmd->footer(std::string("\n") + angle_help +
                 "\n\n" + start_help + "\n\n" + omega0_help +
                 "\n\nColumns: t_over_T, theta (radians). Every method is evaluated at the same "
                 "physical time t = (t/T) T, with T the exact period. With --time the first column is t_over_T0 "
                 "or t_s; a state or energy adds omega (theta'/w0), and theta is unwrapped: a rotation's angle "
                 "keeps rising. The approximants describe librations only: on a rotation or the separatrix "
                 "they are an error. Any finite time is accepted, up to the largest double: it is reduced modulo "
                 "the exact period (and an approximant's phase (w/w0) w0 t modulo 2 pi) in exact arithmetic, "
                 "so theta is right to a few ulps at any time. A rotation's unwrapped angle is the double "
                 "nearest its exact value (right relative to itself: far out its digits count the turns, not "
                 "the place in the turn; omega, periodic, keeps every digit); where it exceeds the largest "
                 "double the field is empty (null in JSON).\n\n"
                 "Several methods (--method exact,lowest) give one column each, named by the method: "
                 "theta:exact, theta:lowest (and omega:exact, ... for a state), each the same number as the "
                 "method alone writes. Their JSON is an object: start, theta0, time (column and unit), methods "
                 "(id, columns, period T/T0 of a libration, units) and rows.\n\n"
                 "Examples:\n"
                 "  pendulum-figures trajectory --theta0 0 --omega0 2.2 --samples 5\n"
                 "  pendulum-figures trajectory --energy 2 --time t/T0 --at 0,0.5,1\n"
                 "  pendulum-figures trajectory --theta0 9pi/10 --method second --samples 201 --periods 2\n"
                 "  pendulum-figures trajectory --theta0 pi/2 --method order --order 8 --at 0,0.125,0.25\n"
                 "  pendulum-figures trajectory --theta0 9pi/10 --method exact,lowest,order:6 --samples 101");

    return {cmd, [tr, order_opt, periods_opt] {
                trajectory_stream(std::cout, *tr, order_opt->count() > 0, periods_opt->count() > 0);
                return write_stdout("");
            }};
}

}  // namespace pendulum::cli
