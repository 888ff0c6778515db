// SPDX-License-Identifier: GPL-3.0-or-later
#include "figures/data_series.hpp"

#include "figures/data_reader.hpp"
#include "figures/input_file.hpp"
#include "figures/panel_support.hpp"
#include "plot/tex_markup.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <system_error>
#include <variant>

namespace figures {

namespace {

constexpr std::array<std::pair<std::string_view, data_unit>, 8> unit_names = {{
    {"rad", data_unit::rad},
    {"deg", data_unit::deg},
    {"s", data_unit::seconds},
    {"T/T0", data_unit::period_ratio},
    {"t/T0", data_unit::small_period},
    {"t/T", data_unit::period},
    {"1", data_unit::number},
    {"%", data_unit::percent},
}};

constexpr std::string_view data_keys = "file x y x_err y_err x_unit y_unit label";

/// The units a quantity may be given in, the first its default where it has one.
std::vector<data_unit> units_of(quantity q) {
    switch (q) {
        case quantity::angle: return {data_unit::deg, data_unit::rad};
        case quantity::period: return {data_unit::seconds, data_unit::period_ratio};
        case quantity::time: return {data_unit::seconds, data_unit::small_period, data_unit::period};
        case quantity::number: return {data_unit::number};
        case quantity::percent: return {data_unit::percent};
    }
    return {};
}

std::string_view quantity_name(quantity q) {
    switch (q) {
        case quantity::angle: return "an angle";
        case quantity::period: return "a period";
        case quantity::time: return "a time";
        case quantity::number: return "a pure number";
        case quantity::percent: return "a relative error in %";
    }
    return "";
}

/// "\"deg\" or \"rad\"".
std::string unit_choices(quantity q) {
    std::string out;
    const auto units = units_of(q);
    for (std::size_t i = 0; i < units.size(); ++i) {
        if (i > 0) out += i + 1 == units.size() ? " or " : ", ";
        out += "\"" + std::string(unit_name(units[i])) + "\"";
    }
    return out;
}

/// One cell of a data file: its text and its 1-based column in the line.
struct cell {
    std::string_view text;
    int column;
};

/// A data file split into its header and rows.
struct data_table {
    std::string shown;                ///< the file as the spec names it
    int header_line = 0;              ///< 1-based
    std::vector<std::string> names;   ///< the header's names, trimmed and unquoted
    std::vector<int> name_columns;    ///< where each name starts
    struct row {
        int line;
        std::vector<cell> cells;
    };
    std::vector<row> rows;
};

std::string_view trim(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
    return s;
}

/// The cells of a line, split at `sep`, each trimmed, with the column where its text starts.
std::vector<cell> split_cells(std::string_view line, char sep) {
    std::vector<cell> cells;
    std::size_t start = 0;
    while (true) {
        const std::size_t end = std::min(line.find(sep, start), line.size());
        const std::string_view raw = line.substr(start, end - start);
        const std::string_view text = trim(raw);
        const auto lead = text.empty() ? raw.size() : static_cast<std::size_t>(text.data() - raw.data());
        cells.push_back({text, static_cast<int>(start + lead + 1)});
        if (end == line.size()) break;
        start = end + 1;
    }
    return cells;
}

/// Collects the problems of one data file, up to max_data_problems.
struct file_problems {
    reader& r;
    std::string shown;
    std::size_t count = 0;

