// SPDX-License-Identifier: GPL-3.0-or-later
// trajectory: theta(t) of one amplitude, exact or approximate, at times t/T.
#include "cli/commands.hpp"
#include "cli/options.hpp"
#include "cli/report.hpp"
#include "cli/table.hpp"
#include "pendulum/approximants.hpp"
#include "pendulum/exact.hpp"
#include "pendulum/methods.hpp"

#include <CLI/CLI.hpp>

#include <cmath>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

namespace pendulum::cli {

namespace {

constexpr int max_samples = 10'000'000;
constexpr double max_periods = 1e6;

struct trajectory_options {
    std::string theta0;
    std::string method = "exact";
    std::string order;
    std::string at;
    int samples = 0;
    double periods = 1.0;
    std::string format = "csv";
};

/// Writes trajectory's table row by row; every input is checked before the first row.
void trajectory_stream(std::ostream& out, const trajectory_options& o, bool order_given, bool periods_given) {
    const auto format = parse_table_format(o.format);
    const auto amplitudes = parse_amplitudes(o.theta0);
    if (amplitudes.size() != 1) throw usage_error("--theta0 takes one amplitude for trajectory");
    const amplitude theta0 = amplitudes.front().theta0();
    std::string method_text = o.method;
    if (o.method == "order") {
        if (!order_given) throw usage_error("--method order needs --order N (or write --method order:N)");
        method_text = "order:" + std::to_string(parse_order(o.order));
    } else if (order_given) {
        throw usage_error("--order is only used with --method order, not --method " + o.method);
    }
    const method_choice method = parse_method_option("--method", method_text);
    if (!method.has_motion()) {
        throw usage_error("--method " + method.text() + " gives a period only, not a law of motion; see 'list'");
    }
    if (o.at.empty() == (o.samples == 0)) {
        throw usage_error("give either --at LIST or --samples N (with --periods P)");
    }
    std::vector<double> times;
    if (!o.at.empty()) {
        if (periods_given) throw usage_error("--periods goes with --samples, not with --at");
        for (const auto& item : split_list(o.at)) {
            try {
                times.push_back(parse_expression(item));
            } catch (const std::invalid_argument& e) {
                throw usage_error(std::string("--at '") + item + "': " + e.what());
            }
            // t/T is multiplied by the period: a huge one overflows.
            if (!(std::fabs(times.back()) <= max_periods)) {
                throw usage_error("--at '" + item + "': a time t/T must be finite and at most " +
                                  format_double(max_periods) + " in size");
            }
        }
    } else {
        if (o.samples < 2 || o.samples > max_samples) {
            throw usage_error("--samples " + std::to_string(o.samples) + ": must be between 2 and " +
                              std::to_string(max_samples));
        }
        if (!(o.periods > 0.0) || !(o.periods <= max_periods)) {
            throw usage_error("--periods " + format_double(o.periods) +
                              ": must be greater than 0 and at most " + format_double(max_periods));
        }
    }

    const exact_solution exact(theta0);
    const bool is_exact = method.is_exact();
    const fourier_solution approx = is_exact ? fourier_solution{} : method_solution(method, theta0);
    if (!is_exact && !approx.exists()) {
        throw usage_error("--theta0 " + amplitudes.front().text + ": the iteration has no period at order " +
                          std::to_string(method.n) + " there (lambda = (w/w0)^2 < 0: the scheme itself breaks down " +
                          "near pi); choose another order, or an amplitude further from pi");
    }

    const double period = 4.0 * exact.quarter_period();  // exact T in units of 1/w0
    table_writer writer(out, {"t_over_T", "theta"}, format);
    const auto write = [&](double s) {
        writer.row({s, is_exact ? exact.theta_at_fraction(s) : approx.theta(s * period)});
    };
    if (o.at.empty()) {
        // Sample times computed as they are written: ten million rows need no memory.
        for (int i = 0; i < o.samples; ++i) write(o.periods * i / (o.samples - 1));
    } else {
        for (double s : times) write(s);
    }
    writer.finish();
}

}  // namespace

command add_trajectory_command(CLI::App& app) {
    auto tr = std::make_shared<trajectory_options>();
    auto* cmd = app.add_subcommand(
        "trajectory", "Print theta(t) for one amplitude, exact or approximate, at times t/T.");
    cmd->add_option("--theta0", tr->theta0, "Amplitude, one angle")->required()->type_name("ANGLE")->check(non_empty);
    cmd->add_option("--method", tr->method,
                     "A method with a law of motion: exact (default), harmonic, lowest, first, second, "
                     "polynomial, or order:N (or order with --order N); see 'list'")
        ->type_name("METHOD");
    auto* order_opt = cmd->add_option("--order", tr->order, "Order N of --method order (0.." +
                                                                std::to_string(max_order) + ")")
                          ->type_name("N");
    cmd->add_option("--at", tr->at, "Times t/T, a comma-separated list (T is the exact period)")
        ->type_name("LIST")->check(non_empty);
    cmd->add_option("--samples", tr->samples, "Number of equally spaced times from 0 to --periods")
        ->type_name("N");
    auto* periods_opt =
        cmd->add_option("--periods", tr->periods, "Time span in exact periods T (default 1)")
            ->type_name("P");
    cmd->add_option("--format", tr->format, "Output format: csv (default) or json")
        ->type_name("csv|json");
    cmd->footer(std::string("\n") + angle_help +
                 "\n\nColumns: t_over_T, theta (radians). Every method is evaluated at the same "
                 "physical time t = (t/T) T, with T the exact period.\n\n"
                 "Examples:\n"
                 "  pendulum-figures trajectory --theta0 9pi/10 --method second --samples 201 --periods 2\n"
                 "  pendulum-figures trajectory --theta0 pi/2 --method order --order 8 --at 0,0.125,0.25");

    return {cmd, [tr, order_opt, periods_opt] {
                trajectory_stream(std::cout, *tr, order_opt->count() > 0, periods_opt->count() > 0);
                return write_stdout("");
            }};
}

}  // namespace pendulum::cli
