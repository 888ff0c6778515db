// SPDX-License-Identifier: GPL-3.0-or-later
#include "figures/panel_keys.hpp"

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

namespace {

constexpr std::string_view method_keys = "method formula label style color marker";

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


/// The names of the kinds whose rows satisfy `fits`, "a, b or c".
template <class Fits>
std::string kinds_where(Fits fits, std::string_view last_word = "or") {
    std::vector<std::string> names;
    for (const auto& row : plot_table()) {
        if (fits(row)) names.emplace_back(row.name);
    }
    std::string out;
    for (std::size_t i = 0; i < names.size(); ++i) {
        if (i > 0) out += i + 1 == names.size() ? " " + std::string(last_word) + " " : ", ";
        out += names[i];
    }
    return out;
}

/// A kind where a method that gives a period only fits.
bool period_only_fits(const plot_row& row) { return !row.needs_motion; }

/// Where a user's formula may go: a period formula (in theta0) in the kinds that take period
/// formulas, a law of motion (in t and theta0) in those that take laws of motion; empty where
/// it fits, else the problem.
std::string formula_misplaced(const pendulum::method_choice& m, const plot_row& plot) {
    if (!m.user) return {};
    if (m.has_motion() && plot.formulas != formula_kind::law_of_motion) {
        return "formula '" + m.user->text() + "' uses t: it is a law of motion theta(t), whose period is not defined; "
               "use it in a " + kinds_taking(formula_kind::law_of_motion) + " panel, or write T/T0 in theta0 alone for a " +
               std::string(plot.name) + " panel";
    }
    if (!m.has_motion() && plot.formulas != formula_kind::period) {
        return "formula '" + m.user->text() + "' is a period T/T0 in theta0; use it in a " +
               kinds_taking(formula_kind::period) + " panel (plot '" + std::string(plot.name) +
               "' needs a law of motion theta(t): a formula in t and theta0)";
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
                                  "' needs a law of motion (use it in a " + kinds_where(period_only_fits) + " panel)");
        return std::nullopt;
    }
    return m;
}

/// One value of a time or energy range, or nothing (its problem reported).
std::optional<double> range_time_or_energy(reader& r, const toml::node& e, bool energy_axis) {
    double v = 0;
    if (energy_axis && (e.is_number() || e.is_string())) {
        const auto x = r.expression(e, "range", false);
        if (!x) return std::nullopt;
        v = x->second;
    } else if (e.is_number()) {
        v = e.is_integer() ? static_cast<double>(e.as_integer()->get()) : e.as_floating_point()->get();
    } else {
        r.problem(e, energy_axis ? "an energy range is two numbers, energies E/(m g L), e.g. [0, 4]"
                                 : "a time range is two numbers in the time unit, e.g. [0, 3]");
        return std::nullopt;
    }
    if (!std::isfinite(v) || std::fabs(v) > 1e6) {
        r.problem(e, std::string(energy_axis ? "an energy" : "a time") +
                         " in 'range' must be finite and at most 1e6 in size");
        return std::nullopt;
    }
    return v;
}

/// One value of a panel's range: a time, an energy, or an angle; nothing if refused.
std::optional<double> range_value(reader& r, const toml::node& e, const panel_spec& p) {
    if (p.plot->range == range_kind::times || p.energy_axis) return range_time_or_energy(r, e, p.energy_axis);
    const auto angle = r.angle(e, "range", true);
    if (!angle) return std::nullopt;
    return angle->value;
}

/// Where a key is, or the panel's header without it.
source_position key_place(const key_reading& k, std::string_view key) {
    const toml::node* n = k.t.get(key);
    return n ? k.r.at(n->source()) : k.p.where;
}

/// The iteration to order N at each of an amplitude axis' amplitudes: its cost grows with N.
void check_iteration_orders(key_reading& k) {
    if (k.p.plot->amplitudes != amplitude_policy::none) return;
    int orders = 0;
    for (const auto& m : k.p.methods) {
        if (m.method.row->role == pendulum::method_role::iterated) orders += m.method.n;
    }
    if (orders > max_iteration_orders_per_panel) {
        k.r.problem(key_place(k, "methods"), "the orders of the order:N methods add up to " + std::to_string(orders) +
                                                 "; on an amplitude axis at most " +
                                                 std::to_string(max_iteration_orders_per_panel));
    }
}

