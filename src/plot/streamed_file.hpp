// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <filesystem>
#include <memory>
#include <string_view>

namespace plot {

/// A file written piece by piece, as write_atomically writes one whole: under a temporary
/// name beside it, on disk, then renamed by commit(), so that a failure or a crash leaves
/// the old file or the complete new one. A device, FIFO or socket is written through. A file
/// destroyed before commit() is removed.
class streamed_file {
public:
    /// Opens the temporary for path; throws std::runtime_error naming the path.
    explicit streamed_file(const std::filesystem::path& path);
    ~streamed_file();
    streamed_file(const streamed_file&) = delete;
    streamed_file& operator=(const streamed_file&) = delete;

    /// Appends bytes; throws std::runtime_error naming the path (the temporary is then gone).
    void write(std::string_view bytes);

    /// Puts the file on disk and gives it its name.
    void commit();

private:
    struct state;
    std::unique_ptr<state> state_;
};

}  // namespace plot
