// SPDX-License-Identifier: GPL-3.0-or-later
// pendulum-figures: the command line. Parsing and validation only; the work is in the libraries.
#include "cli/angle.hpp"
#include "cli/errors.hpp"
#include "cli/eval_columns.hpp"
#include "cli/table.hpp"
#include "figures/animation.hpp"
#include "figures/batch.hpp"
#include "figures/catalog.hpp"
#include "figures/spec_build.hpp"
#include "figures/themes.hpp"
#include "plot/output.hpp"
#include "plot/render.hpp"
#include "plot/theme.hpp"
#include "pendulum/amplitude.hpp"
#include "pendulum/approximants.hpp"
#include "pendulum/claims.hpp"
#include "pendulum/exact.hpp"
#include "pendulum/methods.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <deque>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <iostream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <unistd.h>
#include <vector>

namespace {

using namespace pendulum;

using cli::usage_error;

constexpr int max_samples = 10'000'000;
constexpr double max_periods = 1e6;

/// Calls take(item) for each item of a list option: its text, or the lines (each
/// comma-separated, # comments) of FILE for @FILE and of standard input for -, read as
/// they come, so that a million amplitudes need no more memory than their values.
template <class Take>
void for_each_item(const std::string& text, const std::string& option, Take take) {
    if (text != "-" && (text.empty() || text[0] != '@')) {
        for (const auto& item : cli::split_list(text)) take(item);
        return;
    }
    std::ifstream file;
    if (text != "-") {
        file.open(text.substr(1), std::ios::binary);
        if (!file) throw usage_error(option + " " + text + ": cannot read '" + text.substr(1) + "'");
    }
    std::istream& in = text == "-" ? std::cin : file;
    bool any = false;
    for (std::string line; std::getline(in, line);) {
        line = line.substr(0, line.find('#'));
        if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
        for (auto& item : cli::split_list(line)) {
            const auto first = item.find_first_not_of(" \t\r");
            take(first == std::string::npos ? std::string()
                                             : item.substr(first, item.find_last_not_of(" \t\r") - first + 1));
            any = true;
        }
    }
    if (!any) throw usage_error(option + " " + text + ": no values");
}

/// One --theta0 item, checked; take(text, value) receives it.
template <class Take>
void for_each_amplitude(const std::string& given, Take take) {
    for_each_item(given, "--theta0", [&](const std::string& item) {
        double v = 0;
        try {
            v = cli::parse_angle(item);
            check_amplitude(v);
        } catch (const std::invalid_argument& e) {
            const std::string shown = item.size() <= 80 ? item : item.substr(0, 40) + "..." + item.substr(item.size() - 20);
            throw usage_error("--theta0 '" + shown + "': " + e.what());
        }
        take(item, v);
    });
}

/// The values of --theta0, checked (a million of them take 8 MB).
std::vector<double> parse_amplitude_values(const std::string& given) {
    std::vector<double> values;
    for_each_amplitude(given, [&](const std::string&, double v) { values.push_back(v); });
    return values;
}

/// Amplitudes as typed and their values; figure titles show them as typed.
std::vector<figures::amplitude> parse_amplitudes(const std::string& given) {
    std::vector<figures::amplitude> values;
    for_each_amplitude(given, [&](const std::string& item, double v) { values.push_back({item, v}); });
    return values;
}

/// Parses a method name (NAME or NAME:N) for the option `option`.
method_choice parse_method_option(const std::string& option, const std::string& text) {
    try {
        return parse_method(text);
    } catch (const domain_error& e) {
        throw usage_error(option + " '" + text + "': " + e.what());
    }
}

void check_order(int order) {
    if (order < 0 || order > max_order) {
        throw usage_error("--order " + std::to_string(order) + ": order must be between 0 and " +
                          std::to_string(max_order));
    }
}

/// Parses an order N given as text, with a message that names it.
int parse_order(const std::string& text) {
    // Spaces around the number are allowed on both sides, as in angles.
    const auto first = text.find_first_not_of(" \t");
    const auto last = text.find_last_not_of(" \t");
    const std::string digits = first == std::string::npos ? "" : text.substr(first, last - first + 1);
    if (digits.empty()) throw usage_error("--order: empty value; orders are 0.." + std::to_string(max_order));
    if (digits.find_first_not_of("0123456789") != std::string::npos) {
        throw usage_error("--order '" + text + "': not a whole number; orders are 0.." + std::to_string(max_order));
    }
    if (digits.size() > 9) {
        throw usage_error("--order " + digits + ": order must be between 0 and " + std::to_string(max_order));
    }
    const int order = std::stoi(digits);
    check_order(order);
    return order;
}

/// Parses --order items: orders N and ranges a..b, in the order given, each order once.
std::vector<int> parse_orders(const std::vector<std::string>& items) {
    std::vector<int> orders;
    const auto add = [&](int n) {
        if (std::find(orders.begin(), orders.end(), n) == orders.end()) orders.push_back(n);
    };
    for (const auto& text : items) {
        const auto dots = text.find("..");
        if (dots == std::string::npos) {
            add(parse_order(text));
            continue;
        }
        const int from = parse_order(text.substr(0, dots));
        const int to = parse_order(text.substr(dots + 2));
        if (from > to) {
            throw usage_error("--order '" + text + "': a range a..b needs a <= b, e.g. 0.." + std::to_string(max_order));
        }
        for (int n = from; n <= to; ++n) add(n);
    }
    return orders;
}

/// Says on standard error which levels of the iteration have no period at this amplitude.
void warn_breakdown(double theta0, const std::vector<int>& levels) {
    std::string list;
    for (int n : levels) list += (list.empty() ? "" : ", ") + std::to_string(n);
    std::cerr << "pendulum-figures: warning: theta0 = " << format_double(theta0) << ": the iteration has no period at order "
              << list << " (lambda = (w/w0)^2 < 0 there: the scheme itself breaks down near pi); "
              << (levels.size() == 1 ? "that field is" : "those fields are") << " left empty\n";
}

/// A comma-separated option value as its items, empty ones kept so that they are reported.
std::vector<std::string> list_items(const std::vector<std::string>& values) {
    std::vector<std::string> items;
    for (const auto& v : values) {
        for (auto& item : cli::split_list(v)) items.push_back(std::move(item));
    }
    return items;
}

/// Refuses an empty value (CLI11 validator): '' is never a figure, directory or amplitude.
const CLI::Validator non_empty(
    [](std::string& value) { return value.empty() ? std::string("empty value") : std::string(); }, "", "NON-EMPTY");

/// Prints an error on standard error, one line per line of the message, with control
/// characters shown escaped (a typed ESC or CR must not retitle or clear the terminal).
void report_error(const std::string& message) {
    std::string out = "pendulum-figures: error: ";
    for (const char c : message) {
        const auto u = static_cast<unsigned char>(c);
        if (c == '\n') {
            out += '\n';
        } else if (u < 0x20 || u == 0x7f) {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\x%02x", u);
            out += buf;
        } else {
            out += c;
        }
    }
    std::cerr << out << '\n';
}

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

struct eval_options {
    std::string theta0;
    std::vector<std::string> orders;
    std::vector<std::string> methods;
    std::string format = "csv";
    std::optional<double> length;  // metres: adds the period in seconds
    double g = 9.80665;
};

/// Writes eval's table row by row: every input is checked first (nothing is written for
/// bad input), then each amplitude's row goes out as it is computed.
void eval_stream(std::ostream& out, const eval_options& o) {
    const auto format = cli::parse_table_format(o.format);
    const auto amplitudes = parse_amplitude_values(o.theta0);
    const std::vector<int> orders = parse_orders(list_items(o.orders));
    std::vector<method_choice> methods;
    for (const auto& text : list_items(o.methods)) {
        if (text.empty()) throw usage_error("--method: empty value; see 'list' for the methods");
        const auto m = parse_method_option("--method", text);
        if (std::none_of(methods.begin(), methods.end(), [&](const method_choice& c) { return c.text() == m.text(); })) {
            methods.push_back(m);
        }
    }
    std::vector<std::string> columns;
    for (const auto& c : cli::eval_columns()) columns.emplace_back(c.name);
    for (int n : orders) columns.push_back("period_order" + std::to_string(n));
    for (const auto& m : methods) columns.push_back("period_" + m.text());
    double small_period_s = 0;
    if (o.length) {
        if (!(*o.length > 0 && *o.length <= 1e6)) {
            throw usage_error("--length " + format_double(*o.length) + ": a length in metres above 0 and at most 1e6");
        }
        if (!(o.g > 0 && o.g <= 1e4)) throw usage_error("--g " + format_double(o.g) + ": above 0 and at most 1e4");
        small_period_s = 2 * std::acos(-1.0) * std::sqrt(*o.length / o.g);
        columns.push_back("T_s");
    }
    // The iteration is computed once per amplitude, to the highest level asked for, and
    // every --order and --method order:N column is read off that one sequence.
    int highest = -1;
    for (int n : orders) highest = std::max(highest, n);
    for (const auto& m : methods) {
        if (m.row->name == "order") highest = std::max(highest, m.n);
    }
    cli::table_writer writer(out, columns, format);
    for (const double value : amplitudes) {
        const cli::eval_point point(value);
        const auto levels = highest >= 0 ? iterated_sequence(value, highest) : std::vector<fourier_solution>{};
        std::vector<int> broken;
        const auto level_period = [&](int n) {
            const auto& level = levels[static_cast<std::size_t>(n)];
            if (!level.exists() && std::find(broken.begin(), broken.end(), n) == broken.end()) broken.push_back(n);
            return level.period_ratio();
        };
        std::vector<double> row;
        for (const auto& c : cli::eval_columns()) row.push_back(c.value(point));
        for (int n : orders) row.push_back(level_period(n));
        for (const auto& m : methods) row.push_back(m.row->name == "order" ? level_period(m.n) : method_period(m, value));
        if (o.length) row.push_back(small_period_s * point.exact.period_ratio());
        writer.row(row);
        if (!broken.empty()) warn_breakdown(value, broken);
    }
    writer.finish();
}

struct trajectory_options {
    std::string theta0;
    std::string method = "exact";
    std::string order;
    std::string at;
    int samples = 0;
    double periods = 1.0;
    std::string format = "csv";
};

/// Writes trajectory's table row by row; every input is checked before the first row.
void trajectory_stream(std::ostream& out, const trajectory_options& o, bool order_given, bool periods_given) {
    const auto format = cli::parse_table_format(o.format);
    const auto amplitudes = parse_amplitudes(o.theta0);
    if (amplitudes.size() != 1) throw usage_error("--theta0 takes one amplitude for trajectory");
    const double theta0 = amplitudes.front().value;
    std::string method_text = o.method;
    if (o.method == "order") {
        if (!order_given) throw usage_error("--method order needs --order N (or write --method order:N)");
        method_text = "order:" + std::to_string(parse_order(o.order));
    } else if (order_given) {
        throw usage_error("--order is only used with --method order, not --method " + o.method);
    }
    const method_choice method = parse_method_option("--method", method_text);
    if (!method.has_motion()) {
        throw usage_error("--method " + method.text() + " gives a period only, not a law of motion; see 'list'");
    }
    if (o.at.empty() == (o.samples == 0)) {
        throw usage_error("give either --at LIST or --samples N (with --periods P)");
    }
    std::vector<double> times;
    if (!o.at.empty()) {
        if (periods_given) throw usage_error("--periods goes with --samples, not with --at");
        for (const auto& item : cli::split_list(o.at)) {
            try {
                times.push_back(cli::parse_expression(item));
            } catch (const std::invalid_argument& e) {
                throw usage_error(std::string("--at '") + item + "': " + e.what());
            }
        }
    } else {
        if (o.samples < 2 || o.samples > max_samples) {
            throw usage_error("--samples " + std::to_string(o.samples) + ": must be between 2 and " +
                              std::to_string(max_samples));
        }
        if (!(o.periods > 0.0) || !(o.periods <= max_periods)) {
            throw usage_error("--periods " + format_double(o.periods) +
                              ": must be greater than 0 and at most " + format_double(max_periods));
        }
    }

    const exact_solution exact(theta0);
    const bool is_exact = method.row->name == "exact";
    const fourier_solution approx = is_exact ? fourier_solution{} : method_solution(method, theta0);
    if (!is_exact && !approx.exists()) {
        throw usage_error("--theta0 " + amplitudes.front().text + ": the iteration has no period at order " +
                          std::to_string(method.n) + " there (lambda = (w/w0)^2 < 0: the scheme itself breaks down " +
                          "near pi); choose another order, or an amplitude further from pi");
    }

    const double period = 4.0 * exact.quarter_period();  // exact T in units of 1/w0
    cli::table_writer writer(out, {"t_over_T", "theta"}, format);
    const auto write = [&](double s) {
        writer.row({s, is_exact ? exact.theta_at_fraction(s) : approx.theta(s * period)});
    };
    if (o.at.empty()) {
        // Sample times computed as they are written: ten million rows need no memory.
        for (int i = 0; i < o.samples; ++i) write(o.periods * i / (o.samples - 1));
    } else {
        for (double s : times) write(s);
    }
    writer.finish();
}

struct render_options {
    std::vector<std::string> ids;
    bool all = false;
    std::string dir = ".";
    std::string formats = "pdf,png";
    std::string theme;  // empty: paper for still figures, slides for animations
    std::vector<std::string> sets;
    std::optional<double> dpi;  // the theme's when not given
    std::string theta0;
    bool paper_files = false;
    bool force = false;  // rewrite files that would not change
    std::string frames;  // a..b, 1-based, of an animation
    std::string at;      // t/T of one frame of an animation
    std::optional<double> tex_font_size;  // the document's font size, for pdf_tex and eps_tex
    std::string tex_sizes = "relative";  // how pdf_tex and eps_tex size their text
};

/// Parses --frames a..b (1-based, inclusive) into 0-based indices; b may be left out.
std::pair<int, int> parse_frames(const std::string& text, int count) {
    const auto dots = text.find("..");
    const auto number = [&](const std::string& part, int fallback) {
        if (part.empty()) return fallback;
        std::size_t used = 0;
        long long v = -1;
        try {
            v = std::stoll(part, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (used != part.size() || v < 1 || v > count) {
            throw usage_error("--frames '" + text + "': frames are 1.." + std::to_string(count) + ", as A..B");
        }
        return static_cast<int>(v);
    };
    if (dots == std::string::npos) {
        const int one = number(text, 0);
        return {one - 1, one - 1};
    }
    const int a = number(text.substr(0, dots), 1);
    const int b = number(text.substr(dots + 2), count);
    if (a > b) throw usage_error("--frames '" + text + "': the first frame comes after the last");
    return {a - 1, b - 1};
}

/// The theme of --theme and --set; a bad style file is bad input.
plot::theme chosen_theme(const std::string& name, const std::vector<std::string>& sets) {
    try {
        return figures::load_theme(name, sets);
    } catch (const figures::spec_error& e) {
        throw usage_error(std::string("bad theme:\n") + e.what());
    } catch (const std::runtime_error& e) {
        throw usage_error(e.what());
    }
}

/// Checks that dir exists and can be written to, naming it otherwise.
void check_output_dir(const std::string& dir) {
    std::error_code ec;
    if (!std::filesystem::exists(dir, ec)) throw usage_error("output directory '" + dir + "' does not exist");
    if (!std::filesystem::is_directory(dir, ec)) throw usage_error("output path '" + dir + "' is not a directory");
    if (::access(dir.c_str(), W_OK | X_OK) != 0) {
        throw usage_error("output directory '" + dir + "' is not writable");
    }
}

/// Reads a figure id or spec file; a bad spec is bad input.
figures::entry load_figure(const std::string& id) {
    try {
        return figures::load(id);
    } catch (const figures::spec_error& e) {
        throw usage_error(std::string("bad figure spec:\n") + e.what());
    } catch (const std::runtime_error& e) {
        throw usage_error(e.what());
    }
}

/// The figures named on the command line (ids, aliases or spec files), each once; spec
/// files are read into `loaded`, which must outlive the result.
std::vector<const figures::entry*> selected_figures(const std::vector<std::string>& ids, bool all,
                                                    std::deque<figures::entry>& loaded) {
    if (!all && ids.empty()) throw usage_error("name the figures to render, or use --all (see 'list')");
    std::vector<const figures::entry*> chosen;
    if (all) {
        // Every still figure; animations are rendered by name.
        for (const auto& e : figures::catalog()) {
            if (!e.spec.animation) chosen.push_back(&e);
        }
    }
    for (const auto& id : ids) {
        const figures::entry* e = nullptr;
        if (id.ends_with(".toml")) {
            e = &loaded.emplace_back(load_figure(id));
        } else {
            e = &figures::find(id);
        }
        const auto same = std::find_if(chosen.begin(), chosen.end(), [&](const auto* c) { return c->id == e->id; });
        if (same != chosen.end()) {
            // The same figure twice is drawn once; two different ones cannot share file names.
            if ((*same)->source != e->source) {
                throw usage_error("two different figures are named '" + e->id + "' and would write the same files");
            }
            continue;
        }
        chosen.push_back(e);
    }
    return chosen;
}

/// Renders the chosen figures with the options of `o` other than the ids.
int render_entries(const std::vector<const figures::entry*>& chosen, const render_options& o) {
    // The environment is input too: a bad SOURCE_DATE_EPOCH stops the run before any work.
    plot::pdf_creation_date();
    std::vector<std::string> formats;
    for (const auto& f : cli::split_list(o.formats)) {
        plot::check_format(f);
        if (std::find(formats.begin(), formats.end(), f) == formats.end()) formats.push_back(f);
    }
    // An overlay format writes its drawing under the drawing format's name.
    for (const auto& row : plot::format_table()) {
        if (row.graphics.empty()) continue;
        const std::string overlay(row.name);
        const std::string graphics(row.graphics);
        if (std::count(formats.begin(), formats.end(), graphics) && std::count(formats.begin(), formats.end(), overlay)) {
            throw usage_error("-f " + o.formats + ": " + graphics + " and " + overlay + " both write ID." + graphics +
                              " (" + overlay + "'s without its text); render them into different directories");
        }
    }
    plot::output_options overlay;  // what the LaTeX overlays need; dpi is set per theme below
    try {
        overlay.tex_sizes = plot::find_tex_sizing(o.tex_sizes).value;
    } catch (const plot::bad_input& e) {
        throw usage_error(std::string("--tex-sizes: ") + e.what());
    }
    if (o.tex_font_size) {
        if (!(*o.tex_font_size >= 5 && *o.tex_font_size <= 30)) {
            throw usage_error("--tex-font-size " + format_double(*o.tex_font_size) +
                              ": the document's font size in points, 5 to 30");
        }
        if (overlay.tex_sizes == plot::tex_sizing::absolute) {
            throw usage_error("--tex-font-size does nothing with --tex-sizes absolute: the text has the theme's "
                              "sizes in points (--set tick_font_pt=... changes them)");
        }
        overlay.tex_font_pt = *o.tex_font_size;
    }
    const plot::theme theme = chosen_theme(o.theme.empty() ? "paper" : o.theme, o.sets);
    // Animations are for slides: theirs unless a theme is asked for.
    const plot::theme moving_theme = o.theme.empty() ? chosen_theme("slides", o.sets) : theme;
    const double dpi = o.dpi.value_or(theme.dpi);
    const double moving_dpi = o.dpi.value_or(moving_theme.dpi);
    for (const double d : {dpi, moving_dpi}) {
        if (!(d >= plot::min_dpi && d <= plot::max_dpi)) {
            throw usage_error("--dpi " + format_double(d) + ": must be between " + format_double(plot::min_dpi) +
                              " and " + format_double(plot::max_dpi));
        }
    }
    figures::build_options build;
    if (!o.theta0.empty()) {
        if (std::none_of(chosen.begin(), chosen.end(), [](const auto* e) { return e->takes_amplitudes(); })) {
            throw usage_error("--theta0 applies to figures with trajectory, phase, convergence or spectrum panels, "
                              "and none was chosen");
        }
        build.amplitudes = parse_amplitudes(o.theta0);
    }
    if (o.dir == "-") {
        // One still figure in one format, to standard output.
        if (chosen.size() != 1 || formats.size() != 1 || o.paper_files || chosen.front()->spec.animation) {
            throw usage_error("-o - writes one still figure in one format to standard output");
        }
        figures::build_options one = build;
        one.panel_width_cm = theme.panel_width_cm;
        one.panel_aspect = theme.panel_aspect;
        plot::check_raster_size(figures::figure_grid(chosen.front()->spec, one), theme, dpi);
        const std::string bytes = plot::render(figures::build(*chosen.front(), one), theme, formats.front(),
                                               plot::output_options{dpi});
        std::cout.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
        std::cout.flush();
        if (!std::cout) {
            report_error("cannot write to standard output");
            return 1;
        }
        return 0;
    }
    check_output_dir(o.dir);

    std::vector<const figures::entry*> stills;
    std::vector<const figures::entry*> animations;
    for (const auto* e : chosen) (e->spec.animation ? animations : stills).push_back(e);
    if ((!o.frames.empty() || !o.at.empty()) && animations.empty()) {
        throw usage_error("--frames and --at apply to animations, and none was chosen (see 'list')");
    }
    if (!o.frames.empty() && !o.at.empty()) throw usage_error("give --frames or --at, not both");
    if (o.paper_files && !animations.empty()) throw usage_error("--paper-files applies to still figures, not to animations");

    const std::vector<figures::figure_file> jobs = figures::files_for(stills, formats, o.dir, o.paper_files, build);
    if (jobs.empty() && animations.empty()) {
        throw usage_error("the chosen figures have no panels in the paper; drop --paper-files");
    }
    // Every animation is checked before any file is written.
    struct animation_job {
        const figures::entry* entry;
        figures::animation_plan plan;
        std::pair<int, int> frames;
    };
    std::vector<animation_job> moving;
    std::optional<double> at;
    if (!o.at.empty()) {
        try {
            at = cli::parse_expression(o.at);
        } catch (const std::invalid_argument& e) {
            throw usage_error(std::string("--at: ") + e.what());
        }
    }
    // Rasters too large for Cairo or for memory are refused before any work.
    for (const auto* e : chosen) {
        const bool moving = e->spec.animation.has_value();
        const plot::theme& th = moving ? moving_theme : theme;
        figures::build_options grid{build.amplitudes, th.panel_width_cm, th.panel_aspect};
        for (const auto& f : formats) {
            if (!plot::find_format(f).raster) continue;
            try {
                plot::check_raster_size(figures::figure_grid(e->spec, grid), th, moving ? moving_dpi : dpi);
            } catch (const plot::bad_input& err) {
                throw usage_error(e->id + "." + f + ": " + err.what());
            }
        }
    }
    for (const auto* e : animations) {
        const auto plan = figures::plan_animation(*e, build);
        moving.push_back({e, plan, o.frames.empty() ? std::pair{0, plan.frames - 1} : parse_frames(o.frames, plan.frames)});
    }

    {
        if (!jobs.empty()) figures::write_figures(jobs, build, theme, plot::output_options{dpi, o.force, overlay.tex_font_pt, overlay.tex_sizes});
        for (const auto& m : moving) {
            for (const auto& f : formats) {
                const plot::format_row& row = plot::find_format(f);
                if (!at && row.animate) {
                    figures::write_animation(*m.entry, build, moving_theme, row, o.dir, plot::output_options{moving_dpi},
                                             m.frames.first, m.frames.second);
                    continue;
                }
                // A still format, or --at: one frame.
                figures::build_options still = build;
                still.animated = true;
                still.panel_width_cm = moving_theme.panel_width_cm;
                still.panel_aspect = moving_theme.panel_aspect;
                const double w0_t = at ? *at * m.plan.reference_period : m.plan.time(m.frames.first);
                const auto frame = figures::animation_frame(*m.entry, still, m.plan, figures::build(*m.entry, still), w0_t);
                plot::save(frame, moving_theme, std::filesystem::path(o.dir) / (m.entry->id + "." + f),
                           plot::output_options{moving_dpi, o.force, overlay.tex_font_pt, overlay.tex_sizes});
            }
        }
    }
    return 0;
}

int run_render(const render_options& o) {
    std::deque<figures::entry> loaded;
    return render_entries(selected_figures(o.ids, o.all, loaded), o);
}

/// True for a LaTeX overlay format.
bool is_overlay(const plot::format_row& f) { return !f.graphics.empty(); }

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
            << (m.kind == method_kind::motion ? "motion" : "period") << " | " << m.description << " |\n";
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
        out << "  " << padded(name, 28) << padded(m.kind == method_kind::motion ? "motion" : "period", 8)
            << m.description << "\n";
    }
    out << "\nPlot kinds (plot = KIND in a spec's [[panel]], or the plot command):\n";
    for (const auto& p : figures::plot_table()) {
        out << "  " << padded(std::string(p.name), 28) << p.description << "; keys: " << p.keys << "\n";
    }
    return out.str();
}

std::string figure_data(const std::string& id, const std::string& theta0) {
    const figures::entry e = load_figure(id);
    figures::build_options build;
    if (!theta0.empty()) {
        if (!e.takes_amplitudes()) {
            throw usage_error("--theta0 applies to figures with trajectory, phase, convergence or spectrum panels, "
                              "not to " + e.id);
        }
        build.amplitudes = parse_amplitudes(theta0);
    }
    return figures::figure_csv(figures::build(e, build));
}

std::string format_list() {
    std::string out;
    for (const auto& f : plot::format_names()) out += (out.empty() ? "" : ", ") + f;
    return out;
}

/// The raster formats, for --help: "png, gif".
std::string raster_formats() {
    return plot::format_names([](const plot::format_row& f) { return f.raster; }, " and ");
}

/// The LaTeX overlay formats, for --help: "pdf_tex, eps_tex".
std::string overlay_formats() { return plot::format_names(is_overlay); }

/// How each format writes an animation, for --help.
std::string animation_help() {
    std::vector<std::string_view> ways;
    for (const auto& f : plot::format_table()) {
        if (f.animate) ways.push_back(f.animation);
    }
    std::string out;
    for (std::size_t i = 0; i < ways.size(); ++i) {
        out += std::string(i == 0 ? "" : i + 1 == ways.size() ? ", or " : ", ") + std::string(ways[i]);
    }
    return out + "; " + plot::format_names([](const plot::format_row& f) { return f.animate == nullptr; }, " and ") +
           ", and every format with --at, get one frame";
}

/// The formats with what each is, for --help.
std::string format_help() {
    std::string out;
    for (const auto& f : plot::format_table()) {
        out += (out.empty() ? "" : ", ") + std::string(f.name) + " (" + std::string(f.description) + ")";
    }
    return out;
}

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
    for (const auto& item : cli::split_list(text)) out += (out.size() > 1 ? ", " : "") + toml_string(item);
    return out + "]";
}

