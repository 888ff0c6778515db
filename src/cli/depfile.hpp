// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Dependency files for build systems, in Make syntax (as gcc -MD writes them).

#include <string>
#include <string_view>
#include <vector>

namespace pendulum::cli {

/// A file name as a Make rule writes it, read alike by GNU make and ninja: space and # after a
/// backslash, $ doubled. Throws std::invalid_argument, naming the character, for a name that
/// Make would read as more than a file name: a control character, a backslash, any of
/// : ; = % | & * ? [ ] ( ) " ' < > ^ `, a leading ~, or a special target's form (.PHONY).
std::string make_escaped(std::string_view name);

/// One Make rule, "TARGET...: PREREQUISITE...", wrapped with backslash-newlines, each name
/// escaped by make_escaped, with an empty rule per prerequisite (as gcc -MP) so that a
/// deleted prerequisite does not stop make.
std::string make_rule(const std::vector<std::string>& targets, const std::vector<std::string>& prerequisites);

}  // namespace pendulum::cli
