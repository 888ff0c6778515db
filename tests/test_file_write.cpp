// SPDX-License-Identifier: GPL-3.0-or-later
// Output files: written whole as a regular file at the path; a FIFO, a symbolic link (dangling
// or not) or a directory refused; an existing file's mode kept, long names, leftovers.
#include "plot/output.hpp"
#include "plot/streamed_file.hpp"
#include "process.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <future>
#include <string>
#include <thread>

namespace {

namespace fs = std::filesystem;
using plot::write_atomically;
using test_support::files_in;
using test_support::slurp;
using test_support::temp_dir;

/// Runs f on a thread and waits at most 20 s for it; a FIFO opened for writing blocks until
/// a reader comes, so a write that went through one would hang: then the FIFO is opened for
/// reading (which frees the writer) and false is returned.
template <typename F>
bool finishes(F f, const fs::path& fifo) {
    auto done = std::async(std::launch::async, std::move(f));
    if (done.wait_for(std::chrono::seconds(20)) == std::future_status::ready) {
        done.get();
        return true;
    }
    const int fd = ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK);
    done.wait();
    if (fd >= 0) ::close(fd);
    return false;
}

// The old behaviour (a FIFO written through) is refused now: -o - is the way into a FIFO.
TEST(FileWrite, AFifoIsRefusedNotWrittenThrough) {
    const auto dir = temp_dir("fifo");
    const auto fifo = dir / "pipe";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    std::string message;
    const bool done = finishes(
        [&] {
            try {
                write_atomically(fifo, "figure bytes");
            } catch (const plot::bad_input& e) {
                message = e.what();
            }
        },
        fifo);
    ASSERT_TRUE(done) << "writing blocked on the FIFO";
    EXPECT_NE(message.find("'" + fifo.string() + "' is a FIFO"), std::string::npos) << message;
    EXPECT_NE(message.find("-o -"), std::string::npos) << message;
    struct stat st {};
    ASSERT_EQ(::lstat(fifo.c_str(), &st), 0);
    EXPECT_TRUE(S_ISFIFO(st.st_mode));  // still a FIFO, not a regular file
    EXPECT_EQ(files_in(dir), (std::set<std::string>{"pipe"}));  // no temporary left
    fs::remove_all(dir);
}

// The old behaviour (the link's target replaced) is refused now, the link and its target untouched.
TEST(FileWrite, ASymlinkIsRefusedAndItsTargetKept) {
    const auto dir = temp_dir("symlink");
    fs::create_directories(dir / "real");
    std::ofstream(dir / "real" / "f.csv") << "old";
    ASSERT_EQ(::chmod((dir / "real" / "f.csv").c_str(), 0755), 0);
    fs::create_symlink("real/f.csv", dir / "link.csv");
    try {
        write_atomically(dir / "link.csv", "new");
        ADD_FAILURE() << "a symbolic link was written through";
    } catch (const plot::bad_input& e) {
        EXPECT_NE(std::string(e.what()).find("link.csv' is a symbolic link"), std::string::npos) << e.what();
    }
    EXPECT_TRUE(fs::is_symlink(dir / "link.csv"));
    EXPECT_EQ(fs::read_symlink(dir / "link.csv"), "real/f.csv");
    EXPECT_EQ(slurp(dir / "real" / "f.csv"), "old");
    struct stat st {};
    ASSERT_EQ(::stat((dir / "real" / "f.csv").c_str(), &st), 0);
    EXPECT_EQ(st.st_mode & 07777, 0755u);
    EXPECT_EQ(files_in(dir / "real"), (std::set<std::string>{"f.csv"}));
    EXPECT_EQ(files_in(dir), (std::set<std::string>{"real", "link.csv"}));
    // A pair, a streamed file and a file written by name are refused the same way.
    EXPECT_THROW(write_atomically({{dir / "a.pdf", "pdf"}, {dir / "link.csv", "tex"}}), plot::bad_input);
    EXPECT_THROW(plot::streamed_file(dir / "link.csv"), plot::bad_input);
    EXPECT_THROW(plot::write_atomically_by(dir / "link.csv", [](const fs::path&) {}), plot::bad_input);
    EXPECT_EQ(files_in(dir), (std::set<std::string>{"real", "link.csv"}));
    EXPECT_EQ(slurp(dir / "real" / "f.csv"), "old");
    fs::remove_all(dir);
}

