// SPDX-License-Identifier: GPL-3.0-or-later
// list: the figures, the methods and the plot kinds; with --markdown also the formats, text sizes and themes.
#include "cli/commands.hpp"
#include "cli/format_help.hpp"
#include "cli/report.hpp"
#include "figures/catalog.hpp"
#include "figures/themes.hpp"
#include "pendulum/methods.hpp"
#include "plot/output.hpp"

#include <CLI/CLI.hpp>

#include <memory>
#include <sstream>
#include <string>
#include <string_view>

namespace pendulum::cli {

namespace {

/// `text` padded with spaces to `width` (at least one space).
std::string padded(const std::string& text, std::size_t width) {
    return text + std::string(text.size() < width ? width - text.size() : 1, ' ');
}

/// Text for a Markdown table cell: | would end the cell.
std::string md_cell(std::string_view text) {
    std::string out;
    for (const char c : text) {
        if (c == '|') out += '\\';
        out += c;
    }
    return out;
}

/// The tables of `list` in Markdown, as the README shows them.
std::string list_markdown() {
    std::ostringstream out;
    out << "| figure (alias) | paper | shows |\n| --- | --- | --- |\n";
    for (const auto& e : figures::catalog()) {
        out << "| `" << e.id << "`" << (e.alias.empty() ? "" : " (`" + e.alias + "`)") << " | " << e.paper_figure
            << " | " << md_cell(e.description()) << " |\n";
    }
    out << "\n| method | gives | what |\n| --- | --- | --- |\n";
    for (const auto& m : method_table()) {
        out << "| `" << m.name << (m.min_n < 0 ? "" : ":N") << "`"
            << (m.min_n < 0 ? "" : " (N = " + std::to_string(m.min_n) + ".." + std::to_string(m.max_n) + ")") << " | "
            << (m.has_motion() ? "motion" : "period") << " | " << m.description << " |\n";
    }
    out << "\n| plot | x | y | keys |\n| --- | --- | --- | --- |\n";
    for (const auto& p : figures::plot_table()) {
        out << "| `" << p.name << "` | " << md_cell(p.x) << " | " << md_cell(p.y) << " | " << p.keys << " |\n";
    }
    out << "\n| format | what |\n| --- | --- |\n";
    for (const auto& f : plot::format_table()) out << "| `" << f.name << "` | " << f.description << " |\n";
    out << "\n| text sizes | what (`render --tex-sizes`, for " << plot::format_names(is_overlay, " and ")
        << ") |\n| --- | --- |\n";
    for (const auto& t : plot::tex_sizing_table()) out << "| `" << t.name << "` | " << md_cell(std::string(t.description)) << " |\n";
    out << "\n| theme | what |\n| --- | --- |\n";
    for (const auto& t : figures::builtin_themes()) out << "| `" << t.name << "` | " << t.description << " |\n";
    return out.str();
}

/// The tables of `list` as text.
std::string list_text() {
    std::ostringstream out;
    out << "Figures (render ID, or a spec file NAME.toml; show ID prints a figure's spec):\n";
    for (const auto& e : figures::catalog()) {
        out << "  " << padded(e.id + (e.alias.empty() ? "" : " (" + e.alias + ")"), 28) << padded(e.paper_figure, 8)
            << e.description() << "\n";
    }
    out << "\nMethods (NAME, or NAME:N where marked):\n";
    for (const auto& m : method_table()) {
        const std::string name = std::string(m.name) +
                                 (m.min_n < 0 ? "" : ":N (N = " + std::to_string(m.min_n) + ".." + std::to_string(m.max_n) + ")");
        out << "  " << padded(name, 28) << padded(m.has_motion() ? "motion" : "period", 8)
            << m.description << "\n";
    }
    out << "\nPlot kinds (plot = KIND in a spec's [[panel]], or the plot command):\n";
    for (const auto& p : figures::plot_table()) {
        out << "  " << padded(std::string(p.name), 28) << p.description << "; keys: " << p.keys << "\n";
    }
    return out.str();
}

}  // namespace

command add_list_command(CLI::App& app) {
    auto markdown = std::make_shared<bool>(false);
    auto* cmd = app.add_subcommand("list", "List the figures, the methods and the plot kinds.");
    cmd->add_flag("--markdown", *markdown,
                   "Print the tables in Markdown, with the output formats and themes (as in the README)");
    cmd->footer("\nExamples:\n  pendulum-figures list\n  pendulum-figures render fig7 -f pdf\n"
                 "  pendulum-figures show fig2 > my-figure.toml");

    return {cmd, [markdown] { return write_stdout(*markdown ? list_markdown() : list_text()); }};
}

}  // namespace pendulum::cli
