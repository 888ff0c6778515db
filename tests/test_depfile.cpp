// SPDX-License-Identifier: GPL-3.0-or-later
// Dependency files from strangers' names: every byte value in a prerequisite's or a target's
// name is refused or read back by GNU make and by ninja as that very file, with nothing run;
// hostile spec and style names, --depfile-target and a dependency file that would overwrite
// an input or an output are exit 2 with nothing written.
#include "cli/depfile.hpp"
#include "process.hpp"

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <utime.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <string>

namespace {

namespace fs = std::filesystem;
using test_support::files_in;
using test_support::run_cli;
using test_support::temp_dir;

/// text in single quotes for sh.
std::string sh_quoted(const std::string& text) {
    std::string out = "'";
    for (const char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

/// Runs a command in dir, its output discarded; the exit code.
/// make runs without the make flags of a make that may run this test.
int run_in(const fs::path& dir, const std::string& command) {
    const std::string line = "cd " + sh_quoted(dir.string()) + " && unset MAKEFLAGS MFLAGS MAKELEVEL && " + command;
    const int s = std::system(("{ " + line + " ; } >/dev/null 2>&1").c_str());
    return WIFEXITED(s) ? WEXITSTATUS(s) : -1;
}

/// Sets a file's times to t seconds after the epoch.
void set_time(const fs::path& p, long t) {
    const utimbuf times{t, t};
    ASSERT_EQ(::utime(p.c_str(), &times), 0) << p;
}

void write(const fs::path& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }

/// GNU make reads the rule "out.png: NAME" (as make_rule writes it) as out.png depending on
/// the file NAME and on nothing else, with nothing run: built once, then up to date, then
/// out of date when NAME is newer, and no file made but out.png.
void make_reads_prerequisite(const std::string& name) {
    const auto dir = temp_dir("dep-make");
    write(dir / "dep.d", pendulum::cli::make_rule({"out.png"}, {name}));
    write(dir / "Makefile", "out.png:\n\ttouch out.png\ninclude dep.d\n");
    write(dir / name, "");
    set_time(dir / name, 1000000);
    EXPECT_EQ(run_in(dir, "make"), 0) << name;
    EXPECT_EQ(run_in(dir, "make -q"), 0) << name << ": not up to date after a build";
    set_time(dir / name, 2000000000);
    EXPECT_EQ(run_in(dir, "make -q"), 1) << name << ": not a prerequisite";
    EXPECT_EQ(files_in(dir), (std::set<std::string>{"Makefile", "dep.d", name, "out.png"})) << name;
    fs::remove_all(dir);
}

/// GNU make reads the rule "NAME: in.toml" (as make_rule writes it) as the file NAME
/// depending on in.toml and nothing else: its database has that very line, and nothing runs.
void make_reads_target(const std::string& name) {
    const auto dir = temp_dir("dep-make-target");
    write(dir / "dep.d", pendulum::cli::make_rule({name}, {"in.toml"}));
    write(dir / "in.toml", "");
    const std::string db = (dir.parent_path() / (dir.filename().string() + ".db")).string();
    run_in(dir, "make -r -R -p -q -f dep.d > " + sh_quoted(db));
    const std::string text = test_support::slurp(db);
    fs::remove(db);
    EXPECT_NE(text.find("\n" + name + ": in.toml\n"), std::string::npos) << name;
    EXPECT_EQ(files_in(dir), (std::set<std::string>{"dep.d", "in.toml"})) << name;
    fs::remove_all(dir);
}

/// ninja reads the rule, as the README's recipe has it read (depfile, deps = gcc), as out.png
/// depending on the file NAME.
void ninja_reads_prerequisite(const std::string& name) {
    const auto dir = temp_dir("dep-ninja");
    write(dir / "dep.src", pendulum::cli::make_rule({"out.png"}, {name}));
    write(dir / "build.ninja", "rule r\n  command = cp dep.src dep.d && touch out.png\n  depfile = dep.d\n"
                               "  deps = gcc\nbuild out.png: r\n");
    write(dir / name, "");
    set_time(dir / name, 1000000);
    EXPECT_EQ(run_in(dir, "ninja"), 0) << name;
    EXPECT_EQ(run_in(dir, "ninja -n | grep -x 'ninja: no work to do.'"), 0) << name << ": not up to date";
    set_time(dir / name, 2000000000);
    EXPECT_NE(run_in(dir, "ninja -n | grep -x 'ninja: no work to do.'"), 0) << name << ": not a prerequisite";
    fs::remove_all(dir);
}

/// Bytes that make_escaped must refuse: every one Make reads as more than a name's character.
bool refused_byte(unsigned char c) {
    return c < 0x20 || c == 0x7f || std::string_view(":;=%|&*?[]()\\\"'<>^`").find(static_cast<char>(c)) != std::string_view::npos;
}

TEST(DepfileHostile, EveryByteOfAPrerequisiteIsRefusedOrReadBackAsThatFile) {
    for (int b = 1; b < 256; ++b) {
        if (b == '/') continue;  // a directory separator, not a name's byte
        const std::string name = std::string("p") + static_cast<char>(b) + "q.toml";
        if (refused_byte(static_cast<unsigned char>(b))) {
            EXPECT_THROW(pendulum::cli::make_escaped(name), std::invalid_argument) << "byte " << b;
            continue;
        }
        ASSERT_NO_THROW(pendulum::cli::make_escaped(name)) << "byte " << b;
        make_reads_prerequisite(name);
        ninja_reads_prerequisite(name);
    }
}

TEST(DepfileHostile, EveryByteOfATargetIsRefusedOrReadBackAsThatFile) {
    for (int b = 1; b < 256; ++b) {
        if (b == '/') continue;
        const std::string name = std::string("t") + static_cast<char>(b) + "u.png";
        if (refused_byte(static_cast<unsigned char>(b))) {
            EXPECT_THROW(pendulum::cli::make_escaped(name), std::invalid_argument) << "byte " << b;
            continue;
        }
        make_reads_target(name);
    }
}

TEST(DepfileHostile, NamesMakeWouldExpandOrTreatAsSpecial) {
    for (const char* bad : {"~/x.toml", "~root/x.toml", ".PHONY", ".SECONDEXPANSION", ".DEFAULT", "", "a\\b",
                            "a\nb", "a\tb", "%.toml", "x&"}) {
        EXPECT_THROW(pendulum::cli::make_escaped(bad), std::invalid_argument) << bad;
    }
    // A ~ inside a name, a dot-name that is no special target's form: plain names.
    EXPECT_EQ(pendulum::cli::make_escaped("a~b.toml"), "a~b.toml");
    EXPECT_EQ(pendulum::cli::make_escaped(".Phony"), ".Phony");
    EXPECT_EQ(pendulum::cli::make_escaped(".PHONY.toml"), ".PHONY.toml");
    try {
        pendulum::cli::make_escaped("X=1;touch.toml");
        ADD_FAILURE() << "accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("'=', which Make reads as a variable's value"), std::string::npos)
            << e.what();
    }
}

/// A small spec, as a stranger's pull request might add under any name.
const std::string small_spec = "[[panel]]\nplot = \"coefficient\"\nharmonic = 1\nmethods = [\"exact\"]\n";

TEST(DepfileHostile, AHostileSpecNameIsRefusedAndNothingRuns) {
    const auto dir = temp_dir("dep-spec-name");
    const std::string name = "%:zz;touch${IFS}PWNED;.toml";
    write(dir / name, small_spec);
    fs::create_directory(dir / "out");
    const auto r = run_cli("render " + sh_quoted((dir / name).string()) + " -f svg -o " +
                           sh_quoted((dir / "out").string()) + " --depfile " + sh_quoted((dir / "out/all.d").string()));
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_NE(r.err.find("the name before .toml has the character '%'"), std::string::npos) << r.err;
    EXPECT_TRUE(files_in(dir / "out").empty());
    EXPECT_EQ(files_in(dir), (std::set<std::string>{name, "out"}));
    fs::remove_all(dir);
}

TEST(DepfileHostile, EveryByteOfASpecNameIsRefusedOrNamesTheFiles) {
    const auto dir = temp_dir("dep-spec-bytes");
    for (int b = 1; b < 256; ++b) {
        if (b == '/') continue;
        const std::string name = std::string("s") + static_cast<char>(b) + "t.toml";
        write(dir / name, small_spec);
        const auto r = run_cli("describe " + sh_quoted((dir / name).string()));
        const bool plain = std::isalnum(b) != 0 && b < 0x80;
        const bool ok = plain || b == '.' || b == '_' || b == '+' || b == '-';
        EXPECT_EQ(r.status, ok ? 0 : 2) << "byte " << b << ": " << r.err;
        if (!ok) {
            EXPECT_NE(r.err.find("rename the spec"), std::string::npos) << r.err;
        }
        fs::remove(dir / name);
    }
    fs::remove_all(dir);
}

TEST(DepfileHostile, AHostileStyleNameIsRefusedBeforeAnyWork) {
    const auto dir = temp_dir("dep-style-name");
    const std::string style = "X=1;touch${IFS}PWNED4;.toml";
    write(dir / style, "tick_font_pt = 9\n");
    write(dir / "X=1", "");
    write(dir / "f.toml", "[figure]\nstyle = \"" + style + "\"\n" + small_spec);
    fs::create_directory(dir / "out");
    const auto r = run_cli("render " + sh_quoted((dir / "f.toml").string()) + " -f svg -o " +
                           sh_quoted((dir / "out").string()) + " --depfile " + sh_quoted((dir / "out/f.d").string()));
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_NE(r.err.find("--depfile: "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("'='"), std::string::npos) << r.err;
    EXPECT_TRUE(files_in(dir / "out").empty());
    // Without --depfile the name reaches no Make rule, and the figure is drawn.
    const auto plain = run_cli("render " + sh_quoted((dir / "f.toml").string()) + " -f svg -o " +
                               sh_quoted((dir / "out").string()));
    EXPECT_EQ(plain.status, 0) << plain.err;
    EXPECT_EQ(files_in(dir / "out"), (std::set<std::string>{"f.svg"}));
    fs::remove_all(dir);
}

TEST(DepfileHostile, TargetWithAColonIsRefused) {
    const auto dir = temp_dir("dep-target");
    const auto r = run_cli("render fig1 -f svg -o " + sh_quoted(dir.string()) + " --depfile " +
                           sh_quoted((dir / "f.d").string()) + " --depfile-target 'a:b'");
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_NE(r.err.find("':', which Make reads as the end of the targets"), std::string::npos) << r.err;
    EXPECT_TRUE(files_in(dir).empty());
    fs::remove_all(dir);
}

TEST(DepfileHostile, ADependencyFileThatIsAnInputOrAnOutputIsRefused) {
    const auto dir = temp_dir("dep-overwrite");
    write(dir / "f.toml", small_spec);
    const std::string spec = sh_quoted((dir / "f.toml").string());
    const std::string out = " -f svg,png -o " + sh_quoted(dir.string());
    for (const std::string& depfile : {(dir / "f.toml").string(), (dir / "." / "f.toml").string(),
                                       (dir / "f.svg").string(), (dir / "f.png").string()}) {
        const auto r = run_cli("render " + spec + out + " --depfile " + sh_quoted(depfile));
        EXPECT_EQ(r.status, 2) << depfile << ": " << r.err;
        EXPECT_NE(r.err.find("of the render"), std::string::npos) << r.err;
        EXPECT_EQ(test_support::slurp(dir / "f.toml"), small_spec);
        EXPECT_EQ(files_in(dir), (std::set<std::string>{"f.toml"})) << depfile;
    }
    // Through a hard link too: the same file by another name.
    fs::create_hard_link(dir / "f.toml", dir / "g.d");
    const auto r = run_cli("render " + spec + out + " --depfile " + sh_quoted((dir / "g.d").string()));
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_EQ(test_support::slurp(dir / "f.toml"), small_spec);
    fs::remove_all(dir);
}

}  // namespace
