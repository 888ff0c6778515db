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

/// The label as plain text for CSV headers and file metadata: the same rules, no markup.
std::string tex_to_plain(std::string_view tex);

}  // namespace plot
