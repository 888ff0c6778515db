// SPDX-License-Identifier: GPL-3.0-or-later
#include "cli/lists.hpp"

#include "pendulum/angle.hpp"


namespace pendulum::cli {

std::vector<std::string> split_list(std::string_view text) {
    // A comma inside parentheses belongs to its item: formula:besselj(1, theta0) is one.
    std::vector<std::string> items;
    std::size_t start = 0;
    long depth = 0;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text[i] == '(') ++depth;
        if (text[i] == ')' && depth > 0) --depth;
        if (text[i] == ',' && depth == 0) {
            items.emplace_back(text.substr(start, i - start));
            start = i + 1;
        }
    }
    items.emplace_back(text.substr(start));
    return items;
}

std::string shown_text(std::string_view text) { return message_text(text); }

}  // namespace pendulum::cli
