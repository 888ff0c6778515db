// SPDX-License-Identifier: GPL-3.0-or-later
#include "figures/themes.hpp"

#include "figures/input_file.hpp"
#include "figures/toml_reader.hpp"
#include "plot/render.hpp"

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <utility>
#include <variant>

namespace figures {

namespace {

constexpr std::pair<std::string_view, std::string_view> sources[] = {
#include "builtin_themes.inc"
};

// Paper first: every other theme starts from it.
constexpr std::string_view order[] = {"paper", "slides", "slides-dark"};

/// One key of a style file and where it goes in plot::theme.
struct number_key {
    std::string_view name;
    double plot::theme::*field;
    double lo;
    double hi;
};

/// The smallest whole figure, as wide or high as the smallest panel.
constexpr double min_figure_cm = 1;

constexpr number_key number_keys[] = {
    {"tick_font_pt", &plot::theme::tick_font_pt, 1, 200},
    {"label_font_pt", &plot::theme::label_font_pt, 1, 200},
    {"legend_font_pt", &plot::theme::legend_font_pt, 1, 200},
    {"title_font_pt", &plot::theme::title_font_pt, 0, 200},
    {"min_text_pt", &plot::theme::min_text_pt, 0, 50},
    {"min_script_pt", &plot::theme::min_script_pt, 0, 50},
    {"min_line_pt", &plot::theme::min_line_pt, 0, 50},
    {"tex_agree_pt", &plot::theme::tex_agree_pt, 0, 30},
    {"line_width_pt", &plot::theme::line_width_pt, 0.05, 50},
    {"frame_width_pt", &plot::theme::frame_width_pt, 0.05, 50},
    {"marker_radius_pt", &plot::theme::marker_radius_pt, 0.1, 50},
    {"tick_length_pt", &plot::theme::tick_length_pt, 0, 50},
    {"padding_pt", &plot::theme::padding_pt, 0, 50},
    {"panel_width_cm", &plot::theme::panel_width_cm, min_figure_cm, 100},
    {"panel_aspect", &plot::theme::panel_aspect, 0.1, 10},
    {"figure_width_cm", &plot::theme::fixed_width_cm, 0, 200},
    {"figure_height_cm", &plot::theme::fixed_height_cm, 0, 200},
    {"dpi", &plot::theme::dpi, 10, 2400},
};

struct color_key {
    std::string_view name;
    plot::rgb plot::theme::*field;
};

constexpr color_key color_keys[] = {{"foreground", &plot::theme::foreground}, {"background", &plot::theme::background}};

/// A yes-or-no key of a style file.
struct flag_key {
    std::string_view name;
    bool plot::theme::*field;
};

constexpr flag_key flag_keys[] = {{"opaque_vector_background", &plot::theme::opaque_vector_background}};

/// How an SVG holds its text: glyph outlines, or <text> in the theme's fonts.
constexpr std::array<std::pair<std::string_view, plot::svg_text_mode>, 2> svg_text_modes = {
    {{"path", plot::svg_text_mode::path}, {"text", plot::svg_text_mode::text}}};

/// What an SVG's width and height are in.
constexpr std::array<std::pair<std::string_view, plot::svg_size_unit>, 3> svg_size_units = {
    {{"pt", plot::svg_size_unit::pt}, {"px", plot::svg_size_unit::px}, {"viewbox", plot::svg_size_unit::viewbox}}};

std::vector<std::string> all_keys() {
    std::vector<std::string> keys = {"base",    "description", "font_family", "palette",      "styles",
                                     "size_px", "svg_text",    "svg_size",    "data_palette", "data_markers"};
    for (const auto& k : number_keys) keys.emplace_back(k.name);
    for (const auto& k : color_keys) keys.emplace_back(k.name);
    for (const auto& k : flag_keys) keys.emplace_back(k.name);
    return keys;
}

std::optional<plot::rgb> color(reader& r, const toml::node& n, std::string_view key) {
    const auto* s = n.as_string();
    const auto c = s ? parse_color(s->get()) : std::nullopt;
    if (!c) r.problem(n, "'" + std::string(key) + "' must be a colour \"#rrggbb\"");
    return c;
}

/// The keys of a style file whose values are strings: --set takes their values as typed
/// (--set size_px=0x10 is the text 0x10, not the TOML number 16).
constexpr std::string_view string_keys[] = {"base", "description", "font_family", "size_px", "svg_text", "svg_size"};

/// The smallest and largest side of a raster in pixels.
constexpr int min_side_px = 16;
constexpr int max_side_px = 20000;

/// A raster's size "WIDTHxHEIGHT" in pixels, or what is wrong with it.
std::variant<std::pair<int, int>, std::string> parse_size_px(const std::string& text) {
    // A side: up to 6 digits, else -1.
    const auto side = [](std::string_view digits) {
        if (digits.empty() || digits.size() > 6 || digits.find_first_not_of("0123456789") != std::string_view::npos) {
            return -1;
        }
        return std::stoi(std::string(digits));
    };
    const auto x = text.find('x');
    const int w = x == std::string::npos ? -1 : side(std::string_view(text).substr(0, x));
    const int h = x == std::string::npos ? -1 : side(std::string_view(text).substr(x + 1));
    const std::string range = std::to_string(min_side_px) + " to " + std::to_string(max_side_px) + " pixels";
    if (w < 0 || h < 0) return "not WIDTHxHEIGHT, two whole numbers of pixels (" + range + " each), e.g. \"1920x1080\"";
    for (const auto& [name, v] : {std::pair{"width", w}, std::pair{"height", h}}) {
        if (v < min_side_px || v > max_side_px) {
            return std::string("the ") + name + " " + std::to_string(v) + " is out of range; each side is " + range;
        }
    }
    return std::pair{w, h};
}

/// Markers of measured data: the filled shapes (the methods' circles stay theirs).
constexpr std::array<std::pair<std::string_view, plot::marker_style>, 4> data_marker_names = {{
    {"square", plot::marker_style::filled_square},
    {"triangle", plot::marker_style::filled_triangle},
    {"diamond", plot::marker_style::filled_diamond},
    {"dot", plot::marker_style::filled_circle},
}};

/// A list of `key` whose items `read` reads (nothing for a bad one): all of them, or nothing
/// (reported with `what`) when the list is not one or is empty or has a bad item.
template <class T, class Read>
std::optional<std::vector<T>> read_list(reader& r, const toml::table& doc, std::string_view key, const char* what,
                                        Read read) {
    const toml::node* n = doc.get(key);
    if (!n) return std::nullopt;
    const auto* a = n->as_array();
    std::vector<T> items;
    for (std::size_t i = 0; a && i < a->size(); ++i) {
        if (auto v = read(*a->get(i))) items.push_back(*v);
    }
    if (!a || a->empty()) r.problem(*n, what);
    if (a && !a->empty() && items.size() == a->size()) return items;
    return std::nullopt;
}

/// data_palette and data_markers: the colours and markers measured data series take in turn.
void read_data_style(reader& r, const toml::table& doc, plot::theme& t) {
    if (auto palette = read_list<plot::rgb>(r, doc, "data_palette", "'data_palette' must be a list of colours \"#rrggbb\"",
                                            [&](const toml::node& e) { return color(r, e, "data_palette"); })) {
        t.data_palette = std::move(*palette);
    }
    if (auto shapes = read_list<plot::marker_style>(
            r, doc, "data_markers", "'data_markers' must be a list of square, triangle, diamond or dot",
            [&](const toml::node& e) { return r.choice_of(e, "data_markers", data_marker_names); })) {
        t.data_markers = std::move(*shapes);
    }
}

/// font_family and size_px.
void read_font_and_size(reader& r, const toml::table& doc, plot::theme& t) {
    if (auto v = r.string(doc, "font_family")) {
        if (v->empty()) {
            r.problem(*doc.get("font_family"), "'font_family' must name a font");
        } else {
            t.font_family = *v;
        }
    }
    if (auto v = r.string(doc, "size_px")) {
        const auto size = parse_size_px(*v);
        if (const auto* why = std::get_if<std::string>(&size)) {
            r.problem(*doc.get("size_px"), "'size_px' = \"" + *v + "\": " + *why);
        } else {
            t.width_px = std::get<0>(size).first;
            t.height_px = std::get<0>(size).second;
        }
    }
}

/// The number keys; a whole figure's size is 0 (sized by its panels) or as large as a panel
/// at least: a smaller one would be a raster of no pixels.
void read_numbers(reader& r, const toml::table& doc, plot::theme& t) {
    for (const auto& k : number_keys) {
        auto v = r.number(doc, k.name, k.lo, k.hi);
        const bool whole = k.field == &plot::theme::fixed_width_cm || k.field == &plot::theme::fixed_height_cm;
        if (v && whole && *v > 0 && *v < min_figure_cm) {
            r.problem(*doc.get(k.name), "'" + std::string(k.name) + "' = " + pendulum::format_double(*v) +
                                            " is too small; the smallest allowed is " +
                                            pendulum::format_double(min_figure_cm) +
                                            " (or 0 to size the figure by its panels)");
            v.reset();
        }
        if (v) t.*k.field = *v;
    }
}

/// palette = ["#rrggbb", ...]: all of them, or the theme's where one is bad.
void read_palette(reader& r, const toml::table& doc, plot::theme& t) {
    const toml::node* n = doc.get("palette");
    if (!n) return;
    const auto* a = n->as_array();
    if (!a || a->empty()) {
        r.problem(*n, "'palette' must be a list of colours \"#rrggbb\"");
        return;
    }
    std::vector<plot::rgb> palette;
    for (const auto& e : *a) {
        if (auto c = color(r, e, "palette")) palette.push_back(*c);
    }
    if (palette.size() == a->size()) t.palette = std::move(palette);
}

/// [styles]: NAME = { line = ..., marker = ... }.
void read_named_styles(reader& r, const toml::table& doc, plot::theme& t) {
    const toml::node* n = doc.get("styles");
    if (!n) return;
    const auto* styles = n->as_table();
    if (!styles) {
        r.problem(*n, "'styles' must be a table: [styles] with NAME = { line = ..., marker = ... }");
        return;
    }
    for (const auto& [key, value] : *styles) {
        const auto* st = value.as_table();
        if (!st) {
            r.problem(value, "a style is a table, e.g. exact = { line = \"none\", marker = \"circle\" }");
            continue;
        }
        r.check_keys(*st, {"line", "marker"}, "a style");
        plot::named_style& s = t.styles[std::string(key.str())];
        if (auto v = r.choice(*st, "line", line_styles)) s.line = *v;
        if (auto v = r.choice(*st, "marker", markers)) s.marker = *v;
    }
}

void apply(reader& r, const toml::table& doc, plot::theme& t) {
    r.check_keys(doc, all_keys(), "a style file");
    read_font_and_size(r, doc, t);
    read_numbers(r, doc, t);
    for (const auto& k : color_keys) {
        if (const toml::node* n = doc.get(k.name)) {
            if (auto c = color(r, *n, k.name)) t.*k.field = *c;
        }
    }
    for (const auto& k : flag_keys) {
        if (auto v = r.boolean(doc, k.name)) t.*k.field = *v;
    }
    if (auto v = r.choice(doc, "svg_text", svg_text_modes)) t.svg_text = *v;
    if (auto v = r.choice(doc, "svg_size", svg_size_units)) t.svg_size = *v;
    read_palette(r, doc, t);
    read_data_style(r, doc, t);
    read_named_styles(r, doc, t);
}

std::string read_file(const std::string& path) { return read_input_file(path, "style file"); }

toml::table parse(reader& r, std::string_view text) {
    try {
        return parse_toml(text, r.file());
    } catch (const toml::parse_error& e) {
        throw spec_error({{r.at(e.source()), "not valid TOML: " + std::string(e.description())}});
    }
}

void throw_problems(reader& r) {
    if (!r.problems().empty()) throw spec_error(std::move(r.problems()));
}

/// Throws one problem of a command-line option, which has no line or column.
[[noreturn]] void throw_option_problem(std::string option, std::string what) {
    std::vector<spec_problem> problems(1);
    problems.front().where.file = std::move(option);
    problems.front().what = std::move(what);
    throw spec_error(std::move(problems));
}

/// Refuses a font_family whose first family is not installed, before any work: fontconfig
/// would draw every text in another font. `from` is where the family was given.
void check_font(const std::string& family, const std::string& from) {
    if (plot::font_family_installed(family)) return;
    const std::string first = family.substr(0, family.find(','));
    const std::string package = first.starts_with("CMU ") ? " (Debian package fonts-cmu)" : "";
    throw_option_problem(from, "'font_family' = \"" + family + "\": font '" + first + "' is not installed" + package +
                                   "; fc-list : family lists the installed families");
}

/// The TOML of one --set KEY=VALUE. A value that is not TOML, or is given to a key that
/// takes a string, is a string: --set font_family=DejaVu Sans, --set size_px=0x10.
toml::table parse_set(const std::string& key, const std::string& value) {
    std::string quoted = "\"";
    for (char c : value) {
        if (c == '"' || c == '\\') quoted += '\\';
        quoted += c;
    }
    quoted += '"';
    const bool key_shown = plot::text_problem(key).empty();
    if (const std::string why = plot::text_problem(value); !why.empty()) {
        throw_option_problem(key_shown ? "--set " + key : std::string("--set"), "the value " + why);
    }
    const bool is_string_key = std::find(std::begin(string_keys), std::end(string_keys), key) != std::end(string_keys);
    const bool typed_string = value.starts_with('"') || value.starts_with('\'');
    try {
        try {
            return parse_toml(key + " = " + (is_string_key && !typed_string ? quoted : value), "--set");
        } catch (const toml::parse_error&) {
            return parse_toml(key + " = " + quoted, "--set");
        }
    } catch (const toml::parse_error& e) {
        throw_option_problem("--set " + key, "not a value: " + std::string(e.description()));
    } catch (const spec_error& e) {
        // Positions in a one-line --set mean nothing: the option is named instead.
        std::vector<spec_problem> problems = e.problems();
        for (auto& p : problems) p.where = {key_shown ? "--set " + key : std::string("--set"), 0, 0};
        throw spec_error(std::move(problems));
    }
}

plot::theme load(std::string_view name_or_file, int depth) {
    const bool is_file = name_or_file.ends_with(".toml");
    const std::string file = is_file ? std::string(name_or_file) : std::string(name_or_file) + ".toml";
    const std::string text = is_file ? read_file(file) : std::string(theme_source(name_or_file));
    reader r(file);
    const toml::table doc = parse(r, text);
    plot::theme t;
    const auto base = r.string(doc, "base");
    throw_problems(r);
    if (base) {
        const bool known = std::any_of(builtin_themes().begin(), builtin_themes().end(),
                                       [&](const builtin_theme& b) { return b.name == *base; });
        if (!known || depth > 4) {
            throw spec_error({{r.at(doc.get("base")->source()), "'base' must be a built-in theme: " + theme_names()}});
        }
        t = load(*base, depth + 1);
    } else if (name_or_file != "paper") {
        t = load("paper", depth + 1);
    }
    apply(r, doc, t);
    throw_problems(r);
    if (is_file) {
        for (const auto& [key, value] : doc) t.given.emplace(key.str());
    }
    t.name = is_file ? std::filesystem::path(file).stem().string() : std::string(name_or_file);
    return t;
}

}  // namespace

std::span<const builtin_theme> builtin_themes() {
    static const auto themes = [] {
        static_assert(std::size(order) == std::size(sources), "a theme file without a row in the theme table");
        std::vector<builtin_theme> v;
        for (const auto name : order) {
            for (const auto& [file, text] : sources) {
                if (file == name) {
                    const std::string file = std::string(name) + ".toml";
                    const auto doc = parse_toml(text, file);
                    v.push_back({name, text, doc["description"].value_or(std::string())});
                }
            }
        }
        if (v.size() != std::size(order)) throw std::logic_error("a built-in theme has no style file");
        return v;
    }();
    return themes;
}

std::string theme_names() {
    std::string out;
    for (const auto& t : builtin_themes()) out += (out.empty() ? "" : ", ") + std::string(t.name);
    return out;
}

std::string theme_help() {
    std::string out;
    for (const auto& t : builtin_themes()) {
        out += (out.empty() ? "" : ", ") + std::string(t.name) + " (" + t.description + ")";
    }
    return out + ", or a style file NAME.toml";
}

std::string_view theme_source(std::string_view name) {
    for (const auto& t : builtin_themes()) {
        if (t.name == name) return t.text;
    }
    std::vector<std::string> names;
    for (const auto& t : builtin_themes()) names.emplace_back(t.name);
    const std::string guess = suggest(name, names);
    const std::string shown = plot::text_problem(name).empty() ? "'" + std::string(name) + "'" : std::string("name");
    throw bad_input("unknown theme " + shown + "; themes: " + theme_names() +
                                ", or a style file NAME.toml" + (guess.empty() ? "" : "; did you mean " + guess + "?"));
}

plot::theme load_theme(std::string_view name_or_file, const std::vector<std::string>& sets) {
    plot::theme t = load(name_or_file, 0);
    std::string font_from = (name_or_file.ends_with(".toml") ? "style file " : "theme ") + std::string(name_or_file);
    for (const auto& set : sets) {
        const auto eq = set.find('=');
        if (eq == std::string::npos || eq == 0) {
            const std::string shown = plot::text_problem(set).empty() ? "'" + set + "'" : std::string("the value");
            throw_option_problem("--set", shown + " must be KEY=VALUE, e.g. tick_font_pt=9");
        }
        const std::string key = set.substr(0, eq);
        std::string value = set.substr(eq + 1);
        const toml::table doc = parse_set(key, value);
        reader r("--set " + key);
        apply(r, doc, t);
        // Positions in a one-line --set mean nothing: name the option instead.
        for (auto& p : r.problems()) p.where = {"--set " + set, 0, 0};
        throw_problems(r);
        if (key == "font_family") font_from = "--set " + set;
        t.given.insert(key);
    }
    check_font(t.font_family, font_from);
    if (const std::string why = plot::text_size_problem(t); !why.empty()) {
        throw_option_problem((name_or_file.ends_with(".toml") ? "style file " : "theme ") + std::string(name_or_file), why);
    }
    if (t.width_px > 0) {
        // A size in pixels is a size in points at the theme's resolution: the layout follows
        // from it like any other size, and the raster has exactly those pixels.
        for (const char* key : {"figure_width_cm", "figure_height_cm"}) {
            if (t.given.contains(key) && t.given.contains("size_px")) {
                throw_option_problem("size_px", std::string("size_px and ") + key + " both size the figure; give one");
            }
        }
        // A slide is seen whole, at any size: where the theme has a page width and no
        // resolution is given, the resolution follows the pixels, so text keeps its share of
        // the frame (the slides theme at 1920 x 1080 is 25.4 cm at 192 dpi, not 38.1 at 128).
        if (!t.given.contains("dpi") && t.fixed_width_cm > 0) t.dpi = t.width_px / (t.fixed_width_cm / 2.54);
        t.fixed_width_cm = t.width_px / t.dpi * 2.54;
        t.fixed_height_cm = t.height_px / t.dpi * 2.54;
    }
    return t;
}

std::vector<std::string> style_keys() { return all_keys(); }

}  // namespace figures
