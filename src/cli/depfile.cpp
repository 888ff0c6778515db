// SPDX-License-Identifier: GPL-3.0-or-later
#include "cli/depfile.hpp"

#include "cli/lists.hpp"

#include <stdexcept>

namespace pendulum::cli {

namespace {

/// Why Make (or ninja) cannot hold the byte c of a name in a rule, or null where it can
/// (escaped or as it is). Make reads ':' and '&:' as separators, ';' as the start of a
/// recipe, '=' as a target-specific variable, '%' as a pattern, '|' as order-only
/// prerequisites, '*?[]' and a leading '~' as file names to expand, '(' ')' as an archive's
/// member; ninja's reader takes none of " ' < > ^ `. No escaping of them reads the same in
/// make and ninja, so a name with one is refused rather than written.
const char* unwritable(unsigned char c) {
    if (c < 0x20 || c == 0x7f) return "a control character";
    switch (c) {
        case ':': return "':', which Make reads as the end of the targets";
        case ';': return "';', which Make reads as the start of a command";
        case '=': return "'=', which Make reads as a variable's value";
        case '%': return "'%', which Make reads as a pattern";
        case '|': return "'|', which Make reads as order-only prerequisites";
        case '&': return "'&', which Make reads as grouped targets";
        case '*': case '?': case '[': case ']': return "a wildcard character (* ? [ ]), which Make expands";
        case '(': case ')': return "'(' or ')', which Make reads as an archive's member";
        case '\\': return "a backslash, which Make and ninja read as an escape";
        case '"': case '\'': case '<': case '>': case '^': case '`':
            return "a character that ninja's dependency-file reader does not take (\" ' < > ^ `)";
        default: return nullptr;
    }
}

/// True for a name Make reads as a special target (.PHONY, .SECONDEXPANSION, ...): a dot
/// and capital letters or underscores, nothing else.
bool special_target(std::string_view name) {
    if (name.size() < 2 || name[0] != '.') return false;
    for (const char c : name.substr(1)) {
        if (!((c >= 'A' && c <= 'Z') || c == '_')) return false;
    }
    return true;
}

[[noreturn]] void refuse(std::string_view name, const std::string& why) {
    throw std::invalid_argument("'" + shown_text(name) + "' has " + why +
                                ", so no dependency file can name it; rename the file");
}

}  // namespace

std::string make_escaped(std::string_view name) {
    if (name.empty()) throw std::invalid_argument("an empty file name cannot be named in a dependency file");
    if (name[0] == '~') refuse(name, "a '~' at its start, which Make expands to a home directory");
    if (special_target(name)) refuse(name, "the form of a Make special target");
    std::string out;
    for (const char c : name) {
        if (const char* why = unwritable(static_cast<unsigned char>(c))) refuse(name, why);
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
