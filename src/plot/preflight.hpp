// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A preflight: a figure measured as drawn (every text's size at final size, every stroke's
// width, the figure's width, the series' greys) against a journal's rules for figures.

#include "plot/figure.hpp"
#include "plot/theme.hpp"

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace plot {

/// One journal's rules for a figure at final size: a row of journal_table().
struct journal_rules {
    std::string_view name;   ///< as --check takes it: aps, aip, ajp
    std::string_view title;  ///< the journals it stands for
    double column_cm;        ///< the widest one-column figure
    double page_cm;          ///< the widest two-column figure
    double min_text_pt;      ///< the smallest lettering
    double min_script_pt;    ///< the smallest superscript or subscript
    double min_line_pt;      ///< the thinnest line
    std::string_view source; ///< where the rules are written
};

/// Every journal --check knows, one row each.
std::span<const journal_rules> journal_table();

/// The journals' names, comma-separated, for messages and help.
std::string journal_names();

/// Which width a check holds a figure to.
enum class column_span {
    either,  ///< one column if it fits, else two columns
    one,     ///< one column (NAME:1)
    two,     ///< two columns (NAME:2)
};

/// A journal and the width a figure is checked at.
struct journal_check {
    const journal_rules* rules = nullptr;  ///< the journal's row
    column_span span = column_span::either;  ///< the width asked for
};

/// Parses JOURNAL, JOURNAL:1 or JOURNAL:2; throws bad_input naming the value and the known
/// journals otherwise.
journal_check find_journal(std::string_view text);

/// Two labelled series of one panel, of different colours, whose greys differ by less than
/// this (of black to white, 0 to 1) and that have the same dash and marker cannot be told
/// apart in greyscale print.
constexpr double min_grey_step = 0.15;

/// The grey a colour prints as in greyscale: its luma (ITU-R BT.601 weights of the
/// gamma-encoded components), 0 black to 1 white.
double grey_of(const rgb& c);

/// One run of text as set: its characters and the size of its glyphs at final size.
struct set_text {
    std::string text;    ///< the run's characters (plain text)
    std::string whole;   ///< the whole label it belongs to (plain text)
    double size_pt = 0;  ///< the size its glyphs are set at
    bool script = false; ///< a superscript or subscript (smaller than its label's size)
    std::string where;   ///< the panel ("(a)", "panel 2") or "" for a one-panel figure
    std::string key;     ///< the style key of its label's size (tick_font_pt, ...), for advice
};

/// One stroke as drawn: its width at final size and what it draws.
struct set_stroke {
    double width_pt = 0;  ///< the line's width
    std::string where;    ///< the panel, as set_text's
};

/// A labelled series as drawn: what tells it apart from the others of its panel.
struct set_series {
    std::string label;  ///< its legend text (plain)
    rgb color;          ///< its colour
    line_style line = line_style::solid;  ///< its dash
    marker_style marker = marker_style::none;  ///< its marker
    std::string where;  ///< the panel
};

/// What a figure sets, measured while it is drawn.
struct figure_measure {
    double width_cm = 0;                 ///< the page's width
    double height_cm = 0;                ///< the page's height
    std::vector<set_text> texts;         ///< every run of every text
    std::vector<set_stroke> strokes;     ///< every stroke
    std::vector<std::vector<set_series>> series;  ///< each panel's labelled series
};

/// Draws the figure as a vector file draws it and records what it sets: the sizes of the
/// glyph runs Pango shaped for each text, the width of each stroke Cairo was asked for (at
/// the page's scale), the page's size and the labelled series' colours and styles.
figure_measure measure_figure(const figure& fig, const theme& th);

/// Each rule of the journal the measured figure breaks, one line each naming the panel, the
/// text or line, the measured value, the rule and what to do; empty when it keeps to them.
std::vector<std::string> preflight_problems(const figure_measure& m, const journal_check& check);

/// For a figure checked without a span (--check NAME) that is wider than the journal's column and
/// no wider than its page: that it must be included at its natural size, and its smallest text
/// if it were scaled to the column (to 0.1 pt, rounded down); else "".
std::string scaling_note(const figure_measure& m, const journal_check& check);

/// How an angle is written in a label: "9π/10" (a fraction of π), "0.95π" (a decimal).
/// Empty where a figure writes its angles one way; else one line naming an angle of each
/// way, which the layout notes on stderr: a figure writes π one way in all its labels.
std::string angle_notation_problem(const figure& fig);

}  // namespace plot
