// SPDX-License-Identifier: GPL-3.0-or-later
#include "figures/spec.hpp"

#include "common/suggest.hpp"
#include "figures/data_reader.hpp"
#include "figures/input_file.hpp"
#include "figures/panel_keys.hpp"
#include "figures/panel_support.hpp"
#include "figures/toml_reader.hpp"
#include "plot/latex_overlay.hpp"
#include "pendulum/amplitude.hpp"
#include "pendulum/angle.hpp"
#include "pendulum/formula.hpp"
#include "pendulum/seconds.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <fstream>
#include <sstream>

namespace figures {

std::string spec_problem::text() const {
    std::string out = where.file;
    if (where.line > 0) out += ":" + std::to_string(where.line) + ":" + std::to_string(where.column);
    return out + ": " + what;
}

namespace {

std::string join_problems(const std::vector<spec_problem>& problems) {
    std::string out;
    for (const auto& p : problems) {
        if (!out.empty()) out += '\n';
        out += p.text();
    }
    return out;
}

/// Keys every panel takes.
constexpr std::string_view common_panel_keys = "plot title x_label y_label y_range paper_y_range paper_file line";
constexpr std::string_view figure_keys = "columns panel_width_cm panel_aspect legend title description style";
constexpr std::string_view pendulum_keys = "length_m g";
constexpr std::string_view top_keys = "figure pendulum animation panel";
constexpr std::string_view animation_keys = "fps periods duration_s speed clock loop";
constexpr std::string_view line_keys = "x y label style span";

constexpr std::array<std::pair<std::string_view, legend_mode>, 3> legend_modes = {{
    {"first", legend_mode::first},
    {"each", legend_mode::each},
    {"none", legend_mode::none},
}};

/// The names of loop_rows, as the reader's choice takes them.
constexpr std::array<std::pair<std::string_view, loop_mode>, loop_rows.size()> loop_choices() {
    std::array<std::pair<std::string_view, loop_mode>, loop_rows.size()> out{};
    for (std::size_t i = 0; i < loop_rows.size(); ++i) out[i] = {loop_rows[i].name, loop_rows[i].mode};
    return out;
}

/// A reference line's span: two numbers or expressions ("pi/2"), the first below the second.
std::optional<std::array<double, 2>> read_span(reader& r, const toml::node& n) {
    const auto* a = n.as_array();
    const char* what = "'span' must be two values [from, to] along the other axis, numbers or expressions such as \"pi/2\"";
    if (!a || a->size() != 2) {
        r.problem(n, what);
        return std::nullopt;
    }
    std::array<double, 2> v{};
    for (std::size_t i = 0; i < 2; ++i) {
        const toml::node& e = *a->get(i);
        try {
            if (const auto* s = e.as_string()) {
                v[i] = pendulum::parse_expression(s->get());
            } else if (auto d = e.value<double>()) {
                v[i] = *d;
            } else {
                r.problem(e, what);
                return std::nullopt;
            }
        } catch (const std::exception& err) {
            r.problem(e, std::string("'span': ") + err.what());
            return std::nullopt;
        }
        if (!std::isfinite(v[i]) || std::fabs(v[i]) > 1e300) {
            r.problem(e, "'span' values lie within 1e300");
            return std::nullopt;
        }
    }
    if (!(v[0] < v[1])) {
        r.problem(n, "'span' = [from, to] needs from < to");
        return std::nullopt;
    }
    return v;
}

std::vector<std::string> panel_keys_of(const plot_row& plot) {
    auto keys = words(common_panel_keys);
    for (auto& k : words(plot.keys)) keys.push_back(std::move(k));
    return keys;
}

/// Reports every empty list under `n` (the value of `key`), the lists of [[panel.line]]
/// tables too: no list key of any panel means anything empty. True if there was one.
bool empty_lists(reader& r, const toml::node& n, std::string_view key) {
    bool any = false;
    if (const auto* a = n.as_array()) {
        if (a->empty()) {
            r.problem(n, "'" + std::string(key) + "' is an empty list; give at least one value, or leave the key out");
            return true;
        }
        for (const auto& e : *a) any = empty_lists(r, e, key) || any;
    } else if (const auto* t = n.as_table()) {
        for (const auto& [k, v] : *t) any = empty_lists(r, v, k.str()) || any;
    }
    return any;
}

/// [figure] style: a style file NAME.toml inside the spec's directory (its tree; a symbolic
/// link leading out of it is refused when the spec is loaded, see load_spec).
void read_style(reader& r, const toml::node& n, const std::string& v, figure_spec& f) {
    const std::filesystem::path given(v);
    if (!v.ends_with(".toml") || v.size() == 5) {
        r.problem(n, "'style' names a style file NAME.toml, relative to the spec; a built-in theme is chosen with --theme");
    } else if (given.is_absolute() || given.has_root_name() || given.has_root_directory()) {
        r.problem(n, "'style' must be a path relative to the spec's directory, not an absolute path");
    } else if (const auto normal = given.lexically_normal(); normal.empty() || *normal.begin() == "..") {
        r.problem(n, "'style' must stay inside the spec's directory: no '..' leading out of it");
    } else {
        // Resolved now, through symbolic links: a link in the spec's tree may lead anywhere.
        const auto dir = std::filesystem::path(r.file()).parent_path();
        const auto style = dir / normal;
        if (const std::string why = outside_problem(dir.empty() ? "." : dir, style); !why.empty()) {
            r.problem(n, "'style' = \"" + v + "\" " + why);
        } else {
            f.style = style.string();
        }
    }
}

/// y_range or paper_y_range (`key`) = [from, to]: two numbers the tick labels can tell apart.
void read_y_range(reader& r, const toml::table& t, const std::string& key, std::optional<std::array<double, 2>>& out) {
    const toml::node* n = t.get(key);
    if (!n) return;
    const auto* a = n->as_array();
    if (!a || a->size() != 2 || !a->get(0)->is_number() || !a->get(1)->is_number()) {
        r.problem(*n, "'" + key + "' must be two numbers, [from, to]");
        return;
    }
    const auto value = [](const toml::node& e) {
        return e.is_integer() ? static_cast<double>(e.as_integer()->get()) : e.as_floating_point()->get();
    };
    const double lo = value(*a->get(0));
    const double hi = value(*a->get(1));
    // Ranges the tick labels can tell apart: values within 1e300, a span of 1e-300 at
    // least and of 1e-9 of the largest magnitude.
    const double span = hi - lo;
    if (!(std::isfinite(lo) && std::isfinite(hi) && lo < hi)) {
        r.problem(*n, "'" + key + "' must go from a smaller to a larger finite value");
    } else if (!(std::fabs(lo) <= 1e300 && std::fabs(hi) <= 1e300 && span >= 1e-300 &&
                 span >= 1e-9 * std::max(std::fabs(lo), std::fabs(hi)))) {
        r.problem(*n, "'" + key + "' = [" + pendulum::format_double(lo) + ", " + pendulum::format_double(hi) +
                          "] cannot be labelled: values must be within -1e300 to 1e300, and the span at "
                          "least 1e-300 and at least 1e-9 of the largest magnitude");
    } else {
        out = std::array<double, 2>{lo, hi};
    }
}

/// One [[panel.line]] table.
reference_line read_line(reader& r, const toml::node& e) {
    const auto& lt = *e.as_table();
    r.check_keys(lt, words(line_keys), "a [[panel.line]]");
    reference_line line;
    line.x = r.number(lt, "x", -1e300, 1e300);
    line.y = r.number(lt, "y", -1e300, 1e300);
    if (line.x.has_value() == line.y.has_value() && (lt.contains("x") == lt.contains("y"))) {
        r.problem(e, "a reference line has either x = ... or y = ...");
    }
    if (auto label = r.label(lt, "label")) line.label = *label;
    if (auto style = r.choice(lt, "style", line_styles)) line.style = *style;
    if (const toml::node* sn = lt.get("span")) line.span = read_span(r, *sn);
    return line;
}

/// [[panel.line]]: reference lines.
void read_lines(reader& r, const toml::table& t, panel_spec& p) {
    const toml::node* n = t.get("line");
    if (!n) return;
    const auto* a = n->as_array();
    if (!a || !a->is_array_of_tables()) {
        r.problem(*n, "reference lines are [[panel.line]] tables");
        return;
    }
    for (const auto& e : *a) p.lines.push_back(read_line(r, e));
}

/// The keys every panel takes besides plot: title, axis labels, y range, paper file, lines.
void read_common_keys(reader& r, const toml::table& t, panel_spec& p) {
    read_y_range(r, t, "y_range", p.y_range);
    read_y_range(r, t, "paper_y_range", p.paper_y_range);
    p.title = r.label(t, "title");
    p.x_label = r.label(t, "x_label");
    p.y_label = r.label(t, "y_label");
    if (auto v = r.string(t, "paper_file")) {
        if (const std::string why = file_name_problem(*v); !why.empty()) {
            r.problem(*t.get("paper_file"), "'paper_file' " + why);
        } else {
            p.paper_file = *v;
        }
    }
    read_lines(r, t, p);
}

/// The kind named by the panel's plot key, or null (reported).
const plot_row* read_plot(reader& r, const toml::table& t, const source_position& where) {
    const toml::node* plot_node = t.get("plot");
    if (!plot_node || !plot_node->is_string()) {
        r.problem(plot_node ? r.at(plot_node->source()) : where, "a panel needs plot = one of " + plot_names());
        return nullptr;
    }
    const std::string given = plot_node->as_string()->get();
    if (const plot_row* plot = find_plot(given)) return plot;
    std::vector<std::string> names;
    for (const auto& row : plot_table()) names.emplace_back(row.name);
    std::string what = "unknown plot '" + given + "'; plots: " + listed(names);
    if (const auto guess = suggest(given, names); !guess.empty()) what += "; did you mean " + guess + "?";
    r.problem(*plot_node, what);
    return nullptr;
}

/// The problem of a key of other kinds given to a `plot` panel, naming the kinds that take
/// it; empty for a key no kind takes.
std::string key_elsewhere(const plot_row& plot, const std::string& key) {
    std::vector<std::string> takers;
    for (const auto& row : plot_table()) {
        if (contains(words(row.keys), key)) takers.emplace_back(row.name);
    }
    if (takers.empty()) return {};
    return "key '" + key + "' does not apply to plot '" + std::string(plot.name) + "'; " +
           (takers.size() == 1 ? "plot " : "plots ") + listed(takers) + (takers.size() == 1 ? " takes it" : " take it");
}

std::optional<panel_spec> read_panel(reader& r, const toml::table& t, const figure_spec& f) {
    panel_spec p;
    p.where = r.at(t.source());
    // An empty list is refused before the keys are read: the panel's builders take the first
    // start, amplitude or method of each list.
    if (empty_lists(r, t, "panel")) return std::nullopt;
    p.plot = read_plot(r, t, p.where);
    if (!p.plot) return std::nullopt;
    const plot_row& plot = *p.plot;
    r.check_keys(t, panel_keys_of(plot), "a " + std::string(plot.name) + " panel",
                 [&plot](const std::string& key) { return key_elsewhere(plot, key); });
    key_reading k{r, t, f, p};
    plot.read_keys(k);
    read_common_keys(r, t, p);
    check_panel(k);
    return p;
}

}  // namespace

std::string file_name_problem(std::string_view name) {
    static constexpr std::string_view allowed_characters = "letters, digits and . _ + -";
    if (name.empty()) return "is empty; give a file name such as Fig.C1.Lowest";
    if (name.size() > max_file_name_bytes) {
        return "has " + std::to_string(name.size()) + " characters; at most " + std::to_string(max_file_name_bytes);
    }
    for (const char c : name) {
        if (!plot::plain_file_name_character(c)) {
            const auto u = static_cast<unsigned char>(c);
            char shown[16];
            std::snprintf(shown, sizeof shown, u < 0x20 || u >= 0x7f ? "\\x%02x" : "'%c'", u);
            return std::string("has the character ") + shown + ": a file name here is " + std::string(allowed_characters) +
                   ", without a directory";
        }
    }
    if (name[0] == '.' || name[0] == '-') return "must not start with '" + std::string(1, name[0]) + "'";
    if (name.find("..") != std::string_view::npos) return "must not contain '..'";
    return {};
}

spec_error::spec_error(std::vector<spec_problem> problems)
    : bad_input(join_problems(problems)), problems_(std::move(problems)) {}

std::string suggest(std::string_view word, const std::vector<std::string>& names) {
    // A name within a third of the word's length (at least 1) is a likely typo.
    return common::nearest_name(word, names, std::max<std::size_t>(1, word.size() / 3) + 1);
}

namespace {

/// [figure]: columns, sizes, legend, title, description, style.
void read_figure_table(reader& r, const toml::node& n, figure_spec& f) {
    const auto* t = n.as_table();
    if (!t) {
        r.problem(n, "'figure' must be a table: [figure]");
        return;
    }
    r.check_keys(*t, words(figure_keys), "[figure]");
    f.columns = r.integer(*t, "columns", 1, 6);
    f.panel_width_cm = r.number(*t, "panel_width_cm", 1.0, 100.0);
    f.panel_aspect = r.number(*t, "panel_aspect", 0.1, 10.0);
    if (auto v = r.choice(*t, "legend", legend_modes)) f.legend = *v;
    if (auto v = r.label(*t, "title")) f.title = *v;
    if (auto v = r.string(*t, "description")) f.description = *v;
    if (auto v = r.string(*t, "style")) read_style(r, *t->get("style"), *v, f);
}

/// [pendulum]: length_m and g.
void read_pendulum_table(reader& r, const toml::node& n, figure_spec& f) {
    const auto* t = n.as_table();
    if (!t) {
        r.problem(n, "'pendulum' must be a table: [pendulum]");
        return;
    }
    r.check_keys(*t, words(pendulum_keys), "[pendulum]");
    pendulum_spec p;
    if (!t->contains("length_m")) r.problem(n, "[pendulum] needs length_m");
    if (auto v = r.number(*t, "length_m", 0.0, 1e6, true)) p.length_m = *v;
    if (auto v = r.number(*t, "g", 0.0, 1e4, true)) p.g = *v;
    f.pendulum = p;
}

/// [animation]: frame rate, length (periods or seconds), speed, clock, loop.
void read_animation_table(reader& r, const toml::node& n, figure_spec& f) {
    const auto* t = n.as_table();
    if (!t) {
        r.problem(n, "'animation' must be a table: [animation]");
        return;
    }
    r.check_keys(*t, words(animation_keys), "[animation]");
    animation_spec a;
    if (auto v = r.number(*t, "fps", 1, 120)) a.fps = *v;
    a.periods = r.number(*t, "periods", 0.0, 1e4, true);
    a.duration_s = r.number(*t, "duration_s", 0.0, 1e5, true);
    if (auto v = r.number(*t, "speed", 0.0, 1e4, true)) a.speed = *v;
    if (auto v = r.boolean(*t, "clock")) a.clock = *v;
    a.loop = r.choice(*t, "loop", loop_choices());
    const bool periods = t->contains("periods");
    const bool duration = t->contains("duration_s");
    if (periods && duration) {
        r.problem(n, "[animation] takes periods or duration_s, not both");
    } else if (duration && !f.pendulum) {
        r.problem(*t->get("duration_s"), "duration_s needs a [pendulum] table with length_m");
    }
    f.animation = a;
}

/// [[panel]]: one to max_panels panels.
void read_panels(reader& r, const toml::table& doc, const std::string& file, figure_spec& f) {
    const toml::node* panels = doc.get("panel");
    const auto* list = panels ? panels->as_array() : nullptr;
    if (!panels) {
        r.problem(source_position{file, 0, 0}, "the spec has no [[panel]]");
    } else if (!list || !list->is_array_of_tables()) {
        r.problem(*panels, "panels are [[panel]] tables");
    } else if (list->size() > static_cast<std::size_t>(max_panels)) {
        r.problem(*panels, "a figure has at most " + std::to_string(max_panels) + " panels, (a) to (z)");
    } else {
        for (const auto& e : *list) {
            if (auto p = read_panel(r, *e.as_table(), f)) f.panels.push_back(std::move(*p));
        }
    }
}

}  // namespace

figure_spec parse_spec(std::string_view text, const std::string& file) {
    reader r(file);
    figure_spec f;
    f.id = std::filesystem::path(file).stem().string();
    toml::table doc;
    try {
        doc = parse_toml(text, file);
    } catch (const toml::parse_error& e) {
        throw spec_error({{r.at(e.source()), "not valid TOML: " + std::string(e.description())}});
    }
    r.check_keys(doc, words(top_keys), "the spec (tables: [figure], [pendulum], [animation], [[panel]])");
    if (const toml::node* n = doc.get("figure")) read_figure_table(r, *n, f);
    if (const toml::node* n = doc.get("pendulum")) read_pendulum_table(r, *n, f);
    if (const toml::node* n = doc.get("animation")) read_animation_table(r, *n, f);
    read_panels(r, doc, file, f);
    auto& problems = r.problems();
    if (!problems.empty()) {
        std::stable_sort(problems.begin(), problems.end(), [](const spec_problem& a, const spec_problem& b) {
            return std::tie(a.where.line, a.where.column) < std::tie(b.where.line, b.where.column);
        });
        throw spec_error(std::move(problems));
    }
    return f;
}

std::string outside_problem(const std::filesystem::path& tree, const std::filesystem::path& file) {
    std::error_code ec;
    const auto root = std::filesystem::weakly_canonical(std::filesystem::absolute(tree, ec), ec);
    const auto target = ec ? std::filesystem::path()
                           : std::filesystem::weakly_canonical(std::filesystem::absolute(file, ec), ec);
    if (ec) return "cannot be resolved: " + ec.message();
    const auto relative = target.lexically_relative(root);
    if (relative.empty() || *relative.begin() == "..") {
        return "leads out of the spec's directory (through a symbolic link); a spec's style and data files stay inside it";
    }
    return {};
}

figure_spec load_spec(const std::filesystem::path& path) {
    return parse_spec(read_input_file(path, "spec file"), path.string());
}

}  // namespace figures
