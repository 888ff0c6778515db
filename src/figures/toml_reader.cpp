// SPDX-License-Identifier: GPL-3.0-or-later
#include "figures/toml_reader.hpp"

#include <algorithm>
#include <sstream>

namespace figures {

std::vector<std::string> words(std::string_view text) {
    std::vector<std::string> out;
    std::istringstream in{std::string(text)};
    for (std::string w; in >> w;) out.push_back(w);
    return out;
}

bool contains(const std::vector<std::string>& names, std::string_view name) {
    return std::find(names.begin(), names.end(), name) != names.end();
}

std::string listed(const std::vector<std::string>& names) {
    std::string out;
    for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
    return out;
}

std::optional<plot::rgb> parse_color(std::string_view text) {
    if (text.size() != 7 || text[0] != '#') return std::nullopt;
    double v[3];
    for (int i = 0; i < 3; ++i) {
        int x = 0;
        for (int j = 1; j <= 2; ++j) {
            const char c = text[static_cast<std::size_t>(2 * i + j)];
            const int d = c >= '0' && c <= '9' ? c - '0' : c >= 'a' && c <= 'f' ? c - 'a' + 10 : c >= 'A' && c <= 'F' ? c - 'A' + 10 : -1;
            if (d < 0) return std::nullopt;
            x = 16 * x + d;
        }
        v[i] = x / 255.0;
    }
    return plot::rgb{v[0], v[1], v[2]};
}

}  // namespace figures