/// The most periods a time range can hold, whatever the amplitude (T >= T0).
void check_time_range(key_reading& k) {
    const panel_spec& p = k.p;
    if (p.plot->range != range_kind::times || !p.range) return;
    const double span = (*p.range)[1] - (*p.range)[0];
    double periods = span;
    if (p.time == time_unit::seconds && k.f.pendulum) {
        periods = span / static_cast<double>(pendulum::small_period_seconds(k.f.pendulum->length_m, k.f.pendulum->g));
    }
    if (!(periods <= max_periods_per_panel)) {
        k.r.problem(key_place(k, "range"), "'range' spans up to " + pendulum::format_double(periods) + " periods; a " +
                                               std::string(p.plot->name) + " panel draws at most " +
                                               std::to_string(max_periods_per_panel));
    }
}

/// The work a panel asks for is bounded before any is done: amplitudes, methods, the
/// iteration's orders on an amplitude axis, and the periods a time range holds.
void check_costs(key_reading& k) {
    const panel_spec& p = k.p;
    if (p.theta0.size() > max_amplitudes_per_panel) {
        k.r.problem(key_place(k, "theta0"), "'theta0' lists " + std::to_string(p.theta0.size()) +
                                                " amplitudes; a panel takes at most " +
                                                std::to_string(max_amplitudes_per_panel));
    }
    if (p.methods.size() > max_methods_per_panel) {
        k.r.problem(key_place(k, "methods"), "'methods' lists " + std::to_string(p.methods.size()) +
                                                 " methods; a panel takes at most " +
                                                 std::to_string(max_methods_per_panel));
    }
    check_iteration_orders(k);
    check_time_range(k);
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

/// Adds a start made by `make`, or reports the core's refusal of it at `where`.
template <class Make>
void add_start(key_reading& k, const toml::node& where, std::string label, bool is_energy, Make make) {
    try {
        k.p.starts.push_back({std::move(label), make(), is_energy});
    } catch (const pendulum::domain_error& e) {
        k.r.problem(where, e.what());
    }
}

/// An energy with its unit, as TeX sets $E = 1\,mgL$: a thin space (U+2009, \\, in LaTeX, a
/// space in plain text) between the number and mgL. The one source of the energy text in
/// legends, titles and descriptions, in every route.
std::string energy_markup(const std::string& text) {
    return "<i>E</i> = " + typeset_angle(text) + "\u2009<i>mgL</i>";
}

/// energy = [...]: launches from the bottom.
void read_energy_starts(key_reading& k, const toml::node& energy) {
    for (const toml::node* e : items_of(energy)) {
        if (auto v = k.r.expression(*e, "energy", false)) {
            add_start(k, *e, energy_markup(v->first), true,
                      [text = v->first] { return pendulum::motion::from_energy(pendulum::written_number::expression(text)); });
        }
    }
}

/// The expressions of a key that takes one value or a list, those that are valid.
std::vector<std::pair<std::string, double>> expressions_of(key_reading& k, const toml::node& n, std::string_view key,
                                                           bool is_angle) {
    std::vector<std::pair<std::string, double>> out;
    for (const toml::node* e : items_of(n)) {
        if (auto v = k.r.expression(*e, key, is_angle)) out.push_back(*v);
    }
    return out;
}

/// theta0 = [...] with omega0 = [...]: states, paired item by item, one item on either side
/// going with each of the other.
void read_state_starts(key_reading& k, const toml::node& theta0, const toml::node& omega0) {
    const auto angles = expressions_of(k, theta0, "theta0", true);
    const auto speeds = expressions_of(k, omega0, "omega0", false);
    if (angles.empty() || speeds.empty()) return;
    if (angles.size() != speeds.size() && angles.size() != 1 && speeds.size() != 1) {
        k.r.problem(omega0, "theta0 has " + std::to_string(angles.size()) + " values and omega0 " +
                                std::to_string(speeds.size()) + ": give as many of each, or one of either");
        return;
    }
    for (std::size_t i = 0; i < std::max(angles.size(), speeds.size()); ++i) {
        const auto& [angle_text, angle] = angles[angles.size() == 1 ? 0 : i];
        const auto& [speed_text, speed] = speeds[speeds.size() == 1 ? 0 : i];
        add_start(k, omega0,
                  // omega0 is the launch velocity in units of the natural frequency w0 = sqrt(g/L), which
                  // the phase axis calls w0 too: the title says so, theta'(0) = 1.9 w0.
                  std::string(theta0_markup) + " = " + typeset_angle(angle_text) + ", <i>\u03d1</i>\u2032(0) = " +
                      typeset_angle(speed_text) + " <i>\u03c9</i><sub>0</sub>",
                  false, [&angle_text = angle_text, &speed_text = speed_text] {
                      // As written, as the command line reads them: pi-1e-9 keeps its distance from pi,
                      // 2pi/3 with 1 is the separatrix.
                      return pendulum::motion::from_state(pendulum::written_number::angle(angle_text),
                                                          pendulum::written_number::expression(speed_text));
                  });
    }
}

/// The starts of a panel: energy = [...] (launches from the bottom) or theta0 = [...] with
/// omega0 = [...] (states), as many as the kind takes.
void read_starts(key_reading& k) {
    const toml::node* energy = k.t.get("energy");
    const toml::node* theta0 = k.t.get("theta0");
    const toml::node* omega0 = k.t.get("omega0");
    if (energy && (theta0 || omega0)) {
        k.r.problem(*energy, "'energy' launches from the bottom: give either energy or theta0 with omega0, not both");
        return;
    }
    if (!energy && !theta0) {
        k.r.problem(*omega0, "'omega0' needs theta0, the start angles (theta0 = 0 launches from the bottom)");
        return;
    }
    if (energy) {
        read_energy_starts(k, *energy);
    } else {
        read_state_starts(k, *theta0, *omega0);
    }
    const toml::node& where = energy ? *energy : *omega0;
    if (k.p.plot->amplitudes != amplitude_policy::list && k.p.starts.size() > 1) {
        k.r.problem(where, "a " + std::string(k.p.plot->name) + " panel takes one start");
    }
    if (k.p.starts.size() > max_amplitudes_per_panel) {
        k.r.problem(where, "a panel takes at most " + std::to_string(max_amplitudes_per_panel) + " starts");
    }
}

}  // namespace

