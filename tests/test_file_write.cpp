// SPDX-License-Identifier: GPL-3.0-or-later
// Output files: written whole into what the path names, a FIFO written through, a
// symbolic link's target replaced, an existing file's mode kept, long names, leftovers.
#include "plot/output.hpp"
#include "process.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

namespace {

namespace fs = std::filesystem;
using plot::write_atomically;
using test_support::files_in;
using test_support::slurp;
using test_support::temp_dir;

TEST(FileWrite, AFifoIsWrittenThroughNotReplaced) {
    const auto dir = temp_dir("fifo");
    const auto fifo = dir / "pipe";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    std::string got;
    std::thread reader([&] { got = slurp(fifo); });
    write_atomically(fifo, "figure bytes");
    reader.join();
    EXPECT_EQ(got, "figure bytes");
    struct stat st {};
    ASSERT_EQ(::lstat(fifo.c_str(), &st), 0);
    EXPECT_TRUE(S_ISFIFO(st.st_mode));  // still a FIFO, not a regular file
    EXPECT_EQ(files_in(dir), (std::set<std::string>{"pipe"}));
    fs::remove_all(dir);
}

TEST(FileWrite, ASymlinksTargetIsReplacedAndTheLinkKept) {
    const auto dir = temp_dir("symlink");
    fs::create_directories(dir / "real");
    std::ofstream(dir / "real" / "f.csv") << "old";
    fs::create_symlink("real/f.csv", dir / "link.csv");
    write_atomically(dir / "link.csv", "new");
    EXPECT_TRUE(fs::is_symlink(dir / "link.csv"));
    EXPECT_EQ(slurp(dir / "real" / "f.csv"), "new");
    EXPECT_EQ(files_in(dir / "real"), (std::set<std::string>{"f.csv"}));
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
    const auto fnv1a = [](const std::string& name) {
        std::uint64_t h = 0xcbf29ce484222325ULL;
        for (const char c : name) {
            h ^= static_cast<unsigned char>(c);
            h *= 0x100000001b3ULL;
        }
        char hex[17];
        std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
        return std::string(hex);
    };
    const std::string ours = ".pendulum-figures-" + fnv1a("f.svg") + "-";
    const std::string other = ".pendulum-figures-" + fnv1a("g.svg") + "-";
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
    EXPECT_THROW(write_atomically(dir, "x"), std::runtime_error);  // a directory
    fs::remove_all(dir);
}

TEST(FileWrite, DataIntoAFifoFromTheCommandLine) {
    const auto dir = temp_dir("fifo-cli");
    ASSERT_EQ(::mkfifo((dir / "out").c_str(), 0600), 0);
    std::string got;
    std::thread reader([&] { got = slurp(dir / "out"); });
    const auto r = test_support::run_cli("data fig1 -o '" + (dir / "out").string() + "'");
    reader.join();
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(got.rfind("panel,series,x,y\n", 0), 0u);
    fs::remove_all(dir);
}

}  // namespace
