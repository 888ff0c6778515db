// SPDX-License-Identifier: GPL-3.0-or-later
#include "figures/batch.hpp"

#include "common/terminal_text.hpp"
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

namespace {

/// A panel as the paper's files draw it: the paper's y range (paper_y_range), kept exactly.
plot::panel in_paper_range(plot::panel p) {
    if (p.y.paper_range) {
        p.y.min = p.y.paper_range->first;
        p.y.max = p.y.paper_range->second;
        p.y.exact_range = true;
    }
    return p;
}

}  // namespace

plot::figure single_panel(const plot::figure& f, int panel, double width_cm) {
    plot::figure one;
    one.panel_width_cm = width_cm;
    one.panel_aspect = f.panel_aspect;
    one.panels.push_back(in_paper_range(f.panels.at(panel)));
    // The other panels' margins are shared, so every file of the figure has the same frame.
    for (std::size_t i = 0; i < f.panels.size(); ++i) {
        if (static_cast<int>(i) != panel) one.peers.push_back(in_paper_range(f.panels[i]));
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

/// The files' figures, each once, in the order of the files.
std::vector<const entry*> distinct_figures(const std::vector<figure_file>& files) {
    std::vector<const entry*> distinct;
    for (const auto& f : files) {
        if (std::find(distinct.begin(), distinct.end(), f.figure) == distinct.end()) distinct.push_back(f.figure);
    }
    return distinct;
}

/// The pool's queue of tasks and what the tasks share. Building comes first, costliest first
/// (the catalog ends with the iteration to order 40 and the period sweep); a built figure's
/// files go to the front of the queue, so any free core draws them and no core waits at a
/// barrier.
class figure_queue {
public:
    figure_queue(const std::vector<figure_file>& files, const build_options& options, const plot::theme& theme,
                 const plot::output_options& output)
        : files_(files), options_(options), theme_(theme), output_(output), distinct_(distinct_figures(files)),
          built_(distinct_.size()) {
        for (std::size_t i = distinct_.size(); i-- > 0;) queue_.push_back({i, build_it});
    }

    /// Takes tasks until none is left and no other worker can add one.
    void work() {
        std::unique_lock lock(mutex_);
        for (;;) {
            changed_.wait(lock, [&] { return !queue_.empty() || busy_ == 0; });
            if (queue_.empty()) return;
            const task t = queue_.front();
            queue_.pop_front();
            ++busy_;
            lock.unlock();
            std::shared_ptr<const plot::figure> figure;
            std::exception_ptr error;
            std::string warnings;  // what the layout left out, said once the lock is held
            try {
                const plot::thread_slot slot;  // the --jobs limit, shared with a figure's own threads
                figure = run(t, warnings);
            } catch (...) {
                error = std::current_exception();
            }
            lock.lock();
            std::cerr << warnings;
            done(t, figure, error);
        }
    }

    /// Rethrows the first error of any task.
    void rethrow() const {
        if (first_error_) std::rethrow_exception(first_error_);
    }

private:
    static constexpr std::size_t build_it = static_cast<std::size_t>(-1);

    /// Builds the task's figure (returned), or writes its file (null returned), with a
    /// warning line in `warnings` for each thing the layout left out of it.
    std::shared_ptr<const plot::figure> run(const task& t, std::string& warnings) const {
        if (t.file == build_it) {
            return std::make_shared<const plot::figure>(build(*distinct_[t.figure], sized_by(options_, theme_)));
        }
        const figure_file& f = files_[t.file];
        const plot::figure& whole = *built_[t.figure];
        const plot::layout_notes notes;
        plot::save(f.panel < 0 ? whole : single_panel(whole, f.panel, whole.panel_width_cm), theme_, f.path, output_);
        for (const auto& line : notes.lines()) {
            warnings += "pendulum-figures: warning: " +
                        common::terminal_text(f.path.filename().string() + ": " + line) + "\n";
        }
        return nullptr;
    }

    /// A task is done (under the lock): its error kept if the first, its figure's files queued.
    void done(const task& t, const std::shared_ptr<const plot::figure>& figure, const std::exception_ptr& error) {
        --busy_;
        if (error && !first_error_) first_error_ = error;
        if (figure) {
            built_[t.figure] = figure;
            for (std::size_t k = files_.size(); k-- > 0;) {
                if (files_[k].figure == distinct_[t.figure]) queue_.push_front({t.figure, k});
            }
        }
        changed_.notify_all();
    }

    const std::vector<figure_file>& files_;
    const build_options& options_;
    const plot::theme& theme_;
    const plot::output_options& output_;
    std::vector<const entry*> distinct_;
    std::deque<task> queue_;
    std::vector<std::shared_ptr<const plot::figure>> built_;
    std::mutex mutex_;
    std::condition_variable changed_;
    std::size_t busy_ = 0;
    std::exception_ptr first_error_;
};

}  // namespace

void write_figures(const std::vector<figure_file>& files, const build_options& options, const plot::theme& theme,
                   const plot::output_options& output) {
    figure_queue queue(files, options, theme, output);
    plot::set_thread_limit(output.jobs);
    // As many workers as there are files, or CPUs, or rasters that fit the memory budget.
    const unsigned workers = plot::workers_within_budget(plot::worker_count(output.jobs, files.size()),
                                                         largest_raster_bytes(files, options, theme, output));
    std::vector<std::thread> threads;
    for (unsigned i = 1; i < workers; ++i) threads.emplace_back([&queue] { queue.work(); });
    queue.work();
    for (auto& t : threads) t.join();
    queue.rethrow();
}

}  // namespace figures
