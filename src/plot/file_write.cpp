// SPDX-License-Identifier: GPL-3.0-or-later
// Writing output files: whole or not at all, into what the path names.
#include "plot/output.hpp"
#include "plot/streamed_file.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <memory>
#include <mutex>
#include <ctime>
#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace plot {

namespace {

namespace fs = std::filesystem;

/// strerror, lowercased to match the project's messages ("no space left on device").
std::string error_text(int e) {
    std::string s = std::strerror(e);
    if (!s.empty() && s[0] >= 'A' && s[0] <= 'Z') s[0] = static_cast<char>(s[0] - 'A' + 'a');
    return s;
}

[[noreturn]] void fail(const fs::path& path, int e) {
    throw std::runtime_error("cannot write " + path.string() + ": " + error_text(e));
}

/// Writes all bytes to fd; returns 0 or the errno of the failure.
int write_all(int fd, std::string_view bytes) {
    std::size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0) {
            if (errno == EINTR) continue;
            return errno;
        }
        done += static_cast<std::size_t>(n);
    }
    return 0;
}

/// The file a path leads to through any symbolic links (which are kept: their target is
/// what gets replaced).
fs::path resolve_links(const fs::path& path) {
    fs::path target = path;
    for (int i = 0; i < 40; ++i) {
        struct stat st {};
        if (::lstat(target.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return target;
        std::error_code ec;
        const fs::path link = fs::read_symlink(target, ec);
        if (ec) fail(path, ec.value());
        target = link.is_absolute() ? link : target.parent_path() / link;
    }
    fail(path, ELOOP);
}

/// Temporary files are named ".pendulum-figures-H-XXXXXX" beside their target, H the hash
/// of the target's name: a name no one else would choose, and one that says whose it is.
constexpr std::string_view temp_prefix = ".pendulum-figures-";

/// FNV-1a of the name, as 16 hex digits: the same on every machine and in every run.
std::string name_hash(const std::string& name) {
    std::uint64_t h = 0xcbf29ce484222325ULL;
    for (const char c : name) {
        h ^= static_cast<unsigned char>(c);
        h *= 0x100000001b3ULL;
    }
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
    return hex;
}

/// The start of the names of target's temporaries, up to mkstemp's six characters.
std::string temp_stem(const fs::path& target) {
    return std::string(temp_prefix) + name_hash(target.filename().string()) + "-";
}

/// Removes the temporaries of this target that a killed run left more than an hour ago (a
/// running writer's are younger). Only a regular file named as this program names the
/// temporaries of this very target is removed: nothing a user made.
void remove_stale_temporaries(const fs::path& dir, const fs::path& target) {
    DIR* d = ::opendir(dir.c_str());
    if (!d) return;
    const std::string stem = temp_stem(target);
    const std::time_t now = std::time(nullptr);
    while (const dirent* e = ::readdir(d)) {
        const std::string name = e->d_name;
        if (name.size() != stem.size() + 6 || name.rfind(stem, 0) != 0) continue;
        const fs::path p = dir / name;
        struct stat st {};
        if (::lstat(p.c_str(), &st) == 0 && S_ISREG(st.st_mode) && now - st.st_mtime > 3600) ::unlink(p.c_str());
    }
    ::closedir(d);
}

}  // namespace

/// A file written under a temporary name and on disk, waiting to take its name; or a
/// device, FIFO or socket, written through in place.
struct prepared_file {
    fs::path path;    ///< as given, for messages
    fs::path target;  ///< what the path leads to
    std::string temp; ///< the temporary's name; empty when written in place
};

namespace {

/// Opens the file `path` leads to for writing: a temporary beside it, or a device, FIFO or
/// socket itself (written through, in place, never replaced). fd is the open descriptor.
prepared_file open_for(const fs::path& path, int& fd, struct stat& st, bool& exists) {
    prepared_file out{path, resolve_links(path), {}};
    exists = ::stat(out.target.c_str(), &st) == 0;
    if (exists && S_ISDIR(st.st_mode)) fail(path, EISDIR);
    if (exists && !S_ISREG(st.st_mode)) {
        fd = ::open(out.target.c_str(), O_WRONLY | O_CLOEXEC);
        if (fd < 0) fail(path, errno);
        return out;
    }
    const fs::path dir = out.target.has_parent_path() ? out.target.parent_path() : fs::path(".");
    remove_stale_temporaries(dir, out.target);
    std::string temp = (dir / (temp_stem(out.target) + "XXXXXX")).string();
    fd = ::mkstemp(temp.data());
    if (fd < 0) fail(path, errno);
    out.temp = std::move(temp);
    return out;
}

/// Closes fd after an error e and removes the temporary; throws naming the path.
[[noreturn]] void give_up(prepared_file& f, int fd, int e) {
    ::close(fd);
    if (!f.temp.empty()) ::unlink(f.temp.c_str());
    f.temp.clear();
    fail(f.path, e);
}

/// The batch that defers the syncing and renaming of this process's files, if one is open.
std::atomic<durable_batch*> open_batch{nullptr};

/// Ends the writing of fd: a temporary gets the mode (and owner) of the file it replaces
/// and is on disk (unless a batch syncs it later), closed; a device is closed.
void close_written(prepared_file& f, int fd, const struct stat& st, bool exists) {
    if (f.temp.empty()) {
        if (::close(fd) != 0) fail(f.path, errno);
        return;
    }
    // An existing file keeps its mode (and owner, where we may set it); a new one gets the
    // usual 0666 less the umask, which is read once: reading it means setting it.
    static const mode_t mask = [] {
        const mode_t m = ::umask(022);
        ::umask(m);
        return m;
    }();
    if (::fchmod(fd, exists ? (st.st_mode & 07777) : (0666 & ~mask)) != 0) give_up(f, fd, errno);
    if (exists && (st.st_uid != ::geteuid() || st.st_gid != ::getegid())) {
        if (::fchown(fd, st.st_uid, st.st_gid) != 0 && errno != EPERM) give_up(f, fd, errno);
    }
    // On disk before it takes the name: a crash leaves the old file or the new one. In a
    // batch, every temporary is put on disk at once, before the first rename.
    if (!open_batch.load() && ::fsync(fd) != 0) give_up(f, fd, errno);
    if (::close(fd) != 0) {
        const int e = errno;
        ::unlink(f.temp.c_str());
        f.temp.clear();
        fail(f.path, e);
    }
}

/// Writes bytes where `path` leads, under a temporary name, fsynced; the caller renames it.
prepared_file prepare(const fs::path& path, const std::string& bytes) {
    int fd = -1;
    struct stat st {};
    bool exists = false;
    prepared_file out = open_for(path, fd, st, exists);
    if (const int e = write_all(fd, bytes)) give_up(out, fd, e);
    close_written(out, fd, st, exists);
    return out;
}

/// Gives a prepared file its name.
void commit(prepared_file& f) {
    if (f.temp.empty()) return;
    if (std::rename(f.temp.c_str(), f.target.c_str()) != 0) {
        const int e = errno;
        ::unlink(f.temp.c_str());
        f.temp.clear();
        fail(f.path, e);
    }
    f.temp.clear();
}

/// Removes what a failed write prepared and did not rename.
void discard(std::vector<prepared_file>& files) {
    for (auto& f : files) {
        if (!f.temp.empty()) ::unlink(f.temp.c_str());
        f.temp.clear();
    }
}

}  // namespace

void write_atomically(const std::filesystem::path& path, const std::string& bytes) {
    prepared_file f = prepare(path, bytes);
    if (durable_batch* batch = open_batch.load()) return batch->defer(std::move(f));
    commit(f);
}

void write_atomically_by(const std::filesystem::path& path,
                         const std::function<void(const std::filesystem::path& file)>& fill) {
    int fd = -1;
    struct stat st {};
    bool exists = false;
    prepared_file f = open_for(path, fd, st, exists);
    try {
        fill(f.temp.empty() ? f.target : fs::path(f.temp));
    } catch (...) {
        ::close(fd);
        if (!f.temp.empty()) ::unlink(f.temp.c_str());
        throw;
    }
    close_written(f, fd, st, exists);
    if (durable_batch* batch = open_batch.load()) return batch->defer(std::move(f));
    commit(f);
}

void write_atomically(const std::vector<std::pair<std::filesystem::path, std::string>>& files) {
    // Every file is on disk under its temporary name before the first takes its name, so
    // the files change together but for the few microseconds of the renames, in order.
    std::vector<prepared_file> ready;
    try {
        for (const auto& [path, bytes] : files) ready.push_back(prepare(path, bytes));
        if (durable_batch* batch = open_batch.load()) {
            for (auto& f : ready) batch->defer(std::move(f));  // renamed in this order too
            return;
        }
        for (auto& f : ready) commit(f);
    } catch (...) {
        discard(ready);
        throw;
    }
}

struct streamed_file::state {
    prepared_file file;
    int fd = -1;
    struct stat st {};
    bool exists = false;
};

streamed_file::streamed_file(const std::filesystem::path& path) : state_(std::make_unique<state>()) {
    state_->file = open_for(path, state_->fd, state_->st, state_->exists);
}

streamed_file::~streamed_file() {
    if (state_->fd >= 0) ::close(state_->fd);
    if (!state_->file.temp.empty()) ::unlink(state_->file.temp.c_str());
}

void streamed_file::write(std::string_view bytes) {
    if (state_->fd < 0) throw std::logic_error("file already committed");
    if (const int e = write_all(state_->fd, bytes)) {
        const int fd = std::exchange(state_->fd, -1);
        give_up(state_->file, fd, e);
    }
}

void streamed_file::commit() {
    if (state_->fd < 0) throw std::logic_error("file already committed");
    const int fd = std::exchange(state_->fd, -1);
    close_written(state_->file, fd, state_->st, state_->exists);
    if (durable_batch* batch = open_batch.load()) return batch->defer(std::exchange(state_->file, {}));
    plot::commit(state_->file);
}

struct durable_batch::state {
    std::mutex mutex;
    std::vector<prepared_file> files;  // in the order they were finished
};

durable_batch::durable_batch() : state_(std::make_unique<state>()) {
    durable_batch* none = nullptr;
    if (!open_batch.compare_exchange_strong(none, this)) throw std::logic_error("a durable_batch is open already");
}

durable_batch::~durable_batch() {
    open_batch.store(nullptr);
    discard(state_->files);
}

void durable_batch::defer(prepared_file&& f) {
    if (f.temp.empty()) return;  // a device, written through
    std::lock_guard lock(state_->mutex);
    state_->files.push_back(std::move(f));
}

void durable_batch::commit() {
    open_batch.store(nullptr);
    std::vector<prepared_file> files;
    {
        std::lock_guard lock(state_->mutex);
        files.swap(state_->files);
    }
    try {
        // One syncfs per directory's file system puts every temporary on disk together.
        std::vector<fs::path> synced;
        for (const auto& f : files) {
            const fs::path dir = fs::path(f.temp).parent_path();
            if (std::find(synced.begin(), synced.end(), dir) != synced.end()) continue;
            const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
            if (fd < 0) fail(f.path, errno);
            const int status = ::syncfs(fd);
            const int e = errno;
            ::close(fd);
            if (status != 0) fail(f.path, e);
            synced.push_back(dir);
        }
        for (auto& f : files) plot::commit(f);
    } catch (...) {
        discard(files);
        throw;
    }
}

}  // namespace plot
