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

#include <cmath>
#include <map>
#include <memory>
#include <stdexcept>
#include <optional>
#include <string>
#include <vector>

namespace pendulum::cli {

namespace {

/// How an option's text becomes a TOML value of its key.
enum class value_kind { text, list, number, integer, pair, integer_pair, boolean, range };

/// One option of plot: the spec key it sets, in [[panel]] or [figure].
struct key_option {
    std::string_view key;        ///< the spec key
    bool figure;                 ///< a [figure] key, not a [[panel]] one
    std::string_view option;     ///< the option, --name
    std::string_view type_name;  ///< its value in --help
    value_kind kind;             ///< how its value is written in the spec
    std::string_view help;       ///< --help text
};

/// Every spec key that means something for a one-panel figure has its option here; the
/// keys a spec file alone sets (paper_file, line, columns, panel sizes: see --set) do not.
constexpr key_option key_options[] = {
    {"theta0", false, "--theta0", "LIST", value_kind::list, "Amplitudes, a comma-separated LIST (one for trajectory)"},
    {"energy", false, "--energy", "LIST", value_kind::list,
     "Phase, trajectory and pendulum plots: energies E/(m g L) of launches from the bottom (2 is the separatrix)"},
    {"omega0", false, "--omega0", "LIST", value_kind::list,
     "Phase, trajectory and pendulum plots: initial velocities theta'/w0 of states started at --theta0"},
    {"methods", false, "--methods", "LIST", value_kind::list, "Methods, a comma-separated LIST (see 'list')"},
    {"range", false, "--range", "A,B", value_kind::range, "x range a,b: times, or amplitudes as angles"},
    {"time", false, "--time", "UNIT", value_kind::text, "Time axis of a trajectory: t/T (default), t/T0 or t/s"},
    {"harmonic", false, "--harmonic", "N", value_kind::integer, "Coefficient plots: the harmonic 2k+1 (default 1)"},
    {"harmonics", false, "--harmonics", "N", value_kind::integer, "Spectrum plots: how many odd harmonics"},
    {"orders", false, "--orders", "A,B", value_kind::integer_pair, "Convergence plots: the orders N from A to B"},
    {"y", false, "--y", "AXIS", value_kind::text, "Period plots: value (default), error-percent, error-log or residual ((T_meas - T)/T0 of --data)"},
    {"x", false, "--x", "AXIS", value_kind::text,
     "Period plots: against the amplitude (default) or the energy, T/T0 across the separatrix at E = 2"},
    {"angle_unit", false, "--angle-unit", "UNIT", value_kind::text, "Angles on the axes in rad (default) or deg"},
    {"separatrix", false, "--separatrix", "BOOL", value_kind::boolean, "Phase plots: draw the separatrix, true or false"},
    {"trail", false, "--trail", "T", value_kind::number, "Pendulum drawings: a fading trail of T periods"},
    {"y_range", false, "--y-range", "A,B", value_kind::pair, "y axis limits a,b (default: from the data)"},
    {"x_label", false, "--x-label", "TEXT", value_kind::text, "x axis label, text with TeX math in $...$"},
    {"y_label", false, "--y-label", "TEXT", value_kind::text, "y axis label, text with TeX math in $...$"},
    {"title", false, "--panel-title", "TEXT", value_kind::text, "The panel's title above its frame (default: the amplitude)"},
    {"title", true, "--title", "TEXT", value_kind::text, "The figure's title, drawn above it and kept in PDF and SVG metadata"},
    {"legend", true, "--legend", "WHERE", value_kind::text, "Legend: each (default), first or none"},
};

/// The options of plot.
struct plot_options {
    std::string kind;
    std::map<std::string_view, std::string> values;  // by option name, as given
    std::string name;
    std::string dir = ".";
    std::string formats = "pdf,png";
    std::string theme = "paper";
    std::vector<std::string> sets;
    std::optional<double> dpi;
    std::string size;
    std::optional<int> jobs;  // worker threads, as render takes them
    std::vector<std::string> data;  // --data FILE:X[UNIT],Y[UNIT][,YERR], in order
    std::string length;             // --length, metres
    std::string g;                  // --g, m/s^2
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

/// A number as the option gave it, checked: TOML reads it as written.
std::string number_text(const key_option& k, const std::string& text, bool integer) {
    std::size_t used = 0;
    bool ok = false;
    try {
        if (integer) {
            (void)std::stoll(text, &used);
        } else {
            ok = std::isfinite(std::stod(text, &used));
        }
        ok = used == text.size() && (integer || ok);
    } catch (const std::exception&) {
        ok = false;
    }
    if (!ok) throw usage_error(std::string(k.option) + " '" + text + "': not " + (integer ? "a whole number" : "a number"));
    return integer ? std::to_string(std::stoll(text)) : format_double(std::stod(text));
}

/// The option's value as TOML.
std::string toml_value(const key_option& k, const std::string& text, const std::string& kind) {
    switch (k.kind) {
        case value_kind::text: return toml_string(text);
        case value_kind::list: return toml_list(text);
        case value_kind::number: return number_text(k, text, false);
        case value_kind::integer: return number_text(k, text, true);
        case value_kind::boolean:
            if (text != "true" && text != "false") throw usage_error(std::string(k.option) + " '" + text + "': true or false");
            return text;
        case value_kind::pair:
        case value_kind::integer_pair:
        case value_kind::range: {
            const auto parts = split_list(text);
            if (parts.size() != 2) throw usage_error(std::string(k.option) + " '" + text + "': give two values, A,B");
            if (k.kind == value_kind::range && kind != "trajectory") return toml_list(text);
            std::string out = "[";
            for (const auto& part : parts) {
                std::string v;
                if (k.kind == value_kind::range) {
                    // Times may be expressions too: 3*T is not a time, but 1/3 is.
                    try {
                        v = format_double(parse_expression(part));
                    } catch (const std::invalid_argument& e) {
                        throw usage_error(std::string(k.option) + ": " + e.what());
                    }
                } else {
                    v = number_text(k, part, k.kind == value_kind::integer_pair);
                }
                out += (out.size() > 1 ? ", " : "") + v;
            }
            return out + "]";
        }
    }
    throw std::logic_error("unknown option kind");
}

/// One column of --data, "NAME[UNIT]" or "N[UNIT]": its key (a TOML string or number) and
/// its unit key, if a unit is given.
std::string data_column(const std::string& option, const std::string& text, std::string_view key) {
    std::string name = text;
    std::string unit;
    if (const auto open = text.find('['); open != std::string::npos) {
        if (text.back() != ']' || open == 0) {
            throw usage_error("--data '" + option + "': a column is NAME or NAME[UNIT], e.g. theta0[deg]");
        }
        name = text.substr(0, open);
        unit = text.substr(open + 1, text.size() - open - 2);
    }
    const bool number = !name.empty() && name.find_first_not_of("0123456789") == std::string::npos && name.size() < 10;
    std::string out = std::string(key) + " = " + (number ? name : toml_string(name)) + "\n";
    if (!unit.empty() && key != "y_err") out += std::string(key) + "_unit = " + toml_string(unit) + "\n";
    if (!unit.empty() && key == "y_err") {
        throw usage_error("--data '" + option + "': the error column takes the unit of y; leave out [" + unit + "]");
    }
    return out;
}

/// --data FILE:X[UNIT],Y[UNIT][,YERR] as a [[panel.data]] table: the columns by header name
/// or number, their units in brackets, the error symmetric, in y's unit.
std::string data_table(const std::string& option) {
    const auto colon = option.rfind(':');
    if (colon == std::string::npos || colon == 0) {
        throw usage_error("--data '" + option + "': give FILE:X[UNIT],Y[UNIT][,YERR], e.g. "
                          "measured.csv:theta0[deg],T[s],dT");
    }
    const auto columns = split_list(option.substr(colon + 1));
    if (columns.size() < 2 || columns.size() > 3) {
        throw usage_error("--data '" + option + "': give two or three columns after the file, X[UNIT],Y[UNIT][,YERR]");
    }
    std::string out = "[[panel.data]]\nfile = " + toml_string(option.substr(0, colon)) + "\n";
    constexpr std::string_view keys[] = {"x", "y", "y_err"};
    for (std::size_t i = 0; i < columns.size(); ++i) out += data_column(option, columns[i], keys[i]);
    return out;
}

/// --length and --g as a [pendulum] table: seconds on the axes.
std::string pendulum_table(const plot_options& o) {
    if (o.length.empty() && o.g.empty()) return "";
    if (o.length.empty()) throw usage_error("--g '" + o.g + "' needs --length, the pendulum's length in metres");
    const key_option length{"length_m", false, "--length", "M", value_kind::number, ""};
    const key_option g{"g", false, "--g", "G", value_kind::number, ""};
    std::string out = "[pendulum]\nlength_m = " + number_text(length, o.length, false) + "\n";
    if (!o.g.empty()) out += "g = " + number_text(g, o.g, false) + "\n";
    return out;
}

/// The plot command: a one-panel spec made from the options, checked like a spec file.
int run_plot(const plot_options& o) {
    std::string figure;
    std::string toml = "[[panel]]\nplot = " + toml_string(o.kind) + "\n";
    for (const auto& k : key_options) {
        const auto it = o.values.find(k.option);
        if (it == o.values.end()) continue;
        (k.figure ? figure : toml) += std::string(k.key) + " = " + toml_value(k, it->second, o.kind) + "\n";
    }
    for (const auto& d : o.data) toml += data_table(d);
    toml = pendulum_table(o) + toml;
    if (!figure.empty()) toml = "[figure]\n" + figure + toml;
    figures::entry e;
    try {
        e.source = toml;
        e.spec = figures::parse_spec(toml, "plot");
    } catch (const figures::spec_error& err) {
        std::string message;
        for (const auto& p : err.problems()) {
            // The spec is made from the options: name the option, not a line of it.
            // A data file's problem keeps its FILE:LINE:COLUMN.
            const std::string what = p.where.file == "plot" ? p.what : p.text();
            message += (message.empty() ? "" : "\n") + std::string("plot ") + o.kind + ": " + what;
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
    r.size = o.size;
    r.jobs = o.jobs;
    return render_figures({&e}, r);
}

}  // namespace

command add_plot_command(CLI::App& app) {
    auto po = std::make_shared<plot_options>();
    auto* cmd = app.add_subcommand("plot", "Draw a one-panel figure of any plot kind from the command line.");
    cmd->add_option("kind", po->kind, figures::plot_names(false, "or"))
        ->required()
        ->type_name("KIND");
    for (const auto& k : key_options) {
        cmd->add_option_function<std::string>(
               std::string(k.option), [po, option = k.option](const std::string& v) { po->values[option] = v; },
               std::string(k.help))
            ->type_name(std::string(k.type_name))
            ->check(non_empty);
    }
    cmd->add_option("--name", po->name, "File name without extension (default: the kind)")->type_name("NAME")->check(non_empty);
    cmd->add_option("-o,--output-dir", po->dir, "Existing directory for the files (default: .)")->type_name("DIR")->check(non_empty);
    cmd->add_option("-f,--formats", po->formats, "Comma-separated formats: " + format_list() + " (default: pdf,png)")
        ->type_name("LIST")->check(non_empty);
    cmd->add_option("--theme", po->theme, figures::theme_help() + "; default paper")->type_name("NAME")->check(non_empty);
    cmd->add_option("--set", po->sets, "KEY=VALUE of a style file on top of the theme; repeatable")
        ->type_name("KEY=VALUE")->check(non_empty);
    cmd->add_option("--size", po->size, "A raster of WIDTHxHEIGHT pixels, e.g. 1920x1080 (the style key size_px)")
        ->type_name("WxH")
        ->check(non_empty);
    cmd->add_option("--dpi", po->dpi, "Resolution of " + raster_formats() + " in dots per inch, 10..2400 (default: "
                                          "the theme's)")
        ->type_name("N");
    cmd->add_option("--jobs", po->jobs, jobs_help)->type_name("N");
    cmd->add_option("--data", po->data,
                    "Measured data from a CSV or TSV file in the working directory's tree: "
                    "FILE:X[UNIT],Y[UNIT][,YERR], columns by header name or number, "
                    "units deg, rad, s, T/T0, t/T0, t/T; at most " +
                        std::to_string(figures::max_data_rows) + " rows and " +
                        std::to_string(figures::max_data_file_bytes) + " bytes; repeatable (up to " +
                        std::to_string(figures::max_data_series_per_panel) + ")")
        ->type_name("FILE:COLUMNS")
        ->check(non_empty);
    cmd->add_option("--length", po->length, "The pendulum's length in metres: periods and times in seconds")
        ->type_name("M")
        ->check(non_empty);
    cmd->add_option("--g", po->g, "Gravity in m/s^2 with --length (default 9.80665)")->type_name("G")->check(non_empty);
    cmd->footer(std::string("\n") + angle_help +
                     "\n\nThe same as a spec with one [[panel]] of these keys; 'show' prints specs to start from.\n\n"
                     "Examples:\n"
                     "  pendulum-figures plot trajectory --theta0 170deg --methods exact,harmonic,order:6 --range 0,3\n"
                     "  pendulum-figures plot period --methods exact,kidd-fogg,agm:2 --y error-log -f png\n"
                     "  pendulum-figures plot period --x energy --range 0,4\n"
                     "  pendulum-figures plot phase --theta0 'pi/3,2pi/3,0.99pi' --methods exact,first\n"
                     "  pendulum-figures plot phase --energy 0.5,1.5,2,2.5,3 --angle-unit deg\n"
                     "  pendulum-figures plot trajectory --theta0 0 --omega0 2.2\n"
                     "  pendulum-figures plot period --methods exact,harmonic --angle-unit deg --length 1 \\\n"
                     "      --data 'measured.csv:theta0[deg],T[s],dT'");

    return {cmd, [po] { return run_plot(*po); }};
}

}  // namespace pendulum::cli
