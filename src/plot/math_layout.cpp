// SPDX-License-Identifier: GPL-3.0-or-later
#include "plot/math_layout.hpp"

namespace plot {

namespace {

/// The end of the element whose content starts at `from`: the position of its "</tag>",
/// past any element of the same tag nested in it (a subscript of a subscript).
std::size_t closing(const std::string& s, std::size_t from, const std::string& tag) {
    const std::string open = "<" + tag + ">";
    const std::string close = "</" + tag + ">";
    int depth = 0;
    for (std::size_t i = from; i < s.size();) {
        if (s.compare(i, open.size(), open) == 0) {
            ++depth;
            i += open.size();
        } else if (s.compare(i, close.size(), close) == 0) {
            if (depth == 0) return i;
            --depth;
            i += close.size();
        } else {
            ++i;
        }
    }
    return std::string::npos;
}

}  // namespace

std::vector<math_piece> split_scripts(const std::string& markup) {
    std::vector<math_piece> pieces(1);
    int depth = 0;  // open elements other than top-level scripts
    std::size_t i = 0;
    bool after_script = false;
    while (i < markup.size()) {
        if (markup[i] != '<') {
            if (after_script) pieces.emplace_back();
            after_script = false;
            pieces.back().base += markup[i++];
            continue;
        }
        const std::size_t end = markup.find('>', i);
        if (end == std::string::npos) {  // not markup; Pango reports it
            pieces.back().base += markup.substr(i);
            break;
        }
        const std::string tag = markup.substr(i + 1, end - i - 1);
        if (depth == 0 && (tag == "sup" || tag == "sub")) {
            const std::size_t close = closing(markup, end + 1, tag);
            if (close != std::string::npos) {
                const bool is_sup = tag == "sup";
                // A second script of the same kind starts a new piece with an empty base.
                if (!after_script || (is_sup ? pieces.back().has_sup : pieces.back().has_sub)) {
                    if (after_script) pieces.emplace_back();
                }
                math_piece& p = pieces.back();
                (is_sup ? p.sup : p.sub) = markup.substr(end + 1, close - end - 1);
                (is_sup ? p.has_sup : p.has_sub) = true;
                after_script = true;
                i = close + tag.size() + 3;
                continue;
            }
        }
        if (after_script) pieces.emplace_back();
        after_script = false;
        if (!tag.empty() && tag[0] == '/') {
            --depth;
        } else if (tag.empty() || tag.back() != '/') {
            ++depth;
        }
        pieces.back().base += markup.substr(i, end - i + 1);
        i = end + 1;
    }
    return pieces;
}

bool only_primes(const std::string& markup) {
    if (markup.empty()) return false;
    for (std::size_t i = 0; i < markup.size();) {
        if (markup.compare(i, 2, "\u02b9") == 0) {
            i += 2;
        } else if (markup.compare(i, 3, "\u2032") == 0 || markup.compare(i, 3, "\u2033") == 0 ||
                   markup.compare(i, 3, "\u2034") == 0) {
            i += 3;
        } else {
            return false;
        }
    }
    return true;
}

}  // namespace plot
