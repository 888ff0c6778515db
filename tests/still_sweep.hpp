// SPDX-License-Identifier: GPL-3.0-or-later
// The sweep the figure rules run over: every built-in still figure, in every built-in theme,
// at each of a few theme settings (sizes), built as `render` builds it.
#pragma once

#include "figures/build_options.hpp"
#include "figures/catalog.hpp"
#include "figures/themes.hpp"
#include "plot/render.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace test_support {

/// One figure of the sweep: its catalog entry, its theme and setting, and the figure built at that theme's size.
struct still_case {
    const figures::entry& entry;  ///< the built-in
    std::string theme_name;       ///< the built-in theme's name
    std::string setting;          ///< the theme setting ("" for the theme's own size)
    const plot::theme& theme;     ///< the theme with the setting applied
    const plot::figure& figure;   ///< the figure built at the theme's panel size

    /// "id theme setting", to name the case in a failure message.
    std::string where() const { return entry.id + " " + theme_name + (setting.empty() ? "" : " " + setting); }
};

/// What a sweep did: cases checked, and cases refused because the size was too small for the theme's text.
struct sweep_counts {
    int checked = 0;  ///< cases whose check returned
    int refused = 0;  ///< cases whose check threw plot::layout_error (refused with a message, nothing drawn)
};

/// Calls check(case) for every built-in still figure x built-in theme x setting ("" = the theme as it is).
/// A check that throws plot::layout_error counts as refused; the sweep stops once the test has a fatal failure.
template <class Check>
sweep_counts for_each_still_builtin(const std::vector<std::string>& settings, Check check) {
    sweep_counts counts;
    for (const auto& builtin : figures::builtin_themes()) {
        for (const std::string& setting : settings) {
            std::vector<std::string> sets;
            if (!setting.empty()) sets.push_back(setting);
            const plot::theme theme = figures::load_theme(builtin.name, sets);
            for (const auto& e : figures::catalog()) {
                if (e.spec.animation) continue;
                const plot::figure fig = figures::build(e, figures::sized_by({}, theme));
                try {
                    check(still_case{e, std::string(builtin.name), setting, theme, fig});
                    ++counts.checked;
                } catch (const plot::layout_error&) {
                    ++counts.refused;
                }
                if (::testing::Test::HasFatalFailure()) return counts;
            }
        }
    }
    return counts;
}

}  // namespace test_support
