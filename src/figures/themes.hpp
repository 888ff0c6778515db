// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "plot/theme.hpp"

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace figures {

/// A theme compiled into the program: its style file.
struct builtin_theme {
    std::string_view name;  ///< paper, slides, slides-dark
    std::string_view text;  ///< the TOML source, as in src/figures/themes/NAME.toml
    std::string description;  ///< its `description`, for help and lists
};

/// Every built-in theme, paper first.
std::span<const builtin_theme> builtin_themes();

/// The built-in theme names, "paper, slides, slides-dark".
std::string theme_names();

/// The themes for --help: "paper (black and white, ...), slides (...), ..., or a style file NAME.toml".
std::string theme_help();

/// A theme by built-in name or style file (NAME.toml), with `sets` ("key=value", as in a
/// style file) applied on top. A style file starts from its `base` theme (default paper).
/// Throws spec_error listing every problem, std::runtime_error for an unreadable file.
plot::theme load_theme(std::string_view name_or_file, const std::vector<std::string>& sets = {});

/// The keys of a style file, in the order its unknown-key message lists them.
std::vector<std::string> style_keys();

/// The style file of a built-in theme; throws std::invalid_argument for an unknown name.
std::string_view theme_source(std::string_view name);

}  // namespace figures
