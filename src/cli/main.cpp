// SPDX-License-Identifier: GPL-3.0-or-later
// pendulum-figures: the command line. The app, its commands (one file each), and the
// mapping of errors to exit codes: 2 for bad input, 1 for anything else.
#include "cli/commands.hpp"
#include "cli/options.hpp"
#include "cli/report.hpp"
#include "common/errors.hpp"
#include "pendulum/amplitude.hpp"

#include <CLI/CLI.hpp>

#include <iostream>
#include <new>
#include <string>
#include <vector>

namespace {

using namespace pendulum;
using cli::report_error;

/// Prints help or the version as CLI11 does, and fails with 1 if it could not be written.
int exit_with_help(const CLI::App& app, const CLI::Error& e) {
    const int code = app.exit(e);
    std::cout.flush();
    if (!std::cout) {
        report_error("cannot write to standard output");
        return 1;
    }
    return code;
}

/// CLI11's messages, lowercased at the start to match ours.
std::string lowercase_first(std::string s) {
    if (!s.empty() && s[0] >= 'A' && s[0] <= 'Z' && !(s.size() > 1 && s[1] >= 'A' && s[1] <= 'Z')) {
        s[0] = static_cast<char>(s[0] - 'A' + 'a');
    }
    return s;
}

/// The names of the app's commands, in the order of --help, joined with ", " and `last`.
std::string command_names(const CLI::App& app, const std::string& last) {
    const auto commands = app.get_subcommands([](const CLI::App*) { return true; });
    std::string out;
    for (std::size_t i = 0; i < commands.size(); ++i) {
        if (i > 0) out += i + 1 == commands.size() ? last : ", ";
        out += commands[i]->get_name();
    }
    return out;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{
        "pendulum-figures: the simple pendulum solved exactly (Jacobi elliptic functions) and "
        "through the Fourier/Bessel approximants of R. Borghi, arXiv:1303.5023."};
    app.name("pendulum-figures");
    // GNU style: name and version, then copyright and licence.
    app.set_version_flag("--version", std::string("pendulum-figures ") + PENDULUM_VERSION +
                                          "\nCopyright (C) 2026 the pendulum-figures authors.\n"
                                          "License GPL-3.0-or-later: GNU GPL version 3 or later "
                                          "<https://gnu.org/licenses/gpl.html>.\n"
                                          "This is free software: you are free to change and redistribute it.\n"
                                          "There is NO WARRANTY, to the extent permitted by law.");
    app.require_subcommand(1);
    app.set_help_all_flag("--help-all", "Print the help of every command and exit");
    app.footer(std::string("\n") + cli::angle_help +
               "\n\nExamples:\n"
               "  pendulum-figures eval --theta0 pi/2\n"
               "  pendulum-figures eval --theta0 'pi/3,pi/2,9pi/10' --order 4 --order 12 --format json\n"
               "  pendulum-figures trajectory --theta0 162deg --method first --samples 101\n"
               "  pendulum-figures list\n"
               "  pendulum-figures render --all -o figures -f pdf,png\n"
               "\nRun 'pendulum-figures COMMAND --help' for the options of each command, --help-all for all.\n"
               "\nExit status: 0 on success; 2 for bad input (an option, a value, a spec or style file, "
               "SOURCE_DATE_EPOCH), with nothing written; 1 when writing or the work itself fails.");


    // In the order of --help.
    const std::vector<cli::command> commands = {
        cli::add_eval_command(app),   cli::add_trajectory_command(app), cli::add_render_command(app),
        cli::add_list_command(app),   cli::add_claims_command(app),     cli::add_show_command(app),
        cli::add_plot_command(app),   cli::add_data_command(app),     cli::add_describe_command(app),
        cli::add_complete_command(app),
    };

    try {
        app.parse(argc, argv);
        for (const auto& c : commands) {
            if (c.app->parsed()) return c.run();
        }
        return 0;
    } catch (const CLI::CallForHelp& e) {
        return exit_with_help(app, e);
    } catch (const CLI::CallForAllHelp& e) {
        return exit_with_help(app, e);
    } catch (const CLI::CallForVersion& e) {
        return exit_with_help(app, e);
    } catch (const CLI::ParseError& e) {
        std::string message = lowercase_first(e.what());
        if (app.get_subcommands().empty()) {
            // No command, or an unknown word where the command should be.
            if (argc < 2) {
                message = "a command is required: " + command_names(app, " or ") + " (see --help)";
            } else if (argv[1][0] != '-') {
                message = std::string("unknown command '") + argv[1] + "'; commands: " + command_names(app, ", ") +
                          " (see --help)";
            } else {
                message = std::string("unknown option '") + argv[1] +
                          "'; options before the command are --help and --version (see --help)";
            }
        }
        report_error(message);
        return 2;
    } catch (const common::bad_input& e) {
        // plot::bad_input, figures::bad_input and cli::usage_error are this one type: an
        // option or value, a spec or style file with problems, a figure the theme leaves too
        // little room.
        report_error(e.what());
        return 2;
    } catch (const pendulum::domain_error& e) {
        report_error(e.what());  // the core's own: an amplitude outside (0, pi)
        return 2;
    } catch (const std::bad_alloc&) {
        report_error("out of memory; a lower --dpi or fewer figures at once need less");
        return 1;
    } catch (const std::exception& e) {
        report_error(e.what());
        return 1;
    }
}
