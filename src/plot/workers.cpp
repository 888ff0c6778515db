// SPDX-License-Identifier: GPL-3.0-or-later
#include "plot/workers.hpp"

#include "plot/errors.hpp"

#include <sched.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

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

namespace {

/// The process's slots: how many threads may work at once, and how many do.
struct slots {
    std::mutex lock;
    std::condition_variable freed;
    unsigned limit = 0;  // 0: not set, usable_cpus()
    unsigned busy = 0;
    unsigned most() const { return limit ? limit : usable_cpus(); }
};

slots& process_slots() {
    static slots s;
    return s;
}

/// Whether this thread holds a slot (a worker running a task).
thread_local bool holds_slot = false;

/// Takes up to `want` free slots without waiting; returns how many it took.
unsigned take_free_slots(unsigned want) {
    slots& s = process_slots();
    const std::lock_guard hold(s.lock);
    // A thread without a slot (a command's main thread) counts as one.
    const unsigned taken = s.busy + (holds_slot ? 0 : 1);
    const unsigned free = s.most() > taken ? s.most() - taken : 0;
    const unsigned n = std::min(want, free);
    s.busy += n;
    return n;
}

void give_back_slots(unsigned n) {
    slots& s = process_slots();
    {
        const std::lock_guard hold(s.lock);
        s.busy -= n;
    }
    s.freed.notify_all();
}

}  // namespace

void set_thread_limit(unsigned jobs) {
    slots& s = process_slots();
    {
        const std::lock_guard hold(s.lock);
        s.limit = jobs;
    }
    s.freed.notify_all();
}

thread_slot::thread_slot() {
    slots& s = process_slots();
    std::unique_lock hold(s.lock);
    s.freed.wait(hold, [&] { return s.busy < s.most(); });
    ++s.busy;
    holds_slot = true;
}

thread_slot::~thread_slot() {
    holds_slot = false;
    give_back_slots(1);
}

void parallel_for(std::size_t n, const std::function<void(std::size_t)>& f) {
    std::atomic<std::size_t> next{0};
    std::exception_ptr first_error;
    std::mutex error_lock;
    const auto work = [&] {
        for (std::size_t i; (i = next.fetch_add(1)) < n;) {
            try {
                f(i);
            } catch (...) {
                const std::lock_guard hold(error_lock);
                if (!first_error) first_error = std::current_exception();
                next = n;  // the others stop
            }
        }
    };
    const unsigned helpers = n > 1 ? take_free_slots(static_cast<unsigned>(std::min<std::size_t>(n - 1, 64))) : 0;
    std::vector<std::thread> threads;
    try {
        for (unsigned k = 0; k < helpers; ++k) threads.emplace_back(work);
    } catch (...) {
        // Fewer threads than slots taken: this thread does the rest.
    }
    give_back_slots(helpers - static_cast<unsigned>(threads.size()));
    work();
    for (auto& t : threads) t.join();
    give_back_slots(static_cast<unsigned>(threads.size()));
    if (first_error) std::rethrow_exception(first_error);
}

void parallel_for_each(std::size_t n, std::size_t per_task, const std::function<void(std::size_t)>& f) {
    parallel_for((n + per_task - 1) / per_task, [&](std::size_t task) {
        for (std::size_t i = task * per_task; i < std::min(n, (task + 1) * per_task); ++i) f(i);
    });
}

}  // namespace plot
