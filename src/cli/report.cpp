// SPDX-License-Identifier: GPL-3.0-or-later
#include "cli/report.hpp"

#include <cstdio>
#include <iostream>

namespace pendulum::cli {

void report_error(const std::string& message) {
    // Every line starts with the program's name, as gcc's do: a line break in a spec's key or
    // a file's name cannot begin a line of its own (a CI log's "::error ..." command).
    static constexpr std::string_view prefix = "pendulum-figures: error: ";
    std::string out(prefix);
    for (const char c : message) {
        const auto u = static_cast<unsigned char>(c);
        if (c == '\n') {
            out += '\n';
            out += prefix;
        } else if (u < 0x20 || u == 0x7f) {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\x%02x", u);
            out += buf;
        } else {
            out += c;
        }
    }
    std::cerr << out << '\n';
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
