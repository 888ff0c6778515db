// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// How many threads the writers run: the CPUs this process may use, or what was asked for.

#include <cstddef>
#include <functional>
#include <string>

namespace plot {

/// The CPUs this process may run on (its affinity mask, which taskset and cgroups' cpusets
/// narrow), at least 1.
unsigned usable_cpus();

/// The workers for `tasks` tasks: `jobs` if not 0, else usable_cpus(); never more than the
/// tasks, never fewer than 1.
unsigned worker_count(unsigned jobs, std::size_t tasks);

/// At most `workers` workers for frames of `frame_bytes` each, fewer where each would hold
/// a large frame: their frames in flight take 48 MiB at most, or one frame (at 3840 x 2160,
/// 32 MiB a frame, one worker).
unsigned workers_for_frames(unsigned workers, std::size_t frame_bytes);

/// The most memory the rasters of a render's workers may hold together: 2 GiB. Workers
/// are fewer where each would hold a large raster; what one worker cannot hold within it is
/// refused before any work.
inline constexpr double raster_budget_bytes = 2.0 * 1024 * 1024 * 1024;

/// What a worker holds to write one PNG (or a still GIF) of `pixels` pixels: the raster (4
/// bytes a pixel), the pixels as the PNG stores them (up to 3) and its bytes (up to 3, for
/// pixels that do not compress), measured at 10000 x 10000 (see bench/calibrate_costs.sh).
inline constexpr double raster_bytes_per_pixel = 10;

/// At most `workers`, fewer so that each holding `bytes_each` they take at most
/// raster_budget_bytes together; at least 1 (check_worker_memory refuses what 1 cannot).
unsigned workers_within_budget(unsigned workers, double bytes_each);

/// Throws plot::bad_input if one worker holding `bytes_each` would take more than
/// raster_budget_bytes: `what` names the file, `reduce` what to make smaller.
void check_worker_memory(double bytes_each, const std::string& what, const std::string& reduce);

/// The most threads that do a render's work at once (its --jobs; 0: usable_cpus()). Set
/// before a render's workers start; until set, usable_cpus().
void set_thread_limit(unsigned jobs);

/// A slot among the thread limit's, held by a worker while it runs a task: made, it waits
/// for a free one (a figure's own threads may hold them for a while).
class thread_slot {
public:
    thread_slot();
    ~thread_slot();
    thread_slot(const thread_slot&) = delete;
    thread_slot& operator=(const thread_slot&) = delete;
};

/// Runs f(0) ... f(n - 1), each once, on this thread and on as many more as free slots
/// allow (none waits for one), and returns when all have run; the first exception any
/// throws is rethrown. f(i) must depend on i only: the results do not depend on the threads.
void parallel_for(std::size_t n, const std::function<void(std::size_t)>& f);

/// parallel_for over f(0) ... f(n - 1) in tasks of `per_task` consecutive indices (where one
/// f is too short to be a task of its own); the first exception any throws is rethrown.
void parallel_for_each(std::size_t n, std::size_t per_task, const std::function<void(std::size_t)>& f);

}  // namespace plot
