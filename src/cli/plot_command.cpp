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
#include "plot/output.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <optional>
#include <string>
#include <vector>

namespace pendulum::cli {

namespace {

/// How an option's text becomes a TOML value of its key.
enum class value_kind { text, list, number, integer, pair, integer_pair, boolean, range, flag };

/// The table of the spec an option's key goes into.
enum class spec_table { panel, figure, animation, pendulum };

/// One option of plot: the spec key it sets, in [[panel]], [figure] or [animation].
struct key_option {
    std::string_view key;        ///< the spec key
    spec_table table;            ///< the table it goes into
    std::string_view option;     ///< the option, --name
    std::string_view type_name;  ///< its value in --help
    value_kind kind;             ///< how its value is written in the spec
    std::string_view help;       ///< --help text
};

/// Every spec key that means something for a one-panel figure has its option here; the
/// keys a spec file alone sets (paper_file, line, columns, panel sizes: see --set) do not.
constexpr key_option key_options[] = {
    {"theta0", spec_table::panel, "--theta0", "LIST", value_kind::list, "Amplitudes, a comma-separated LIST (one for trajectory)"},
    {"energy", spec_table::panel, "--energy", "LIST", value_kind::list,
     "Phase, trajectory and pendulum plots: energies E/(m g L) of launches from the bottom (2 is the separatrix)"},
    {"omega0", spec_table::panel, "--omega0", "LIST", value_kind::list,
     "Phase, trajectory and pendulum plots: launch velocities theta'(0) of states started at --theta0, in units "
     "of w0 = sqrt(g/L), the natural frequency; in rad/s with --length (2.5rad/s)"},
    {"methods", spec_table::panel, "--methods", "LIST", value_kind::list, "Methods, a comma-separated LIST (see 'list')"},
    {"range", spec_table::panel, "--range", "A,B", value_kind::range, "x range a,b: times in the --time unit or in seconds with --length (0,5s), or amplitudes as angles"},
    {"time", spec_table::panel, "--time", "UNIT", value_kind::text, "Time axis of a trajectory: t/T (default), t/T0 or t/s"},
    {"harmonic", spec_table::panel, "--harmonic", "N", value_kind::integer, "Coefficient plots: the harmonic 2k+1 (default 1)"},
    {"harmonics", spec_table::panel, "--harmonics", "N", value_kind::integer, "Spectrum plots: how many odd harmonics"},
    {"orders", spec_table::panel, "--orders", "A,B", value_kind::integer_pair, "Convergence plots: the orders N from A to B"},
    {"y", spec_table::panel, "--y", "AXIS", value_kind::text, "Period plots: value (default), error-percent, error-log or residual ((T_meas - T)/T0 of --data)"},
    {"x", spec_table::panel, "--x", "AXIS", value_kind::text,
     "Period plots: against the amplitude (default) or the energy, T/T0 across the separatrix at E = 2"},
    {"angle_unit", spec_table::panel, "--angle-unit", "UNIT", value_kind::text, "Angles on the axes in rad (default) or deg"},
    {"separatrix", spec_table::panel, "--separatrix", "BOOL", value_kind::boolean, "Phase plots: draw the separatrix, true or false"},
    {"trail", spec_table::panel, "--trail", "T", value_kind::number, "Pendulum drawings: a fading trail of T periods"},
    {"energy_bars", spec_table::panel, "--energy-bars", "", value_kind::flag,
     "Pendulum drawings: kinetic, potential and total energy bars, in units of m g L, from the exact motion"},
    {"arrows", spec_table::panel, "--arrows", "LIST", value_kind::list,
     "Pendulum drawings: arrows on each bob, velocity and/or acceleration (comma-separated), the longest of the "
     "motion 0.6 rod lengths (its value in the legend)"},
    {"timer", spec_table::panel, "--timer", "", value_kind::flag,
     "Pendulum drawings: a period timer, the measured period once the bob has completed one"},
    {"y_range", spec_table::panel, "--y-range", "A,B", value_kind::pair, "y axis limits a,b (default: from the data)"},
    {"x_label", spec_table::panel, "--x-label", "TEXT", value_kind::text, "x axis label, text with TeX math in $...$"},
    {"y_label", spec_table::panel, "--y-label", "TEXT", value_kind::text, "y axis label, text with TeX math in $...$"},
    {"title", spec_table::panel, "--panel-title", "TEXT", value_kind::text, "The panel's title above its frame (default: the amplitude)"},
    {"title", spec_table::figure, "--title", "TEXT", value_kind::text, "The figure's title, drawn above it and kept in PDF and SVG metadata"},
    {"legend", spec_table::figure, "--legend", "WHERE", value_kind::text, "Legend: each (default), first or none"},
    {"fps", spec_table::animation, "--fps", "N", value_kind::number,
     "Animations: frames per second, 1..120 (default 25; a GIF plays the nearest of 100/k: 50, 33.33, 25, ...)"},
    {"periods", spec_table::animation, "--periods", "P", value_kind::number,
     "Animations: length in exact periods of the first start (default: whole periods of every drawn motion)"},
    {"duration_s", spec_table::animation, "--duration", "S", value_kind::number,
     "Animations: length in seconds, with --length (instead of --periods)"},
    {"speed", spec_table::animation, "--speed", "X", value_kind::number,
     "Animations: playback speed against real time (default 1; 0.25 is slow motion)"},
    {"clock", spec_table::animation, "--clock", "BOOL", value_kind::boolean,
     "Animations: show the time in the first panel's title, true or false"},
    {"loop", spec_table::animation, "--loop", "MODE", value_kind::text,
     "Animations: how the end meets the start: periods (default where the motions' periods meet), crossfade or hold"},
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
    bool apart = false;             // --apart: one panel per start
};

/// A TOML string: the text in quotes, with backslashes and quotes escaped.
std::string toml_string(const std::string& text) {
    std::string out = "\"";
    for (const char c : text) {
        if (c == '"' || c == '\\') out += '\\';
        if (static_cast<unsigned char>(c) < 0x20) {
            throw usage_error("'" + shown_text(text.substr(0, 80)) +
                              "' has a control character: an option's text is one line of printable characters");
        }
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
    if (!ok) throw usage_error(std::string(k.option) + " '" + shown_text(text.substr(0, 80)) + "': not " + (integer ? "a whole number" : "a number"));
    return integer ? std::to_string(std::stoll(text)) : format_double(std::stod(text));
}

/// The option's value as TOML.
std::string toml_value(const key_option& k, const std::string& text, const std::string& kind) {
    switch (k.kind) {
        case value_kind::text: return toml_string(text);
        case value_kind::list: return toml_list(text);
        case value_kind::number: return number_text(k, text, false);
        case value_kind::integer: return number_text(k, text, true);
        case value_kind::flag: return "true";
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

/// The [figure] keys --set takes beside a style file's: columns, legend, title.
constexpr std::string_view figure_set_keys[] = {"columns", "legend", "title"};

/// --set KEY=VALUE items cut into [figure] lines (its keys by name) and style file items.
struct cut_sets {
    std::map<std::string, std::string> figure;  ///< key to its TOML line
    std::vector<std::string> style;             ///< KEY=VALUE of a style file
};

/// Cuts --set items into [figure] keys and style keys; a key of neither is a usage_error
/// that names the keys of both.
cut_sets cut_set_options(const std::vector<std::string>& sets) {
    cut_sets out;
    const auto style_keys = figures::style_keys();
    for (const auto& item : sets) {
        const auto eq = item.find('=');
        const std::string key = item.substr(0, eq);
        if (eq == std::string::npos || std::find(style_keys.begin(), style_keys.end(), key) != style_keys.end()) {
            out.style.push_back(item);  // the style file's reader says what is wrong with it
            continue;
        }
        const std::string value = item.substr(eq + 1);
        if (key == "columns") {
            const key_option k{"columns", spec_table::figure, "--set columns", "N", value_kind::integer, ""};
            out.figure[key] = "columns = " + number_text(k, value, true) + "\n";
        } else if (std::find(std::begin(figure_set_keys), std::end(figure_set_keys), key) != std::end(figure_set_keys)) {
            out.figure[key] = key + " = " + toml_string(value) + "\n";
        } else {
            std::string keys;
            for (const auto k : figure_set_keys) keys += (keys.empty() ? "" : ", ") + std::string(k);
            std::string styles;
            for (const auto& k : style_keys) styles += (styles.empty() ? "" : ", ") + k;
            throw usage_error("--set '" + shown_text(item.size() <= 80 ? item : item.substr(0, 80) + "...") +
                              "': unknown key '" + shown_text(key.substr(0, 40)) + "'; plot --set takes the figure keys " +
                              keys + " and a style file's keys " + styles);
        }
    }
    return out;
}

/// The [figure] lines of the options and of --set, a key given both ways refused.
std::string figure_lines(const std::string& from_options, const cut_sets& sets, std::size_t panels) {
    std::string out = from_options;
    for (const auto& [key, line] : sets.figure) {
        if (from_options.starts_with(key + " = ") || from_options.find("\n" + key + " = ") != std::string::npos) {
            throw usage_error("--set " + key + " and --" + key + " both give the figure's " + key + ": give one");
        }
        out += line;
    }
    // --apart sets columns unless --set does.
    if (panels > 1 && !sets.figure.contains("columns")) {
        out += "columns = " + std::to_string(std::min<std::size_t>(panels, 6)) + "\n";
    }
    return out;
}

/// --length and --g as a [pendulum] table: seconds on the axes.
std::string pendulum_table(const plot_options& o) {
    if (o.length.empty() && o.g.empty()) return "";
    if (o.length.empty()) throw usage_error("--g '" + o.g + "' needs --length, the pendulum's length in metres");
    const key_option length{"length_m", spec_table::pendulum, "--length", "M", value_kind::number, ""};
    const key_option g{"g", spec_table::pendulum, "--g", "G", value_kind::number, ""};
    std::string out = "[pendulum]\nlength_m = " + number_text(length, o.length, false) + "\n";
    if (!o.g.empty()) out += "g = " + number_text(g, o.g, false) + "\n";
    return out;
}

/// The plot kinds that animate, "trajectory, phase or pendulum", from the kinds' rows.
std::string moving_plot_names() {
    std::vector<std::string> names;
    for (const auto& row : figures::plot_table()) {
        if (row.add_frame) names.emplace_back(row.name);
    }
    std::string out;
    for (std::size_t i = 0; i < names.size(); ++i) {
        out += (i == 0 ? "" : i + 1 == names.size() ? " and " : ", ") + names[i];
    }
    return out;
}

/// True where one of the formats (a comma-separated list) has a row with that property.
bool any_format(const std::string& formats, bool (*has)(const plot::format_row&)) {
    const auto names = split_list(formats);
    for (const auto& row : plot::format_table()) {
        if (has(row) && std::find(names.begin(), names.end(), row.name) != names.end()) return true;
    }
    return false;
}

/// The [animation] table of the figure: the animation options given (`keys`), or an
/// animation with the spec's defaults where the kind moves and a format holds moving
/// pictures (GIF, video); empty for a still figure. A kind that does not move refuses the
/// animation options and the video formats with a word on what does.
std::string animation_table(const plot_options& o, const std::string& keys) {
    const auto* row = figures::find_plot(o.kind);
    if (!row) return "";  // the spec reader names the kinds
    const bool video = any_format(o.formats, [](const plot::format_row& f) { return f.write == nullptr; });
    const bool moving = any_format(o.formats, [](const plot::format_row& f) { return f.plays_motion; });
    if (!row->add_frame && (video || !keys.empty())) {
        throw usage_error("plot " + o.kind + ": a " + o.kind + " plot does not move, so it cannot be " +
                          (keys.empty() ? "written as a video (-f " + o.formats + ")" : "animated (--fps, --periods, --duration, --speed, --clock)") +
                          "; the plots that animate are " + moving_plot_names() + ", and a still " + o.kind +
                          " plot is written by -f png, pdf, svg, eps or gif");
    }
    if (!row->add_frame || (keys.empty() && !moving)) return "";
    return "[animation]\n" + keys;
}

/// The start options, whose lists --apart cuts into one panel per item.
constexpr std::string_view start_options[] = {"--theta0", "--energy", "--omega0"};

/// The options of each panel: all of them in one panel, or with --apart one panel per start,
/// the i-th item of each start list in the i-th panel (a state's angle and velocity together).
std::vector<std::map<std::string_view, std::string>> panel_values(const plot_options& o) {
    if (!o.apart) return {o.values};
    if (!o.data.empty()) throw usage_error("--apart draws one panel per start; --data goes in one panel: leave out one of them");
    std::size_t count = 0;
    for (const auto option : start_options) {
        if (const auto it = o.values.find(option); it != o.values.end()) count = std::max(count, split_list(it->second).size());
    }
    if (count == 0) throw usage_error("--apart draws one panel per start: give --theta0, --energy or --omega0 with a list");
    std::vector<std::map<std::string_view, std::string>> panels(count, o.values);
    for (const auto option : start_options) {
        const auto it = o.values.find(option);
        if (it == o.values.end()) continue;
        const auto items = split_list(it->second);
        if (items.size() != 1 && items.size() != count) {
            throw usage_error("--apart: " + std::string(option) + " has " + std::to_string(items.size()) +
                              " items where another start list has " + std::to_string(count) + "; give as many, or one for all");
        }
        for (std::size_t i = 0; i < count; ++i) panels[i][option] = items[items.size() == 1 ? 0 : i];
    }
    return panels;
}

/// The options with their start lists read (@FILE, -) and --omega0 in units of
/// w0 = sqrt(g/L): items in rad/s converted with --length and --g (checked as the
/// [pendulum] table checks them).
plot_options in_w0(const plot_options& given) {
    plot_options o = given;
    // A start list from @FILE or standard input (-), read as the other commands read it.
    for (const std::string_view option : {"--theta0", "--energy", "--omega0"}) {
        const auto list = o.values.find(option);
        if (list == o.values.end() || (list->second != "-" && !list->second.starts_with("@"))) continue;
        std::string items;
        for_each_item(list->second, std::string(option),
                      [&](const std::string& item) { items += (items.empty() ? "" : ",") + item; });
        list->second = items;
    }
    const auto it = o.values.find("--omega0");
    if (it == o.values.end()) return o;
    (void)pendulum_table(o);  // numbers, and --g only with --length
    const std::optional<double> length = o.length.empty() ? std::nullopt : std::optional<double>(std::stod(o.length));
    it->second = omega0_in_w0(it->second, length, o.g.empty() ? 9.80665 : std::stod(o.g));
    return o;
}

/// A trajectory's --range with items in seconds (0,5s) in the unit of its time axis: t/s
/// (then --time t/s is implied), or t/T0 converted with --length and --g; the exact period
/// of t/T is not known here, so seconds with --time t/T are refused.
void range_in_time_unit(plot_options& o) {
    const auto range = o.values.find("--range");
    if (o.kind != "trajectory" || range == o.values.end()) return;
    const auto parts = split_list(range->second);
    // An item that is no time at all is left to the spec's reader and its message.
    const auto in_seconds = [](const std::string& p) {
        try {
            return parse_time("--range", p).seconds;
        } catch (const usage_error&) {
            return false;
        }
    };
    if (std::none_of(parts.begin(), parts.end(), in_seconds)) return;
    const std::string shown = "--range '" + shown_text(range->second.substr(0, 80)) + "'";
    if (o.length.empty()) throw usage_error(shown + " in seconds needs the pendulum's --length L in metres (and --g)");
    const auto time = o.values.find("--time");
    const std::string unit = time == o.values.end() ? "t/s" : time->second;
    if (unit != "t/s" && unit != "t/T0") {
        throw usage_error(shown + " in seconds goes with --time t/s (the default then) or t/T0, not --time " +
                          shown_text(unit.substr(0, 40)));
    }
    (void)pendulum_table(o);  // --length and --g are numbers
    const double seconds_per_t0 = 2 * std::numbers::pi * std::sqrt(std::stod(o.length) / (o.g.empty() ? 9.80665 : std::stod(o.g)));
    std::string items;
    for (const auto& p : parts) {
        const auto t = parse_time("--range", p);
        const double v = t.seconds && unit == "t/T0" ? t.value / seconds_per_t0 : t.value;
        items += (items.empty() ? "" : ",") + format_double(v);
    }
    range->second = items;
    o.values["--time"] = unit;
}

/// The plot command: a spec made from the options (one panel, or one per start with
/// --apart), checked like a spec file.
int run_plot(const plot_options& given) {
    std::map<spec_table, std::string> tables;
    std::string toml;
    plot_options o = in_w0(given);
    range_in_time_unit(o);
    const auto panels = panel_values(o);
    for (const auto& values : panels) {
        std::string panel = "[[panel]]\nplot = " + toml_string(o.kind) + "\n";
        for (const auto& k : key_options) {
            const auto it = values.find(k.option);
            if (it == values.end()) continue;
            const std::string line = std::string(k.key) + " = " + toml_value(k, it->second, o.kind) + "\n";
            if (k.table == spec_table::panel) {
                panel += line;
            } else if (&values == &panels.front()) {
                tables[k.table] += line;
            }
        }
        toml += panel;
    }
    const cut_sets sets = cut_set_options(o.sets);
    tables[spec_table::figure] = figure_lines(tables[spec_table::figure], sets, panels.size());
    for (const auto& d : o.data) toml += data_table(d);
    toml = animation_table(o, tables[spec_table::animation]) + toml;
    toml = pendulum_table(o) + toml;
    if (!tables[spec_table::figure].empty()) toml = "[figure]\n" + tables[spec_table::figure] + toml;
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
    // The one rule for the names of figures' files (a spec file's name obeys it too).
    if (const std::string why = figures::file_name_problem(e.id); !why.empty()) {
        throw usage_error("--name '" + shown_text(e.id.substr(0, 80)) + "' " + why);
    }
    render_options r;
    r.dir = o.dir;
    r.formats = o.formats;
    r.theme = o.theme;
    r.sets = sets.style;
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
        if (k.kind == value_kind::flag) {
            cmd->add_flag_function(
                std::string(k.option), [po, option = k.option](std::int64_t) { po->values[option] = "true"; },
                std::string(k.help));
            continue;
        }
        auto* opt = cmd->add_option_function<std::string>(
            std::string(k.option), [po, option = k.option](const std::string& v) { po->values[option] = v; },
            std::string(k.help));
        opt->type_name(std::string(k.type_name));
        // A label may be empty, as in a spec (title = "" leaves the title out); a value may not.
        if (k.type_name != "TEXT") opt->check(non_empty);
    }
    cmd->add_option("--name", po->name, "File name without extension (default: the kind)")->type_name("NAME")->check(non_empty);
    cmd->add_option("-o,--output-dir", po->dir, "Existing directory for the files (default: .)")->type_name("DIR")->check(non_empty);
    cmd->add_option("-f,--formats", po->formats, "Comma-separated formats: " + format_list() + " (default: pdf,png)")
        ->type_name("LIST")->check(non_empty);
    cmd->add_option("--theme", po->theme, figures::theme_help() + "; default paper")->type_name("NAME")->check(non_empty);
    cmd->add_option("--set", po->sets,
                    "KEY=VALUE of a style file on top of the theme, or of the figure: columns, legend or title; "
                    "repeatable")
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
    cmd->add_flag("--apart", po->apart,
                  "One panel per amplitude, energy or state, side by side (default: all in one panel)");
    cmd->add_option("--g", po->g, "Gravity in m/s^2 with --length (default 9.80665)")->type_name("G")->check(non_empty);
    cmd->footer(std::string("\n") + angle_help + "\n\n" + omega0_help +
                     "\n\nThe same as a spec with one [[panel]] of these keys; 'show' prints specs to start from.\n\n"
                     "Examples:\n"
                     "  pendulum-figures plot trajectory --theta0 170deg --methods exact,harmonic,order:6 --range 0,3\n"
                     "  pendulum-figures plot period --methods exact,kidd-fogg,agm:2 --y error-log -f png\n"
                     "  pendulum-figures plot period --x energy --range 0,4\n"
                     "  pendulum-figures plot phase --theta0 'pi/3,2pi/3,0.99pi' --methods exact,first\n"
                     "  pendulum-figures plot phase --energy 0.5,1.5,2,2.5,3 --angle-unit deg\n"
                     "  pendulum-figures plot trajectory --theta0 0 --omega0 2.2\n"
                     "  pendulum-figures plot period --methods exact,harmonic --angle-unit deg --length 1 \\\n"
                     "      --data 'measured.csv:theta0[deg],T[s],dT'\n"
                     "  pendulum-figures plot pendulum --theta0 10deg,170deg --methods exact --apart --periods 2 -f gif,mp4 \\\n"
                     "      --theme slides\n\n"
                     "A trajectory, phase or pendulum plot animates when a format holds moving pictures (gif, mp4, "
                     "webm) or an animation option is given (--fps, --periods, --duration, --speed, --clock); "
                     "png then writes one file per frame.");

    return {cmd, [po] { return run_plot(*po); }};
}

}  // namespace pendulum::cli
