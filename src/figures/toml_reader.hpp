// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "pendulum/angle.hpp"
#include "figures/spec.hpp"
#include "pendulum/amplitude.hpp"
#include "plot/figure.hpp"
#include "plot/tex_markup.hpp"

#include <toml++/toml.h>

#include <array>
#include <cmath>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace figures {

/// The words of a space-separated list.
std::vector<std::string> words(std::string_view text);

/// True if `name` is one of `names`.
bool contains(const std::vector<std::string>& names, std::string_view name);

/// "a, b, c".
std::string listed(const std::vector<std::string>& names);

/// A colour written "#rrggbb", or nothing if it is not one.
std::optional<plot::rgb> parse_color(std::string_view text);

/// Line styles by the names specs and style files use.
inline constexpr std::array<std::pair<std::string_view, plot::line_style>, 6> line_styles = {{
    {"solid", plot::line_style::solid},
    {"dashed", plot::line_style::dashed},
    {"dotted", plot::line_style::dotted},
    {"dash-dot", plot::line_style::dash_dot},
    {"dash-dot-dot", plot::line_style::dash_dot_dot},
    {"none", plot::line_style::none},
}};

/// Markers by the names specs and style files use.
inline constexpr std::array<std::pair<std::string_view, plot::marker_style>, 2> markers = {{
    {"none", plot::marker_style::none},
    {"circle", plot::marker_style::open_circle},
}};

/// The deepest a spec, style file or --set line may nest its keys: dotted keys, [table] and
/// [[array.of.tables]] headers, with the inline tables and lists around a key, counted
/// together. toml++ bounds the nesting of values (TOML_MAX_NESTED_VALUES, 256) but not of
/// keys, and a key 50,000 deep overflows the stack; this is the same bound for keys.
inline constexpr std::size_t max_toml_depth = 256;

/// Parses TOML text from a spec, style file or --set line (`file` names it in messages):
/// the one way such text is parsed. First measures how deep its keys nest (without
/// parsing: strings and comments skipped, a quoted key's dots not counted) and refuses
/// text deeper than max_toml_depth; then parses it; then checks every key and string in it
/// with plot::text_problem. Throws spec_error (with file, line and column) for text too
/// deep or with a bad key or string, and toml::parse_error for text that is not TOML.
toml::table parse_toml(std::string_view text, const std::string& file);

/// Reads typed values from TOML tables, collecting one problem per bad value with its
/// file, line and column (specs and style files).
class reader {
public:
    explicit reader(std::string file) : file_(std::move(file)) {}

    const std::string& file() const { return file_; }
    std::vector<spec_problem>& problems() { return problems_; }

    source_position at(const toml::source_region& r) const {
        return {file_, static_cast<int>(r.begin.line), static_cast<int>(r.begin.column)};
    }

    void problem(const toml::node& n, std::string what) { problems_.push_back({at(n.source()), std::move(what)}); }
    void problem(const source_position& where, std::string what) { problems_.push_back({where, std::move(what)}); }

    /// Reports keys of `table` outside `allowed`, with a suggestion; `context` names the table.
    /// `elsewhere` gives the whole message for a key that belongs to other tables of the sort
    /// (empty for a key unknown to all of them).
    void check_keys(const toml::table& table, const std::vector<std::string>& allowed, const std::string& context,
                    const std::function<std::string(const std::string&)>& elsewhere = {}) {
        for (const auto& [key, value] : table) {
            const std::string name(key.str());
            if (contains(allowed, name)) continue;
            // A long key is shown by its ends, cut between UTF-8 characters.
            const auto boundary = [&](std::size_t i) {
                while (i > 0 && (static_cast<unsigned char>(name[i]) & 0xc0) == 0x80) --i;
                return i;
            };
            const std::string shown =
                name.size() <= 80 ? name : name.substr(0, boundary(40)) + "..." + name.substr(boundary(name.size() - 20));
            std::string what = "unknown key '" + shown + "' in " + context;
            if (std::string why = elsewhere ? elsewhere(name) : std::string(); !why.empty()) {
                what = std::move(why);
            } else if (const auto guess = suggest(name, allowed); !guess.empty()) {
                what += "; did you mean " + guess + "?";
            } else {
                what += "; keys: " + listed(allowed);
            }
            problems_.push_back({at(key.source()), what});
        }
    }

    std::optional<std::string> string(const toml::table& t, std::string_view key) {
        const toml::node* n = t.get(key);
        if (!n) return std::nullopt;
        if (const auto* s = n->as_string()) return s->get();
        problem(*n, "'" + std::string(key) + "' must be a string");
        return std::nullopt;
    }

    /// A string that is a label: TeX math in $...$, checked now so that an unbalanced $ or
    /// brace, or a macro the tool does not know, is reported at its file and line.
    std::optional<std::string> label(const toml::table& t, std::string_view key) {
        auto text = string(t, key);
        if (!text) return text;
        try {
            plot::tex_to_markup(*text);
        } catch (const std::invalid_argument& e) {
            problem(*t.get(key), "'" + std::string(key) + "': " + e.what());
            return std::nullopt;
        }
        return text;
    }

