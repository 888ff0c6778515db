// SPDX-License-Identifier: GPL-3.0-or-later
// Output paths from strangers: a pull request can commit a symbolic link, or a build machine
// have a FIFO, a socket, a device or a directory, where a command is to write a file. Every
// command refuses every one of them (exit 2, naming the path) before any work, writes nothing
// anywhere and never blocks; and two runs writing one pdf_tex pair at once never tear it.
#include "process.hpp"

#include <gtest/gtest.h>

#include <fcntl.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/un.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <utility>
#include <vector>

extern char** environ;

namespace {

namespace fs = std::filesystem;
using test_support::files_in;
using test_support::run_command;
using test_support::run_result;
using test_support::slurp;
using test_support::temp_dir;

/// What stands at an output's path.
enum class hostile { link_to_file, dangling_link, link_to_device, fifo, socket, directory, device, block_device };

/// Every kind, in the order the sweep tries them.
constexpr hostile all_kinds[] = {hostile::link_to_file, hostile::dangling_link, hostile::link_to_device, hostile::fifo,
                                 hostile::socket,       hostile::directory,     hostile::device,
                                 hostile::block_device};

/// How the refusal names a kind: "'PATH' is " and this.
std::string words(hostile kind) {
    switch (kind) {
        case hostile::link_to_file:
        case hostile::dangling_link:
        case hostile::link_to_device: return "a symbolic link";
        case hostile::fifo: return "a FIFO";
        case hostile::socket: return "a socket";
        case hostile::directory: return "a directory";
        case hostile::device: return "a character device";
        case hostile::block_device: return "a block device";
    }
    return "";
}

/// A bound Unix socket at a path, closed (the path stays) when it goes.
struct bound_socket {
    int fd = -1;
    ~bound_socket() {
        if (fd >= 0) ::close(fd);
    }
};

/// A scratch tree: DIR/out, where the command writes, and DIR/victim, where a link leads:
/// a script (mode 755) such as a pull request would point a figure's name at.
struct scene {
    fs::path dir;
    fs::path out;
    fs::path victim;
    bound_socket socket;

    explicit scene(const std::string& name) : dir(temp_dir(name)), out(dir / "out"), victim(dir / "victim") {
        fs::create_directories(out);
        fs::create_directories(victim);
        std::ofstream(victim / "deploy.sh") << "#!/bin/sh\necho deploy\n";
        ::chmod((victim / "deploy.sh").c_str(), 0755);
    }
    ~scene() { fs::remove_all(dir); }
    scene(const scene&) = delete;
    scene& operator=(const scene&) = delete;

