// SPDX-License-Identifier: GPL-3.0-or-later
#include "figures/input_file.hpp"

#include "figures/errors.hpp"

#include <fstream>
#include <system_error>

namespace figures {

std::string read_input_file(const std::filesystem::path& path, std::string_view what) {
    const std::string named = std::string(what) + " '" + path.string() + "'";
    std::error_code ec;
    const auto status = std::filesystem::status(path, ec);  // through symbolic links
    if (ec || !std::filesystem::exists(status)) throw bad_input("cannot read " + named + ": no such file");
    if (std::filesystem::is_directory(status)) throw bad_input(named + " is a directory");
    if (!std::filesystem::is_regular_file(status)) {
        throw bad_input(named + " is not a regular file (a device, FIFO or socket)");
    }
    const auto size = std::filesystem::file_size(path, ec);
    if (!ec && size > max_input_file_bytes) {
        throw bad_input(named + " has " + std::to_string(size) + " bytes; at most " +
                        std::to_string(max_input_file_bytes));
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) throw bad_input("cannot read " + named);
    // Read one byte past the limit: a file that grew since it was measured is refused too.
    std::string text(max_input_file_bytes + 1, '\0');
    in.read(text.data(), static_cast<std::streamsize>(text.size()));
    if (in.bad()) throw bad_input("cannot read " + named);
    text.resize(static_cast<std::size_t>(in.gcount()));
    if (text.size() > max_input_file_bytes) {
        throw bad_input(named + " has more than " + std::to_string(max_input_file_bytes) + " bytes");
    }
    return text;
}

}  // namespace figures
