// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Dependency files for build systems, in Make syntax (as gcc -MD writes them).

#include <string>
#include <string_view>
#include <vector>

namespace pendulum::cli {

/// A file name as a Make rule writes it: space and # after a backslash, $ doubled. Throws
/// std::invalid_argument for a name Make cannot write (a newline, or a backslash before a
/// space or # or at the end).
std::string make_escaped(std::string_view name);

/// One Make rule, "TARGET...: PREREQUISITE...", wrapped with backslash-newlines, each name
/// escaped by make_escaped, with an empty rule per prerequisite (as gcc -MP) so that a
/// deleted prerequisite does not stop make.
std::string make_rule(const std::vector<std::string>& targets, const std::vector<std::string>& prerequisites);

}  // namespace pendulum::cli
