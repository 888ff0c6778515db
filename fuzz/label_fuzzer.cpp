// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer harness: any bytes as a spec label give an error, or markup that Pango accepts
// and LaTeX that holds only the characters and control sequences the engine draws, with
// balanced braces and dollars (so that no label can reach into a document that \inputs it).
#include "plot/math_layout.hpp"
#include "plot/tex_markup.hpp"

#include <pango/pango.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <set>
#include <stdexcept>
#include <string>
#include <string_view>

namespace {

/// What an overlay's text may contain after a backslash.
/// The macro names in a piece of LaTeX: "\\sin " -> sin.
void add_names(std::string_view latex, std::set<std::string>& names) {
    for (std::size_t i = 0; i < latex.size(); ++i) {
        if (latex[i] != '\\' || i + 1 >= latex.size()) continue;
        std::size_t end = i + 1;
        while (end < latex.size() && std::isalpha(static_cast<unsigned char>(latex[end]))) ++end;
        if (end == i + 1) ++end;  // a control symbol: \, \{ ...
        names.emplace(latex.substr(i + 1, end - i - 1));
        i = end - 1;
    }
}

/// What the LaTeX of a label may hold: the macros of the label table (plot::tex_macros(),
/// whose names the notation tests check against every dangerous one), and the text-mode
/// escapes and accents of characters outside math.
bool allowed(const std::string& name) {
    static const std::set<std::string> names = [] {
        std::set<std::string> n = {
            "textbackslash", "textbar", "textless", "textgreater", "backslash", "ss", "ae", "AE", "o", "O", "oe",
            "OE", "l", "L", "i", "c", "H", "v", "u", "r", "prime", "ldots", "dots", "lvert", "rvert", "operatorname",
            ",", ":", ">", ";", "!", " ", "{", "}", "%", "$", "&", "#", "_", "|", "^", "~", "`", "'", "\"", "=", "."};
        for (const auto& m : plot::tex_macros()) {
            add_names(m.latex, n);
        }
        return n;
    }();
    return names.count(name) > 0;
}

void check_latex(const std::string& latex) {
    int braces = 0;
    int dollars = 0;
    for (std::size_t i = 0; i < latex.size(); ++i) {
        const auto c = static_cast<unsigned char>(latex[i]);
        if (c < 0x20 || c >= 0x7f) std::abort();  // only printable ASCII reaches LaTeX
        if (latex[i] == '\\') {
            if (i + 1 >= latex.size()) std::abort();  // a trailing backslash escapes what follows
            std::size_t end = i + 1;
            if (std::isalpha(static_cast<unsigned char>(latex[end]))) {
                while (end < latex.size() && std::isalpha(static_cast<unsigned char>(latex[end]))) ++end;
            } else {
                ++end;
            }
            if (!allowed(latex.substr(i + 1, end - i - 1))) std::abort();
            i = end - 1;
            continue;
        }
        if (latex[i] == '{') ++braces;
        if (latex[i] == '}' && --braces < 0) std::abort();
        if (latex[i] == '$') ++dollars;
    }
    if (braces != 0 || dollars % 2 != 0) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view tex(reinterpret_cast<const char*>(data), size);
    std::string markup;
    try {
        markup = plot::tex_to_markup(tex);
    } catch (const std::invalid_argument&) {
        return 0;  // refused: documented
    }
    // What is drawn is markup Pango reads (or invalid UTF-8 that the spec reader refuses):
    // the whole with its fractions written in line (what Pango, plain text and SVG text
    // get), and each stacked fraction's parts and each run the layout sets.
    const auto pango_reads = [](const std::string& m) {
        return pango_parse_markup(m.c_str(), -1, 0, nullptr, nullptr, nullptr, nullptr) != 0;
    };
    if (g_utf8_validate(markup.data(), static_cast<gssize>(markup.size()), nullptr)) {
        if (!pango_reads(plot::inline_fractions(markup))) std::abort();
        for (const auto& piece : plot::split_boxes(markup)) {
            if (piece.type == plot::box_piece::kind::fraction &&
                (!pango_reads(plot::inline_fractions(piece.num)) || !pango_reads(plot::inline_fractions(piece.den)))) {
                std::abort();
            }
        }
    }
    try {
        check_latex(plot::tex_to_latex(tex));
    } catch (const std::invalid_argument&) {
        // A character LaTeX has no form for: the overlay names it when one is written.
    }
    return 0;
}
