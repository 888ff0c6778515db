// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The commands of pendulum-figures: each adds its subcommand, options and help to the app
// and returns what runs it once the command line has been parsed.

#include <functional>

namespace CLI {
class App;
}

namespace pendulum::cli {

/// A command added to the app: its subcommand, and what runs it (returning the exit code).
struct command {
    CLI::App* app = nullptr;    ///< the subcommand, parsed or not
    std::function<int()> run;   ///< runs it with the parsed options
};

/// eval: periods and coefficients per amplitude, as CSV or JSON.
command add_eval_command(CLI::App& app);
/// trajectory: theta(t) of one amplitude.
command add_trajectory_command(CLI::App& app);
/// render: figures into files.
command add_render_command(CLI::App& app);
/// list: the figures, methods and plot kinds.
command add_list_command(CLI::App& app);
/// claims: the paper's quantitative statements, measured.
command add_claims_command(CLI::App& app);
/// show: a figure's spec or a theme's style file.
command add_show_command(CLI::App& app);
/// plot: a one-panel figure from options.
command add_plot_command(CLI::App& app);
/// data: a figure's data as CSV.
command add_data_command(CLI::App& app);
/// describe: a figure in words (alt text and a description).
command add_describe_command(CLI::App& app);
/// complete (hidden): the words of the shell completions, from the tables.
command add_complete_command(CLI::App& app);

}  // namespace pendulum::cli
