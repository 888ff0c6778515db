// SPDX-License-Identifier: GPL-3.0-or-later
// data: the numbers of a figure as drawn, as CSV (long or wide) or JSON.
#include "cli/commands.hpp"
#include "cli/errors.hpp"
#include "cli/options.hpp"
#include "cli/report.hpp"
#include "figures/batch.hpp"
#include "figures/figure_data.hpp"
#include "figures/plots.hpp"
#include "figures/render_cost.hpp"
#include "figures/render_plan.hpp"
#include "plot/output.hpp"
#include "plot/workers.hpp"

#include <CLI/CLI.hpp>

#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

namespace pendulum::cli {

namespace {

/// The figure's numbers in the format and layout, with the amplitudes of --theta0 if given.
std::string figure_data(const std::string& id, const std::string& theta0, const std::string& format,
                        const std::string& layout) {
    const figures::entry e = figures::load_input(id);
    figures::build_options build;
    if (!theta0.empty()) {
        if (!e.takes_amplitudes()) {
            throw usage_error("--theta0 applies to figures with " + figures::plot_names(true, "or") + " panels, "
                              "not to " + e.id);
        }
        build.amplitudes = parse_amplitudes(theta0, figures::max_amplitudes_per_panel);
    }
    if (format == "json" && layout != "long") {
        throw usage_error("--layout " + layout + " is for CSV: JSON holds each series' x and y arrays; leave it out");
    }
    figures::check_cost({figures::costed_figure{&e, 0, {"csv"}, 0}}, build);  // with the amplitudes of --theta0
    // Curves are sampled as the PNG of the figure's style (paper by default) draws them.
    plot::theme theme;
    try {
        theme = chosen_theme(e.spec.style.empty() ? "paper" : e.spec.style, {});
    } catch (const std::invalid_argument& err) {
        if (e.spec.style.empty()) throw;
        throw usage_error("figure '" + e.id + "' ([figure] style = " + e.spec.style + "): " + err.what());
    }
    const figures::figure_numbers n = figures::numbers_of(e, build, theme, theme.dpi);
    if (n.without_legends) {
        std::cerr << "pendulum-figures: note: figure '" << e.id << "' leaves no room for its axes with its legends "
                  << "at its size; its curves are sampled on axes without them\n";
    }
    if (format == "json") return figures::numbers_json(n);
    return figures::numbers_csv(n, layout == "wide" ? figures::data_layout::wide : figures::data_layout::long_rows);
}

}  // namespace

command add_data_command(CLI::App& app) {
    struct data_options {
        std::string id;
        std::string file;
        std::string theta0;
        std::string format = "csv";
        std::string layout = "long";
        std::optional<int> jobs;  // worker threads, as render takes them
    };
    auto o = std::make_shared<data_options>();
    auto* cmd = app.add_subcommand("data", "Print the numbers of a figure as drawn: CSV (long or wide) or JSON.");
    cmd->add_option("id", o->id, "Figure id or alias (see 'list')")->required()->type_name("ID");
    cmd->add_option("-o,--output", o->file, "Write to FILE instead of standard output (- is standard output)")->type_name("FILE")->check(non_empty);
    cmd->add_option("--theta0", o->theta0, "Amplitudes of a trajectory figure, a comma-separated LIST")
        ->type_name("LIST")->check(non_empty);
    cmd->add_option("-f,--format", o->format, "csv or json")->type_name("FORMAT")
        ->check(CLI::IsMember({"csv", "json"}));
    cmd->add_option("--layout", o->layout, "CSV layout: long (a row per point) or wide (columns per series)")
        ->type_name("LAYOUT")->check(CLI::IsMember({"long", "wide"}));
    cmd->add_option("--jobs", o->jobs, jobs_help)->type_name("N");
    cmd->footer(std::string("\n") + angle_help + "\n\nWhat is drawn: the samples of every curve as the figure's PNG draws it (within 0.05 pt),\n"
                "the points of other series, and reference lines as their two ends within the panel.\n"
                "Panels are a, b, c, ... as in the paper's captions; each series has an id (exact,\n"
                "order:6, theta0:2, line:1, ...) that stays when its label changes.\n\n"
                "--layout long (default): panel,series,x,y,id, one row per point (series: the label).\n"
                "--layout wide: columns PANEL_ID_x, PANEL_ID_y per series (':', '.', '-' of the id as '_'),\n"
                "padded with nan; a curve's breaks are nan too.\n"
                "-f json: panels with their axes, series with id, label, method, theta0, period, x, y.\n\n"
                "Examples:\n"
                "  pendulum-figures data period -o period.csv\n"
                "  pendulum-figures data period --layout wide -o period.csv\n"
                "    pgfplots: \\addplot table[x=a_exact_x, y=a_exact_y, col sep=comma] {period.csv};\n"
                "              (with unbounded coords=jump, a curve's breaks stay breaks)\n"
                "    numpy:    d = numpy.genfromtxt('period.csv', names=True, delimiter=','); d['a_exact_y']\n"
                "  pendulum-figures data period -f json -o period.json");

    return {cmd, [o] {
                // The threads a figure's numbers may take: --jobs, else PENDULUM_FIGURES_JOBS, else the CPUs.
                plot::set_thread_limit(chosen_jobs(o->jobs));
                std::string file = o->file == "-" ? "" : o->file;  // - is standard output
                if (!file.empty()) {
                    // Where the file goes is checked before the work, as render checks its outputs.
                    plot::check_output_file(file);
                    const auto parent = std::filesystem::path(file).parent_path();
                    if (!parent.empty()) check_output_dir(parent.string());
                }
                const std::string csv = figure_data(o->id, o->theta0, o->format, o->layout);
                if (file.empty()) return write_stdout(csv);
                plot::write_atomically(file, csv);
                return 0;
            }};
}

}  // namespace pendulum::cli
