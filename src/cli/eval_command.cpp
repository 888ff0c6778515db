// SPDX-License-Identifier: GPL-3.0-or-later
// eval: periods T/T0 and Fourier coefficients per amplitude, as CSV or JSON.
#include "cli/commands.hpp"
#include "cli/eval_columns.hpp"
#include "cli/options.hpp"
#include "cli/report.hpp"
#include "cli/table.hpp"
#include "pendulum/approximants.hpp"
#include "pendulum/formula.hpp"
#include "pendulum/methods.hpp"
#include "pendulum/seconds.hpp"
#include "plot/workers.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <tuple>
#include <utility>
#include <vector>

namespace pendulum::cli {

namespace {

/// Says on standard error which levels of the iteration have no period at this amplitude.
void warn_breakdown(const amplitude& theta0, const std::vector<int>& levels) {
    std::string list;
    for (int n : levels) list += (list.empty() ? "" : ", ") + std::to_string(n);
    std::cerr << "pendulum-figures: warning: theta0 = " << format_amplitude(theta0) << ": the iteration has no period at order "
              << list << " (lambda = (w/w0)^2 < 0 there: the scheme itself breaks down near pi); "
              << (levels.size() == 1 ? "that field is" : "those fields are") << " left empty\n";
}

struct eval_options {
    std::string theta0;
    std::string omega0;
    std::string energy;
    std::vector<std::string> orders;
    std::vector<std::string> methods;
    std::string format = "csv";
    std::optional<double> length;  // metres: adds the period in seconds
    double g = 9.80665;
    std::string columns;            // only these columns (fixed ones and T_s); empty: every fixed column
    std::optional<int> jobs;        // worker threads, as render takes them
};

/// The name of the column of the period in seconds (--length).
constexpr std::string_view seconds_column = "T_s";

/// The fixed columns --columns keeps, in the table's order, and whether it keeps T_s; every
/// fixed column (and T_s with --length) without it. Its error columns (err:METHOD) go to
/// `errors`, in its order. An unknown name is bad input.
std::pair<std::vector<const eval_column*>, bool> chosen_columns(const eval_options& o, std::vector<method_choice>& errors) {
    std::vector<const eval_column*> fixed;
    if (o.columns.empty()) {
        for (const auto& c : eval_columns()) {
            if (c.by_default) fixed.push_back(&c);
        }
        return {fixed, o.length.has_value()};
    }
    const auto names = split_list(o.columns);
    bool seconds = false;
    for (const auto& name : names) {
        if (const auto m = error_column_method(name)) {
            errors.push_back(*m);
            continue;
        }
        const bool known = name == seconds_column ||
                           std::any_of(eval_columns().begin(), eval_columns().end(), [&](const eval_column& c) { return c.name == name; });
        if (!known) {
            std::string all;
            for (const auto& c : eval_columns()) all += std::string(c.name) + ", ";
            throw usage_error("--columns: unknown column '" + shown_text(name) + "'; the columns are " + all +
                              std::string(seconds_column) + " and err:METHOD for any method of 'list'");
        }
        seconds = seconds || name == seconds_column;
    }
    for (const auto& c : eval_columns()) {
        if (std::find(names.begin(), names.end(), c.name) != names.end()) fixed.push_back(&c);
    }
    if (seconds && !o.length) throw usage_error("--columns T_s: the period in seconds needs --length");
    return {fixed, seconds};
}

/// The methods of --method, each once.
std::vector<method_choice> parse_methods(const std::vector<std::string>& given) {
    std::vector<method_choice> methods;
    int formulas = 0;
    const auto same = [](const method_choice& a, const method_choice& b) {
        return a.user || b.user ? a.user && b.user && a.user->text() == b.user->text() : a.text() == b.text();
    };
    for (const auto& text : list_items(given)) {
        if (text.empty()) throw usage_error("--method: empty value; see 'list' for the methods");
        auto m = parse_method_option("--method", text);
        if (m.user && m.user->uses_t()) {
            throw usage_error("--method '" + shown_text(text) + "': the formula uses t, a law of motion theta(t) whose "
                              "period is not defined; eval takes a period formula in theta0 alone (use it with trajectory)");
        }
        if (std::none_of(methods.begin(), methods.end(), [&](const method_choice& c) { return same(c, m); })) {
            if (m.user) m.n = ++formulas;  // formula:1, formula:2 in the order given
            methods.push_back(std::move(m));
        }
    }
    return methods;
}

/// T0 in seconds for --length and --g, in extended precision; 0 without --length.
long double small_period_seconds(const eval_options& o) {
    if (!o.length) return 0.0;
    if (!(*o.length > 0 && *o.length <= 1e6)) {
        throw usage_error("--length " + format_double(*o.length) + ": a length in metres above 0 and at most 1e6");
    }
    if (!(o.g > 0 && o.g <= 1e4)) throw usage_error("--g " + format_double(o.g) + ": above 0 and at most 1e4");
    return pendulum::small_period_seconds(*o.length, o.g);
}

/// T_s for a period ratio: a usage error where it overflows a double.
double period_seconds(double ratio, long double small_period_s) {
    try {
        return seconds(ratio, small_period_s);
    } catch (const domain_error& e) {
        throw usage_error(std::string("--length and --g: ") + e.what());
    }
}

/// The highest level of the iteration that --order and --method order:N ask for (-1: none).
int highest_level(const std::vector<int>& orders, const std::vector<method_choice>& methods) {
    int highest = -1;
    for (int n : orders) highest = std::max(highest, n);
    for (const auto& m : methods) {
        if (m.row->role == method_role::iterated) highest = std::max(highest, m.n);
    }
    return highest;
}

/// The periods of the --order and --method columns at an amplitude; the levels of the
/// iteration without a period (their fields are empty) go into `broken`.
std::vector<double> method_periods(const amplitude& theta0, const std::vector<int>& orders,
                                   const std::vector<method_choice>& methods, int highest, std::vector<int>& broken) {
    const auto levels = highest >= 0 ? iterated_sequence(theta0, highest) : std::vector<fourier_solution>{};
    broken.clear();
    const auto level_period = [&](int n) {
        const auto& level = levels[static_cast<std::size_t>(n)];
        if (!level.exists() && std::find(broken.begin(), broken.end(), n) == broken.end()) broken.push_back(n);
        return level.period_ratio();
    };
    std::vector<double> periods;
    for (int n : orders) periods.push_back(level_period(n));
    for (const auto& m : methods) {
        periods.push_back(m.row->role == method_role::iterated ? level_period(m.n) : method_period(m, theta0));
    }
    return periods;
}

/// The methods less those whose column is one of `fixed` (--method exact is period_exact):
/// a table has each column once.
std::vector<method_choice> without_fixed(const std::vector<method_choice>& methods, const std::vector<std::string>& fixed) {
    std::vector<method_choice> kept;
    for (const auto& m : methods) {
        if (std::find(fixed.begin(), fixed.end(), "period_" + m.text()) == fixed.end()) kept.push_back(m);
    }
    return kept;
}

/// The columns of eval for starts (states or energies), before --order, --method and T_s.
constexpr const char* start_columns[] = {"theta0", "omega0", "energy", "regime", "amplitude", "period_exact",
                                         "revolution_period"};

/// Says on standard error that a start's energy is not held by a double (its field is the
/// double nearest, with fewer digits where subnormal, or empty where it is 0 or beyond the largest).
void warn_energy(const start_option& start) {
    const auto& m = start.motion;
    const bool empty = m.energy() == 0 || !std::isfinite(m.energy());
    std::cerr << "pendulum-figures: warning: " << start.text << ": the energy is " << m.energy_unheld()
              << ", which a double cannot hold "
              << (empty ? "(beyond its range): the energy field is left empty"
                        : "to every digit (it is below 2.2250738585072014e-308): the energy field has fewer digits")
              << "; the other fields are computed from the exact energy\n";
}

/// Refuses --columns, and a method or order on a start that is not a libration.
void check_starts(const eval_options& o, const std::vector<start_option>& starts, const std::vector<int>& orders,
                  const std::vector<method_choice>& methods) {
    if (!o.columns.empty()) {
        throw usage_error("--columns chooses among the columns of amplitudes (--theta0 alone); with --omega0 or "
                          "--energy every column is written");
    }
    for (const auto& start : starts) {
        for (const auto& m : methods) check_method_applies(m, start);
        if (!orders.empty() && start.motion.kind() != regime::libration) {
            check_method_applies(parse_method("order:" + std::to_string(orders.front())), start);
        }
    }
}

/// One start's row: the fixed fields, then --order and --method periods, then T_s.
std::vector<field> start_row(const start_option& start, const eval_options& o, const std::vector<int>& orders,
                             const std::vector<method_choice>& methods, long double small_period_s, std::vector<int>& broken) {
    const auto& m = start.motion;
    const double none = std::numeric_limits<double>::quiet_NaN();
    const bool libration = m.kind() == regime::libration;
    const auto ratio = m.has_period() ? m.period_ratio() : none;
    const double energy = m.energy() != 0 && std::isfinite(m.energy()) ? m.energy() : none;
    std::vector<field> row{m.start().theta, m.start().omega, energy, std::string(row_of(m.kind()).name),
                           libration ? m.amplitude().radians() : none, libration ? ratio : none,
                           m.kind() == regime::rotation ? ratio : none};
    broken.clear();
    if (libration) {
        for (double x : method_periods(m.amplitude(), orders, methods, highest_level(orders, methods), broken)) {
            row.emplace_back(x);
        }
    }
    if (o.length) row.emplace_back(std::isnan(ratio) ? ratio : period_seconds(ratio, small_period_s));
    return row;
}

/// eval for states and energies: regime, energy, amplitude or revolution period per start.
void eval_starts(std::ostream& out, const eval_options& o, const std::vector<int>& orders,
                 const std::vector<method_choice>& all_methods, long double small_period_s) {
    const auto format = parse_table_format(o.format);
    const auto starts = parse_starts(o.theta0, omega0_in_w0(o.omega0, o.length, o.g), o.energy);
    std::vector<std::string> columns(std::begin(start_columns), std::end(start_columns));
    const auto methods = without_fixed(all_methods, columns);
    check_starts(o, starts, orders, methods);
    for (int n : orders) columns.push_back("period_order" + std::to_string(n));
    for (const auto& m : methods) columns.push_back("period_" + m.text());
    if (o.length) columns.push_back("T_s");
    table_writer writer(out, columns, format);
    std::vector<int> broken;
    for (const auto& start : starts) {
        writer.record(start_row(start, o, orders, methods, small_period_s, broken));
        if (broken.empty() && start.motion.energy_unheld().empty()) continue;
        writer.flush();  // the warning follows its row
        if (!broken.empty()) warn_breakdown(start.motion.amplitude(), broken);
        if (!start.motion.energy_unheld().empty()) warn_energy(start);
    }
    writer.finish();
}

/// Refuses an err:formula column in --columns: a formula's column comes with its --method.
void check_error_columns(const std::vector<method_choice>& errors) {
    for (const auto& e : errors) {
        if (e.user) {
            throw usage_error("--columns 'err:formula:" + shown_text(e.user->text()) + "': give the formula with --method "
                              "'formula:...'; its err:formula:K column comes with it");
        }
    }
}

/// What eval writes for amplitudes: the chosen columns, the methods and error columns.
struct amplitude_table {
    std::vector<const eval_column*> fixed;
    bool seconds = false;
    std::vector<method_choice> methods;
    std::vector<method_choice> errors;
    std::vector<std::string> columns;
    unsigned needs = 0;
};

amplitude_table amplitude_columns(const eval_options& o, const std::vector<int>& orders,
                                  const std::vector<method_choice>& all_methods) {
    amplitude_table t;
    std::tie(t.fixed, t.seconds) = chosen_columns(o, t.errors);
    // A user's formula comes with its error column, err:formula:K (T_f/T - 1 without cancellation):
    // one written in --columns would be numbered apart from the --method ones.
    check_error_columns(t.errors);
    for (const auto* c : t.fixed) t.columns.emplace_back(c->name);
    t.methods = without_fixed(all_methods, t.columns);
    for (const auto& m : t.methods) {
        if (m.user) t.errors.push_back(m);
    }
    // Only the solutions the chosen columns read are computed.
    t.needs = t.seconds ? static_cast<unsigned>(need_exact_period) : 0u;
    for (const auto* c : t.fixed) t.needs |= c->needs;
    for (int n : orders) t.columns.push_back("period_order" + std::to_string(n));
    for (const auto& m : t.methods) t.columns.push_back("period_" + m.text());
    for (const auto& m : t.errors) t.columns.push_back(std::string(error_column_prefix) + m.text());
    if (t.seconds) t.columns.emplace_back(seconds_column);
    return t;
}

/// One amplitude's fields, into `fields`; the iteration's levels without a period go to `broken`.
void amplitude_row(const amplitude& value, const amplitude_table& t, const std::vector<int>& orders,
                   long double small_period_s, std::vector<int>& broken, std::vector<field>& fields) {
    const eval_point point(value, t.needs);
    fields.clear();
    for (const auto* c : t.fixed) fields.emplace_back(c->value(point));
    for (double x : method_periods(value, orders, t.methods, highest_level(orders, t.methods), broken)) {
        fields.emplace_back(x);
    }
    for (const auto& m : t.errors) {
        const period_error e = method_period_error(m, value);
        fields.push_back(period_error_field(e));
        // An iteration without a period is said, as for its period's column.
        const bool iterated = !m.user && m.row->role == method_role::iterated;
        if (iterated && e.what == period_error::kind::no_period &&
            std::find(broken.begin(), broken.end(), m.n) == broken.end()) {
            broken.push_back(m.n);
        }
    }
    if (t.seconds) fields.emplace_back(period_seconds(*point.exact_period, small_period_s));
}

/// Rows computed and formatted at a time, on every worker, before they are written in order:
/// a block's text takes about 0.2 MB, and a warning still follows its row.
constexpr std::size_t rows_per_block = 4096;
/// Rows one worker takes at a time from a block.
constexpr std::size_t rows_per_task = 128;

/// A block's rows as the table writes them: each task's rows in a text of its own, where each
/// row ends in it, and each row's levels of the iteration without a period.
struct block_rows {
    std::vector<std::string> texts;
    std::vector<std::size_t> ends;
    std::vector<std::vector<int>> broken;
};

/// The rows of amplitudes [first, first + n), computed and formatted on every worker.
void amplitude_block(const std::vector<amplitude>& amplitudes, std::size_t first, std::size_t n,
                     const amplitude_table& t, const std::vector<int>& orders, long double small_period_s,
                     const table_writer& writer, block_rows& rows) {
    const std::size_t tasks = (n + rows_per_task - 1) / rows_per_task;
    rows.texts.resize(tasks);
    rows.ends.assign(n, 0);
    rows.broken.assign(n, {});
    plot::parallel_for(tasks, [&](std::size_t task) {
        std::string& text = rows.texts[task];
        text.clear();
        std::vector<field> fields;
        for (std::size_t i = task * rows_per_task; i < std::min(n, (task + 1) * rows_per_task); ++i) {
            amplitude_row(amplitudes[first + i], t, orders, small_period_s, rows.broken[i], fields);
            writer.format(text, fields, first + i == 0);
            rows.ends[i] = text.size();
        }
    });
}

/// Writes a block's rows in order, each warning after its row.
void write_block(table_writer& writer, const block_rows& rows, const std::vector<amplitude>& amplitudes,
                 std::size_t first) {
    for (std::size_t task = 0; task < rows.texts.size(); ++task) {
        const std::string_view text = rows.texts[task];
        const std::size_t begin = task * rows_per_task;
        const std::size_t end = std::min(rows.ends.size(), begin + rows_per_task);
        std::size_t written = 0;  // bytes of the text
        std::size_t row = begin;  // the first row not yet written
        for (std::size_t i = begin; i < end; ++i) {
            if (rows.broken[i].empty()) continue;
            writer.write_formatted(text.substr(written, rows.ends[i] - written), i + 1 - row);
            writer.flush();  // the warning follows its row
            warn_breakdown(amplitudes[first + i], rows.broken[i]);
            written = rows.ends[i];
            row = i + 1;
        }
        writer.write_formatted(text.substr(written), end - row);
    }
}

void eval_stream(std::ostream& out, const eval_options& o) {
    const auto format = parse_table_format(o.format);
    const std::vector<int> orders = parse_orders(list_items(o.orders));
    const std::vector<method_choice> methods = parse_methods(o.methods);
    const long double small_period_s = small_period_seconds(o);
    if (!o.omega0.empty() || !o.energy.empty()) return eval_starts(out, o, orders, methods, small_period_s);
    if (o.theta0.empty()) throw usage_error("give --theta0 (amplitudes, or with --omega0 states) or --energy");
    const auto amplitudes = parse_amplitude_values(o.theta0);
    const amplitude_table t = amplitude_columns(o, orders, methods);
    // The iteration is computed once per amplitude, to the highest level asked for, and
    // every --order and --method order:N column is read off that one sequence.
    table_writer writer(out, t.columns, format);
    block_rows rows;
    for (std::size_t first = 0; first < amplitudes.size(); first += rows_per_block) {
        const std::size_t n = std::min(rows_per_block, amplitudes.size() - first);
        amplitude_block(amplitudes, first, n, t, orders, small_period_s, writer, rows);
        write_block(writer, rows, amplitudes, first);
    }
    writer.finish();
}

}  // namespace

command add_eval_command(CLI::App& app) {
    auto ev = std::make_shared<eval_options>();
    auto* cmd = app.add_subcommand(
        "eval", "Print periods T/T0 and Fourier coefficients, exact and approximate, per amplitude.");
    cmd->add_option("--theta0", ev->theta0,
                    "Amplitudes, a comma-separated LIST of angles; with --omega0 the start angles of states")
        ->type_name("LIST")->check(non_empty);
    cmd->add_option("--omega0", ev->omega0,
                    "Launch velocities theta'(0) of states started at --theta0, a LIST (any sign), in units of "
                    "w0 = sqrt(g/L); in rad/s with --length (2.5rad/s)")
        ->type_name("LIST")->check(non_empty);
    cmd->add_option("--energy", ev->energy,
                    "Energies E/(m g L) of launches from the bottom, a LIST (2 is the separatrix)")
        ->type_name("LIST")->check(non_empty);
    cmd->add_option("--order", ev->orders,
                     "Add a column period_orderN for the iteration to order N (0.." +
                         std::to_string(max_order) + "), or one for each N of a range a..b; repeatable")
        ->type_name("N")
        ->take_all();
    cmd->add_option("--method", ev->methods,
                     "Add a column period_NAME for any method of 'list', e.g. kidd-fogg, agm:2, series:3, or for a "
                     "formula, formula:EXPR (columns period_formula:K and err:formula:K, T_f/T - 1); "
                     "repeatable")
        ->type_name("NAME")
        ->take_all();
    cmd->add_option("--length", ev->length, "Pendulum length in metres: adds T_s, the exact period in seconds")
        ->type_name("L");
    cmd->add_option("--g", ev->g, "Gravity in m/s^2 for --length (default 9.80665)")->type_name("G");
    cmd->add_option("--format", ev->format, "Output format: csv (default) or json")
        ->type_name("csv|json");
    cmd->add_option("--columns", ev->columns,
                     "Only these columns, a comma-separated LIST of the columns below and T_s (with --length), "
                     "written in the table's order; only what they need is computed. --order and --method "
                     "columns follow them, then err:METHOD columns (T_m/T - 1 of any method of 'list', right to "
                     "1e-12: err:lowest, err:order:6; below_limit under 1e-300, not_computed where it could not be resolved, empty where the method has no period)")
        ->type_name("LIST")->check(non_empty);
    cmd->add_option("--jobs", ev->jobs, jobs_help)->type_name("N");
    cmd->footer(std::string("\n") + angle_help + "\n\n" + omega0_help + "\n\nColumns: " + cli::eval_columns_help() +
                 "; then period_orderN for each --order N, period_NAME for each --method NAME, and T_s with "
                 "--length. Periods are T/T0. Numbers round-trip a double.\n\n"
                 "Close to pi (from pi - 6.995e-4) some levels of the iteration have lambda = (w/w0)^2 < 0, "
                 "so no period: at pi - 1e-6 the orders 6, 8, 16 and 17. That field is left empty (null in "
                 "JSON), a warning on standard error names the amplitude and the orders, and the exit status "
                 "stays 0: the table is complete, the value does not exist.\n\n" + start_help +
                 "\n\nWith --omega0 or --energy the columns are: theta0 and omega0 (the start), energy, regime "
                 "(libration, separatrix or rotation), amplitude and period_exact (T/T0, librations only), "
                 "revolution_period (T_rev/T0, rotations only); a field that does not exist for the regime is "
                 "empty (null in JSON). --order and --method apply to librations only: on another regime they "
                 "are an error.\n\n"
                 "Examples:\n"
                 "  pendulum-figures eval --theta0 0 --omega0 1.9,2,2.2\n"
                 "  pendulum-figures eval --energy 0.5,1.5,2,2.5\n"
                 "  pendulum-figures eval --theta0 'pi/2,9pi/10' --order 12\n"
                 "  pendulum-figures eval --theta0 0.99pi --order 0..40\n"
                 "  pendulum-figures eval --theta0 170deg --method kidd-fogg,lima-arun,ganley,agm:2\n"
                 "  pendulum-figures eval --theta0 170deg --length 0.5\n"
                 "  pendulum-figures eval --theta0 170deg --length 0.5 --columns period_exact,T_s");

    return {cmd, [ev] {
                // Amplitudes are read and their rows computed on every worker, and written in order.
                plot::set_thread_limit(chosen_jobs(ev->jobs));
                eval_stream(std::cout, *ev);
                return write_stdout("");
            }};
}

}  // namespace pendulum::cli