    /// Puts `kind` at out/name; false if it cannot be made here (a device node needs root).
    bool plant(hostile kind, const std::string& name) {
        const fs::path path = out / name;
        switch (kind) {
            case hostile::link_to_file: fs::create_symlink("../victim/deploy.sh", path); return true;
            case hostile::dangling_link: fs::create_symlink("../victim/created", path); return true;
            case hostile::link_to_device: fs::create_symlink("/dev/null", path); return true;
            case hostile::fifo: return ::mkfifo(path.c_str(), 0600) == 0;
            case hostile::socket: {
                sockaddr_un address{};
                address.sun_family = AF_UNIX;
                if (path.string().size() >= sizeof address.sun_path) return false;
                std::strcpy(address.sun_path, path.c_str());
                socket.fd = ::socket(AF_UNIX, SOCK_STREAM, 0);
                return socket.fd >= 0 && ::bind(socket.fd, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0;
            }
            case hostile::directory:
                fs::create_directories(path);
                std::ofstream(path / "keep") << "mine";
                return true;
            case hostile::device: return ::mknod(path.c_str(), S_IFCHR | 0600, ::makedev(1, 3)) == 0;  // as /dev/null
            // Major 240 is for local use: no driver here, so even a write through it would go nowhere.
            case hostile::block_device: return ::mknod(path.c_str(), S_IFBLK | 0600, ::makedev(240, 0)) == 0;
        }
        return false;
    }

    /// Checks that out/name is still what plant made and nothing else was written anywhere.
    void expect_untouched(hostile kind, const std::string& name, const std::string& context) const {
        const fs::path path = out / name;
        struct stat st {};
        ASSERT_EQ(::lstat(path.c_str(), &st), 0) << context;
        switch (kind) {
            case hostile::link_to_file:
            case hostile::dangling_link:
            case hostile::link_to_device: EXPECT_TRUE(S_ISLNK(st.st_mode)) << context; break;
            case hostile::fifo: EXPECT_TRUE(S_ISFIFO(st.st_mode)) << context; break;
            case hostile::socket: EXPECT_TRUE(S_ISSOCK(st.st_mode)) << context; break;
            case hostile::directory:
                EXPECT_TRUE(S_ISDIR(st.st_mode)) << context;
                EXPECT_EQ(files_in(path), (std::set<std::string>{"keep"})) << context;
                EXPECT_EQ(slurp(path / "keep"), "mine") << context;
                break;
            case hostile::device: EXPECT_TRUE(S_ISCHR(st.st_mode)) << context; break;
            case hostile::block_device: EXPECT_TRUE(S_ISBLK(st.st_mode)) << context; break;
        }
        // No figure, no temporary: out holds what was planted and nothing else.
        EXPECT_EQ(files_in(out), (std::set<std::string>{name})) << context;
        // The link's target keeps its bytes and its mode; a dangling link's is not created.
        EXPECT_EQ(files_in(victim), (std::set<std::string>{"deploy.sh"})) << context;
        EXPECT_EQ(slurp(victim / "deploy.sh"), "#!/bin/sh\necho deploy\n") << context;
        ASSERT_EQ(::stat((victim / "deploy.sh").c_str(), &st), 0);
        EXPECT_EQ(st.st_mode & 07777, 0755u) << context;
        ASSERT_EQ(::stat("/dev/null", &st), 0);
        EXPECT_TRUE(S_ISCHR(st.st_mode)) << "/dev/null";
    }
};

/// Runs the program with `args` (OUT stands for the output directory) in `cwd`, killed after
/// 60 s: a command that opened a FIFO for writing would block forever (exit 124 then).
run_result run_guarded(std::string args, const fs::path& out) {
    for (std::size_t at; (at = args.find("OUT")) != std::string::npos;) args.replace(at, 3, "'" + out.string() + "'");
    return run_command("timeout -k 5 60 '" + std::string(PENDULUM_EXE) + "' " + args);
}

/// A command of the sweep and the file it writes (under OUT) where something is planted.
struct output_case {
    const char* args;
    const char* file;
};

constexpr output_case commands[] = {
    {"render fig1 -f png -o OUT", "c1-lowest.png"},
    {"render fig1 -f pdf_tex -o OUT", "c1-lowest.pdf_tex"},
    {"render fig1 -f pdf_tex -o OUT", "c1-lowest.pdf"},  // the drawing under the overlay
    {"render swing -f gif --frames 1..2 -o OUT", "swing.gif"},
    {"render swing -f png --frames 1..3 -o OUT", "swing-0002.png"},
    {"render swing -f svg --at 0.25 -o OUT", "swing.svg"},
    {"plot period --methods exact,lowest -f png -o OUT", "period.png"},
    {"plot trajectory --theta0 1 --methods exact -f pdf -o OUT", "trajectory.pdf"},
    {"data fig1 -o OUT/fig1.csv", "fig1.csv"},
    {"render fig1 -f svg -o OUT --depfile OUT/fig1.d", "fig1.d"},
};

TEST(HostileOutputs, EveryKindAtEveryCommandsOutputIsRefusedAndNothingIsWritten) {
    int swept = 0;
    for (const hostile kind : all_kinds) {
        for (const auto& [args, file] : commands) {
            scene s("hostile-out");
            const std::string context = words(kind) + " at " + file + ": " + args;
            if (!s.plant(kind, file)) {
                // Only a device node needs privileges; the link to /dev/null covers devices then.
                EXPECT_TRUE(kind == hostile::device || kind == hostile::block_device) << context;
                continue;
            }
            const auto r = run_guarded(args, s.out);
            ++swept;
            EXPECT_EQ(r.status, 2) << context << "\n" << r.err;
            const std::string named = "'" + (s.out / file).string() + "' is " + words(kind);
            EXPECT_NE(r.err.find(named), std::string::npos) << context << "\n" << r.err;
            if (kind != hostile::directory) {
                EXPECT_NE(r.err.find("-o - > '" + (s.out / file).string() + "'"), std::string::npos) << r.err;
            }
            EXPECT_EQ(r.out, "") << context;
            s.expect_untouched(kind, file, context);
        }
    }
    EXPECT_GE(swept, 6 * static_cast<int>(std::size(commands)));
}

/// The number of frames of the built-in animation `id`, from the message of --frames 0.
int frames_of(const std::string& id) {
    const auto r = run_guarded("render " + id + " -f png --frames 0 -o .", ".");
    const auto at = r.err.find("frames are 1..");
    if (at == std::string::npos) return 0;
    return std::stoi(r.err.substr(at + 14));
}

TEST(HostileOutputs, OneBadOutputAmongManyStopsTheRunBeforeAnyWork) {
    // Every still figure in two formats: the FIFO is one output of many, and the run, which
    // would draw for seconds, stops at once with nothing written (not even the others).
    {
        scene s("hostile-many");
        ASSERT_TRUE(s.plant(hostile::fifo, "c1-lowest.svg"));
        const auto r = run_guarded("render --all -f png,svg -o OUT", s.out);
        EXPECT_EQ(r.status, 2) << r.err;
        EXPECT_NE(r.err.find("c1-lowest.svg' is a FIFO"), std::string::npos) << r.err;
        s.expect_untouched(hostile::fifo, "c1-lowest.svg", "render --all");
    }
    // Every frame of an animation as PNG: the last frame's name is a dangling link.
    {
        const int frames = frames_of("swing");
        ASSERT_GT(frames, 10);
        char last[32];
        std::snprintf(last, sizeof last, "swing-%04d.png", frames);
        scene s("hostile-frames");
        ASSERT_TRUE(s.plant(hostile::dangling_link, last));
        const auto r = run_guarded("render swing fig1 -f png -o OUT", s.out);
        EXPECT_EQ(r.status, 2) << r.err;
        EXPECT_NE(r.err.find(std::string(last) + "' is a symbolic link"), std::string::npos) << r.err;
        s.expect_untouched(hostile::dangling_link, last, "render swing");
    }
}

TEST(HostileOutputs, StandardOutputIsTheWayThroughALinkOrIntoAFifo) {
    scene s("hostile-stdout");
    fs::create_symlink("../victim/figure.png", s.out / "link.png");
    const auto r = run_guarded("render fig1 -f png -o - > OUT/link.png", s.out);
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(slurp(s.victim / "figure.png").substr(1, 3), "PNG");
    EXPECT_TRUE(fs::is_symlink(s.out / "link.png"));
}

TEST(HostileOutputs, ADirectoryGivenWithDashOIsTheUsersAndMayBeALink) {
    scene s("hostile-dir-link");
    fs::create_symlink("../victim", s.out / "figures");
    const auto r = run_guarded("render fig1 -f svg -o OUT/figures", s.out);
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_TRUE(fs::is_regular_file(fs::symlink_status(s.victim / "c1-lowest.svg")));
}

/// Starts `command` under sh; its pid.
pid_t start(const std::string& command) {
    const char* argv[] = {"sh", "-c", command.c_str(), nullptr};
    pid_t pid = -1;
    if (::posix_spawnp(&pid, "sh", nullptr, nullptr, const_cast<char* const*>(argv), environ) != 0) return -1;
    return pid;
}

/// The exit status of pid, waited for.
int status_of(pid_t pid) {
    int raw = 0;
    if (::waitpid(pid, &raw, 0) != pid) return -1;
    return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
}

/// The pdf and pdf_tex of fig1 in dir.
std::pair<std::string, std::string> pair_in(const fs::path& dir) {
    return {slurp(dir / "c1-lowest.pdf"), slurp(dir / "c1-lowest.pdf_tex")};
}

TEST(HostileOutputs, TwoRunsWritingOnePdfTexPairNeverTearIt) {
    // Two settings that change both files of the pair; each alone gives its pair.
    const std::string exe = PENDULUM_EXE;
    const std::string settings[2] = {"--set panel_width_cm=6", "--set panel_width_cm=8 --tex-font-size 12"};
    const auto dir = temp_dir("pair-race");
    std::pair<std::string, std::string> alone[2];
    for (int i = 0; i < 2; ++i) {
        const fs::path one = dir / ("alone" + std::to_string(i));
        fs::create_directories(one);
        const auto r = run_command("'" + exe + "' render fig1 -f pdf_tex " + settings[i] + " -o '" + one.string() + "'");
        ASSERT_EQ(r.status, 0) << r.err;
        alone[i] = pair_in(one);
    }
    ASSERT_NE(alone[0].first, alone[1].first);
    ASSERT_NE(alone[0].second, alone[1].second);
    const fs::path shared = dir / "shared";
    fs::create_directories(shared);
    constexpr int rounds = 40;
    int torn = 0;
    for (int round = 0; round < rounds; ++round) {
        // Half the rounds with --force (both runs rename both files), half without (a run
        // writes the pair only if it differs from what is there).
        const std::string force = round % 2 == 0 ? " --force" : "";
        // Two runs at each setting, started together: more renames meet.
        pid_t pids[4];
        for (int i = 0; i < 4; ++i) {
            pids[i] = start("exec '" + exe + "' render fig1 -f pdf_tex --jobs 1" + force + " " + settings[i % 2] +
                            " -o '" + shared.string() + "' 2>/dev/null");
            ASSERT_GT(pids[i], 0);
        }
        for (const pid_t pid : pids) EXPECT_EQ(status_of(pid), 0) << "round " << round;
        const auto now = pair_in(shared);
        if (now != alone[0] && now != alone[1]) ++torn;
        EXPECT_EQ(files_in(shared), (std::set<std::string>{"c1-lowest.pdf", "c1-lowest.pdf_tex"})) << round;
    }
    EXPECT_EQ(torn, 0) << torn << " of " << rounds << " rounds left a pdf of one run and a pdf_tex of another";
    fs::remove_all(dir);
}

}  // namespace
