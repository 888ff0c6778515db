// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <string>
#include <string_view>

namespace plot {

/// Turns a label written with TeX math in $...$ into Pango markup: plain text outside
/// the dollars (escaped), and inside them italic letters, Greek letters (\vartheta, \pi,
/// ...), primes, _ and ^ with braces, \, and a few symbols, set as TeX sets them.
/// Throws std::invalid_argument naming the label for an unbalanced $ or brace, or a macro
/// it does not know.
std::string tex_to_markup(std::string_view tex);

/// The label as LaTeX for an overlay (pdf_tex, eps_tex): the TeX it was made from by
/// tex_to_markup, verbatim; otherwise plain words as text and everything else as math
/// ($-0.5$, $\pi/2$, $\vartheta_{0} = 3\pi/4$), never a Unicode character LaTeX cannot set.
/// Throws std::invalid_argument naming the label for a character it has no LaTeX for.
std::string markup_to_latex(std::string_view markup);

/// The label as plain text for CSV headers and file metadata: the same rules, no markup.
std::string tex_to_plain(std::string_view tex);

}  // namespace plot
