// SPDX-License-Identifier: GPL-3.0-or-later
#include "figures/batch.hpp"

#include "figures/figure_data.hpp"
#include "figures/spec_build.hpp"
#include "pendulum/amplitude.hpp"
#include "plot/frames.hpp"
#include "plot/render.hpp"
#include "plot/workers.hpp"

#include <algorithm>
#include <condition_variable>
#include <deque>
#include <exception>
#include <memory>
#include <iostream>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <thread>

namespace figures {

std::vector<figure_file> files_for(const std::vector<const entry*>& figures, const std::vector<std::string>& formats,
                                   const std::filesystem::path& dir, bool paper_files, const build_options& options) {
    std::vector<figure_file> files;
    for (const auto* e : figures) {
        if (!paper_files) {
            for (const auto& f : formats) files.push_back({e, -1, dir / (e->id + "." + f)});
            continue;
        }
        const auto panels = panels_of(*e, options);
        // A figure that is not in the paper has no paper files at all, and is left out.
        if (std::all_of(panels.begin(), panels.end(), [](const panel_spec& p) { return p.paper_file.empty(); })) {
            continue;
        }
        for (std::size_t i = 0; i < panels.size(); ++i) {
            if (panels[i].paper_file.empty()) {
                throw bad_input("figure '" + e->id + "' panel " + std::to_string(i + 1) +
                                            " has no paper file name (paper_file in its spec)" +
                                            (options.amplitudes.empty() ? "" : "; give at most as many --theta0 "
                                                                               "amplitudes as the figure has panels"));
            }
            for (const auto& f : formats) files.push_back({e, static_cast<int>(i), dir / (panels[i].paper_file + "." + f)});
        }
    }
    return files;
}

std::string figure_csv(const plot::figure& f) { return numbers_csv(numbers_of(f), data_layout::long_rows); }

plot::figure single_panel(const plot::figure& f, int panel, double width_cm) {
    plot::figure one;
    one.panel_width_cm = width_cm;
    one.panel_aspect = f.panel_aspect;
    one.panels.push_back(f.panels.at(panel));
    // The other panels' margins are shared, so every file of the figure has the same frame.
    for (std::size_t i = 0; i < f.panels.size(); ++i) {
        if (static_cast<int>(i) != panel) one.peers.push_back(f.panels[i]);
    }
    // One legend per figure: the plot layer puts it in the file of the panel the whole
    // figure would put it in, or in a band over the first file (all files leave room).
    one.shared_legend = f.shared_legend;
    one.place_in_set = panel;
    // A panel's file is the figure's, in words as in its frame.
    one.words = f.words;
    return one;
}

namespace {

/// What a worker holds at most while writing one of the files: the largest raster's bytes
/// (a panel alone is smaller than its figure, whose size bounds it).
double largest_raster_bytes(const std::vector<figure_file>& files, const build_options& options,
                            const plot::theme& theme, const plot::output_options& output) {
    double most = 0;
    for (const auto& f : files) {
        std::string ext = f.path.extension().string();
        if (!ext.empty()) ext.erase(0, 1);
        if (!plot::find_format(ext).raster) continue;
        const auto [w, h] = plot::pixel_size(figure_grid(f.figure->spec, sized_by(options, theme)), theme, output.dpi);
        most = std::max(most, plot::raster_bytes_per_pixel * w * h);
    }
    return most;
}

/// Work for the pool: build a figure, or write one file of a built figure.
struct task {
    std::size_t figure;  // index into the distinct figures
    std::size_t file;    // index into the files, or npos to build
};

}  // namespace

void write_figures(const std::vector<figure_file>& files, const build_options& options, const plot::theme& theme,
                   const plot::output_options& output) {
    constexpr std::size_t build_it = static_cast<std::size_t>(-1);
    std::vector<const entry*> distinct;
    for (const auto& f : files) {
        if (std::find(distinct.begin(), distinct.end(), f.figure) == distinct.end()) distinct.push_back(f.figure);
    }
    // Building comes first, costliest first (the catalog ends with the iteration to order
    // 40 and the period sweep); a built figure's files go to the front of the queue, so
    // any free core draws them and no core waits at a barrier.
    std::deque<task> queue;
    for (std::size_t i = distinct.size(); i-- > 0;) queue.push_back({i, build_it});
    std::vector<std::shared_ptr<const plot::figure>> built(distinct.size());
    std::mutex mutex;
    std::condition_variable changed;
    std::size_t busy = 0;
    std::exception_ptr first_error;

    auto worker = [&] {
        std::unique_lock lock(mutex);
        for (;;) {
            changed.wait(lock, [&] { return !queue.empty() || busy == 0; });
            if (queue.empty()) return;
            const task t = queue.front();
            queue.pop_front();
            ++busy;
            lock.unlock();
            std::shared_ptr<const plot::figure> figure;
            std::exception_ptr error;
            std::string warnings;  // what the layout left out, said once the lock is held
            try {
                if (t.file == build_it) {
                    figure = std::make_shared<const plot::figure>(build(*distinct[t.figure], sized_by(options, theme)));
                } else {
                    const figure_file& f = files[t.file];
                    const plot::figure& whole = *built[t.figure];
                    const plot::layout_notes notes;
                    plot::save(f.panel < 0 ? whole : single_panel(whole, f.panel, whole.panel_width_cm), theme,
                               f.path, output);
                    for (const auto& line : notes.lines()) {
                        warnings += "pendulum-figures: warning: " + f.path.filename().string() + ": " + line + "\n";
                    }
                }
            } catch (...) {
                error = std::current_exception();
            }
            lock.lock();
            std::cerr << warnings;
            --busy;
            if (error && !first_error) first_error = error;
            if (figure) {
                built[t.figure] = figure;
                for (std::size_t k = files.size(); k-- > 0;) {
                    if (files[k].figure == distinct[t.figure]) queue.push_front({t.figure, k});
                }
            }
            changed.notify_all();
        }
    };
    // As many workers as there are files, or CPUs, or rasters that fit the memory budget.
    const unsigned workers = plot::workers_within_budget(plot::worker_count(output.jobs, files.size()),
                                                         largest_raster_bytes(files, options, theme, output));
    std::vector<std::thread> threads;
    for (unsigned i = 1; i < workers; ++i) threads.emplace_back(worker);
    worker();
    for (auto& t : threads) t.join();
    if (first_error) std::rethrow_exception(first_error);
}

}  // namespace figures
