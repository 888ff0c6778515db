// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "plot/figure.hpp"

#include <cstddef>
#include <span>
#include <string>
#include <string_view>

namespace plot {

/// The longest label, in bytes: no axis label, title or legend entry comes near it, and it
/// bounds the work a label can ask for.
inline constexpr std::size_t max_label_bytes = 1000;

/// Why `text` cannot be drawn or printed as it is (empty if it can): more than `max_bytes`
/// bytes, not valid UTF-8 (overlong forms, surrogates and code points past U+10FFFF are
/// refused), a C0 or C1 control character or DEL (a label, title or description is one line
/// of text), or a noncharacter (U+FDD0..U+FDEF, U+xxFFFE, U+xxFFFF), which XML forbids. The
/// one check of every text a spec, style file or command line gives; the reason does not
/// quote the text.
std::string text_problem(std::string_view text, std::size_t max_bytes = max_label_bytes);

/// What a macro of a label's math is.
enum class macro_kind {
    symbol,    ///< a character or word on its own: \\theta, \\le, \\sin, \\,
    function,  ///< takes arguments and lays them out: \\sqrt, \\frac, \\left ... \\right
    accent,    ///< a mark over its argument: \\dot, \\hat, \\overline
    font,      ///< its argument in another face: \\mathrm, \\mathbf, \\text
};

/// How TeX spaces a symbol against its neighbours in math.
enum class math_class {
    ordinary,  ///< no space: letters, Greek, \\infty
    binary,    ///< a medium space each side between operands: \\cdot, \\times, \\pm
    relation,  ///< a thick space each side: \\le, \\approx, \\to
};

/// One macro a label's math may use: the one table the parser, the LaTeX writer and the
/// man page's list are made from.
struct tex_macro {
    std::string_view name;    ///< without the backslash: "theta", ","
    std::string_view markup;  ///< symbol: its text; accent: its combining mark (empty: an overline); font: its Pango tag; function: what it draws
    std::string_view latex;   ///< what the overlay's LaTeX writes for it
    macro_kind kind;          ///< symbol, function, accent or font
    bool italic = false;      ///< a symbol set in italic (lowercase Greek)
    math_class spacing = math_class::ordinary;  ///< a symbol's spacing
};

/// Every macro of a label's math, in the order of the man page's list.
std::span<const tex_macro> tex_macros();

/// The man page's list of the macros (tbl(1) rows between .TS and .TE), from tex_macros().
std::string tex_macros_man();

/// Turns a label written with TeX math in $...$ into Pango markup: plain text outside
/// the dollars (escaped), and inside them italic letters, Greek letters (\vartheta, \pi,
/// ...), primes, _ and ^ with braces, \, and a few symbols, set as TeX sets them.
/// Throws std::invalid_argument naming the label for an unbalanced $ or brace, a macro it
/// does not know, a control character, nesting deeper than 50 levels, or more than
/// max_label_bytes.
std::string tex_to_markup(std::string_view tex);

/// The label's TeX as LaTeX for an overlay, written from the same parse as the markup:
/// text escaped (\input is \textbackslash{}input), math holding only the characters and
/// macros the engine draws, so that a label can never make a document read, write or run
/// anything. Throws as tex_to_markup does, and for a character LaTeX has no form for.
std::string tex_to_latex(std::string_view tex);

/// A label from a spec's TeX: its markup, and its LaTeX (empty where a character has no
/// LaTeX form: an overlay then names it). Throws as tex_to_markup does.
label tex_label(std::string_view tex);

/// The LaTeX an overlay sets for the label: its own, or the one made from its markup.
std::string label_latex(const label& l);

/// The label a followed by b, in both forms.
label join(const label& a, const label& b);

/// A label made by the program as LaTeX for an overlay (pdf_tex, eps_tex): plain words as
/// text and everything else as math ($-0.5$, $\pi/2$, $\vartheta_{0} = 3\pi/4$), every
/// character escaped, never a Unicode character LaTeX cannot set. Throws
/// std::invalid_argument naming the label for a character it has no LaTeX for.
std::string markup_to_latex(std::string_view markup);

/// The label as plain text for CSV headers and file metadata: the same rules, no markup.
std::string tex_to_plain(std::string_view tex);

}  // namespace plot