    void add(int line, int column, std::string what) {
        if (++count <= max_data_problems) r.problem(source_position{shown, line, column}, std::move(what));
    }
    bool any() const { return count > 0; }
};

/// A cell's text as a message may quote it: short, printable and valid UTF-8, else nothing.
std::string quoted(std::string_view text) {
    if (text.size() > 40 || !plot::text_problem(text).empty()) return "";
    return " '" + std::string(text) + "'";
}

/// The header: names trimmed, a pair of double quotes around one taken off, each a line of
/// printable text.
void read_header(data_table& t, std::string_view line, char sep, file_problems& fp) {
    for (const cell& c : split_cells(line, sep)) {
        std::string_view name = c.text;
        if (name.size() >= 2 && name.front() == '"' && name.back() == '"') name = name.substr(1, name.size() - 2);
        if (const std::string why = plot::text_problem(name, 200); !why.empty()) {
            fp.add(t.header_line, c.column, "the name of column " + std::to_string(t.names.size() + 1) + " " + why);
        }
        t.names.emplace_back(name);
        t.name_columns.push_back(c.column);
    }
}

/// A ragged row (more or fewer cells than the header has names) is a problem at the first
/// cell too many, or at the end of the row, naming the column.
void check_row_length(const data_table& t, file_problems& fp) {
    const auto& row = t.rows.back();
    const std::size_t n = row.cells.size();
    if (n == t.names.size()) return;
    const std::string counts = "the row has " + std::to_string(n) + " cells and the header " +
                               std::to_string(t.names.size());
    if (n < t.names.size()) {
        const auto& last = row.cells.back();
        fp.add(row.line, last.column + static_cast<int>(last.text.size()),
               counts + ": no cell for column '" + t.names[n] + "'");
    } else {
        fp.add(row.line, row.cells[t.names.size()].column,
               counts + ": a cell past the last column '" + t.names.back() + "'");
    }
}

/// Splits a data file's text into its header and rows: lines are split at commas, or at tabs
/// when the header has one; blank lines and lines starting with # are skipped.
data_table split_table(std::string_view text, file_problems& fp) {
    data_table t;
    t.shown = fp.shown;
    char sep = ',';
    int line_no = 0;
    std::size_t pos = 0;
    while (pos <= text.size() && !fp.any()) {
        const std::size_t end = std::min(text.find('\n', pos), text.size());
        const std::string_view line = text.substr(pos, end - pos);
        pos = end + 1;
        ++line_no;
        const std::string_view content = trim(line);
        if (content.empty() || content.front() == '#') {
            if (end == text.size()) break;
            continue;
        }
        if (t.names.empty()) {
            sep = line.find('\t') != std::string_view::npos ? '\t' : ',';
            t.header_line = line_no;
            read_header(t, line, sep, fp);
        } else if (t.rows.size() == max_data_rows) {
            fp.add(line_no, 1, "more than " + std::to_string(max_data_rows) + " rows; a data file holds at most " +
                                   std::to_string(max_data_rows));
        } else {
            t.rows.push_back({line_no, split_cells(line, sep)});
            check_row_length(t, fp);
        }
        if (end == text.size()) break;
    }
    if (t.names.empty() && !fp.any()) fp.add(0, 0, "has no header row (the names of the columns) and no data");
    if (!t.names.empty() && t.rows.empty() && !fp.any()) fp.add(t.header_line, 1, "has a header but no data rows");
    return t;
}

/// A column chosen by the spec: a header name, or a 1-based number.
using column_choice = std::variant<std::string, long long>;

/// The 0-based index of a chosen column, or a problem at the header.
std::optional<std::size_t> column_index(const data_table& t, const column_choice& c, std::string_view key,
                                        file_problems& fp) {
    if (const auto* n = std::get_if<long long>(&c)) {
        if (*n >= 1 && static_cast<std::size_t>(*n) <= t.names.size()) return static_cast<std::size_t>(*n - 1);
        fp.add(t.header_line, 1, "'" + std::string(key) + "' = " + std::to_string(*n) + ": there is no column " +
                                     std::to_string(*n) + "; the file has " + std::to_string(t.names.size()) +
                                     " (numbered from 1)");
        return std::nullopt;
    }
    const auto& name = std::get<std::string>(c);
    const auto it = std::find(t.names.begin(), t.names.end(), name);
    if (it != t.names.end()) return static_cast<std::size_t>(it - t.names.begin());
    // The first few names: a header may have thousands.
    std::vector<std::string> names(t.names.begin(), t.names.begin() + std::min<std::ptrdiff_t>(12, t.names.size()));
    if (names.size() < t.names.size()) names.push_back("... (" + std::to_string(t.names.size()) + " in all)");
    fp.add(t.header_line, 1, "'" + std::string(key) + "' = \"" + name + "\": no such column in the header; columns: " +
                                 listed(names));
    return std::nullopt;
}

/// The values of one column, each cell a finite number (>= 0 for an error).
std::vector<double> column_values(const data_table& t, std::size_t index, bool is_error, file_problems& fp) {
    std::vector<double> out;
    out.reserve(t.rows.size());
    const std::string name = "column '" + t.names[index] + "'";
    for (const auto& row : t.rows) {
        const cell& c = row.cells[index];
        std::string_view text = c.text;
        if (text.size() > 1 && text.front() == '+') text.remove_prefix(1);
        double v = 0;
        const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
        if (c.text.empty()) {
            fp.add(row.line, c.column, name + ": an empty cell; each cell is a number");
        } else if (ec != std::errc() || end != text.data() + text.size()) {
            fp.add(row.line, c.column, name + ":" + quoted(c.text) + " is not a number");
        } else if (!std::isfinite(v)) {
            fp.add(row.line, c.column, name + ":" + quoted(c.text) + " is not a finite number");
        } else if (is_error && v < 0) {
            fp.add(row.line, c.column, name + ": an uncertainty is >= 0, got" + quoted(c.text));
        }
        out.push_back(v);
    }
    return out;
}

/// A column key of a file series: "NAME" or a number.
std::optional<column_choice> column_key(reader& r, const toml::node& n, std::string_view key) {
    if (const auto* s = n.as_string()) return column_choice{s->get()};
    if (const auto* i = n.as_integer()) return column_choice{i->get()};
    r.problem(n, "'" + std::string(key) + "' names a column of the file: its header name, or its number from 1");
    return std::nullopt;
}

/// An error key's columns or lists: one (symmetric) or two [lower, upper].
std::vector<const toml::node*> error_parts(reader& r, const toml::node& n, std::string_view key, bool inline_values) {
    const auto* a = n.as_array();
    const bool pair = a && a->size() == 2 && (inline_values ? a->get(0)->is_array() : !a->get(0)->is_array());
    if (inline_values ? (pair || (a && !a->get(0)->is_array())) : (pair || !a)) {
        if (!pair) return {&n};
        return {a->get(0), a->get(1)};
    }
    r.problem(n, "'" + std::string(key) + "' is one " + (inline_values ? "list of errors" : "column") +
                     " (symmetric), or two [lower, upper]");
    return {};
}

/// Reads one column (or error column) of a file series into `out`.
bool file_column(reader& r, const data_table& t, const toml::node& n, std::string_view key, bool is_error,
                 file_problems& fp, std::vector<double>& out) {
    const auto choice = column_key(r, n, key);
    if (!choice) return false;
    const auto index = column_index(t, *choice, key, fp);
    if (!index) return false;
    out = column_values(t, *index, is_error, fp);
    return true;
}

/// The file of a [[panel.data]]: relative to the spec's directory and inside its tree.
std::optional<std::string> data_path(reader& r, const toml::node& n, const std::string& v) {
    const std::filesystem::path given(v);
    if (given.is_absolute() || given.has_root_name() || given.has_root_directory()) {
        r.problem(n, "'file' = \"" + v + "\" must be a path relative to the spec's directory, not an absolute path");
        return std::nullopt;
    }
    const auto normal = given.lexically_normal();
    if (normal.empty() || *normal.begin() == "..") {
        r.problem(n, "'file' = \"" + v + "\" must stay inside the spec's directory: no '..' leading out of it");
        return std::nullopt;
    }
    const auto dir = std::filesystem::path(r.file()).parent_path();
    const auto path = dir / normal;
    if (const std::string why = outside_problem(dir.empty() ? "." : dir, path); !why.empty()) {
        r.problem(n, "'file' = \"" + v + "\" " + why);
        return std::nullopt;
    }
    return path.string();
}

/// The error keys of a series, lower and upper: x_err to errors.x_lower/x_upper, and so on.
struct error_target {
    std::string_view key;
    std::vector<double> plot::error_bars::*lower;
    std::vector<double> plot::error_bars::*upper;
};
constexpr error_target error_targets[] = {{"x_err", &plot::error_bars::x_lower, &plot::error_bars::x_upper},
                                          {"y_err", &plot::error_bars::y_lower, &plot::error_bars::y_upper}};

/// A series from a file: x, y and errors by column.
void read_file_series(reader& r, const toml::table& t, data_series& d) {
    const toml::node& file_node = *t.get("file");
    std::string text;
    try {
        text = read_input_file(d.file, "data file");
    } catch (const std::exception& e) {
        r.problem(file_node, "'file' = \"" + d.shown_file + "\": " + e.what());
        return;
    }
    file_problems fp{r, d.file};
    const data_table table = split_table(text, fp);
    if (fp.any()) return;
    for (const auto& [key, out] : {std::pair{"x", &d.x}, std::pair{"y", &d.y}}) {
        if (const toml::node* n = t.get(key)) {
            file_column(r, table, *n, key, false, fp, *out);
        } else {
            r.problem(source_position{r.file(), d.where[0], d.where[1]},
                      "a [[panel.data]] with a file needs '" + std::string(key) + "', a column's name or number");
        }
    }
    for (const auto& target : error_targets) {
        const toml::node* n = t.get(target.key);
        if (!n) continue;
        const auto parts = error_parts(r, *n, target.key, false);
        if (parts.empty()) continue;
        file_column(r, table, *parts[0], target.key, true, fp, d.errors.*target.lower);
        if (parts.size() == 2) {
            file_column(r, table, *parts[1], target.key, true, fp, d.errors.*target.upper);
        } else {
            d.errors.*target.upper = d.errors.*target.lower;
        }
    }
}

/// An inline list of numbers: finite, at most max_data_rows, errors >= 0.
std::optional<std::vector<double>> inline_values(reader& r, const toml::node& n, std::string_view key, bool is_error) {
    const auto* a = n.as_array();
    if (!a) {
        r.problem(n, "'" + std::string(key) + "' without 'file' is a list of numbers");
        return std::nullopt;
    }
    if (a->size() > max_data_rows) {
        r.problem(n, "'" + std::string(key) + "' lists " + std::to_string(a->size()) + " values; at most " +
                         std::to_string(max_data_rows));
        return std::nullopt;
    }
    std::vector<double> out;
    for (const auto& e : *a) {
        const auto v = e.value<double>();
        if (!v || !e.is_number() || !std::isfinite(*v) || (is_error && *v < 0)) {
            r.problem(e, "'" + std::string(key) + "' holds " + (is_error ? "finite numbers >= 0" : "finite numbers"));
            return std::nullopt;
        }
        out.push_back(*v);
    }
    return out;
}

/// A series given inline: x, y and errors as lists of one length.
/// x = [...] and y = [...] of an inline series; false (reported) if one is missing or bad.
bool read_inline_xy(reader& r, const toml::table& t, data_series& d) {
    const source_position where{r.file(), d.where[0], d.where[1]};
    for (const auto& [key, out] : {std::pair{"x", &d.x}, std::pair{"y", &d.y}}) {
        const toml::node* n = t.get(key);
        if (!n) {
            r.problem(where, "a [[panel.data]] needs 'file' with columns, or lists x = [...] and y = [...]");
            return false;
        }
        auto v = inline_values(r, *n, key, false);
        if (!v) return false;
        *out = std::move(*v);
    }
    return true;
}

/// The error bars of an inline series; false (reported) at the first bad one.
bool read_inline_errors(reader& r, const toml::table& t, data_series& d) {
    for (const auto& target : error_targets) {
        const toml::node* n = t.get(target.key);
        if (!n) continue;
        const auto parts = error_parts(r, *n, target.key, true);
        for (std::size_t i = 0; i < parts.size(); ++i) {
            auto v = inline_values(r, *parts[i], target.key, true);
            if (!v) return false;
            d.errors.*(i == 0 ? target.lower : target.upper) = std::move(*v);
        }
        if (parts.size() == 1) d.errors.*target.upper = d.errors.*target.lower;
    }
    return true;
}

/// Every list of an inline series is as long as x.
void check_inline_lengths(reader& r, const toml::table& t, const data_series& d) {
    const auto length_problem = [&](const std::vector<double>& v, std::string_view key) {
        if (v.empty() || v.size() == d.x.size()) return;
        r.problem(*t.get(key), "'" + std::string(key) + "' has " + std::to_string(v.size()) + " values and x " +
                                   std::to_string(d.x.size()) + "; every list of a series is as long as x");
    };
    length_problem(d.y, "y");
    for (const auto& target : error_targets) {
        if (!t.get(target.key)) continue;
        length_problem(d.errors.*target.lower, target.key);
        if ((d.errors.*target.upper).size() != (d.errors.*target.lower).size()) {
            length_problem(d.errors.*target.upper, target.key);
        }
    }
}

void read_inline_series(reader& r, const toml::table& t, data_series& d) {
    if (!read_inline_xy(r, t, d) || !read_inline_errors(r, t, d)) return;
    check_inline_lengths(r, t, d);
}

/// The unit of one axis' data: given, or the quantity's only unit; checked against the axis.
std::optional<data_unit> read_unit(reader& r, const toml::table& t, std::string_view key, quantity q,
                                   const figure_spec& f, const source_position& where) {
    const auto allowed = units_of(q);
    const toml::node* n = t.get(key);
    if (!n) {
        if (allowed.size() == 1) return allowed.front();
        r.problem(where, "a [[panel.data]] needs " + std::string(key) + ": this axis shows " +
                             std::string(quantity_name(q)) + "; give " + unit_choices(q));
        return std::nullopt;
    }
    const auto u = r.choice_of(*n, key, unit_names);
    if (!u) return std::nullopt;
    if (std::find(allowed.begin(), allowed.end(), *u) == allowed.end()) {
        r.problem(*n, "'" + std::string(key) + "' = \"" + std::string(unit_name(*u)) + "\" does not fit this axis, which shows " +
                          std::string(quantity_name(q)) + "; give " + unit_choices(q));
        return std::nullopt;
    }
    if (*u == data_unit::seconds && !f.pendulum) {
        r.problem(*n, "'" + std::string(key) + "' = \"s\" needs a [pendulum] table with length_m (and g): seconds are "
                      "converted with T0 = 2 pi sqrt(L/g)");
        return std::nullopt;
    }
    return u;
}

/// One [[panel.data]] table.
std::optional<data_series> read_one(reader& r, const toml::table& t, const figure_spec& f,
                                    const std::array<quantity, 2>& axes) {
    r.check_keys(t, words(data_keys), "a [[panel.data]]");
    data_series d;
    const source_position where = r.at(t.source());
    d.where = {where.line, where.column};
    if (auto label = r.label(t, "label")) d.label = *label;
    const auto xu = read_unit(r, t, "x_unit", axes[0], f, where);
    const auto yu = read_unit(r, t, "y_unit", axes[1], f, where);
    if (xu) d.x_unit = *xu;
    if (yu) d.y_unit = *yu;
    const std::size_t before = r.problems().size();
    if (auto file = r.string(t, "file")) {
        d.shown_file = *file;
        const auto path = data_path(r, *t.get("file"), *file);
        if (!path) return std::nullopt;
        d.file = *path;
        read_file_series(r, t, d);
    } else if (!t.get("file")) {
        read_inline_series(r, t, d);
    }
    if (r.problems().size() != before || !xu || !yu) return std::nullopt;
    return d;
}

}  // namespace

std::string_view unit_name(data_unit u) {
    for (const auto& [name, unit] : unit_names) {
        if (unit == u) return name;
    }
    return "";
}

std::optional<std::array<quantity, 2>> data_axes(const panel_spec& p) {
    if (!p.plot) return std::nullopt;
    const std::string_view kind = p.plot->name;
    if (kind == "trajectory") return std::array{quantity::time, quantity::angle};
    if (kind == "phase" || kind == "coefficient") return std::array{quantity::angle, quantity::number};
    if (kind != "period") return std::nullopt;
    const quantity x = p.energy_axis ? quantity::number : quantity::angle;
    switch (p.y) {
        case period_axis::value:
        case period_axis::residual: return std::array{x, quantity::period};
        case period_axis::error_percent: return std::array{x, quantity::percent};
        case period_axis::error_log: return std::array{x, quantity::number};
    }
    return std::nullopt;
}

void read_panel_data(reader& r, const toml::table& panel, const figure_spec& f, panel_spec& p) {
    const toml::node* n = panel.get("data");
    if (!n) return;
    const auto* a = n->as_array();
    if (!a || !a->is_array_of_tables()) {
        r.problem(*n, "measured data are [[panel.data]] tables");
        return;
    }
    if (a->size() > max_data_series_per_panel) {
        r.problem(*n, "a panel takes at most " + std::to_string(max_data_series_per_panel) +
                          " [[panel.data]] series; this one has " + std::to_string(a->size()));
        return;
    }
    const auto axes = data_axes(p);
    if (!axes) return;  // the key was refused with the panel's keys
    for (const auto& e : *a) {
        if (auto d = read_one(r, *e.as_table(), f, *axes)) p.data.push_back(std::move(*d));
    }
}

double unit_factor(data_unit from, data_unit to, double t0_seconds, double period_ratio) {
    // Each unit's value in its quantity's base: radians, or small-swing periods T0.
    const auto base = [&](data_unit u) {
        switch (u) {
            case data_unit::deg: return std::numbers::pi / 180;
            case data_unit::seconds: return 1 / t0_seconds;
            case data_unit::period: return period_ratio;
            default: return 1.0;
        }
    };
    return base(from) / base(to);
}

namespace {

/// Beside measured points the markers are the data's: the exact solution, which the themes
/// draw with circles, is drawn as a solid line instead, unless the spec gave it a style or
/// marker of its own (then it has no theme style_key).
void exact_as_line(plot::panel& panel) {
    for (auto& s : panel.data) {
        if (s.data_slot >= 0 || s.style_key != "exact" || s.overlay) continue;
        s.style_key.clear();
        s.line = plot::line_style::solid;
        s.marker = plot::marker_style::none;
    }
}

}  // namespace

void add_data_series(plot::panel& panel, const panel_spec& p, const data_placement& at) {
    if (!p.data.empty()) exact_as_line(panel);
    for (std::size_t k = 0; k < p.data.size(); ++k) {
        const data_series& d = p.data[k];
        plot::series s;
        s.label = !d.label.empty()         ? plot::tex_label(d.label)
                  : !d.shown_file.empty() ? plot::label(plot::escape_markup(d.shown_file))
                                          : plot::label("data");
        s.line = plot::line_style::none;
        s.marker = plot::marker_style::filled_square;
        s.data_slot = static_cast<int>(k);
        s.id = "data:" + std::to_string(k + 1);
        const double fx = at.x_factor(d.x_unit);
        const double fy = at.y_factor(d.y_unit);
        for (std::size_t i = 0; i < d.x.size(); ++i) {
            const double x = fx * d.x[i];
            s.x.push_back(x);
            s.y.push_back(fy * d.y[i] + (at.y_offset ? at.y_offset(x) : 0.0));
        }
        const auto scaled = [](const std::vector<double>& v, double f) {
            std::vector<double> out;
            for (const double e : v) out.push_back(f * e);
            return out;
        };
        s.errors = {scaled(d.errors.x_lower, fx), scaled(d.errors.x_upper, fx), scaled(d.errors.y_lower, fy),
                    scaled(d.errors.y_upper, fy)};
        panel.data.push_back(std::move(s));
    }
}

void add_angle_number_data(plot::panel& panel, const panel_spec& p) {
    data_placement at;
    at.x_factor = [&p](data_unit u) { return unit_factor(u, angle_axis_unit(p), 0.0, 1.0); };
    at.y_factor = [](data_unit) { return 1.0; };
    add_data_series(panel, p, at);
}

data_unit angle_axis_unit(const panel_spec& p) { return p.degrees ? data_unit::deg : data_unit::rad; }

double small_period_seconds_of(const figure_spec& f) {
    return f.pendulum ? 2 * std::numbers::pi * seconds_per_radian(f) : 0.0;
}

}  // namespace figures
