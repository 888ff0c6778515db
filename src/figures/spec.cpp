// SPDX-License-Identifier: GPL-3.0-or-later
#include "figures/spec.hpp"

#include "figures/data_reader.hpp"
#include "figures/input_file.hpp"
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
constexpr std::string_view common_panel_keys = "plot title x_label y_label y_range paper_file line";
constexpr std::string_view figure_keys = "columns panel_width_cm panel_aspect legend title description style";
constexpr std::string_view pendulum_keys = "length_m g";
constexpr std::string_view top_keys = "figure pendulum animation panel";
constexpr std::string_view animation_keys = "fps periods duration_s speed clock";
constexpr std::string_view line_keys = "x y label style span";
constexpr std::string_view method_keys = "method formula label style color marker";

constexpr std::array<std::pair<std::string_view, legend_mode>, 3> legend_modes = {{
    {"first", legend_mode::first},
    {"each", legend_mode::each},
    {"none", legend_mode::none},
}};

constexpr std::array<std::pair<std::string_view, time_unit>, 3> time_units = {{
    {"t/T", time_unit::period},
    {"t/T0", time_unit::small_period},
    {"t/s", time_unit::seconds},
}};

constexpr std::array<std::pair<std::string_view, period_axis>, 4> period_axes = {{
    {"value", period_axis::value},
    {"error-percent", period_axis::error_percent},
    {"error-log", period_axis::error_log},
    {"residual", period_axis::residual},
}};

constexpr std::array<std::pair<std::string_view, bool>, 2> period_x_axes = {{
    {"amplitude", false},
    {"energy", true},
}};

constexpr std::array<std::pair<std::string_view, bool>, 2> angle_units = {{
    {"rad", false},
    {"deg", true},
}};


/// Where a user's formula may go: a period formula (in theta0) in period panels, a law of
/// motion (in t and theta0) in trajectory panels; empty where it fits, else the problem.
std::string formula_misplaced(const pendulum::method_choice& m, const plot_row& plot) {
    if (!m.user) return {};
    if (m.has_motion() && plot.name != "trajectory") {
        return "formula '" + m.user->text() + "' uses t: it is a law of motion theta(t), whose period is not defined; "
               "use it in a trajectory panel, or write T/T0 in theta0 alone for a " + std::string(plot.name) + " panel";
    }
    if (!m.has_motion() && plot.name != "period") {
        return "formula '" + m.user->text() + "' is a period T/T0 in theta0; use it in a period panel (plot '" +
               std::string(plot.name) + "' needs a law of motion theta(t): a formula in t and theta0)";
    }
    return {};
}

/// The method's name: method = "NAME", or formula = "EXPR" (read as "formula:EXPR").
const toml::node* method_name_node(reader& r, const toml::table& t, const toml::node& n) {
    const toml::node* name_node = t.get("method");
    const toml::node* formula_node = t.get("formula");
    if (name_node && formula_node) {
        r.problem(*formula_node, "a method table takes method = \"NAME\" or formula = \"EXPR\", not both");
        return nullptr;
    }
    if (!name_node && !formula_node) r.problem(n, "a method table needs method = \"NAME\" or formula = \"EXPR\"");
    return name_node ? name_node : formula_node;
}

/// Parses a method's name, reporting a problem (with a guess) at the node.
std::optional<pendulum::method_choice> read_method_name(reader& r, const toml::node& node, const std::string& text) {
    try {
        return pendulum::parse_method(text);
    } catch (const pendulum::domain_error& e) {
        std::vector<std::string> names;
        for (const auto& row : pendulum::method_table()) names.emplace_back(row.name);
        names.emplace_back("formula");
        std::string what = e.what();
        const std::string base = text.substr(0, text.find(':'));
        if (!contains(names, base)) {
            if (const auto guess = suggest(base, names); !guess.empty()) what += "; did you mean " + guess + "?";
        }
        r.problem(node, what);
        return std::nullopt;
    }
}

