// SPDX-License-Identifier: GPL-3.0-or-later
#include "cli/report.hpp"

#include "common/terminal_text.hpp"

#include <iostream>

namespace pendulum::cli {

void report_error(const std::string& message) {
    // Every line starts with the program's name, as gcc's do: a line break in a spec's key or
    // a file's name cannot begin a line of its own (a CI log's "::error ..." command).
    static constexpr std::string_view prefix = "pendulum-figures: error: ";
    std::string out;
    std::string_view rest = message;
    for (;;) {
        const std::size_t end = rest.find('\n');
        out += std::string(prefix) + common::terminal_text(rest.substr(0, end)) + '\n';
        if (end == std::string_view::npos) break;
        rest.remove_prefix(end + 1);
    }
    std::cerr << out;
}

int write_stdout(std::string_view bytes) {
    std::cout.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    std::cout.flush();
    if (!std::cout) {
        report_error("cannot write to standard output");
        return 1;
    }
    return 0;
}

}  // namespace pendulum::cli
