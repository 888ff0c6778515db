// SPDX-License-Identifier: GPL-3.0-or-later
// plot: a one-panel figure of any plot kind, made from options as a spec would be.
#include "cli/commands.hpp"
#include "cli/errors.hpp"
#include "cli/format_help.hpp"
#include "cli/options.hpp"
#include "cli/render_figures.hpp"
#include "figures/plots.hpp"
#include "figures/spec.hpp"
#include "figures/themes.hpp"

#include <CLI/CLI.hpp>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace pendulum::cli {

namespace {

/// The options of plot.
struct plot_options {
    std::string kind;
    std::string theta0;
    std::string methods;
    std::string range;
    std::string time;
    int harmonic = 0;
    std::string y;
    std::string name;
    std::string dir = ".";
    std::string formats = "pdf,png";
    std::string theme = "paper";
    std::vector<std::string> sets;
    std::optional<double> dpi;
};

/// A TOML string: the text in quotes, with backslashes and quotes escaped.
std::string toml_string(const std::string& text) {
    std::string out = "\"";
    for (const char c : text) {
        if (c == '"' || c == '\\') out += '\\';
        if (static_cast<unsigned char>(c) < 0x20) throw usage_error("control character in an option");
        out += c;
    }
    return out + "\"";
}

/// A TOML array of strings from a comma-separated list.
std::string toml_list(const std::string& text) {
    std::string out = "[";
    for (const auto& item : split_list(text)) out += (out.size() > 1 ? ", " : "") + toml_string(item);
    return out + "]";
}

/// The plot command: a one-panel spec made from the options, checked like a spec file.
int run_plot(const plot_options& o) {
    std::string toml = "[[panel]]\nplot = " + toml_string(o.kind) + "\n";
    if (!o.theta0.empty()) toml += "theta0 = " + toml_list(o.theta0) + "\n";
    if (!o.methods.empty()) toml += "methods = " + toml_list(o.methods) + "\n";
    if (!o.range.empty()) {
        const auto parts = split_list(o.range);
        if (parts.size() != 2) throw usage_error("--range '" + o.range + "': give two values, A,B");
        if (o.kind == "trajectory") {
            double v[2];
            for (int i = 0; i < 2; ++i) {
                try {
                    v[i] = parse_expression(parts[static_cast<std::size_t>(i)]);
                } catch (const std::invalid_argument& e) {
                    throw usage_error(std::string("--range: ") + e.what());
                }
            }
            toml += "range = [" + format_double(v[0]) + ", " + format_double(v[1]) + "]\n";
        } else {
            toml += "range = " + toml_list(o.range) + "\n";
        }
    }
    if (!o.time.empty()) toml += "time = " + toml_string(o.time) + "\n";
    if (o.harmonic != 0) toml += "harmonic = " + std::to_string(o.harmonic) + "\n";
    if (!o.y.empty()) toml += "y = " + toml_string(o.y) + "\n";
    figures::entry e;
    try {
        e.source = toml;
        e.spec = figures::parse_spec(toml, "plot");
    } catch (const figures::spec_error& err) {
        std::string message;
        for (const auto& p : err.problems()) {
            // The spec is made from the options: name the option, not a line of it.
            message += (message.empty() ? "" : "\n") + std::string("plot ") + o.kind + ": " + p.what;
        }
        throw usage_error(message);
    }
    e.id = o.name.empty() ? o.kind : o.name;
    if (e.id.find('/') != std::string::npos || e.id.empty() || e.id[0] == '.') {
        throw usage_error("--name '" + e.id + "': a file name without a directory");
    }
    render_options r;
    r.dir = o.dir;
    r.formats = o.formats;
    r.theme = o.theme;
    r.sets = o.sets;
    r.dpi = o.dpi;
    return render_figures({&e}, r);
}

}  // namespace

command add_plot_command(CLI::App& app) {
    auto po = std::make_shared<plot_options>();
    auto* cmd = app.add_subcommand("plot", "Draw a one-panel figure of any plot kind from the command line.");
    cmd->add_option("kind", po->kind, figures::plot_names(false, "or"))
        ->required()
        ->type_name("KIND");
    cmd->add_option("--theta0", po->theta0, "Amplitudes, a comma-separated LIST (one for trajectory)")
        ->type_name("LIST")->check(non_empty);
    cmd->add_option("--methods", po->methods, "Methods, a comma-separated LIST (see 'list')")->type_name("LIST");
    cmd->add_option("--range", po->range, "x range a,b: times, or amplitudes as angles")->type_name("A,B");
    cmd->add_option("--time", po->time, "Time axis of a trajectory: t/T (default) or t/T0")->type_name("UNIT");
    cmd->add_option("--harmonic", po->harmonic, "Coefficient plots: the harmonic 2k+1 (default 1)")
        ->type_name("N");
    cmd->add_option("--y", po->y, "Period plots: value (default), error-percent or error-log")->type_name("AXIS");
    cmd->add_option("--name", po->name, "File name without extension (default: the kind)")->type_name("NAME")->check(non_empty);
    cmd->add_option("-o,--output-dir", po->dir, "Existing directory for the files (default: .)")->type_name("DIR")->check(non_empty);
    cmd->add_option("-f,--formats", po->formats, "Comma-separated formats: " + format_list() + " (default: pdf,png)")
        ->type_name("LIST")->check(non_empty);
    cmd->add_option("--theme", po->theme, figures::theme_help() + "; default paper")->type_name("NAME")->check(non_empty);
    cmd->add_option("--set", po->sets, "KEY=VALUE of a style file on top of the theme; repeatable")
        ->type_name("KEY=VALUE")->check(non_empty);
    cmd->add_option("--dpi", po->dpi, "Resolution of " + raster_formats() + " in dots per inch, 10..2400 (default: "
                                          "the theme's)")
        ->type_name("N");
    cmd->footer(std::string("\n") + angle_help +
                     "\n\nThe same as a spec with one [[panel]] of these keys; 'show' prints specs to start from.\n\n"
                     "Examples:\n"
                     "  pendulum-figures plot trajectory --theta0 170deg --methods exact,harmonic,order:6 --range 0,3\n"
                     "  pendulum-figures plot period --methods exact,kidd-fogg,agm:2 --y error-log -f png\n"
                     "  pendulum-figures plot phase --theta0 'pi/3,2pi/3,0.99pi' --methods exact,first");

    return {cmd, [po] { return run_plot(*po); }};
}

}  // namespace pendulum::cli
