// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// How many threads the writers run: the CPUs this process may use, or what was asked for.

#include <cstddef>

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

}  // namespace plot
