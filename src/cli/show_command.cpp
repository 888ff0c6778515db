// SPDX-License-Identifier: GPL-3.0-or-later
// show: the spec of a built-in figure, or a theme's style file, to copy and edit.
#include "cli/commands.hpp"
#include "cli/errors.hpp"
#include "cli/options.hpp"
#include "cli/report.hpp"
#include "figures/catalog.hpp"
#include "figures/themes.hpp"

#include <CLI/CLI.hpp>

#include <memory>
#include <string>

namespace pendulum::cli {

command add_show_command(CLI::App& app) {
    struct show_options {
        std::string id;
        std::string theme;
    };
    auto o = std::make_shared<show_options>();
    auto* cmd = app.add_subcommand("show", "Print the spec of a built-in figure, or a theme's style file, to copy "
                                            "and edit.");
    cmd->add_option("id", o->id, "Figure id or alias (see 'list')")->type_name("ID");
    cmd->add_option("--theme", o->theme, "Print this built-in theme's style file instead: " +
                                                figures::theme_names())
        ->type_name("NAME")->check(non_empty);
    cmd->footer("\nThe spec is TOML: [figure], an optional [pendulum], and one [[panel]] per panel. Edit it and "
                 "render it with 'render FILE.toml'.\n\nExample:\n"
                 "  pendulum-figures show fig2 > my-figure.toml\n  pendulum-figures render my-figure.toml -f png\n"
                 "  pendulum-figures show --theme slides > talk.toml\n"
                 "  pendulum-figures render fig7 --theme talk.toml --set tick_font_pt=18");

    return {cmd, [o] {
                if (o->id.empty() == o->theme.empty()) throw usage_error("give a figure ID or --theme NAME to show");
                return write_stdout(o->theme.empty() ? figures::find(o->id).source : figures::theme_source(o->theme));
            }};
}

}  // namespace pendulum::cli