/// The plot command: a one-panel spec made from the options, checked like a spec file.
int run_plot(const plot_options& o) {
    std::string toml = "[[panel]]\nplot = " + toml_string(o.kind) + "\n";
    if (!o.theta0.empty()) toml += "theta0 = " + toml_list(o.theta0) + "\n";
    if (!o.methods.empty()) toml += "methods = " + toml_list(o.methods) + "\n";
    if (!o.range.empty()) {
        const auto parts = cli::split_list(o.range);
        if (parts.size() != 2) throw usage_error("--range '" + o.range + "': give two values, A,B");
        if (o.kind == "trajectory") {
            double v[2];
            for (int i = 0; i < 2; ++i) {
                try {
                    v[i] = cli::parse_expression(parts[static_cast<std::size_t>(i)]);
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
    return render_entries({&e}, r);
}

const char* const angle_help =
    "Angles are expressions in radians: 1.2, pi/2, 9pi/10, 9*pi/10, 0.9pi, pi-1e-6, or degrees "
    "with deg: 162deg. A LIST is comma-separated: --theta0 'pi/3,pi/2,162deg'.";

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
    app.footer(std::string("\n") + angle_help +
               "\n\nExamples:\n"
               "  pendulum-figures eval --theta0 pi/2\n"
               "  pendulum-figures eval --theta0 'pi/3,pi/2,9pi/10' --order 4 --order 12 --format json\n"
               "  pendulum-figures trajectory --theta0 162deg --method first --samples 101\n"
               "  pendulum-figures list\n"
               "  pendulum-figures render --all -o figures -f pdf,png\n"
               "\nRun 'pendulum-figures COMMAND --help' for the options of each command, --help-all for all.\n"
               "\nExit status: 0 on success; 2 for bad input (an option, a value, a spec or style file, "
               "SOURCE_DATE_EPOCH), with nothing written; 1 when writing or the work itself fails.");

    eval_options ev;
    auto* eval = app.add_subcommand(
        "eval", "Print periods T/T0 and Fourier coefficients, exact and approximate, per amplitude.");
    eval->add_option("--theta0", ev.theta0, "Amplitudes, a comma-separated LIST of angles")
        ->required()
        ->type_name("LIST")->check(non_empty);
    eval->add_option("--order", ev.orders,
                     "Add a column period_orderN for the iteration to order N (0.." +
                         std::to_string(max_order) + "), or one for each N of a range a..b; repeatable")
        ->type_name("N")
        ->take_all();
    eval->add_option("--method", ev.methods,
                     "Add a column period_NAME for any method of 'list', e.g. kidd-fogg, agm:2, series:3; "
                     "repeatable")
        ->type_name("NAME")
        ->take_all();
    eval->add_option("--length", ev.length, "Pendulum length in metres: adds T_s, the exact period in seconds")
        ->type_name("L");
    eval->add_option("--g", ev.g, "Gravity in m/s^2 for --length (default 9.80665)")->type_name("G");
    eval->add_option("--format", ev.format, "Output format: csv (default) or json")
        ->type_name("csv|json");
    eval->footer(std::string("\n") + angle_help + "\n\nColumns: " + cli::eval_columns_help() +
                 "; then period_orderN for each --order N, period_NAME for each --method NAME, and T_s with "
                 "--length. Periods are T/T0. Numbers round-trip a double.\n\n"
                 "Close to pi (from about pi - 3e-4) some levels of the iteration have lambda = (w/w0)^2 < 0, "
                 "so no period: at pi - 1e-6 the orders 6, 8, 16 and 17. That field is left empty (null in "
                 "JSON), a warning on standard error names the amplitude and the orders, and the exit status "
                 "stays 0: the table is complete, the value does not exist.\n\n"
                 "Examples:\n"
                 "  pendulum-figures eval --theta0 'pi/2,9pi/10' --order 12\n"
                 "  pendulum-figures eval --theta0 0.99pi --order 0..40\n"
                 "  pendulum-figures eval --theta0 170deg --method kidd-fogg,lima-arun,ganley,agm:2\n"
                 "  pendulum-figures eval --theta0 170deg --length 0.5");

    trajectory_options tr;
    auto* traj = app.add_subcommand(
        "trajectory", "Print theta(t) for one amplitude, exact or approximate, at times t/T.");
    traj->add_option("--theta0", tr.theta0, "Amplitude, one angle")->required()->type_name("ANGLE")->check(non_empty);
    traj->add_option("--method", tr.method,
                     "A method with a law of motion: exact (default), harmonic, lowest, first, second, "
                     "polynomial, or order:N (or order with --order N); see 'list'")
        ->type_name("METHOD");
    auto* order_opt = traj->add_option("--order", tr.order, "Order N of --method order (0.." +
                                                                std::to_string(max_order) + ")")
                          ->type_name("N");
    traj->add_option("--at", tr.at, "Times t/T, a comma-separated list (T is the exact period)")
        ->type_name("LIST")->check(non_empty);
    traj->add_option("--samples", tr.samples, "Number of equally spaced times from 0 to --periods")
        ->type_name("N");
    auto* periods_opt =
        traj->add_option("--periods", tr.periods, "Time span in exact periods T (default 1)")
            ->type_name("P");
    traj->add_option("--format", tr.format, "Output format: csv (default) or json")
        ->type_name("csv|json");
    traj->footer(std::string("\n") + angle_help +
                 "\n\nColumns: t_over_T, theta (radians). Every method is evaluated at the same "
                 "physical time t = (t/T) T, with T the exact period.\n\n"
                 "Examples:\n"
                 "  pendulum-figures trajectory --theta0 9pi/10 --method second --samples 201 --periods 2\n"
                 "  pendulum-figures trajectory --theta0 pi/2 --method order --order 8 --at 0,0.125,0.25");

    render_options ro;
    auto* render = app.add_subcommand("render", "Draw figures (built-in or spec files) into files: " + format_list() + ".");
    render->add_option("ids", ro.ids, "Figure ids or aliases (see 'list'), or spec files NAME.toml")->type_name("ID");
    render->add_flag("--all", ro.all, "Render every built-in still figure (and the figures given with it); animations are rendered by name");
    render->add_option("-o,--output-dir", ro.dir, "Existing directory for the files (default: .); - writes one "
                                                  "figure in one format to standard output")->type_name("DIR")->check(non_empty);
    render->add_option("-f,--formats", ro.formats, "Comma-separated formats (default: pdf,png): " + format_help())
        ->type_name("LIST")->check(non_empty);
    render->add_option("--theme", ro.theme, figures::theme_help() + "; default paper, slides for animations")
        ->type_name("NAME")->check(non_empty);
    render->add_option("--set", ro.sets, "KEY=VALUE of a style file on top of the theme, e.g. tick_font_pt=9; "
                                         "repeatable ('show --theme paper' lists the keys)")
        ->type_name("KEY=VALUE")->check(non_empty);
    render->add_option("--dpi", ro.dpi, "Resolution of " + raster_formats() + " in dots per inch, 10..2400 (default: "
                                        "the theme's, 300 for paper)")
        ->type_name("N");
    render->add_option("--theta0", ro.theta0, "Amplitudes of the trajectory figures, a comma-separated LIST")
        ->type_name("LIST")->check(non_empty);
    render->add_option("--frames", ro.frames, "Animations: only frames A..B (from 1; A.. or ..B for the rest)")
        ->type_name("A..B")->check(non_empty);
    render->add_option("--at", ro.at, "Animations: one frame at time t/T (T the exact period of the first "
                                      "amplitude), in every format")
        ->type_name("T")->check(non_empty);
    render->add_flag("--force", ro.force, "Rewrite files that would not change (by default they are left alone, "
                                          "so their time stays and make does not rebuild)");
    render->add_option("--tex-font-size", ro.tex_font_size,
                       overlay_formats() + ": the document's font size in points, 5..30 (default 10); the figure's "
                       "text is set at sizes relative to it (\\footnotesize, \\small) and laid out to fit")
        ->type_name("PT");
    {
        std::string help = overlay_formats() + ": how the text is sized (default relative):";
        for (const auto& row : plot::tex_sizing_table()) {
            help += "\n  " + std::string(row.name) + ": " + std::string(row.description);
        }
        render->add_option("--tex-sizes", ro.tex_sizes, help)->type_name("HOW");
    }
    render->add_flag("--paper-files", ro.paper_files,
                     "One file per panel, named and sized as in the paper's LaTeX source (Fig.C1.Lowest, ...)");
    render->footer(std::string("\n") + angle_help +
                   "\n\nFiles are DIR/ID.EXT (or the paper's names with --paper-files). Each file is written "
                   "under a temporary name and renamed, so a failed run never leaves a partial figure. Set "
                   "SOURCE_DATE_EPOCH to stamp PDF and EPS files with that date; otherwise they carry none.\n\n"
                   "Examples:\n"
                   "  pendulum-figures render --all -o figures -f pdf,png\n"
                   "  pendulum-figures render fig2 --theta0 170deg --theme slides -f png --dpi 150\n"
                   "  pendulum-figures render --all --paper-files -f eps -o paper/\n"
                   "\nLaTeX sets the text: -f pdf_tex writes ID.pdf without text and ID.pdf_tex, which the document "
                   "reads with \\usepackage{graphicx} and \\input{ID.pdf_tex}: every label in the document's own "
                   "fonts, at \\footnotesize or \\small of its size (--tex-font-size), or at the theme's sizes in "
                   "points with --tex-sizes absolute (with Computer Modern: \\RequirePackage{fix-cm} first). "
                   "\\def\\figurewidth{8.6cm} "
                   "before \\input scales the drawing, not the text. eps_tex is the same for latex and dvips. Labels "
                   "are the specs' TeX, verbatim; a macro LaTeX lacks shows only when the document is compiled.\n"
                   "  pendulum-figures render fig2 -f pdf_tex -o figures --tex-font-size 10\n"
                   "  pendulum-figures render fig7 -f eps_tex --tex-sizes absolute --set tick_font_pt=8\n"
                   "\nAnimations (a spec with [animation]; built in: swing, separatrix) are written as " +
                   animation_help() + ". In Beamer: \\usepackage{animate} and "
                   "\\animategraphics[loop,autoplay]{30}{swing}{}{} (30: the spec's fps). A video: ffmpeg -framerate "
                   "30 -i swing-%04d.png -pix_fmt yuv420p swing.mp4\n"
                   "  pendulum-figures render swing --theme slides -f gif,pdf\n"
                   "  pendulum-figures render swing --at 0.25 -f svg");

    bool list_markdown_flag = false;
    auto* list = app.add_subcommand("list", "List the figures, the methods and the plot kinds.");
    list->add_flag("--markdown", list_markdown_flag,
                   "Print the tables in Markdown, with the output formats and themes (as in the README)");
    list->footer("\nExamples:\n  pendulum-figures list\n  pendulum-figures render fig7 -f pdf\n"
                 "  pendulum-figures show fig2 > my-figure.toml");

    std::string claims_format = "csv";
    auto* claims = app.add_subcommand(
        "claims", "Print every quantitative statement of the paper, where it is made, what the tool measures, and "
                  "a verdict.");
    claims->add_option("--format", claims_format, "Output format: csv (default) or json")->type_name("csv|json");
    claims->footer("\nColumns: claim (a short id), where (the paper's section or figure), statement, quantity (what "
                   "is measured), value, unit (%, rad, deg, or empty for orders), verdict. Periods are compared with "
                   "the exact one; deviations of theta are the largest over one exact period.\n\n"
                   "Examples:\n"
                   "  pendulum-figures claims\n"
                   "  pendulum-figures claims --format json");

    std::string show_id;
    std::string show_theme;
    auto* show = app.add_subcommand("show", "Print the spec of a built-in figure, or a theme's style file, to copy "
                                            "and edit.");
    show->add_option("id", show_id, "Figure id or alias (see 'list')")->type_name("ID");
    show->add_option("--theme", show_theme, "Print this built-in theme's style file instead: " +
                                                figures::theme_names())
        ->type_name("NAME")->check(non_empty);
    show->footer("\nThe spec is TOML: [figure], an optional [pendulum], and one [[panel]] per panel. Edit it and "
                 "render it with 'render FILE.toml'.\n\nExample:\n"
                 "  pendulum-figures show fig2 > my-figure.toml\n  pendulum-figures render my-figure.toml -f png\n"
                 "  pendulum-figures show --theme slides > talk.toml\n"
                 "  pendulum-figures render fig7 --theme talk.toml --set tick_font_pt=18");

    plot_options po;
    auto* plot_cmd = app.add_subcommand("plot", "Draw a one-panel figure of any plot kind from the command line.");
    plot_cmd->add_option("kind", po.kind, "trajectory, phase, period, coefficient, convergence or spectrum")
        ->required()
        ->type_name("KIND");
    plot_cmd->add_option("--theta0", po.theta0, "Amplitudes, a comma-separated LIST (one for trajectory)")
        ->type_name("LIST")->check(non_empty);
    plot_cmd->add_option("--methods", po.methods, "Methods, a comma-separated LIST (see 'list')")->type_name("LIST");
    plot_cmd->add_option("--range", po.range, "x range a,b: times, or amplitudes as angles")->type_name("A,B");
    plot_cmd->add_option("--time", po.time, "Time axis of a trajectory: t/T (default) or t/T0")->type_name("UNIT");
    plot_cmd->add_option("--harmonic", po.harmonic, "Coefficient plots: the harmonic 2k+1 (default 1)")
        ->type_name("N");
    plot_cmd->add_option("--y", po.y, "Period plots: value (default), error-percent or error-log")->type_name("AXIS");
    plot_cmd->add_option("--name", po.name, "File name without extension (default: the kind)")->type_name("NAME")->check(non_empty);
    plot_cmd->add_option("-o,--output-dir", po.dir, "Existing directory for the files (default: .)")->type_name("DIR")->check(non_empty);
    plot_cmd->add_option("-f,--formats", po.formats, "Comma-separated formats: " + format_list() + " (default: pdf,png)")
        ->type_name("LIST")->check(non_empty);
    plot_cmd->add_option("--theme", po.theme, figures::theme_help() + "; default paper")->type_name("NAME")->check(non_empty);
    plot_cmd->add_option("--set", po.sets, "KEY=VALUE of a style file on top of the theme; repeatable")
        ->type_name("KEY=VALUE")->check(non_empty);
    plot_cmd->add_option("--dpi", po.dpi, "Resolution of " + raster_formats() + " in dots per inch, 10..2400 (default: "
                                          "the theme's)")
        ->type_name("N");
    plot_cmd->footer(std::string("\n") + angle_help +
                     "\n\nThe same as a spec with one [[panel]] of these keys; 'show' prints specs to start from.\n\n"
                     "Examples:\n"
                     "  pendulum-figures plot trajectory --theta0 170deg --methods exact,harmonic,order:6 --range 0,3\n"
                     "  pendulum-figures plot period --methods exact,kidd-fogg,agm:2 --y error-log -f png\n"
                     "  pendulum-figures plot phase --theta0 'pi/3,2pi/3,0.99pi' --methods exact,first");

    std::string data_id;
    std::string data_file;
    std::string data_theta0;
    auto* data = app.add_subcommand("data", "Print the data of a figure as CSV: panel,series,x,y.");
    data->add_option("id", data_id, "Figure id or alias (see 'list')")->required()->type_name("ID");
    data->add_option("-o,--output", data_file, "Write to FILE instead of standard output (- is standard output)")->type_name("FILE")->check(non_empty);
    data->add_option("--theta0", data_theta0, "Amplitudes of a trajectory figure, a comma-separated LIST")
        ->type_name("LIST")->check(non_empty);
    data->footer("\nOne row per plotted point; panels are a, b, c, ... as in the paper's captions.\n\n"
                 "Example:\n  pendulum-figures data period -o period.csv");

    try {
        app.parse(argc, argv);
        std::ostringstream out;
        if (*render) return run_render(ro);
        if (*plot_cmd) return run_plot(po);
        if (*show) {
            if (show_id.empty() == show_theme.empty()) throw usage_error("give a figure ID or --theme NAME to show");
            if (!show_theme.empty()) {
                out << figures::theme_source(show_theme);
            } else {
                out << figures::find(show_id).source;
            }
        } else if (*list) {
            out << (list_markdown_flag ? list_markdown() : list_text());
        } else if (*data) {
            if (data_file == "-") data_file.clear();  // standard output
            if (!data_file.empty()) {
                // Where the file goes is checked before the work, as render checks its directory.
                std::error_code ec;
                if (std::filesystem::is_directory(data_file, ec)) {
                    throw usage_error("--output '" + data_file + "' is a directory; give a file name");
                }
                const auto parent = std::filesystem::path(data_file).parent_path();
                if (!parent.empty()) check_output_dir(parent.string());
            }
            const std::string csv = figure_data(data_id, data_theta0);
            if (!data_file.empty()) {
                plot::write_atomically(data_file, csv);
                return 0;
            }
            out << csv;
        } else if (*claims) {
            const auto format = cli::parse_table_format(claims_format);
            std::vector<std::vector<cli::field>> rows;
            for (const auto& c : paper_claims()) {
                rows.push_back({c.claim, c.where, c.statement, c.quantity, c.value, c.unit, c.verdict});
            }
            cli::write_records(out, {"claim", "where", "statement", "quantity", "value", "unit", "verdict"}, rows, format);
        } else if (*eval) {
            eval_stream(std::cout, ev);
        } else if (*traj) {
            trajectory_stream(std::cout, tr, order_opt->count() > 0, periods_opt->count() > 0);
        }
        std::cout << out.str() << std::flush;
        if (!std::cout) {
            std::cerr << "pendulum-figures: error: cannot write to standard output\n";
            return 1;
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
                message = "a command is required: eval, trajectory, claims, list, show, render, plot or data (see --help)";
            } else if (argv[1][0] != '-') {
                message = std::string("unknown command '") + argv[1] +
                          "'; commands: eval, trajectory, claims, list, show, render, plot, data (see --help)";
            } else {
                message = std::string("unknown option '") + argv[1] +
                          "'; options before the command are --help and --version (see --help)";
            }
        }
        report_error(message);
        return 2;
    } catch (const cli::usage_error& e) {
        report_error(e.what());
        return 2;
    } catch (const figures::bad_input& e) {
        report_error(e.what());  // includes a spec or style file with problems
        return 2;
    } catch (const plot::bad_input& e) {
        report_error(e.what());  // includes a figure the theme leaves too little room
        return 2;
    } catch (const pendulum::domain_error& e) {
        report_error(e.what());
        return 2;
    } catch (const std::bad_alloc&) {
        report_error("out of memory; a lower --dpi or fewer figures at once need less");
        return 1;
    } catch (const std::exception& e) {
        report_error(e.what());
        return 1;
    }
}
