// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What several commands parse and check alike: lists of values, amplitudes, orders,
// methods, the output directory and the theme.

#include "cli/lists.hpp"
#include "pendulum/angle.hpp"
#include "cli/errors.hpp"
#include "figures/spec.hpp"
#include "pendulum/amplitude.hpp"
#include "pendulum/methods.hpp"
#include "plot/theme.hpp"

#include <CLI/CLI.hpp>

#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace pendulum::cli {

/// What the help of the commands that take angles says about them.
extern const char* const angle_help;

/// Refuses an empty value (CLI11 validator): '' is never a figure, directory or amplitude.
extern const CLI::Validator non_empty;

/// Calls take(item) for each item of a list option: its text, or the lines (each
/// comma-separated, # comments) of FILE for @FILE and of standard input for -, read as
/// they come, so that a million amplitudes need no more memory than their values.
template <class Take>
void for_each_item(const std::string& text, const std::string& option, Take take) {
    if (text != "-" && (text.empty() || text[0] != '@')) {
        for (const auto& item : split_list(text)) take(item);
        return;
    }
    std::ifstream file;
    if (text != "-") {
        file.open(text.substr(1), std::ios::binary);
        if (!file) throw usage_error(option + " " + shown_text(text) + ": cannot read '" + shown_text(text.substr(1)) + "'");
    }
    std::istream& in = text == "-" ? std::cin : file;
    bool any = false;
    for (std::string line; std::getline(in, line);) {
        line = line.substr(0, line.find('#'));
        if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
        for (auto& item : split_list(line)) {
            const auto first = item.find_first_not_of(" \t\r");
            take(first == std::string::npos ? std::string()
                                             : item.substr(first, item.find_last_not_of(" \t\r") - first + 1));
            any = true;
        }
    }
    if (!any) throw usage_error(option + " " + text + ": no values");
}

/// One --theta0 item, checked; take(text, value) receives it.
template <class Take>
void for_each_amplitude(const std::string& given, Take take) {
    for_each_item(given, "--theta0", [&](const std::string& item) {
        double v = 0;
        try {
            v = parse_angle(item);
            check_amplitude(v);
        } catch (const std::invalid_argument& e) {
            const std::string shown =
                shown_text(item.size() <= 80 ? item : item.substr(0, 40) + "..." + item.substr(item.size() - 20));
            throw usage_error("--theta0 '" + shown + "': " + e.what());
        }
        take(item, v);
    });
}

/// The values of --theta0, checked (a million of them take 8 MB).
std::vector<double> parse_amplitude_values(const std::string& given);

/// Amplitudes as typed and their values; figure titles show them as typed.
std::vector<figures::amplitude> parse_amplitudes(const std::string& given);

/// Parses a method name (NAME or NAME:N) for the option `option`.
method_choice parse_method_option(const std::string& option, const std::string& text);

/// Parses an order N given as text, with a message that names it.
int parse_order(const std::string& text);

/// Parses --order items: orders N and ranges a..b, in the order given, each order once.
std::vector<int> parse_orders(const std::vector<std::string>& items);

/// A comma-separated option value as its items, empty ones kept so that they are reported.
std::vector<std::string> list_items(const std::vector<std::string>& values);

/// The theme of --theme and --set; a bad style file is bad input.
plot::theme chosen_theme(const std::string& name, const std::vector<std::string>& sets);

/// Checks that dir exists and can be written to, naming it otherwise.
void check_output_dir(const std::string& dir);

}  // namespace pendulum::cli