void read_theta0(key_reading& k) {
    const toml::node* n = k.t.get("theta0");
    const plot_row& plot = *k.p.plot;
    if (!n) {
        k.r.problem(k.p.where, "a " + std::string(plot.name) + " panel needs theta0");
        return;
    }
    const auto* a = n->as_array();
    if (!a) {
        if (auto v = k.r.angle(*n, "theta0", false)) k.p.theta0.push_back(*v);
        return;
    }
    if (plot.amplitudes != amplitude_policy::list && a->size() != 1) {
        k.r.problem(*n, "a " + std::string(plot.name) + " panel takes one theta0");
    } else if (a->empty()) {
        k.r.problem(*n, "'theta0' lists no amplitude");
    }
    for (const auto& e : *a) {
        if (auto v = k.r.angle(e, "theta0", false)) k.p.theta0.push_back(*v);
    }
}

namespace {

/// The problem of one start with one method, or empty: the approximants describe
/// librations only, and a formula starts at rest at its amplitude.
std::string start_method_problem(const motion_start& start, const method_spec& m, const std::string& what) {
    if (m.method.user) {
        return "method '" + m.method.text() + "' (a formula theta(t) = f(t, theta0)) starts at rest at its "
               "amplitude: give the panel theta0 = ..., not " + plain_text(start.label);
    }
    if (m.method.is_exact() || start.motion.kind() == pendulum::regime::libration) return {};
    return "method '" + m.method.text() + "' describes librations only (E < 2), but " + what +
           ": use methods = [\"exact\"], or a start with E < 2";
}

/// The approximants describe librations only, and the separatrix has no period T to measure
/// time in: each start is checked against the panel's methods and time unit.
void check_starts(key_reading& k) {
    const panel_spec& p = k.p;
    for (const auto& start : p.starts) {
        const auto& row = pendulum::row_of(start.motion.kind());
        const std::string what = plain_text(start.label) + " is a " + std::string(row.name) + " (E = " +
                                 pendulum::format_double(start.motion.energy()) + ")";
        for (const auto& m : p.methods) {
            if (std::string why = start_method_problem(start, m, what); !why.empty()) {
                k.r.problem(key_place(k, "methods"), std::move(why));
            }
        }
        if (p.plot->range == range_kind::times && p.time == time_unit::period && !start.motion.has_period()) {
            k.r.problem(key_place(k, "time"), what + ": it has no period T; give time = \"t/T0\" or \"t/s\"");
        }
    }
}

/// A panel of periods against the energy draws the exact period of librations and the revolution
/// of rotations, which no approximation of the paper describes, on energies from 0 up.
void check_energy_axis(key_reading& k) {
    const panel_spec& p = k.p;
    for (const auto& m : p.methods) {
        if (m.method.is_exact()) continue;
        k.r.problem(key_place(k, "methods"), "x = \"energy\" draws the exact period, across the separatrix where method '" +
                                                 m.method.text() + "' has none: use methods = [\"exact\"], or x = "
                                                 "\"amplitude\" to compare methods");
    }
    if (p.y != period_axis::value) {
        k.r.problem(key_place(k, "y"), "x = \"energy\" draws the period's value: y = \"value\" (the errors of the "
                                       "methods are drawn against the amplitude, x = \"amplitude\")");
    }
    if (p.degrees) k.r.problem(key_place(k, "angle_unit"), "x = \"energy\" has no angle axis: leave out angle_unit");
    if (p.range && (*p.range)[0] < 0) {
        k.r.problem(key_place(k, "range"), "x = \"energy\": 'range' = [" + pendulum::format_double((*p.range)[0]) + ", " +
                                               pendulum::format_double((*p.range)[1]) +
                                               "] goes below 0, the pendulum at rest at the bottom; give energies "
                                               "from 0 up, e.g. [0, 4]");
    }
}

/// Starts (even ones refused), the energy axis and residuals take the exact method by
/// default; so does a panel whose x axis was refused, which is reported once.
bool exact_by_default(const key_reading& k) {
    return k.t.get("energy") || k.t.get("omega0") || k.p.energy_axis || (k.t.get("x") && !k.x_axis) ||
           k.y_axis == period_axis::residual;
}

/// The methods of a methods = [...] list, the formulas numbered in panel order.
void read_method_list(key_reading& k, const toml::array& a) {
    int formulas = 0;
    for (const auto& e : a) {
        auto m = read_method(k.r, e, *k.p.plot);
        if (!m) continue;
        if (m->method.user) m->method.n = ++formulas;  // formula:1, formula:2 in panel order
        k.p.methods.push_back(std::move(*m));
    }
}

}  // namespace

