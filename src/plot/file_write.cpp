// SPDX-License-Identifier: GPL-3.0-or-later
// Writing output files: whole or not at all, as a new regular file at the path (never through
// a link, device or FIFO), the renames of a group exclusive between processes.
#include "plot/output.hpp"
#include "plot/streamed_file.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <climits>
#include <atomic>
#include <chrono>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <memory>
#include <random>
#include <mutex>
#include <ctime>
#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <tuple>
#include <utility>
#include <vector>

namespace plot {

namespace fs = std::filesystem;

/// A file written under a temporary name beside its path and on disk, waiting to take its name.
struct prepared_file {
    fs::path path;     ///< as given: what the temporary is renamed to, and named in messages
    std::string temp;  ///< the temporary's name; empty once renamed or removed
};

namespace {

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

/// The directory a file at `path` is in: its parent, or "." for a bare name.
fs::path directory_of(const fs::path& path) {
    return path.has_parent_path() ? path.parent_path() : fs::path(".");
}

/// An open file descriptor, closed when it goes.
class descriptor {
public:
    explicit descriptor(int fd) : fd_(fd) {}
    ~descriptor() {
        if (fd_ >= 0) ::close(fd_);
    }
    descriptor(descriptor&& other) noexcept : fd_(std::exchange(other.fd_, -1)) {}
    descriptor(const descriptor&) = delete;
    descriptor& operator=(const descriptor&) = delete;
    descriptor& operator=(descriptor&&) = delete;
    /// The descriptor, or -1.
    int get() const { return fd_; }

private:
    int fd_;
};

/// In words, what stands at an output's path that is not a regular file.
std::string_view kind_of(mode_t mode) {
    if (S_ISLNK(mode)) return "a symbolic link";
    if (S_ISDIR(mode)) return "a directory";
    if (S_ISCHR(mode)) return "a character device";
    if (S_ISBLK(mode)) return "a block device";
    if (S_ISFIFO(mode)) return "a FIFO";
    if (S_ISSOCK(mode)) return "a socket";
    return "not a regular file";
}

/// The message refusing to write at `path`, where a `mode` file stands that is not regular.
std::string refusal(const fs::path& path, mode_t mode) {
    const std::string named = "'" + path.string() + "' is " + std::string(kind_of(mode));
    if (S_ISDIR(mode)) return named + "; give a file name, or move the directory away";
    return named + ": an output replaces a regular file or makes a new one, and is never written through a "
                   "link, device, FIFO or socket; remove it, or write to standard output (-o -) and redirect "
                   "that, e.g. -o - > '" + path.string() + "'";
}

/// The bytes of a temporary's name: the prefix, 16 hex digits, '-' and six characters.
constexpr std::size_t temp_name_bytes = temp_prefix.size() + 16 + 1 + 6;

/// A long path for a message: its first and last 40 bytes.
std::string shortened(const std::string& path) {
    return path.size() <= 100 ? path : path.substr(0, 40) + "..." + path.substr(path.size() - 40);
}

/// Refuses, as bad input, a path the system cannot name: a part of more than NAME_MAX bytes,
/// or a path, or its temporary's beside it, of PATH_MAX bytes or more (the limit counts the NUL).
void check_name_lengths(const fs::path& path) {
    for (const auto& part : path) {
        if (part.native().size() > NAME_MAX) {
            throw bad_input("output path '" + shortened(path.native()) + "' has a name of " +
                            std::to_string(part.native().size()) + " bytes; a file name holds at most " +
                            std::to_string(NAME_MAX) + " (NAME_MAX): give a shorter name");
        }
    }
    const std::size_t longest = std::max(path.native().size(), directory_of(path).native().size() + 1 + temp_name_bytes);
    if (longest >= PATH_MAX) {
        throw bad_input("output path '" + shortened(path.native()) + "' (or its temporary's beside it, " +
                        std::to_string(temp_name_bytes) + " bytes of name) has " + std::to_string(longest) +
                        " bytes; a path holds at most " + std::to_string(PATH_MAX - 1) +
                        " (PATH_MAX less its NUL): give a shorter output directory");
    }
}

/// True if a regular file stands at path, its status in st; false if nothing does. Throws
/// plot::bad_input naming the path if anything else does, or if its name or its temporary's
/// is too long (see check_output_file).
bool check_existing_output(const fs::path& path, struct stat& st) {
    check_name_lengths(path);
    // O_PATH opens nothing (a FIFO does not block, a device is not touched) and, with
    // O_NOFOLLOW, a symbolic link is the link itself, never what it leads to.
    const descriptor fd(::open(path.c_str(), O_PATH | O_NOFOLLOW | O_CLOEXEC));
    if (fd.get() < 0) {
        // Nothing there, or a file above it in its place: for the directory checks and the write to report.
        if (errno == ENOENT || errno == ENOTDIR) return false;
        fail(path, errno);
    }
    if (::fstat(fd.get(), &st) != 0) fail(path, errno);
    if (!S_ISREG(st.st_mode)) throw bad_input(refusal(path, st.st_mode));
    return true;
}

}  // namespace

void check_output_file(const std::filesystem::path& path) {
    struct stat st {};
    check_existing_output(path, st);
}

void check_output_files(const std::vector<std::filesystem::path>& paths) {
    for (const auto& path : paths) check_output_file(path);
}

namespace {

/// Exclusive flock(2) on the directories of a group of renames, held while it lives: another
/// process's group of renames into one of them waits, so a pair that belongs together (a
/// drawing and its LaTeX overlay) is never half one run's and half another's. The lock is on
/// the directory itself, so nothing is left behind and a killed run's lock goes with it.
/// Best effort: a directory that cannot be opened for reading, or a file system without
/// flock (NFS emulates it only for files open for writing), is renamed into unlocked.
class directory_locks {
public:
    explicit directory_locks(const std::vector<const prepared_file*>& files) {
        struct held {
            dev_t dev;
            ino_t ino;
            std::size_t index;
        };
        std::vector<held> order;
        fs::path previous;  // the frames of an animation are all in one directory
        for (const prepared_file* f : files) {
            const fs::path dir = directory_of(f->path);
            if (!previous.empty() && dir == previous) continue;
            previous = dir;
            descriptor fd(::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
            struct stat st {};
            if (fd.get() < 0 || ::fstat(fd.get(), &st) != 0) continue;
            const auto same = [&](const held& h) { return h.dev == st.st_dev && h.ino == st.st_ino; };
            if (std::any_of(order.begin(), order.end(), same)) continue;
            order.push_back({st.st_dev, st.st_ino, fds_.size()});
            fds_.push_back(std::move(fd));
        }
        // Taken in one order (device, inode) by every process, so that two never wait on each other.
        std::sort(order.begin(), order.end(),
                  [](const held& a, const held& b) { return std::tie(a.dev, a.ino) < std::tie(b.dev, b.ino); });
        for (const held& h : order) {
            while (::flock(fds_[h.index].get(), LOCK_EX) != 0 && errno == EINTR) {
            }
        }
    }

private:
    std::vector<descriptor> fds_;
};

/// Six characters for a temporary's name, as mkstemp's XXXXXX: letters and digits.
std::string random_suffix() {
    static std::atomic<std::uint64_t> counter{0};
    constexpr std::string_view chars = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789";
    std::uint64_t x = (static_cast<std::uint64_t>(std::random_device{}()) << 32) ^
                      static_cast<std::uint64_t>(std::chrono::steady_clock::now().time_since_epoch().count()) ^
                      (counter.fetch_add(1) * 0x9e3779b97f4a7c15ULL);
    std::string out;
    for (int i = 0; i < 6; ++i) {
        out += chars[x % chars.size()];
        x /= chars.size();
    }
    return out;
}

/// Creates the temporary for `path`, which check_existing_output has found fit, beside it
/// with O_EXCL: a new file no one else has, whatever stands at `path`. fd is the
/// open descriptor.
prepared_file open_for(const fs::path& path, int& fd, struct stat& st, bool& exists) {
    exists = check_existing_output(path, st);
    const fs::path dir = directory_of(path);
    remove_stale_temporaries(dir, path);
    fd = -1;
    std::string temp;
    // As mkstemp does, but with the mode a new file gets (0666 less the umask, which the
    // kernel applies: the umask is never read, so never set to read it); a temporary that
    // replaces a file is private (0600) until close_written gives it the file's mode.
    for (int attempt = 0; attempt < 100 && fd < 0; ++attempt) {
        temp = (dir / (temp_stem(path) + random_suffix())).string();
        fd = ::open(temp.c_str(), O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC, exists ? 0600 : 0666);
        if (fd < 0 && errno != EEXIST) fail(path, errno);
    }
    if (fd < 0) fail(path, EEXIST);
    return {path, std::move(temp)};
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

/// Ends the writing of fd: the temporary gets the mode (and owner) of the file it replaces
/// and is on disk (unless a batch syncs it later), closed.
void close_written(prepared_file& f, int fd, const struct stat& st, bool exists) {
    // An existing file keeps its mode (and owner, where we may set it); a new one has the
    // mode open_for created it with.
    if (exists && ::fchmod(fd, st.st_mode & 07777) != 0) give_up(f, fd, errno);
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

/// Removes what a failed write prepared and did not rename.
void discard(std::vector<prepared_file>& files) {
    for (auto& f : files) {
        if (!f.temp.empty()) ::unlink(f.temp.c_str());
        f.temp.clear();
    }
}

/// Gives prepared files their names, in order, as one group: rename(2), which replaces the
/// directory entry (a link that took the name meanwhile is replaced, never followed), under
/// the lock of their directories. On a failure, the files not yet renamed are removed.
void commit(std::vector<prepared_file>& files) {
    std::vector<const prepared_file*> group;
    for (const auto& f : files) group.push_back(&f);
    const directory_locks lock(group);
    for (auto& f : files) {
        if (f.temp.empty()) continue;
        if (std::rename(f.temp.c_str(), f.path.c_str()) != 0) {
            const int e = errno;
            discard(files);
            fail(f.path, e);
        }
        f.temp.clear();
    }
}

/// Gives one prepared file its name.
void commit(prepared_file& f) {
    std::vector<prepared_file> one;
    one.push_back(std::exchange(f, {}));
    commit(one);
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
        fill(fs::path(f.temp));
    } catch (...) {
        ::close(fd);
        ::unlink(f.temp.c_str());
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
        commit(ready);
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
    if (f.temp.empty()) return;
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
        plot::commit(files);
    } catch (...) {
        discard(files);
        throw;
    }
}

}  // namespace plot