    std::optional<double> number(const toml::table& t, std::string_view key, double lo, double hi,
                                 bool open_lo = false) {
        const toml::node* n = t.get(key);
        if (!n) return std::nullopt;
        double v = 0;
        if (const auto* i = n->as_integer()) {
            v = static_cast<double>(i->get());
        } else if (const auto* f = n->as_floating_point()) {
            v = f->get();
        } else {
            problem(*n, "'" + std::string(key) + "' must be a number");
            return std::nullopt;
        }
        if (!std::isfinite(v) || (open_lo ? v <= lo : v < lo) || v > hi) {
            problem(*n, "'" + std::string(key) + "' = " + pendulum::format_double(v) + " is out of range; allowed " +
                            (open_lo ? "above " : "from ") + pendulum::format_double(lo) + " to " +
                            pendulum::format_double(hi));
            return std::nullopt;
        }
        return v;
    }

    std::optional<int> integer(const toml::table& t, std::string_view key, int lo, int hi) {
        const toml::node* n = t.get(key);
        if (!n) return std::nullopt;
        const auto* i = n->as_integer();
        if (!i) {
            problem(*n, "'" + std::string(key) + "' must be a whole number");
            return std::nullopt;
        }
        if (i->get() < lo || i->get() > hi) {
            problem(*n, "'" + std::string(key) + "' = " + std::to_string(i->get()) + " is out of range; allowed " +
                            std::to_string(lo) + " to " + std::to_string(hi));
            return std::nullopt;
        }
        return static_cast<int>(i->get());
    }

    std::optional<bool> boolean(const toml::table& t, std::string_view key) {
        const toml::node* n = t.get(key);
        if (!n) return std::nullopt;
        if (const auto* b = n->as_boolean()) return b->get();
        problem(*n, "'" + std::string(key) + "' must be true or false");
        return std::nullopt;
    }

    /// A value from a fixed set of names, reported with the names and a suggestion.
    template <class T, std::size_t N>
    std::optional<T> choice(const toml::table& t, std::string_view key,
                            const std::array<std::pair<std::string_view, T>, N>& options) {
        const toml::node* n = t.get(key);
        if (!n) return std::nullopt;
        return choice_of(*n, key, options);
    }

    template <class T, std::size_t N>
    std::optional<T> choice_of(const toml::node& n, std::string_view key,
                               const std::array<std::pair<std::string_view, T>, N>& options) {
        std::vector<std::string> names;
        for (const auto& [name, value] : options) names.emplace_back(name);
        const auto* s = n.as_string();
        if (!s) {
            problem(n, "'" + std::string(key) + "' must be one of " + listed(names));
            return std::nullopt;
        }
        for (const auto& [name, value] : options) {
            if (name == s->get()) return value;
        }
        std::string what = "'" + std::string(key) + "' = \"" + s->get() + "\" is not one of " + listed(names);
        if (const auto guess = suggest(s->get(), names); !guess.empty()) what += "; did you mean " + guess + "?";
        problem(n, what);
        return std::nullopt;
    }

    /// An expression (an angle, with deg, where `is_angle`) given as a string or a number: its
    /// text and value.
    std::optional<std::pair<std::string, double>> expression(const toml::node& n, std::string_view key, bool is_angle) {
        std::string text;
        if (const auto* s = n.as_string()) {
            text = s->get();
        } else if (const auto* i = n.as_integer()) {
            text = std::to_string(i->get());
        } else if (const auto* f = n.as_floating_point()) {
            text = pendulum::format_double(f->get());
        } else {
            problem(n, "'" + std::string(key) + "' must be a number or an expression such as \"pi/2\"");
            return std::nullopt;
        }
        try {
            return std::pair{text, is_angle ? pendulum::parse_angle(text) : pendulum::parse_expression(text)};
        } catch (const std::invalid_argument& e) {
            problem(n, "'" + std::string(key) + "': " + e.what());
            return std::nullopt;
        }
    }

    /// An angle expression given as a string or a number.
    std::optional<amplitude> angle(const toml::node& n, std::string_view key, bool amplitude_range) {
        amplitude a;
        if (const auto* s = n.as_string()) {
            a.text = s->get();
        } else if (const auto* i = n.as_integer()) {
            a.text = std::to_string(i->get());
        } else if (const auto* f = n.as_floating_point()) {
            a.text = pendulum::format_double(f->get());
        } else {
            problem(n, "'" + std::string(key) + "' must be an angle such as \"9pi/10\" or \"170deg\"");
            return std::nullopt;
        }
        try {
            if (amplitude_range) {
                a.value = pendulum::parse_angle(a.text);
            } else {
                a.exact = pendulum::parse_amplitude(a.text, key);
                a.value = a.exact->radians();
            }
            if (amplitude_range && !(a.value >= 0 && a.value <= std::acos(-1.0))) {
                throw std::invalid_argument(std::string(key) + " must lie in [0, pi], got " +
                                            pendulum::format_double(a.value));
            }
        } catch (const std::invalid_argument& e) {
            problem(n, "'" + std::string(key) + "': " + e.what());
            return std::nullopt;
        }
        return a;
    }

private:
    std::string file_;
    std::vector<spec_problem> problems_;
};


}  // namespace figures
