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