// A dangling link is refused too: its target is not created.
TEST(FileWrite, ADanglingSymlinkIsRefused) {
    const auto dir = temp_dir("dangling");
    fs::create_symlink("missing/target.png", dir / "f.png");
    fs::create_directories(dir / "missing");
    EXPECT_THROW(write_atomically(dir / "f.png", "png"), plot::bad_input);
    EXPECT_TRUE(fs::is_empty(dir / "missing"));
    EXPECT_EQ(files_in(dir), (std::set<std::string>{"f.png", "missing"}));
    // A link among the directories above the file is followed: those are the user's.
    fs::create_symlink("missing", dir / "to-missing");
    write_atomically(dir / "to-missing" / "g.png", "png");
    EXPECT_EQ(slurp(dir / "missing" / "g.png"), "png");
    fs::remove_all(dir);
}

TEST(FileWrite, AnExistingFileKeepsItsMode) {
    const auto dir = temp_dir("mode");
    std::ofstream(dir / "f.pdf") << "old";
    ASSERT_EQ(::chmod((dir / "f.pdf").c_str(), 0640), 0);
    write_atomically(dir / "f.pdf", "new");
    struct stat st {};
    ASSERT_EQ(::stat((dir / "f.pdf").c_str(), &st), 0);
    EXPECT_EQ(st.st_mode & 07777, 0640u);
    EXPECT_EQ(slurp(dir / "f.pdf"), "new");
    fs::remove_all(dir);
}

TEST(FileWrite, LongNamesAndLeftovers) {
    const auto dir = temp_dir("names");
    const std::string long_name = std::string(250, 'x') + ".png";  // 254 bytes: a name may have 255
    write_atomically(dir / long_name, "ok");
    EXPECT_EQ(slurp(dir / long_name), "ok");
    // A temporary that a killed run left long ago while writing f.svg goes when f.svg is
    // written again; a fresh one (another run's), one of another file, and a user's file
    // that merely looks like one stay.
    // Their names: ".pendulum-figures-", the 64-bit FNV-1a of the target's name in hex
    // (python: h = 0xcbf29ce484222325; for each byte h = ((h ^ byte) * 0x100000001b3) mod 2^64), "-".
    const std::string ours = ".pendulum-figures-b2664dce40f08f91-";   // f.svg
    const std::string other = ".pendulum-figures-638fe4b0d39ceec6-";  // g.svg
    const auto old = fs::file_time_type::clock::now() - std::chrono::hours(2);
    for (const std::string& name : {ours + "AbC123", ours + "XyZ789", other + "AbC123", std::string(".pf-notes1"),
                                   std::string(".pf-AbC123"), ours + "AbC12"}) {
        std::ofstream(dir / name) << "x";
        if (name != ours + "XyZ789") fs::last_write_time(dir / name, old);
    }
    write_atomically(dir / "f.svg", "svg");
    EXPECT_FALSE(fs::exists(dir / (ours + "AbC123")));
    EXPECT_TRUE(fs::exists(dir / (ours + "XyZ789")));
    EXPECT_TRUE(fs::exists(dir / (other + "AbC123")));
    EXPECT_TRUE(fs::exists(dir / ".pf-notes1"));
    EXPECT_TRUE(fs::exists(dir / ".pf-AbC123"));
    EXPECT_TRUE(fs::exists(dir / (ours + "AbC12")));
    EXPECT_THROW(write_atomically(dir, "x"), plot::bad_input);  // a directory: bad input now, as the CLI checks it
    fs::remove_all(dir);
}

// The old behaviour (data written into a FIFO at -o FILE) is refused now, before any work and
// without opening the FIFO; -o - into it is the way.
TEST(FileWrite, DataIntoAFifoFromTheCommandLine) {
    const auto dir = temp_dir("fifo-cli");
    ASSERT_EQ(::mkfifo((dir / "out").c_str(), 0600), 0);
    test_support::run_result r;
    const bool done = finishes([&] { r = test_support::run_cli("data fig1 -o '" + (dir / "out").string() + "'"); },
                               dir / "out");
    ASSERT_TRUE(done) << "data blocked on the FIFO";
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_NE(r.err.find("/out' is a FIFO"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("-o -"), std::string::npos) << r.err;
    EXPECT_EQ(r.out, "");
    struct stat st {};
    ASSERT_EQ(::lstat((dir / "out").c_str(), &st), 0);
    EXPECT_TRUE(S_ISFIFO(st.st_mode));
    EXPECT_EQ(files_in(dir), (std::set<std::string>{"out"}));
    // Standard output redirected into the FIFO is the deliberate way.
    std::string got;
    std::thread reader([&] { got = slurp(dir / "out"); });
    const auto piped = test_support::run_cli("data fig1 -o - > '" + (dir / "out").string() + "'");
    reader.join();
    EXPECT_EQ(piped.status, 0) << piped.err;
    EXPECT_EQ(got.rfind("panel,series,x,y,id\n", 0), 0u);
    fs::remove_all(dir);
}

}  // namespace