std::optional<method_spec> read_method(reader& r, const toml::node& n, const plot_row& plot) {
    method_spec m;
    const toml::node* name_node = &n;
    bool formula = false;
    if (const auto* t = n.as_table()) {
        r.check_keys(*t, words(method_keys), "a method table");
        name_node = method_name_node(r, *t, n);
        if (!name_node) return std::nullopt;
        formula = name_node == t->get("formula");
        if (auto label = r.label(*t, "label")) m.label = *label;
        m.style = r.choice(*t, "style", line_styles);
        m.marker = r.choice(*t, "marker", markers);
        if (auto color = r.string(*t, "color")) {
            m.color = parse_color(*color);
            if (!m.color) r.problem(*t->get("color"), "'color' = \"" + *color + "\" is not a colour #rrggbb");
        }
    }
    const auto* s = name_node->as_string();
    if (!s) {
        r.problem(*name_node, formula ? "formula = \"EXPR\" takes a string, e.g. \"1/sqrt(cos(theta0/2))\""
                                      : "a method is a name such as \"exact\" or \"order:6\", or a table with method = NAME");
        return std::nullopt;
    }
    auto chosen = read_method_name(r, *name_node, formula ? "formula:" + s->get() : s->get());
    if (!chosen) return std::nullopt;
    m.method = std::move(*chosen);
    if (const std::string why = formula_misplaced(m.method, plot); !why.empty()) {
        r.problem(*name_node, why);
        return std::nullopt;
    }
    if (plot.needs_motion && !m.method.has_motion()) {
        r.problem(*name_node, "method " + m.method.text() + " gives a period only; plot '" + std::string(plot.name) +
                                  "' needs a law of motion (use it in a period panel)");
        return std::nullopt;
    }
    return m;
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

std::vector<std::string> all_panel_keys() {
    std::vector<std::string> keys = words(common_panel_keys);
    for (const auto& p : plot_table()) {
        for (auto& k : words(p.keys)) {
            if (!contains(keys, k)) keys.push_back(std::move(k));
        }
    }
    return keys;
}

void read_range(reader& r, const toml::table& t, const plot_row& plot, panel_spec& p) {
    const toml::node* n = t.get("range");
    if (!n) return;
    const auto* a = n->as_array();
    if (!a || a->size() != 2) {
        r.problem(*n, "'range' must be a list of two values, [from, to]");
        return;
    }
    std::array<double, 2> v{};
    for (std::size_t i = 0; i < 2; ++i) {
        const toml::node& e = *a->get(i);
        if (plot.range == range_kind::times || p.energy_axis) {
            const char* unit = p.energy_axis ? "an energy range is two numbers, energies E/(m g L), e.g. [0, 4]"
                                             : "a time range is two numbers in the time unit, e.g. [0, 3]";
            if (p.energy_axis && (e.is_number() || e.is_string())) {
                const auto x = r.expression(e, "range", false);
                if (!x) return;
                v[i] = x->second;
            } else if (e.is_number()) {
                v[i] = e.is_integer() ? static_cast<double>(e.as_integer()->get()) : e.as_floating_point()->get();
            } else {
                r.problem(e, unit);
                return;
            }
            if (!std::isfinite(v[i]) || std::fabs(v[i]) > 1e6) {
                r.problem(e, std::string(p.energy_axis ? "an energy" : "a time") +
                                 " in 'range' must be finite and at most 1e6 in size");
                return;
            }
        } else {
            const auto angle = r.angle(e, "range", true);
            if (!angle) return;
            v[i] = angle->value;
        }
    }
    if (!(v[0] < v[1])) {
        r.problem(*n, "'range' must go from a smaller to a larger value");
        return;
    }
    p.range = v;
}

/// The work a panel asks for is bounded before any is done: amplitudes, methods, the
/// iteration's orders on an amplitude axis, and the periods a trajectory draws.
void check_costs(reader& r, const toml::table& t, const figure_spec& f, const panel_spec& p) {
    const auto at = [&](std::string_view key) -> source_position {
        const toml::node* n = t.get(key);
        return n ? r.at(n->source()) : p.where;
    };
    if (p.theta0.size() > max_amplitudes_per_panel) {
        r.problem(at("theta0"), "'theta0' lists " + std::to_string(p.theta0.size()) + " amplitudes; a panel takes at most " +
                                    std::to_string(max_amplitudes_per_panel));
    }
    if (p.methods.size() > max_methods_per_panel) {
        r.problem(at("methods"), "'methods' lists " + std::to_string(p.methods.size()) + " methods; a panel takes at most " +
                                     std::to_string(max_methods_per_panel));
    }
    if (p.plot->amplitudes == amplitude_policy::none) {
        // The iteration to order N at each of the axis' amplitudes: its cost grows with N.
        int orders = 0;
        for (const auto& m : p.methods) {
            if (m.method.row->role == pendulum::method_role::iterated) orders += m.method.n;
        }
        if (orders > max_iteration_orders_per_panel) {
            r.problem(at("methods"), "the orders of the order:N methods add up to " + std::to_string(orders) +
                                         "; on an amplitude axis at most " +
                                         std::to_string(max_iteration_orders_per_panel));
        }
    }
    if (p.plot->range == range_kind::times && p.range) {
        // The most periods the time range can hold, whatever the amplitude (T >= T0).
        const double span = (*p.range)[1] - (*p.range)[0];
        double periods = span;
        if (p.time == time_unit::seconds && f.pendulum) {
            periods = span / static_cast<double>(pendulum::small_period_seconds(f.pendulum->length_m, f.pendulum->g));
        }
        if (!(periods <= max_periods_per_panel)) {
            r.problem(at("range"), "'range' spans up to " + pendulum::format_double(periods) +
                                       " periods; a trajectory panel draws at most " +
                                       std::to_string(max_periods_per_panel));
        }
    }
}

/// The items of a key that takes one value or a list.
std::vector<const toml::node*> items_of(const toml::node& n) {
    std::vector<const toml::node*> items;
    if (const auto* a = n.as_array()) {
        for (const auto& e : *a) items.push_back(&e);
    } else {
        items.push_back(&n);
    }
    return items;
}

/// The starts of a panel: energy = [...] (launches from the bottom) or theta0 = [...] with
/// omega0 = [...] (states, paired item by item, one item on either side going with each of the
/// other), checked against the panel's methods: the approximants describe librations only.
void read_starts(reader& r, const toml::table& t, const plot_row& plot, panel_spec& p) {
    const toml::node* energy = t.get("energy");
    const toml::node* theta0 = t.get("theta0");
    const toml::node* omega0 = t.get("omega0");
    const auto add = [&](const toml::node& where, std::string label, bool is_energy, auto make) {
        try {
            p.starts.push_back({std::move(label), make(), is_energy});
        } catch (const pendulum::domain_error& e) {
            r.problem(where, e.what());
        }
    };
    if (energy) {
        if (theta0 || omega0) {
            r.problem(*energy, "'energy' launches from the bottom: give either energy or theta0 with omega0, not both");
            return;
        }
        for (const toml::node* e : items_of(*energy)) {
            if (auto v = r.expression(*e, "energy", false)) {
                add(*e, "<i>E</i> = " + typeset_angle(v->first), true,
                    [x = v->second] { return pendulum::motion::from_energy(x); });
            }
        }
    } else if (!theta0) {
        r.problem(*omega0, "'omega0' needs theta0, the start angles (theta0 = 0 launches from the bottom)");
        return;
    } else {
        std::vector<std::pair<std::string, double>> angles;
        std::vector<std::pair<std::string, double>> speeds;
        for (const toml::node* e : items_of(*theta0)) {
            if (auto v = r.expression(*e, "theta0", true)) angles.push_back(*v);
        }
        for (const toml::node* e : items_of(*omega0)) {
            if (auto v = r.expression(*e, "omega0", false)) speeds.push_back(*v);
        }
        if (angles.empty() || speeds.empty()) return;
        if (angles.size() != speeds.size() && angles.size() != 1 && speeds.size() != 1) {
            r.problem(*omega0, "theta0 has " + std::to_string(angles.size()) + " values and omega0 " +
                                   std::to_string(speeds.size()) + ": give as many of each, or one of either");
            return;
        }
        for (std::size_t i = 0; i < std::max(angles.size(), speeds.size()); ++i) {
            const auto& [angle_text, angle] = angles[angles.size() == 1 ? 0 : i];
            const auto& [speed_text, speed] = speeds[speeds.size() == 1 ? 0 : i];
            add(*omega0,
                std::string(theta0_markup) + " = " + typeset_angle(angle_text) + ", <i>\u03c9</i><sub>0</sub> = " +
                    typeset_angle(speed_text),
                false, [angle = angle, speed = speed] { return pendulum::motion::from_state({angle, speed}); });
        }
    }
    const toml::node& where = energy ? *energy : *omega0;
    if (plot.amplitudes != amplitude_policy::list && p.starts.size() > 1) {
        r.problem(where, "a " + std::string(plot.name) + " panel takes one start");
    }
    if (p.starts.size() > max_amplitudes_per_panel) {
        r.problem(where, "a panel takes at most " + std::to_string(max_amplitudes_per_panel) + " starts");
    }
}

/// The approximants describe librations only, and the separatrix has no period T to measure
/// time in: each start is checked against the panel's methods and time unit.
void check_starts(reader& r, const toml::table& t, const panel_spec& p) {
    for (const auto& start : p.starts) {
        const auto& row = pendulum::row_of(start.motion.kind());
        const std::string what = plain_text(start.label) + " is a " + std::string(row.name) + " (E = " +
                                 pendulum::format_double(start.motion.energy()) + ")";
        for (const auto& m : p.methods) {
            if (m.method.user) {
                r.problem(t.get("methods") ? r.at(t.get("methods")->source()) : p.where,
                          "method '" + m.method.text() + "' (a formula theta(t) = f(t, theta0)) starts at rest at its "
                          "amplitude: give the panel theta0 = ..., not " + plain_text(start.label));
                continue;
            }
            if (m.method.is_exact() || start.motion.kind() == pendulum::regime::libration) continue;
            r.problem(t.get("methods") ? r.at(t.get("methods")->source()) : p.where,
                      "method '" + m.method.text() + "' describes librations only (E < 2), but " + what +
                          ": use methods = [\"exact\"], or a start with E < 2");
        }
        if (p.plot->range == range_kind::times && p.time == time_unit::period && !start.motion.has_period()) {
            r.problem(t.get("time") ? r.at(t.get("time")->source()) : p.where,
                      what + ": it has no period T; give time = \"t/T0\" or \"t/s\"");
        }
    }
}

/// A period panel against the energy draws the exact period of librations and the revolution
/// of rotations, which no approximation of the paper describes, on energies from 0 up.
void check_energy_axis(reader& r, const toml::table& t, const panel_spec& p) {
    const auto at = [&](std::string_view key) { return t.get(key) ? r.at(t.get(key)->source()) : p.where; };
    for (const auto& m : p.methods) {
        if (m.method.is_exact()) continue;
        r.problem(at("methods"), "x = \"energy\" draws the exact period, across the separatrix where method '" +
                                     m.method.text() + "' has none: use methods = [\"exact\"], or x = \"amplitude\" "
                                     "to compare methods");
    }
    if (p.y != period_axis::value) {
        r.problem(at("y"), "x = \"energy\" draws the period's value: y = \"value\" (the errors of the methods are "
                           "drawn against the amplitude, x = \"amplitude\")");
    }
    if (p.degrees) r.problem(at("angle_unit"), "x = \"energy\" has no angle axis: leave out angle_unit");
    if (p.range && (*p.range)[0] < 0) {
        r.problem(at("range"), "x = \"energy\": 'range' = [" + pendulum::format_double((*p.range)[0]) + ", " +
                                   pendulum::format_double((*p.range)[1]) +
                                   "] goes below 0, the pendulum at rest at the bottom; give energies from 0 up, "
                                   "e.g. [0, 4]");
    }
}

/// residual_of = "METHOD": the reference of a residual panel (any method; default exact).
void read_residual_of(reader& r, const toml::table& t, panel_spec& p) {
    const toml::node* n = t.get("residual_of");
    if (!n) return;
    if (p.y != period_axis::residual) {
        r.problem(*n, "'residual_of' is the reference of a residual panel: give it with y = \"residual\"");
        return;
    }
    if (auto read = read_method(r, *n, *p.plot)) p.residual_of = read->method;
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

std::optional<panel_spec> read_panel(reader& r, const toml::table& t, const figure_spec& f) {
    panel_spec p;
    p.where = r.at(t.source());
    // An empty list is refused before the keys are read: the panel's builders take the first
    // start, amplitude or method of each list.
    if (empty_lists(r, t, "panel")) return std::nullopt;
    const toml::node* plot_node = t.get("plot");
    if (!plot_node || !plot_node->is_string()) {
        r.problem(plot_node ? r.at(plot_node->source()) : p.where,
                  "a panel needs plot = one of " + plot_names());
        return std::nullopt;
    }
    const plot_row* plot = nullptr;
    std::vector<std::string> names;
    for (const auto& row : plot_table()) {
        names.emplace_back(row.name);
        if (row.name == plot_node->as_string()->get()) plot = &row;
    }
    if (!plot) {
        const std::string given = plot_node->as_string()->get();
        std::string what = "unknown plot '" + given + "'; plots: " + listed(names);
        if (const auto guess = suggest(given, names); !guess.empty()) what += "; did you mean " + guess + "?";
        r.problem(*plot_node, what);
        return std::nullopt;
    }
    p.plot = plot;
    const auto keys = panel_keys_of(*plot);
    r.check_keys(t, keys, "a " + std::string(plot->name) + " panel", all_panel_keys(),
                 "does not apply to plot '" + std::string(plot->name) + "'");

    // Amplitudes: one for a trajectory, a list for the plots that draw several; or starts,
    // energies or states, where the plot takes them.
    if (contains(keys, "energy") && (t.get("energy") || t.get("omega0"))) {
        read_starts(r, t, *plot, p);
    } else if (contains(keys, "theta0")) {
        const toml::node* n = t.get("theta0");
        if (!n) {
            r.problem(p.where, "a " + std::string(plot->name) + " panel needs theta0");
        } else if (const auto* a = n->as_array()) {
            if (plot->amplitudes != amplitude_policy::list && a->size() != 1) {
                r.problem(*n, "a " + std::string(plot->name) + " panel takes one theta0");
            } else if (a->empty()) {
                r.problem(*n, "'theta0' lists no amplitude");
            }
            for (const auto& e : *a) {
                if (auto v = r.angle(e, "theta0", false)) p.theta0.push_back(*v);
            }
        } else if (auto v = r.angle(*n, "theta0", false)) {
            p.theta0.push_back(*v);
        }
    }
    const auto x_axis = r.choice(t, "x", period_x_axes);
    if (x_axis) p.energy_axis = *x_axis;
    // Starts (even ones refused above) and the energy axis take the exact method by default;
    // so does a panel whose x axis was refused, which is reported once.
    const auto y_axis = r.choice(t, "y", period_axes);
    const bool exact_by_default = t.get("energy") || t.get("omega0") || p.energy_axis || (t.get("x") && !x_axis) ||
                                  y_axis == period_axis::residual;
    if (plot->name == "period" && t.get("energy")) {
        r.problem(*t.get("energy"), "a period panel draws T/T0 against the energy with x = \"energy\" (and range = "
                                    "[0, 4], say), not with energy = ...");
    }
    if (contains(keys, "methods")) {
        const toml::node* n = t.get("methods");
        if (!n && exact_by_default) {
            // Energies and states: the exact motion, the one method for every regime.
            method_spec exact;
            exact.method = pendulum::parse_method("exact");
            p.methods.push_back(exact);
        } else if (!n) {
            r.problem(p.where, "a " + std::string(plot->name) + " panel needs methods, e.g. [\"exact\", \"lowest\"]");
        } else if (const auto* a = n->as_array(); !a || a->empty()) {
            r.problem(*n, "'methods' must be a non-empty list, e.g. [\"exact\", \"lowest\"]");
        } else {
            int formulas = 0;
            for (const auto& e : *a) {
                auto m = read_method(r, e, *plot);
                if (!m) continue;
                if (m->method.user) m->method.n = ++formulas;  // formula:1, formula:2 in panel order
                p.methods.push_back(std::move(*m));
            }
        }
    }
    if (auto v = r.choice(t, "time", time_units)) {
        p.time = *v;
        if (p.time == time_unit::seconds && !f.pendulum) {
            r.problem(*t.get("time"), "time = \"t/s\" needs a [pendulum] table with length_m");
        }
    }
    read_range(r, t, *plot, p);
    if (const toml::node* n = t.get("y_range")) {
        const auto* a = n->as_array();
        if (!a || a->size() != 2 || !a->get(0)->is_number() || !a->get(1)->is_number()) {
            r.problem(*n, "'y_range' must be two numbers, [from, to]");
        } else {
            const auto value = [](const toml::node& e) {
                return e.is_integer() ? static_cast<double>(e.as_integer()->get()) : e.as_floating_point()->get();
            };
            const double lo = value(*a->get(0));
            const double hi = value(*a->get(1));
            // Ranges the tick labels can tell apart: values within 1e300, a span of 1e-300 at
            // least and of 1e-9 of the largest magnitude.
            const double span = hi - lo;
            if (!(std::isfinite(lo) && std::isfinite(hi) && lo < hi)) {
                r.problem(*n, "'y_range' must go from a smaller to a larger finite value");
            } else if (!(std::fabs(lo) <= 1e300 && std::fabs(hi) <= 1e300 && span >= 1e-300 &&
                         span >= 1e-9 * std::max(std::fabs(lo), std::fabs(hi)))) {
                r.problem(*n, "'y_range' = [" + pendulum::format_double(lo) + ", " + pendulum::format_double(hi) +
                                  "] cannot be labelled: values must be within -1e300 to 1e300, and the span at "
                                  "least 1e-300 and at least 1e-9 of the largest magnitude");
            } else {
                p.y_range = std::array<double, 2>{lo, hi};
            }
        }
    }
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
    if (y_axis) p.y = *y_axis;
    read_residual_of(r, t, p);
    if (auto v = r.integer(t, "harmonic", 1, 99)) {
        if (*v % 2 == 0) {
            r.problem(*t.get("harmonic"), "'harmonic' must be odd (1, 3, 5, ...): the even coefficients vanish");
        } else {
            p.harmonic = *v;
        }
    }
    if (auto v = r.integer(t, "harmonics", 1, 100)) p.harmonics = *v;
    if (const toml::node* n = t.get("orders")) {
        const auto* a = n->as_array();
        if (!a || a->size() != 2 || !a->get(0)->is_integer() || !a->get(1)->is_integer()) {
            r.problem(*n, "'orders' must be two whole numbers, [first, last]");
        } else {
            const auto lo = a->get(0)->as_integer()->get();
            const auto hi = a->get(1)->as_integer()->get();
            if (lo < 0 || hi > pendulum::max_order || lo >= hi) {
                r.problem(*n, "'orders' must satisfy 0 <= first < last <= " + std::to_string(pendulum::max_order));
            } else {
                p.orders = {static_cast<int>(lo), static_cast<int>(hi)};
            }
        }
    }
    if (auto v = r.boolean(t, "separatrix")) p.separatrix = *v;
    if (auto v = r.number(t, "trail", 0.0, 10.0)) p.trail = *v;
    if (auto v = r.choice(t, "angle_unit", angle_units)) p.degrees = *v;
    if (const toml::node* n = t.get("line")) {
        const auto* a = n->as_array();
        if (!a || !a->is_array_of_tables()) {
            r.problem(*n, "reference lines are [[panel.line]] tables");
        } else {
            for (const auto& e : *a) {
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
                p.lines.push_back(line);
            }
        }
    }
    read_panel_data(r, t, f, p);
    check_costs(r, t, f, p);
    check_starts(r, t, p);
    if (p.energy_axis) check_energy_axis(r, t, p);
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
    // Edit distance with transpositions (optimal string alignment); a name within a third of
    // the word's length (at least 1) is a likely typo.
    // A word far longer than any name is no typo of one (and would cost length squared).
    if (word.size() > 64) return {};
    std::string best;
    std::size_t best_d = std::max<std::size_t>(1, word.size() / 3) + 1;
    for (const auto& name : names) {
        const std::size_t m = word.size();
        const std::size_t n = name.size();
        std::vector<std::vector<std::size_t>> d(m + 1, std::vector<std::size_t>(n + 1));
        for (std::size_t i = 0; i <= m; ++i) d[i][0] = i;
        for (std::size_t j = 0; j <= n; ++j) d[0][j] = j;
        for (std::size_t i = 1; i <= m; ++i) {
            for (std::size_t j = 1; j <= n; ++j) {
                const std::size_t cost = word[i - 1] == name[j - 1] ? 0 : 1;
                d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
                if (i > 1 && j > 1 && word[i - 1] == name[j - 2] && word[i - 2] == name[j - 1]) {
                    d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
                }
            }
        }
        if (d[m][n] < best_d) {
            best_d = d[m][n];
            best = name;
        }
    }
    return best;
}

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

    if (const toml::node* n = doc.get("figure")) {
        if (const auto* t = n->as_table()) {
            r.check_keys(*t, words(figure_keys), "[figure]");
            f.columns = r.integer(*t, "columns", 1, 6);
            f.panel_width_cm = r.number(*t, "panel_width_cm", 1.0, 100.0);
            f.panel_aspect = r.number(*t, "panel_aspect", 0.1, 10.0);
            if (auto v = r.choice(*t, "legend", legend_modes)) f.legend = *v;
            if (auto v = r.label(*t, "title")) f.title = *v;
            if (auto v = r.string(*t, "description")) f.description = *v;
            if (auto v = r.string(*t, "style")) read_style(r, *t->get("style"), *v, f);
        } else {
            r.problem(*n, "'figure' must be a table: [figure]");
        }
    }
    if (const toml::node* n = doc.get("pendulum")) {
        if (const auto* t = n->as_table()) {
            r.check_keys(*t, words(pendulum_keys), "[pendulum]");
            pendulum_spec p;
            if (!t->contains("length_m")) r.problem(*n, "[pendulum] needs length_m");
            if (auto v = r.number(*t, "length_m", 0.0, 1e6, true)) p.length_m = *v;
            if (auto v = r.number(*t, "g", 0.0, 1e4, true)) p.g = *v;
            f.pendulum = p;
        } else {
            r.problem(*n, "'pendulum' must be a table: [pendulum]");
        }
    }
    if (const toml::node* n = doc.get("animation")) {
        if (const auto* t = n->as_table()) {
            r.check_keys(*t, words(animation_keys), "[animation]");
            animation_spec a;
            if (auto v = r.number(*t, "fps", 1, 120)) a.fps = *v;
            a.periods = r.number(*t, "periods", 0.0, 1e4, true);
            a.duration_s = r.number(*t, "duration_s", 0.0, 1e5, true);
            if (auto v = r.number(*t, "speed", 0.0, 1e4, true)) a.speed = *v;
            if (auto v = r.boolean(*t, "clock")) a.clock = *v;
            if (t->contains("periods") && t->contains("duration_s")) {
                r.problem(*n, "[animation] takes periods or duration_s, not both");
            } else if (t->contains("duration_s") && !f.pendulum) {
                r.problem(*t->get("duration_s"), "duration_s needs a [pendulum] table with length_m");
            }
            if (!a.periods && !a.duration_s && !t->contains("periods") && !t->contains("duration_s")) a.periods = 1.0;
            f.animation = a;
        } else {
            r.problem(*n, "'animation' must be a table: [animation]");
        }
    }
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
        return "leads out of the spec's directory (through a symbolic link); a spec's style file stays inside it";
    }
    return {};
}

figure_spec load_spec(const std::filesystem::path& path) {
    return parse_spec(read_input_file(path, "spec file"), path.string());
}

}  // namespace figures
