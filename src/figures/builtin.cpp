// SPDX-License-Identifier: GPL-3.0-or-later
#include "figures/builtin.hpp"

#include <array>
#include <stdexcept>
#include <string>
#include <utility>

namespace figures {

namespace {

/// The spec files of src/figures/specs, by file name without .toml.
constexpr std::pair<std::string_view, std::string_view> sources[] = {
#include "builtin_specs.inc"
};

std::string_view source_of(std::string_view id) {
    for (const auto& [name, text] : sources) {
        if (name == id) return text;
    }
    throw std::logic_error("no spec file src/figures/specs/" + std::string(id) + ".toml");
}

struct row {
    std::string_view id;
    std::string_view alias;
    std::string_view paper_figure;
};

constexpr row order[] = {
    {"c1-lowest", "fig1", "Fig. 1"},         {"trajectory-lowest", "fig2", "Fig. 2"},
    {"coefficients-first", "fig3", "Fig. 3"}, {"trajectory-first", "fig4", "Fig. 4"},
    {"coefficients-second", "fig5", "Fig. 5"}, {"trajectory-second", "fig6", "Fig. 6"},
    {"period", "fig7", "Fig. 7"},             {"convergence", "", "new"},
    {"period-formulas", "", "new"},           {"period-error", "", "new"},
    {"phase-portrait", "", "new"},            {"spectrum", "", "new"},
    {"regimes", "", "new"},
    {"swing", "", "animation"},               {"separatrix", "", "animation"},
    {"over-the-top", "", "animation"},
};

}  // namespace

std::span<const builtin_spec> builtin_specs() {
    // Checked once at start-up: every row has its file and every file its row.
    static const auto specs = [] {
        static_assert(std::size(order) == std::size(sources), "a spec file without a row in the built-in table");
        std::array<builtin_spec, std::size(order)> s{};
        for (std::size_t i = 0; i < std::size(order); ++i) {
            s[i] = {order[i].id, order[i].alias, order[i].paper_figure, source_of(order[i].id)};
        }
        return s;
    }();
    return specs;
}

const builtin_spec* find_builtin(std::string_view id) {
    for (const auto& s : builtin_specs()) {
        if (s.id == id || (!s.alias.empty() && s.alias == id)) return &s;
    }
    return nullptr;
}

}  // namespace figures
