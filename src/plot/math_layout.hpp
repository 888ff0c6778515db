// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Part of the plot layer's renderer; not a public interface.

#include <string>
#include <vector>

namespace plot {

/// One piece of a label: a run of markup set on the baseline, then the superscript and
/// subscript attached to it, stacked one above the other as TeX stacks them.
struct math_piece {
    std::string base;      ///< markup on the baseline; may be empty
    std::string sup;       ///< superscript markup
    std::string sub;       ///< subscript markup
    bool has_sup = false;  ///< a superscript follows the base
    bool has_sub = false;  ///< a subscript follows the base
};

/// Splits markup at its top-level <sup> and <sub> elements; a <sup> and a <sub> next to
/// each other belong to one piece. Scripts nested in other elements stay in the base.
std::vector<math_piece> split_scripts(const std::string& markup);

/// A run of markup cut at its accented characters: either a run without accents, or one
/// character with the combining marks (U+0300..U+036F, U+20D0..U+20FF) that sat on it, which
/// the layout places from the character's ink, as TeX places a math accent.
struct accent_piece {
    std::string text;  ///< well-formed markup: the run, or the accented character in the elements around it
    std::string mark;  ///< the combining marks over `text`; empty for a run without accents
};

/// Cuts markup at its accented characters, closing the open elements before each cut and
/// opening them again after it, so that every piece is markup of its own (the last piece
/// is left as the markup ends: an element it leaves open, Pango reports). Runs of nothing
/// but tags are left out.
std::vector<accent_piece> split_accents(const std::string& markup);

/// The length in bytes of the combining marks (U+0300..U+036F, U+20D0..U+20FF) at s[pos].
std::size_t combining_marks_at(const std::string& s, std::size_t pos);

/// True if the markup is only prime marks (′ ″ ‴): TeX's prime is a superscript whose
/// glyph stands on the baseline, while the Unicode glyph is drawn already raised.
bool only_primes(const std::string& markup);

/// A piece of a run of markup for the layout: a run Pango sets as it is, a fraction the
/// layout stacks (<frac>, <dfrac>), or a radical (\u221a then <span overline="single">)
/// whose sign and line the layout draws over its radicand.
struct box_piece {
    enum class kind { run, fraction, radical } type = kind::run;
    std::string text;      ///< a run's markup, or a radical's radicand
    std::string num;       ///< a fraction's numerator
    std::string den;       ///< a fraction's denominator
    bool display = false;  ///< \dfrac: its parts at the size of the text around it
    bool sign = false;     ///< a radical's \u221a (without it, \\overline's line alone)
};

/// Cuts markup at its top-level fractions and radicals; the rest is left in runs.
std::vector<box_piece> split_boxes(const std::string& markup);

/// The markup with every fraction written in line as a/b, a part in parentheses where the
/// TeX marked it (a sum, a relation, a quotient or product), and every other element as
/// it is: what Pango, plain text and the SVG's text elements get.
std::string inline_fractions(const std::string& markup);

/// Where a run of markup is cut before an italic letter that follows a slash (t/T, T_N/T),
/// outside other elements: the position after the slash, or npos. The layout sets that
/// letter no farther from the slash than TeX does (text italic letters stand farther right
/// in their advance than math italic ones).
std::size_t italic_after_slash(const std::string& markup);

/// The ink gap TeX sets between a slash and the math italic letter after it, in ems
/// (measured on $t/T$ set by pdfTeX in Computer Modern: 0.08 em).
inline constexpr double slash_gap = 0.08;

/// True if the markup holds a fraction or radical the layout draws.
bool has_boxes(const std::string& markup);

/// How TeX stacks a fraction, in ems of the text's size: cmsy10's axis height, num2 and
/// denom2 (num1 and denom1 in display style), cmex10's rule thickness, and
/// \nulldelimiterspace each side.
struct fraction_metrics {
    double axis = 0.25;             ///< the rule's middle above the baseline
    double rule = 0.04;             ///< the rule's thickness
    double num_shift = 0.394;       ///< numerator's baseline raised (text style)
    double den_shift = 0.344;       ///< denominator's baseline lowered (text style)
    double num_shift_display = 0.677;  ///< numerator's baseline raised (\dfrac)
    double den_shift_display = 0.686;  ///< denominator's baseline lowered (\dfrac)
    double side = 0.12;             ///< space each side of the rule
};

/// Where scripts go, in ems of the base font: TeX's parameters of Computer Modern
/// (cmsy10's sup1, sub1 and sub2) and its script size.
struct script_metrics {
    double size = 0.7;                 ///< script size
    double sup_shift = 0.413;          ///< superscript baseline raised
    double sub_shift = 0.15;           ///< subscript baseline lowered, alone
    double sub_shift_with_sup = 0.247;  ///< subscript baseline lowered, under a superscript
    double prime_height = 0.28;        ///< ink height of a prime (cmsy7's, as it looks beside the text)
};

}  // namespace plot
