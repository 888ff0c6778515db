// SPDX-License-Identifier: GPL-3.0-or-later
#include "figures/figure_data.hpp"
#include "pendulum/formula.hpp"

#include "figures/panel_support.hpp"
#include "figures/plots.hpp"
#include "figures/spec_build.hpp"
#include "pendulum/amplitude.hpp"
#include "pendulum/methods.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <set>
#include <sstream>

namespace figures {

bool series_id_character(char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == ':' ||
           c == '.' || c == '-';
}

namespace {

/// The text with every character outside series_id_character made '_'.
std::string id_of(std::string text) {
    std::replace_if(text.begin(), text.end(), [](char c) { return !series_id_character(c); }, '_');
    return text;
}

}  // namespace

void give_series_ids(plot::panel& p) {
    std::set<std::string> taken;  // as wide columns name them, which must differ too
    const auto used = [&taken](const std::string& id) { return taken.contains(wide_column("", id, 'x')); };
    int lines = 0;
    int others = 0;
    for (auto& s : p.data) {
        const bool line = !s.autoscale;
        const int n = line ? ++lines : ++others;
        std::string id = s.id.empty() ? (line ? "line:" : "series:") + std::to_string(n) : id_of(s.id);
        if (used(id)) {
            int k = 2;
            while (used(id + "." + std::to_string(k))) ++k;
            id += "." + std::to_string(k);
        }
        taken.insert(wide_column("", id, 'x'));
        s.id = std::move(id);
    }
}

std::string csv_field(const std::string& text) {
    const bool formula = !text.empty() && std::string_view("=+-@\t\r").find(text.front()) != std::string_view::npos;
    const std::string field = formula ? "'" + text : text;
    if (field.find_first_of(",\"\n\r") == std::string::npos) return field;
    std::string out = "\"";
    for (char c : field) out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
}

std::string json_string(std::string_view text) {
    std::string out = "\"";
    for (const char c : text) {
        const auto u = static_cast<unsigned char>(c);
        if (c == '"' || c == '\\') {
            out += '\\';
            out += c;
        } else if (u < 0x20 || u == 0x7f) {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\u%04x", u);
            out += buf;
        } else {
            out += c;
        }
    }
    return out + "\"";
}

std::string json_number(double v) { return std::isfinite(v) ? pendulum::format_double(v) : "null"; }

int printed_digits(const panel_spec& p) {
    if (!p.plot) return 0;
    const std::string_view kind = p.plot->name;
    const bool error_axis = (kind == "period" && (p.y == period_axis::error_percent || p.y == period_axis::error_log)) ||
                            kind == "convergence";
    if (!error_axis) return 0;
    return static_cast<int>(std::floor(-std::log10(error_axis_relative) + 1e-9));
}

int difference_digits(double difference, double terms) {
    constexpr int most = 17;
    const double size = std::fabs(terms);
    if (!(size > 0) || !std::isfinite(size) || !std::isfinite(difference)) return most;
    // |a - b| in units of the terms' last bit, 2^-52 max(|a|, |b|): floor(log10) of it,
    // counted against exact powers of ten (no log10 rounding at the boundaries); 13 units
    // know one digit, not two.
    // No cancellation (terms of opposite signs, or one of them 0): the difference is rounded
    // once, every digit.
    if (std::fabs(difference) >= size) return most;
    const double units = std::fabs(difference) / std::ldexp(size, -52);
    int digits = 1;
    double power = 100;
    while (digits < most && units >= power) {
        ++digits;
        power *= 10;
    }
    return digits;
}

int y_digits_at(const series_numbers& s, std::size_t i) {
    return i < s.y_terms.size() ? difference_digits(s.y[i], s.y_terms[i]) : s.y_digits;
}

std::string format_digits(double v, int digits) {
    if (digits <= 0 || !std::isfinite(v)) return pendulum::format_double(v);
    char buf[48];
    std::snprintf(buf, sizeof buf, "%.*g", digits, v);
    // The rounded value's shortest round trip: no trailing zeros, no more digits than asked.
    return pendulum::format_double(std::strtod(buf, nullptr));
}

std::string wide_column(const std::string& panel, const std::string& id, char axis) {
    std::string name = panel + "_" + id + "_" + axis;
    std::replace_if(name.begin(), name.end(), [](char c) { return c == ':' || c == '.' || c == '-'; }, '_');
    return name;
}

namespace {

/// The unit at the end of an axis label in parentheses: "T (s)" -> "s"; else empty.
std::string unit_of(const std::string& label) {
    if (label.empty() || label.back() != ')') return "";
    const auto open = label.rfind('(');
    if (open == std::string::npos || open == 0 || label[open - 1] != ' ') return "";
    return label.substr(open + 1, label.size() - open - 2);
}

axis_numbers axis_of(const plot::axis& a, double lo, double hi) {
    const std::string text = plain_text(a.label.markup);
    // An angle axis says its unit by its ticks.
    const std::string unit = a.ticks == plot::tick_kind::multiples_of_pi ? "rad"
                             : a.ticks == plot::tick_kind::degrees      ? "deg"
                                                                         : unit_of(text);
    return {text, unit, a.kind == plot::scale::log ? "log" : "linear", lo, hi};
}

/// A series' uncertainties, as its error bars draw them.
void add_errors(const plot::series& s, series_numbers& out) {
    out.x_err_lower = s.errors.x_lower;
    out.x_err_upper = s.errors.x_upper;
    out.y_err_lower = s.errors.y_lower;
    out.y_err_upper = s.errors.y_upper;
}

/// The method a series' id names (its repeat suffix dropped), or empty; a user's formula
/// (formula:K) is found among the panel's methods, measured data (data:K) is none.
std::string method_of_id(const std::string& id) {
    const std::string name = id.substr(0, id.find('.'));
    if (name.starts_with("data:") || name.starts_with("formula:")) return "";
    try {
        return pendulum::parse_method(name).text();
    } catch (const std::exception&) {
        return "";
    }
}

/// A user's formula: its text as the method, its T/T0 where the panel has one amplitude.
void formula_meaning(const panel_spec& p, series_numbers& s) {
    const std::string name = s.id.substr(0, s.id.find('.'));
    for (const auto& m : p.methods) {
        if (!m.method.user || m.method.text() != name) continue;
        s.method = "formula:" + m.method.user->text();
        if (p.theta0.size() != 1 || m.method.user->uses_t()) return;
        s.theta0 = p.theta0.front();
        const double t = pendulum::method_period(m.method, s.theta0->theta0());
        if (std::isfinite(t)) s.period = t;
    }
}

/// On a residual panel ((T_meas - T_ref)/T0), the terms of each y: T_ref at its x and
/// T_ref + y, the larger in size (difference_digits()); nothing on other panels.
void add_difference_terms(const panel_spec& p, series_numbers& s) {
    if (!p.plot || p.plot->name != "period" || p.y != period_axis::residual) return;
    const auto ref = p.residual_of ? *p.residual_of : pendulum::parse_method("exact");
    s.y_terms.assign(s.y.size(), 0.0);  // 0: no terms known, every digit
    for (std::size_t i = 0; i < s.y.size() && i < s.x.size(); ++i) {
        const double theta = p.degrees ? s.x[i] * std::numbers::pi / 180 : s.x[i];
        try {
            const double b = pendulum::method_period(ref, theta);
            s.y_terms[i] = std::max(std::fabs(b), std::fabs(b + s.y[i]));
        } catch (const std::exception&) {
            // Outside (0, pi), where the reference has no period: every digit of y.
        }
    }
}

/// The method, amplitude and period a series of panel spec p stands for, where its id says.
void add_meaning(const panel_spec& p, series_numbers& s) {
    s.method = method_of_id(s.id);
    if (s.id.starts_with("formula:")) return formula_meaning(p, s);
    if (s.id.starts_with("theta0:")) {
        const std::size_t i = std::strtoul(s.id.c_str() + 7, nullptr, 10);
        if (i >= 1 && i <= p.theta0.size()) s.theta0 = p.theta0[i - 1];
        if (s.method.empty() && p.methods.size() == 1) s.method = p.methods.front().method.text();
    } else if (!s.method.empty() && p.theta0.size() == 1 && p.plot &&
               p.plot->amplitudes == amplitude_policy::one_per_panel) {
        s.theta0 = p.theta0.front();
    }
    if (s.method.empty() || !s.theta0) return;
    try {
        const double t = pendulum::method_period(pendulum::parse_method(s.method), s.theta0->theta0());
        if (std::isfinite(t)) s.period = t;
    } catch (const std::exception&) {
        // no period at this amplitude: none is written
    }
}

/// A reference line's ends, moved along the line to the panel's limits.
void within_limits(series_numbers& s, const plot::panel_frame& f) {
    const auto clamp = [](double v, double a, double b) { return std::clamp(v, std::min(a, b), std::max(a, b)); };
    for (auto& v : s.x) v = clamp(v, f.x_lo, f.x_hi);
    for (auto& v : s.y) v = clamp(v, f.y_lo, f.y_hi);
}

series_numbers series_of_points(const plot::series& s, std::vector<double> x, std::vector<double> y, bool sampled) {
    series_numbers n;
    n.id = s.id;
    n.label = plain_text(s.label.markup);
    n.x = std::move(x);
    n.y = std::move(y);
    n.sampled = sampled;
    n.reference_line = !s.autoscale;
    add_errors(s, n);
    return n;
}

}  // namespace

figure_numbers numbers_of(const entry& e, const build_options& options, const plot::theme& theme, double dpi) {
    plot::figure f = build(e, sized_by(options, theme));
    std::vector<plot::panel_frame> frames;
    std::vector<std::vector<plot::drawn_points>> drawn;
    figure_numbers n;
    try {
        drawn = plot::drawn_data(f, theme, dpi, frames);
    } catch (const plot::layout_error&) {
        // Legends too large for the PNG (many amplitudes): the numbers do not need them.
        for (auto& p : f.panels) p.legend = plot::legend_place::none;
        f.shared_legend = false;
        drawn = plot::drawn_data(f, theme, dpi, frames);
        n.without_legends = true;
    }
    n.id = e.id;
    n.specs = panels_of(e, options);
    for (std::size_t i = 0; i < f.panels.size() && i < drawn.size(); ++i) {
        const plot::panel& p = f.panels[i];
        panel_numbers pn{panel_name(i), plain_text(p.label.markup), axis_of(p.x, frames[i].x_lo, frames[i].x_hi),
                         axis_of(p.y, frames[i].y_lo, frames[i].y_hi), {}};
        for (std::size_t j = 0; j < p.data.size(); ++j) {
            series_numbers s = series_of_points(p.data[j], drawn[i][j].x, drawn[i][j].y, drawn[i][j].sampled);
            if (s.reference_line) within_limits(s, frames[i]);
            if (i < n.specs.size()) add_meaning(n.specs[i], s);
            if (i < n.specs.size()) s.y_digits = printed_digits(n.specs[i]);
            if (i < n.specs.size()) add_difference_terms(n.specs[i], s);
            pn.series.push_back(std::move(s));
        }
        n.panels.push_back(std::move(pn));
    }
    return n;
}

figure_numbers numbers_of(const plot::figure& f) {
    figure_numbers n;
    for (std::size_t i = 0; i < f.panels.size(); ++i) {
        plot::panel p = f.panels[i];
        give_series_ids(p);
        panel_numbers pn{panel_name(i), plain_text(p.label.markup), axis_of(p.x, p.x.min.value_or(NAN), p.x.max.value_or(NAN)),
                         axis_of(p.y, p.y.min.value_or(NAN), p.y.max.value_or(NAN)), {}};
        for (const auto& s : p.data) {
            const std::size_t m = std::min(s.x.size(), s.y.size());
            pn.series.push_back(series_of_points(s, {s.x.begin(), s.x.begin() + static_cast<std::ptrdiff_t>(m)},
                                                 {s.y.begin(), s.y.begin() + static_cast<std::ptrdiff_t>(m)}, false));
        }
        n.panels.push_back(std::move(pn));
    }
    return n;
}

namespace {

/// The uncertainty columns, by their suffix: "x_err_lower", ...
struct error_column {
    const char* suffix;
    std::vector<double> series_numbers::*values;
};
constexpr error_column error_columns[] = {{"x_err_lower", &series_numbers::x_err_lower},
                                          {"x_err_upper", &series_numbers::x_err_upper},
                                          {"y_err_lower", &series_numbers::y_err_lower},
                                          {"y_err_upper", &series_numbers::y_err_upper}};

/// True when some series has the uncertainties of column c.
bool any_errors(const figure_numbers& n, const error_column& c) {
    for (const auto& p : n.panels) {
        for (const auto& s : p.series) {
            if (!(s.*c.values).empty()) return true;
        }
    }
    return false;
}

/// The i-th value with `digits` significant digits (format_digits), or nan past the end.
std::string cell(const std::vector<double>& v, std::size_t i, int digits = 0) {
    return i < v.size() ? format_digits(v[i], digits) : "nan";
}

/// The i-th y of series s with the digits it deserves (y_digits_at), or nan past the end.
std::string y_cell(const series_numbers& s, std::size_t i) {
    return i < s.y.size() ? format_digits(s.y[i], y_digits_at(s, i)) : "nan";
}

std::string long_csv(const figure_numbers& n) {
    std::vector<const error_column*> errors;
    for (const auto& c : error_columns) {
        if (any_errors(n, c)) errors.push_back(&c);
    }
    std::ostringstream out;
    out << "panel,series,x,y,id";
    for (const auto* c : errors) out << ',' << c->suffix;
    out << '\n';
    for (const auto& p : n.panels) {
        for (const auto& s : p.series) {
            const std::string name = csv_field(s.label);
            for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
                out << p.name << ',' << name << ',' << pendulum::format_double(s.x[i]) << ','
                    << y_cell(s, i) << ',' << csv_field(s.id);
                for (const auto* c : errors) out << ',' << cell(s.*c->values, i);
                out << '\n';
            }
        }
    }
    return out.str();
}

/// One column of the wide layout.
struct column {
    std::string name;
    const std::vector<double>* values;
    const series_numbers* y_of = nullptr;  ///< the series whose y this column is (y_cell)
};

std::string wide_csv(const figure_numbers& n) {
    std::vector<column> columns;
    for (const auto& p : n.panels) {
        for (const auto& s : p.series) {
            columns.push_back({wide_column(p.name, s.id, 'x'), &s.x});
            columns.push_back({wide_column(p.name, s.id, 'y'), &s.y, &s});
            for (const auto& c : error_columns) {
                const auto& v = s.*c.values;
                if (!v.empty()) columns.push_back({wide_column(p.name, s.id, c.suffix[0]) + std::string(c.suffix + 1), &v});
            }
        }
    }
    std::size_t rows = 0;
    std::ostringstream out;
    for (std::size_t c = 0; c < columns.size(); ++c) {
        out << (c ? "," : "") << columns[c].name;
        rows = std::max(rows, columns[c].values->size());
    }
    out << '\n';
    for (std::size_t r = 0; r < rows; ++r) {
        for (std::size_t c = 0; c < columns.size(); ++c) {
            out << (c ? "," : "") << (columns[c].y_of ? y_cell(*columns[c].y_of, r) : cell(*columns[c].values, r));
        }
        out << '\n';
    }
    return out.str();
}

std::string json_array(const std::vector<double>& v) {
    std::string out = "[";
    for (std::size_t i = 0; i < v.size(); ++i) {
        out += (i ? "," : "") + (std::isfinite(v[i]) ? pendulum::format_double(v[i]) : std::string("null"));
    }
    return out + "]";
}

/// The y values of series s, each with the digits it deserves (y_digits_at).
std::string json_y(const series_numbers& s) {
    std::string out = "[";
    for (std::size_t i = 0; i < s.y.size(); ++i) out += (i ? "," : "") + (std::isfinite(s.y[i]) ? y_cell(s, i) : std::string("null"));
    return out + "]";
}

std::string json_axis(const axis_numbers& a) {
    return "{\"label\":" + json_string(a.label) + ",\"unit\":" + json_string(a.unit) + ",\"scale\":" +
           json_string(a.scale) + ",\"min\":" + json_number(a.lo) + ",\"max\":" + json_number(a.hi) + "}";
}

std::string json_series(const panel_numbers& p, const series_numbers& s) {
    std::string out = "{\"id\":" + json_string(s.id) + ",\"label\":" + json_string(s.label);
    out += ",\"kind\":" + json_string(s.reference_line ? "line" : s.sampled ? "curve" : "points");
    out += ",\"method\":" + (s.method.empty() ? std::string("null") : json_string(s.method));
    if (s.theta0) {
        out += ",\"theta0\":{\"text\":" + json_string(s.theta0->text) + ",\"radians\":" +
               json_number(s.theta0->value) + "}";
    } else {
        out += ",\"theta0\":null";
    }
    out += ",\"period\":" + (s.period ? "{\"T_over_T0\":" + json_number(*s.period) + "}" : std::string("null"));
    out += ",\"units\":{\"x\":" + json_string(p.x.unit) + ",\"y\":" + json_string(p.y.unit) + "}";
    out += ",\"columns\":{\"x\":" + json_string(wide_column(p.name, s.id, 'x')) + ",\"y\":" +
           json_string(wide_column(p.name, s.id, 'y')) + "}";
    out += ",\"x\":" + json_array(s.x) + ",\"y\":" + json_y(s);
    for (const auto& c : error_columns) {
        if (!(s.*c.values).empty()) out += ",\"" + std::string(c.suffix) + "\":" + json_array(s.*c.values);
    }
    return out + "}";
}

}  // namespace

std::string numbers_csv(const figure_numbers& n, data_layout layout) {
    return layout == data_layout::wide ? wide_csv(n) : long_csv(n);
}

std::string numbers_json(const figure_numbers& n) {
    std::string out = "{\"figure\":" + json_string(n.id) + ",\"panels\":[";
    for (std::size_t i = 0; i < n.panels.size(); ++i) {
        const auto& p = n.panels[i];
        out += std::string(i ? ",\n" : "\n") + "{\"name\":" + json_string(p.name) + ",\"title\":" +
               json_string(p.title) + ",\"x\":" + json_axis(p.x) + ",\"y\":" + json_axis(p.y) + ",\"series\":[";
        for (std::size_t j = 0; j < p.series.size(); ++j) out += (j ? ",\n" : "\n") + json_series(p, p.series[j]);
        out += "]}";
    }
    return out + "]}\n";
}

}  // namespace figures
