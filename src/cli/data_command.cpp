// SPDX-License-Identifier: GPL-3.0-or-later
// data: the data of a figure as CSV, panel,series,x,y.
#include "cli/commands.hpp"
#include "cli/errors.hpp"
#include "cli/options.hpp"
#include "cli/report.hpp"
#include "figures/batch.hpp"
#include "figures/plots.hpp"
#include "figures/render_cost.hpp"
#include "figures/render_plan.hpp"
#include "plot/output.hpp"

#include <CLI/CLI.hpp>

#include <filesystem>
#include <memory>
#include <string>

namespace pendulum::cli {

namespace {

/// The figure's data as CSV, with the amplitudes of --theta0 if given.
std::string figure_data(const std::string& id, const std::string& theta0) {
    const figures::entry e = figures::load_input(id);
    figures::build_options build;
    if (!theta0.empty()) {
        if (!e.takes_amplitudes()) {
            throw usage_error("--theta0 applies to figures with " + figures::plot_names(true, "or") + " panels, "
                              "not to " + e.id);
        }
        build.amplitudes = parse_amplitudes(theta0, figures::max_amplitudes_per_panel);
    }
    figures::check_cost({figures::costed_figure{&e, 0, {"csv"}, 0}}, build);  // with the amplitudes of --theta0
    return figures::figure_csv(figures::build(e, build));
}

}  // namespace

command add_data_command(CLI::App& app) {
    struct data_options {
        std::string id;
        std::string file;
        std::string theta0;
    };
    auto o = std::make_shared<data_options>();
    auto* cmd = app.add_subcommand("data", "Print the data of a figure as CSV: panel,series,x,y.");
    cmd->add_option("id", o->id, "Figure id or alias (see 'list')")->required()->type_name("ID");
    cmd->add_option("-o,--output", o->file, "Write to FILE instead of standard output (- is standard output)")->type_name("FILE")->check(non_empty);
    cmd->add_option("--theta0", o->theta0, "Amplitudes of a trajectory figure, a comma-separated LIST")
        ->type_name("LIST")->check(non_empty);
    cmd->footer("\nOne row per point of each series: its markers, or the samples of a curve that set the axis\n"
                "limits (a curve's line is drawn from its function, within 0.05 pt, with as many points as\n"
                "it needs); panels are a, b, c, ... as in the paper's captions.\n\n"
                 "Example:\n  pendulum-figures data period -o period.csv");

    return {cmd, [o] {
                std::string file = o->file == "-" ? "" : o->file;  // - is standard output
                if (!file.empty()) {
                    // Where the file goes is checked before the work, as render checks its outputs.
                    plot::check_output_file(file);
                    const auto parent = std::filesystem::path(file).parent_path();
                    if (!parent.empty()) check_output_dir(parent.string());
                }
                const std::string csv = figure_data(o->id, o->theta0);
                if (file.empty()) return write_stdout(csv);
                plot::write_atomically(file, csv);
                return 0;
            }};
}

}  // namespace pendulum::cli
