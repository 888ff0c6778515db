// SPDX-License-Identifier: GPL-3.0-or-later
// Video files through the video module: found beside the program (a build tree) or in
// LIBDIR/pendulum-figures/ (installed), loaded once, kept loaded.
#include "plot/video.hpp"

#include "plot/output.hpp"
#include "plot/video_module.hpp"

#include <dlfcn.h>

#include <mutex>
#include <stdexcept>
#include <system_error>
#include <vector>

#ifndef PENDULUM_MODULE_DIR
#define PENDULUM_MODULE_DIR "lib/pendulum-figures"
#endif

namespace plot {

namespace {

/// Where the module may be: beside the program, then PREFIX/LIBDIR/pendulum-figures for a
/// program in PREFIX/bin (an installed tree may be moved: nothing is absolute).
std::vector<std::filesystem::path> module_places() {
    std::error_code ec;
    const std::filesystem::path program = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (ec) return {};
    const std::filesystem::path dir = program.parent_path();
    return {dir / video_module_file, dir.parent_path() / PENDULUM_MODULE_DIR / video_module_file};
}

/// Loads the module, or says where it looked and why it could not.
const video_module& load() {
    std::string tried;
    for (const auto& place : module_places()) {
        std::error_code ec;
        if (!std::filesystem::exists(place, ec)) {
            tried += (tried.empty() ? "" : ", ") + place.string();
            continue;
        }
        // Kept loaded to the end: its frames and files may outlive any one video.
        void* handle = dlopen(place.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!handle) throw std::runtime_error(std::string("cannot load the video module: ") + dlerror());
        using entry = const video_module* (*)();
        auto* get = reinterpret_cast<entry>(dlsym(handle, "pendulum_figures_video_module"));
        const video_module* module = get ? get() : nullptr;
        if (!module || module->version != video_module_version) {
            throw std::runtime_error("cannot load the video module " + place.string() +
                                     ": it is from another build of pendulum-figures");
        }
        return *module;
    }
    throw std::runtime_error(std::string("cannot write videos: the video module ") + video_module_file +
                             " is not installed (looked for " + (tried.empty() ? "it" : tried) +
                             "); install pendulum-figures again");
}

/// The module, loaded on first use; a failure is thrown again on every use.
const video_module& module() {
    static const video_module* loaded = nullptr;
    static std::mutex mutex;
    std::lock_guard lock(mutex);
    if (!loaded) loaded = &load();
    return *loaded;
}

}  // namespace

std::pair<int, int> video_frame_rate(double fps) { return module().frame_rate(fps); }

video_encoder::video_encoder(const std::filesystem::path& path, const std::string& shown, video_kind kind,
                             int width, int height, double fps)
    : sink_(module().open(path, shown, kind, width, height, fps, pdf_creation_date())) {}

video_encoder::~video_encoder() = default;

video_frame video_encoder::convert(const argb_image& image) const { return sink_->convert(image); }

void video_encoder::add(video_frame frame) { sink_->add(std::move(frame)); }

void video_encoder::finish() { sink_->finish(); }

}  // namespace plot
