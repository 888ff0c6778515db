// SPDX-License-Identifier: GPL-3.0-or-later
#include "plot/workers.hpp"

#include "plot/errors.hpp"

#include <sched.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <thread>

namespace plot {

unsigned usable_cpus() {
    cpu_set_t set;
    CPU_ZERO(&set);
    if (sched_getaffinity(0, sizeof set, &set) == 0) return static_cast<unsigned>(std::max(1, CPU_COUNT(&set)));
    // A mask larger than cpu_set_t (over 1024 CPUs): every CPU the machine has.
    return std::max(1u, std::thread::hardware_concurrency());
}

unsigned worker_count(unsigned jobs, std::size_t tasks) {
    const std::size_t wanted = jobs ? jobs : usable_cpus();
    return static_cast<unsigned>(std::max<std::size_t>(1, std::min(wanted, tasks)));
}

unsigned workers_for_frames(unsigned workers, std::size_t frame_bytes) {
    const std::size_t most = std::size_t{48} << 20;
    const std::size_t fit = frame_bytes ? most / frame_bytes : workers;
    return static_cast<unsigned>(std::clamp<std::size_t>(fit, 1, std::max(1u, workers)));
}

unsigned workers_within_budget(unsigned workers, double bytes_each) {
    const double fit = bytes_each > 0 ? std::floor(raster_budget_bytes / bytes_each) : workers;
    return static_cast<unsigned>(std::clamp<double>(fit, 1, std::max(1u, workers)));
}

void check_worker_memory(double bytes_each, const std::string& what, const std::string& reduce) {
    if (bytes_each <= raster_budget_bytes) return;
    char text[160];
    std::snprintf(text, sizeof text, " would take %.0f MiB of memory; a render takes at most %.0f MiB (",
                  bytes_each / 1048576, raster_budget_bytes / 1048576);
    throw bad_input(what + text + reduce + ")");
}

}  // namespace plot
