// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

namespace figures {

/// The largest spec or style file: a thousand times the largest built-in spec.
inline constexpr std::size_t max_input_file_bytes = 1 << 20;

/// The text of a spec or style file (`what` names it in messages: "spec file"). Throws
/// bad_input unless the path leads to a regular file (not a directory, device or FIFO) of
/// at most max_input_file_bytes, and std::runtime_error if it cannot be read.
std::string read_input_file(const std::filesystem::path& path, std::string_view what);

}  // namespace figures
