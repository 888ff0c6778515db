// SPDX-License-Identifier: GPL-3.0-or-later
#include "cli/depfile.hpp"

#include "cli/lists.hpp"

#include <stdexcept>

namespace pendulum::cli {

std::string make_escaped(std::string_view name) {
    std::string out;
    for (std::size_t i = 0; i < name.size(); ++i) {
        const char c = name[i];
        if (c == '\n' || c == '\r') {
            throw std::invalid_argument("'" + shown_text(name) + "' has a line break, which a Make rule cannot hold");
        }
        // Make reads "\ " as a space; a backslash that comes before one (or ends the name)
        // would be read as an escape, and no escaping of it works in both make and ninja.
        if (c == '\\' && (i + 1 == name.size() || name[i + 1] == ' ' || name[i + 1] == '#')) {
            throw std::invalid_argument("'" + shown_text(name) + "' has a backslash before a space or # or at "
                                        "its end, which a Make rule cannot hold");
        }
        if (c == ' ' || c == '#') out += '\\';
        if (c == '$') out += '$';
        out += c;
    }
    return out;
}

std::string make_rule(const std::vector<std::string>& targets, const std::vector<std::string>& prerequisites) {
    std::string out;
    for (std::size_t i = 0; i < targets.size(); ++i) out += (i ? " \\\n " : "") + make_escaped(targets[i]);
    out += ":";
    for (const auto& p : prerequisites) out += " \\\n  " + make_escaped(p);
    out += "\n";
    for (const auto& p : prerequisites) out += "\n" + make_escaped(p) + ":\n";
    return out;
}

}  // namespace pendulum::cli