std::string kinds_taking(formula_kind formulas, std::string_view last_word) {
    return kinds_where([formulas](const plot_row& row) { return row.formulas == formulas; }, last_word);
}

void read_amplitudes(key_reading& k) {
    if (k.t.get("energy") || k.t.get("omega0")) {
        read_starts(k);
    } else {
        read_theta0(k);
    }
}

void read_methods(key_reading& k) {
    const toml::node* n = k.t.get("methods");
    if (!n && exact_by_default(k)) {
        // Energies and states: the exact motion, the one method for every regime.
        method_spec exact;
        exact.method = pendulum::parse_method("exact");
        k.p.methods.push_back(exact);
    } else if (!n) {
        k.r.problem(k.p.where, "a " + std::string(k.p.plot->name) + " panel needs methods, e.g. [\"exact\", \"lowest\"]");
    } else if (const auto* a = n->as_array(); !a || a->empty()) {
        k.r.problem(*n, "'methods' must be a non-empty list, e.g. [\"exact\", \"lowest\"]");
    } else {
        read_method_list(k, *a);
    }
}

void read_time(key_reading& k) {
    auto v = k.r.choice(k.t, "time", time_units);
    if (!v) return;
    k.p.time = *v;
    if (k.p.time == time_unit::seconds && !k.f.pendulum) {
        k.r.problem(*k.t.get("time"), "time = \"t/s\" needs a [pendulum] table with length_m");
    }
}

void read_range(key_reading& k) {
    const toml::node* n = k.t.get("range");
    if (!n) return;
    const auto* a = n->as_array();
    if (!a || a->size() != 2) {
        k.r.problem(*n, "'range' must be a list of two values, [from, to]");
        return;
    }
    std::array<double, 2> v{};
    for (std::size_t i = 0; i < 2; ++i) {
        const auto value = range_value(k.r, *a->get(i), k.p);
        if (!value) return;
        v[i] = *value;
    }
    if (!(v[0] < v[1])) {
        k.r.problem(*n, "'range' must go from a smaller to a larger value");
        return;
    }
    k.p.range = v;
}

