// SPDX-License-Identifier: GPL-3.0-or-later
// describe: a figure in words, for readers who cannot see it: alt text and a description.
#include "cli/commands.hpp"
#include "cli/errors.hpp"
#include "cli/options.hpp"
#include "cli/report.hpp"
#include "figures/describe.hpp"
#include "figures/render_plan.hpp"

#include <CLI/CLI.hpp>

#include <memory>
#include <string>

namespace pendulum::cli {

command add_describe_command(CLI::App& app) {
    struct describe_options {
        std::string id;
        bool alt = false;
    };
    auto o = std::make_shared<describe_options>();
    auto* cmd = app.add_subcommand("describe", "Print a figure in words: a short alt text, then a description of "
                                                "each panel (axes, ranges, curves, what to notice).");
    cmd->add_option("id", o->id, "Figure id or alias (see 'list'), or a spec file NAME.toml")->required()->type_name("ID");
    cmd->add_flag("--alt", o->alt, "Print only the alt text, one line");
    cmd->footer("\nThe same words are in the figures: an SVG's <desc> and a PDF's subject. Where an approximation "
                "leaves the exact curve, it is by more than 1 % of the y axis; crossings are of the spec's "
                "reference lines.\n\nExample:\n  pendulum-figures describe period-error");
    return {cmd, [o] {
                const figures::entry e = figures::load_input(o->id);
                const auto d = figures::describe(e, figures::build(e));
                return write_stdout(o->alt ? d.alt + "\n" : d.alt + "\n\n" + d.text);
            }};
}

}  // namespace pendulum::cli
