// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <filesystem>
#include <memory>
#include <string_view>

namespace plot {

/// A file written piece by piece, as write_atomically writes one whole: under a temporary
/// name beside it, on disk, then renamed by commit(), so that a failure or a crash leaves
/// the old file or the complete new one. What check_output_file refuses is refused. A file
/// destroyed before commit() is removed.
class streamed_file {
public:
    /// Opens the temporary for path; throws plot::bad_input as check_output_file does, or
    /// std::runtime_error naming the path.
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

struct prepared_file;

/// While it is open, the files this process writes (write_atomically, streamed_file) are
/// complete under their temporary names but neither synced nor renamed; commit() puts them
/// all on disk with one syncfs per file system and then renames them in the order they were
/// finished. A crash leaves each file old or new, as one fsync per file did, for one sync
/// instead of many. Destroyed without commit(), it removes the temporaries. One at a time.
class durable_batch {
public:
    /// Opens the batch; throws std::logic_error if one is open already.
    durable_batch();
    ~durable_batch();
    durable_batch(const durable_batch&) = delete;
    durable_batch& operator=(const durable_batch&) = delete;

    /// Syncs and renames every file finished since it opened, and closes the batch; throws
    /// std::runtime_error naming a file that failed (then no file of the batch has changed,
    /// unless its rename had already been done).
    void commit();

    /// Takes a finished temporary, to be synced and renamed by commit().
    void defer(prepared_file&& f);

private:
    struct state;
    std::unique_ptr<state> state_;
};

}  // namespace plot