void read_period_axes(key_reading& k) {
    k.x_axis = k.r.choice(k.t, "x", period_x_axes);
    if (k.x_axis) k.p.energy_axis = *k.x_axis;
    k.y_axis = k.r.choice(k.t, "y", period_axes);
    if (k.y_axis) k.p.y = *k.y_axis;
    if (const toml::node* energy = k.t.get("energy")) {
        k.r.problem(*energy, "a " + std::string(k.p.plot->name) + " panel draws T/T0 against the energy with x = "
                             "\"energy\" (and range = [0, 4], say), not with energy = ...");
    }
}

void read_residual_of(key_reading& k) {
    const toml::node* n = k.t.get("residual_of");
    if (!n) return;
    if (k.p.y != period_axis::residual) {
        k.r.problem(*n, "'residual_of' is the reference of a residual panel: give it with y = \"residual\"");
        return;
    }
    if (auto read = read_method(k.r, *n, *k.p.plot)) k.p.residual_of = read->method;
}

void read_harmonic(key_reading& k) {
    auto v = k.r.integer(k.t, "harmonic", 1, 99);
    if (!v) return;
    if (*v % 2 == 0) {
        k.r.problem(*k.t.get("harmonic"), "'harmonic' must be odd (1, 3, 5, ...): the even coefficients vanish");
    } else {
        k.p.harmonic = *v;
    }
}

void read_harmonics(key_reading& k) {
    if (auto v = k.r.integer(k.t, "harmonics", 1, 100)) k.p.harmonics = *v;
}

void read_orders(key_reading& k) {
    const toml::node* n = k.t.get("orders");
    if (!n) return;
    const auto* a = n->as_array();
    if (!a || a->size() != 2 || !a->get(0)->is_integer() || !a->get(1)->is_integer()) {
        k.r.problem(*n, "'orders' must be two whole numbers, [first, last]");
        return;
    }
    const auto lo = a->get(0)->as_integer()->get();
    const auto hi = a->get(1)->as_integer()->get();
    if (lo < 0 || hi > pendulum::max_order || lo >= hi) {
        k.r.problem(*n, "'orders' must satisfy 0 <= first < last <= " + std::to_string(pendulum::max_order));
    } else {
        k.p.orders = {static_cast<int>(lo), static_cast<int>(hi)};
    }
}

void read_separatrix(key_reading& k) {
    if (auto v = k.r.boolean(k.t, "separatrix")) k.p.separatrix = *v;
}

void read_trail(key_reading& k) {
    if (auto v = k.r.number(k.t, "trail", 0.0, 10.0)) k.p.trail = *v;
}

namespace {

/// The arrows that may be drawn on each bob.
enum class arrow_kind { velocity, acceleration };

constexpr std::array<std::pair<std::string_view, arrow_kind>, 2> arrow_kinds = {{
    {"velocity", arrow_kind::velocity},
    {"acceleration", arrow_kind::acceleration},
}};

/// arrows = ["velocity", "acceleration"]: each at most once.
void read_arrows(key_reading& k) {
    const toml::node* n = k.t.get("arrows");
    if (!n) return;
    const auto* a = n->as_array();
    if (!a) {
        k.r.problem(*n, "'arrows' must be a list, e.g. [\"velocity\", \"acceleration\"]");
        return;
    }
    for (const auto& item : *a) {
        const auto v = k.r.choice_of(item, "arrows", arrow_kinds);
        if (!v) continue;
        bool& on = *v == arrow_kind::velocity ? k.p.velocity_arrows : k.p.acceleration_arrows;
        if (on) k.r.problem(item, "'arrows' names \"" + std::string(arrow_kinds[static_cast<int>(*v)].first) + "\" twice");
        on = true;
    }
}

}  // namespace

void read_overlays(key_reading& k) {
    if (auto v = k.r.boolean(k.t, "energy_bars")) k.p.energy_bars = *v;
    if (auto v = k.r.boolean(k.t, "timer")) k.p.timer = *v;
    read_arrows(k);
}

void read_angle_unit(key_reading& k) {
    if (auto v = k.r.choice(k.t, "angle_unit", angle_units)) k.p.degrees = *v;
}

void read_data(key_reading& k) { read_panel_data(k.r, k.t, k.f, k.p); }

void check_panel(key_reading& k) {
    check_costs(k);
    check_starts(k);
    if (k.p.energy_axis) check_energy_axis(k);
}

}  // namespace figures
