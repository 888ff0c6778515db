// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <span>
#include <string_view>

namespace figures {

/// A figure spec compiled into the program: the paper's figures and the new ones.
struct builtin_spec {
    std::string_view id;            ///< the spec's name, used for file names
    std::string_view alias;         ///< fig1 ... fig7, or empty
    std::string_view paper_figure;  ///< "Fig. 1" ... or "new"
    std::string_view text;          ///< the TOML source, as in src/figures/specs/ID.toml
};

/// Every built-in spec, in the paper's order, then the new ones.
std::span<const builtin_spec> builtin_specs();

/// The built-in spec with that id or alias, or null.
const builtin_spec* find_builtin(std::string_view id);

}  // namespace figures
