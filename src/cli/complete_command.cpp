// SPDX-License-Identifier: GPL-3.0-or-later
// complete (hidden): the words shell completion offers, one a line, read from the program's
// tables, so that the bash and zsh completions never list a name of their own.
#include "cli/commands.hpp"
#include "cli/report.hpp"
#include "figures/catalog.hpp"
#include "figures/plots.hpp"
#include "figures/themes.hpp"
#include "pendulum/methods.hpp"
#include "plot/output.hpp"

#include <CLI/CLI.hpp>

#include <memory>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace pendulum::cli {

namespace {

/// The keys --set takes: the top-level keys of a style file, all of which the paper theme sets.
std::string set_keys() {
    std::istringstream in{std::string(figures::theme_source("paper"))};
    std::string out;
    for (std::string line; std::getline(in, line);) {
        if (line.starts_with("[")) break;
        const auto eq = line.find(" =");
        if (line.empty() || line[0] == '#' || eq == std::string::npos) continue;
        out += line.substr(0, eq) + "=\n";
    }
    return out;
}

std::string ids() {
    std::string out;
    for (const auto& e : figures::catalog()) out += e.id + "\n" + (e.alias.empty() ? "" : e.alias + "\n");
    return out;
}

/// Method names, NAME: for those that take an N.
std::string method_names(bool motion_only) {
    std::string out;
    for (const auto& m : method_table()) {
        if (!motion_only || m.has_motion()) out += std::string(m.name) + (m.min_n < 0 ? "\n" : ":\n");
    }
    return out;
}

template <typename Table>
std::string names(const Table& table) {
    std::string out;
    for (const auto& row : table) out += std::string(row.name) + "\n";
    return out;
}

/// One list of words: its name on the command line and what prints it.
struct word_list {
    std::string_view name;
    std::string (*words)();
};

constexpr word_list word_lists[] = {
    {"ids", ids},
    {"methods", [] { return method_names(false); }},
    {"motion-methods", [] { return method_names(true); }},
    {"plots", [] { return names(figures::plot_table()); }},
    {"formats", [] { return names(plot::format_table()); }},
    {"themes", [] { return names(figures::builtin_themes()); }},
    {"tex-sizes", [] { return names(plot::tex_sizing_table()); }},
    {"set-keys", set_keys},
    // plot --set takes the figure's columns, legend and title too.
    {"plot-set-keys", [] { return set_keys() + "columns=\nlegend=\ntitle=\n"; }},
};

}  // namespace

command add_complete_command(CLI::App& app) {
    auto what = std::make_shared<std::string>();
    auto* cmd = app.add_subcommand("complete", "The words of a shell completion")->group("");
    std::vector<std::string> list_names;
    for (const auto& w : word_lists) list_names.emplace_back(w.name);
    cmd->add_option("what", *what)->required()->check(CLI::IsMember(list_names));
    return {cmd, [what] {
                for (const auto& w : word_lists) {
                    if (w.name == *what) return write_stdout(w.words());
                }
                return 2;  // not reached: the option admits only the names of word_lists
            }};
}

}  // namespace pendulum::cli
