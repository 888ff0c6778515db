// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <string>
#include <string_view>

namespace pendulum::cli {

/// Prints an error on standard error, one line per line of the message, with control
/// characters shown escaped by common::terminal_text (a typed ESC, CR, CSI or U+202E must
/// not retitle, clear or reorder the terminal).
void report_error(const std::string& message);

/// Writes bytes to standard output and flushes it: 0, or 1 after reporting that it could
/// not be written.
int write_stdout(std::string_view bytes);

}  // namespace pendulum::cli
