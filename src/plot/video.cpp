// SPDX-License-Identifier: GPL-3.0-or-later
// Video files through the video module, loaded once and kept loaded, from where the build
// or the installation put it only: a copy of the program elsewhere does not look beside
// itself, where a repository could put a module of its own.
#include "plot/video.hpp"

#include "plot/output.hpp"
#include "plot/video_module.hpp"
#include "plot/workers.hpp"

#include <dlfcn.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <mutex>
#include <stdexcept>
#include <string_view>
#include <system_error>
#include <vector>

#ifndef PENDULUM_MODULE_DIR
#define PENDULUM_MODULE_DIR "/usr/local/lib/pendulum-figures"
#endif
#ifndef PENDULUM_PACKAGE_MODULE_DIR
#define PENDULUM_PACKAGE_MODULE_DIR "/usr/lib/pendulum-figures"
#endif
#ifndef PENDULUM_BUILD_DIR
#define PENDULUM_BUILD_DIR ""
#endif

namespace plot {

namespace {

/// The same file, however it is written (a build directory under a symbolic link).
bool same_file(const std::filesystem::path& a, const std::filesystem::path& b) {
    std::error_code ec;
    return std::filesystem::equivalent(a, b, ec);
}

}  // namespace

std::filesystem::path video_module_path(const std::filesystem::path& program) {
    const std::filesystem::path build_dir = PENDULUM_BUILD_DIR;
    // The build's program: the module beside it, in the build directory.
    if (!build_dir.empty() && same_file(program, build_dir / "pendulum-figures")) return build_dir / video_module_file;
    // The Debian package's program (installed with the prefix /usr).
    const std::filesystem::path package_dir = PENDULUM_PACKAGE_MODULE_DIR;
    if (program == "/usr/bin/pendulum-figures") return package_dir / video_module_file;
    // Installed, or a copy anywhere: the installation's library directory.
    return std::filesystem::path(PENDULUM_MODULE_DIR) / video_module_file;
}

std::string module_file_problem(const struct stat& file, const struct stat& dir) {
    const auto trusted_owner = [](uid_t uid) { return uid == 0 || uid == geteuid(); };
    if (!S_ISREG(file.st_mode)) return "it is not a regular file";
    if (!trusted_owner(file.st_uid)) return "it is owned by another user";
    if (file.st_mode & (S_IWGRP | S_IWOTH)) return "others may write it";
    if (!trusted_owner(dir.st_uid)) return "its directory is owned by another user";
    if (dir.st_mode & (S_IWGRP | S_IWOTH)) return "others may write its directory";
    return {};
}

namespace {

/// A file descriptor that closes itself.
struct descriptor {
    int fd = -1;
    explicit descriptor(int f) : fd(f) {}
    descriptor(const descriptor&) = delete;
    descriptor& operator=(const descriptor&) = delete;
    ~descriptor() {
        if (fd >= 0) ::close(fd);
    }
};

/// Opens the module and checks it before any of its code can run (dlopen runs its
/// constructors); the file opened is the file checked, and the one loaded.
void* open_checked(const std::filesystem::path& place) {
    const descriptor file(::open(place.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC | O_NONBLOCK));
    const auto refuse = [&](const std::string& why) {
        return std::runtime_error("cannot load the video module " + place.string() + ": " + why +
                                  "; install pendulum-figures again");
    };
    if (file.fd < 0) throw refuse(std::system_category().message(errno));
    struct stat st {};
    struct stat dir {};
    if (::fstat(file.fd, &st) != 0 || ::stat(place.parent_path().c_str(), &dir) != 0) {
        throw refuse(std::system_category().message(errno));
    }
    if (const std::string why = module_file_problem(st, dir); !why.empty()) throw refuse(why);
    const std::string opened = "/proc/self/fd/" + std::to_string(file.fd);
    void* handle = dlopen(opened.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) throw refuse(dlerror());
    return handle;
}

/// Loads the module, or says where it looked and why it could not.
const video_module& load() {
    std::error_code ec;
    const std::filesystem::path program = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (ec) throw std::runtime_error("cannot write videos: cannot find the program's file: " + ec.message());
    const std::filesystem::path place = video_module_path(program);
    if (!std::filesystem::exists(place, ec)) {
        throw std::runtime_error(std::string("cannot write videos: the video module ") + video_module_file +
                                 " is not installed (looked for " + place.string() +
                                 "); install pendulum-figures again");
    }
    // Kept loaded to the end: its frames and files may outlive any one video.
    void* handle = open_checked(place);
    using entry = const video_module* (*)();
    auto* get = reinterpret_cast<entry>(dlsym(handle, "pendulum_figures_video_module"));
    const video_module* module = get ? get() : nullptr;
    if (!module || module->version != video_module_version) {
        throw std::runtime_error("cannot load the video module " + place.string() +
                                 ": it is from another build of pendulum-figures");
    }
    return *module;
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

namespace {

/// Bytes a pixel of each frame the encoder holds (its planes, half-pixel planes and
/// look-ahead copies), and the frames it holds besides its look-ahead and threads (its
/// references and B-frames): measured, see bench/calibrate_costs.md.
constexpr double encoder_bytes_per_pixel = 6;
constexpr int encoder_frames_held = 8;

/// The kind's options with the look-ahead of `settings`.
std::string options_with(const video_kind& kind, video_settings settings) {
    std::string options = kind.codec_options;
    if (!options.empty()) options += ":";
    return options + kind.lookahead_option + "=" + std::to_string(settings.lookahead);
}

}  // namespace

double video_memory(const video_kind& kind, int width, int height, video_settings settings, unsigned workers) {
    (void)kind;
    const double pixels = static_cast<double>(width) * height;
    const double held = settings.lookahead + settings.threads + encoder_frames_held;
    const double ours = pixels * (4.0 * (workers + 1) + 1.5 * (2 * workers + 1));
    return pixels * encoder_bytes_per_pixel * held + ours;
}

video_settings video_settings_for(const video_kind& kind, int width, int height) {
    video_settings s{kind.threads, kind.lookahead};
    // Fewer frames held until the encoder with one worker fits: look-ahead first, then threads.
    while (video_memory(kind, width, height, s, 1) > raster_budget_bytes && (s.lookahead > 0 || s.threads > 1)) {
        if (s.lookahead > 0) {
            s.lookahead = s.lookahead / 2;
        } else {
            --s.threads;
        }
    }
    return s;
}

void check_video_memory(const video_kind& kind, int width, int height) {
    const video_settings least = video_settings_for(kind, width, height);
    check_worker_memory(video_memory(kind, width, height, least, 1),
                        "a video of " + std::to_string(width) + " x " + std::to_string(height) + " pixels",
                        "lower --dpi or size_px: 4K is the most that fits");
}

std::pair<int, int> video_frame_rate(double fps) { return module().frame_rate(fps); }

namespace {

/// The kind with the settings for its size; `options` holds its options' text.
video_kind sized_kind(const video_kind& kind, int width, int height, std::string& options) {
    const video_settings s = video_settings_for(kind, width, height);
    options = options_with(kind, s);
    video_kind sized = kind;
    sized.codec_options = options.c_str();
    sized.threads = s.threads;
    return sized;
}

}  // namespace

video_encoder::video_encoder(const std::filesystem::path& path, const std::string& shown, video_kind kind,
                             int width, int height, double fps) {
    std::string options;
    const video_kind sized = sized_kind(kind, width, height, options);
    sink_ = module().open(path, shown, sized, width, height, fps, pdf_creation_date());
}

video_encoder::~video_encoder() = default;

video_frame video_encoder::convert(const argb_image& image) const { return sink_->convert(image); }

void video_encoder::keep_against(const argb_image& still) { sink_->keep_against(still); }

std::uint64_t video_encoder::pixels_converted() const { return sink_->pixels_converted(); }

void video_encoder::add(video_frame frame) { sink_->add(std::move(frame)); }

void video_encoder::finish() { sink_->finish(); }

}  // namespace plot
