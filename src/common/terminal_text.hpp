// SPDX-License-Identifier: GPL-3.0-or-later
// The one quoting of text that reaches a terminal (stderr's errors, warnings and notes): a
// file name, label or value from a stranger is shown, never obeyed. Header-only, and every
// layer may include src/common (tests/layering_test.sh).
#pragma once

#include <cstddef>
#include <cstdio>
#include <string>
#include <string_view>

namespace common {

/// The length of the UTF-8 sequence at the start of `s` (shortest form, no surrogates, at
/// most U+10FFFF) and its code point in `cp`; 0 if `s` does not start with one.
inline std::size_t utf8_sequence(std::string_view s, char32_t& cp) {
    const auto b = [&](std::size_t i) { return static_cast<unsigned char>(s[i]); };
    const unsigned char lead = b(0);
    if (lead < 0x80) {
        cp = lead;
        return 1;
    }
    const std::size_t n = lead >= 0xc2 && lead <= 0xdf ? 2 : lead >= 0xe0 && lead <= 0xef ? 3
                                                        : lead >= 0xf0 && lead <= 0xf4 ? 4 : 0;
    if (n == 0 || s.size() < n) return 0;
    cp = lead & (0x7f >> n);
    for (std::size_t i = 1; i < n; ++i) {
        if ((b(i) & 0xc0) != 0x80) return 0;
        cp = (cp << 6) | (b(i) & 0x3f);
    }
    const bool overlong = (n == 3 && cp < 0x800) || (n == 4 && cp < 0x10000);
    if (overlong || (cp >= 0xd800 && cp <= 0xdfff) || cp > 0x10ffff) return 0;
    return n;
}

/// True for a code point a terminal may obey or that reorders what is shown: C0 and C1
/// controls, DEL, and the bidirectional marks, embeddings, overrides and isolates.
inline bool terminal_control(char32_t cp) {
    return cp < 0x20 || (cp >= 0x7f && cp <= 0x9f) || cp == 0x061c || cp == 0x200e || cp == 0x200f ||
           (cp >= 0x202a && cp <= 0x202e) || (cp >= 0x2066 && cp <= 0x2069);
}

/// `text` as a terminal may show it: every control character (C0, DEL, C1: ESC, BEL, CR,
/// CSI as U+009B), every bidirectional control (U+202E, U+2066, ...) and every byte that is
/// not UTF-8 written as \xNN or \u{NNNN}; printable UTF-8 as it is.
inline std::string terminal_text(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    while (!text.empty()) {
        char32_t cp = 0;
        const std::size_t n = utf8_sequence(text, cp);
        char buf[16];
        if (n == 0) {
            std::snprintf(buf, sizeof buf, "\\x%02x", static_cast<unsigned char>(text[0]));
            out += buf;
        } else if (cp < 0x80 && terminal_control(cp)) {
            std::snprintf(buf, sizeof buf, "\\x%02x", static_cast<unsigned>(cp));
            out += buf;
        } else if (terminal_control(cp)) {
            std::snprintf(buf, sizeof buf, "\\u{%04x}", static_cast<unsigned>(cp));
            out += buf;
        } else {
            out.append(text.substr(0, n));
        }
        text.remove_prefix(n == 0 ? 1 : n);
    }
    return out;
}

}  // namespace common
