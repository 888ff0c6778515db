// SPDX-License-Identifier: GPL-3.0-or-later
// Hostile inputs to the surfaces added last round (plot --set, seconds and rad/s, @FILE
// lists, the one expression parser) and the holes of earlier rounds again (output paths,
// depfiles, LaTeX overlays): each refused with exit 2 and one message, nothing written, no
// byte of a stranger's text obeyed by the terminal.
#include "common/terminal_text.hpp"
#include "process.hpp"

#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <climits>
#include <cstdint>
#include <cstdio>
#include <set>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

namespace {

namespace fs = std::filesystem;
using test_support::files_in;
using test_support::run_cli;
using test_support::slurp;
using test_support::temp_dir;

void write_file(const fs::path& p, const std::string& bytes) {
    std::ofstream out(p, std::ios::binary);
    out << bytes;
}

/// A shell word for `s`: single-quoted, a quote inside written as '\''.
std::string quoted(const std::string& s) {
    std::string out = "'";
    for (const char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

/// The bytes a terminal would obey or that reorder what it shows: none may reach stderr raw.
void expect_no_terminal_controls(const std::string& err) {
    for (std::size_t i = 0; i < err.size(); ++i) {
        const auto u = static_cast<unsigned char>(err[i]);
        EXPECT_FALSE(u < 0x20 && u != '\n') << "raw control byte " << int(u) << " at " << i << " in: " << err;
        EXPECT_NE(u, 0x7f) << err;
    }
    char32_t cp = 0;
    for (std::string_view rest = err; !rest.empty();) {
        const std::size_t n = common::utf8_sequence(rest, cp);
        ASSERT_NE(n, 0u) << "a byte that is not UTF-8 reached stderr: " << err;
        EXPECT_FALSE(cp != '\n' && common::terminal_control(cp)) << "U+" << std::hex << unsigned(cp) << " in: " << err;
        rest.remove_prefix(n);
    }
}

const std::string trajectory = "plot trajectory --theta0 0.5 --methods exact ";

// ---- the one quoting function -------------------------------------------------------------

TEST(AttackTerminal, QuotingBoundaries) {
    using common::terminal_text;
    EXPECT_EQ(terminal_text("a~"), "a~");                       // U+007E printable
    EXPECT_EQ(terminal_text("\x7f"), "\\x7f");                  // DEL
    EXPECT_EQ(terminal_text("\x1b[2J\a\r"), "\\x1b[2J\\x07\\x0d");
    EXPECT_EQ(terminal_text("\xc2\x9f"), "\\u{009f}");          // U+009F, the last C1 control
    EXPECT_EQ(terminal_text("\xc2\x9b"), "\\u{009b}");          // CSI
    EXPECT_EQ(terminal_text("\xc2\x80"), "\\u{0080}");          // the first C1 control
    EXPECT_EQ(terminal_text("\xc2\xa0"), "\xc2\xa0");           // U+00A0 shown
    EXPECT_EQ(terminal_text("\xe2\x80\xae"), "\\u{202e}");      // RIGHT-TO-LEFT OVERRIDE
    EXPECT_EQ(terminal_text("\xe2\x80\xaa"), "\\u{202a}");
    EXPECT_EQ(terminal_text("\xe2\x80\xa9"), "\xe2\x80\xa9");   // U+2029 (not a bidi control)
    EXPECT_EQ(terminal_text("\xe2\x80\xaf"), "\xe2\x80\xaf");   // U+202F
    EXPECT_EQ(terminal_text("\xe2\x81\xa6\xe2\x81\xa9"), "\\u{2066}\\u{2069}");
    EXPECT_EQ(terminal_text("\xe2\x81\xa5\xe2\x81\xaa"), "\xe2\x81\xa5\xe2\x81\xaa");  // U+2065, U+206A
    EXPECT_EQ(terminal_text("\xe2\x80\x8e\xe2\x80\x8f\xd8\x9c"), "\\u{200e}\\u{200f}\\u{061c}");
    EXPECT_EQ(terminal_text("\xcf\x80 \xc2\xb0"), "\xcf\x80 \xc2\xb0");  // pi and degree
    EXPECT_EQ(terminal_text("\x9b"), "\\x9b");                  // a lone 8-bit CSI
    EXPECT_EQ(terminal_text("\xc0\x80"), "\\xc0\\x80");         // overlong NUL
    EXPECT_EQ(terminal_text("\xed\xa0\x80"), "\\xed\\xa0\\x80");  // a surrogate
    EXPECT_EQ(terminal_text("\xf4\x8f\xbf\xbf"), "\xf4\x8f\xbf\xbf");  // U+10FFFF
    EXPECT_EQ(terminal_text("\xf4\x90\x80\x80"), "\\xf4\\x90\\x80\\x80");
    EXPECT_EQ(terminal_text("\xe2\x80"), "\\xe2\\x80");         // cut short
}

TEST(AttackTerminal, SpecFileNamesAreShownNotObeyed) {
    const auto dir = temp_dir("attack-names");
    const auto spec = run_cli("show trajectory-lowest").out;
    ASSERT_NE(spec.find("[[panel]]"), std::string::npos);
    for (const std::string name : {"e\x1b]8;;http:x\x07y\x1b[31m", "e\xc2\x9b" "2Jx", "e\x9b" "2Jx",
                                   "e\xe2\x80\xae" "fdp.exe", "e\rx", "e\xe2\x81\xa6x"}) {
        write_file(dir / (name + ".toml"), spec);
        const auto r = run_cli("render " + quoted(name + ".toml") + " -o . -f svg", dir);
        EXPECT_EQ(r.status, 2) << r.err;
        EXPECT_NE(r.err.find("the name before .toml has the character"), std::string::npos) << r.err;
        expect_no_terminal_controls(r.err);
        // A name that is not there at all: the same quoting.
        const auto missing = run_cli("render " + quoted("no" + name + ".toml") + " -o . -f svg", dir);
        EXPECT_EQ(missing.status, 2) << missing.err;
        expect_no_terminal_controls(missing.err);
    }
    EXPECT_EQ(files_in(dir).size(), 6u);  // the specs only
}

TEST(AttackTerminal, ListFilesAndValuesAreShownNotObeyed) {
    const auto dir = temp_dir("attack-lists");
    write_file(dir / "c1.txt", "pi/2\xc2\x9b" "2J\n");
    write_file(dir / "bidi.txt", "pi/2\xe2\x80\xae\n");
    write_file(dir / "raw.txt", "M\xb4\xd7w\xe5P\x10\x1c\xc0\xfcx'\xd2\xb9\xf8\xd8V\x90\xd6\xc6qh\n");
    for (const std::string f : {"c1.txt", "bidi.txt", "raw.txt"}) {
        const auto r = run_cli("eval --theta0 @" + f, dir);
        EXPECT_EQ(r.status, 2) << r.err;
        expect_no_terminal_controls(r.err);
    }
    for (const std::string v : {"2\xc2\x9b" "31m", "pi\xe2\x80\xae", "\x1b]0;title\x07"}) {
        const auto r = run_cli("eval --theta0 " + quoted(v), dir);
        EXPECT_EQ(r.status, 2) << r.err;
        expect_no_terminal_controls(r.err);
        const auto s = run_cli(trajectory + "-o . -f svg --set " + quoted("x" + v + "=1"), dir);
        EXPECT_EQ(s.status, 2) << s.err;
        expect_no_terminal_controls(s.err);
    }
    const auto missing = run_cli("eval --theta0 " + quoted("@a\x1b]8;;http://x\x07\xc2\x9b"), dir);
    EXPECT_EQ(missing.status, 2) << missing.err;
    expect_no_terminal_controls(missing.err);
}

// ---- @FILE --------------------------------------------------------------------------------

TEST(AttackLists, FifoDeviceAndSocketAreRefusedWithoutBlocking) {
    const auto dir = temp_dir("attack-fifo");
    ASSERT_EQ(::mkfifo((dir / "fifo").c_str(), 0600), 0);
    for (const std::string option : {"eval --theta0 @fifo", "trajectory --theta0 0.5 --omega0 @fifo",
                                     "eval --energy @fifo", "eval --theta0 @/dev/zero", "eval --theta0 @/dev/null"}) {
        // timeout: before, a FIFO without a writer blocked for ever.
        const auto r = test_support::run_command("cd '" + dir.string() + "' && timeout 20 '" + PENDULUM_EXE + "' " +
                                                 option);
        EXPECT_EQ(r.status, 2) << option << ": " << r.err;
        EXPECT_NE(r.err.find("is not a regular file (a device, FIFO or socket); give a file, or - and redirect it"),
                  std::string::npos)
            << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    }
    // Standard input stays the way to read a pipe.
    const auto piped = test_support::run_command("printf 'pi/2\\n' | '" + std::string(PENDULUM_EXE) + "' eval --theta0 -");
    EXPECT_EQ(piped.status, 0) << piped.err;
}

TEST(AttackLists, AMillionAndOneValuesAreRefusedBeforeAnyWork) {
    const auto dir = temp_dir("attack-million");
    std::string lines;
    for (int i = 0; i < 1'000'001; ++i) lines += "1\n";
    write_file(dir / "many.txt", lines);
    const auto r = run_cli("eval --theta0 @many.txt", dir);
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_NE(r.err.find("--theta0 @many.txt: more than 1000000 values; a list takes at most 1000000"), std::string::npos)
        << r.err;
    EXPECT_TRUE(r.out.empty());
}

TEST(AttackLists, LinksProcFilesNulAndBadUtf8) {
    const auto dir = temp_dir("attack-listfiles");
    write_file(dir / "good.txt", "pi/2\n");
    fs::create_symlink("good.txt", dir / "link.txt");
    fs::create_symlink("nowhere.txt", dir / "dangling.txt");
    fs::create_symlink("/proc/self/mem", dir / "mem.txt");
    write_file(dir / "nul.txt", std::string("pi/2\0pi/3\n", 10));
    write_file(dir / "bad.txt", "pi/2\xff\n");
    EXPECT_EQ(run_cli("eval --theta0 @link.txt", dir).status, 0);  // a link to a regular file is that file
    for (const std::string f : {"dangling.txt", "mem.txt", "nul.txt", "bad.txt", "/proc/self/status",
                                "/proc/self/environ", "."}) {
        const auto r = run_cli("eval --theta0 @" + f, dir);
        EXPECT_EQ(r.status, 2) << f << ": " << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        expect_no_terminal_controls(r.err);
    }
}

// ---- output names and paths ---------------------------------------------------------------

TEST(AttackOutputs, PlotNameObeysTheFileNameRule) {
    const auto dir = temp_dir("attack-plotname");
    const std::string longest(100, 'a');
    EXPECT_EQ(run_cli(trajectory + "-f svg --name " + longest, dir).status, 0);
    EXPECT_TRUE(fs::exists(dir / (longest + ".svg")));
    fs::remove(dir / (longest + ".svg"));
    for (const std::string& name : {longest + "a", std::string("a\xe2\x80\xae" "gvs"), std::string("-rf"),
                                   std::string("a$(touch pwned)"), std::string("a`id`"), std::string("a\nb"),
                                   std::string("../up"), std::string(".hidden"), std::string("a b")}) {
        const auto r = run_cli(trajectory + "-f svg,pdf_tex --name " + quoted(name), dir);
        EXPECT_EQ(r.status, 2) << name << ": " << r.err;
        EXPECT_EQ(r.err.rfind("pendulum-figures: error: --name '", 0), 0u) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        expect_no_terminal_controls(r.err);
    }
    EXPECT_TRUE(files_in(dir).empty());
    EXPECT_FALSE(fs::exists(dir.parent_path() / "up.svg"));
}

TEST(AttackOutputs, NameMaxAcceptedAndOneMoreRefused) {
    const auto dir = temp_dir("attack-namemax");
    const std::string name(NAME_MAX - 2, 'd');
    const std::string render = "render trajectory-lowest -f svg --depfile ";
    const auto ok = run_cli(render + name + ".d", dir);
    EXPECT_EQ(ok.status, 0) << ok.err;
    EXPECT_TRUE(fs::exists(dir / (name + ".d")));
    fs::remove_all(dir);
    fs::create_directories(dir);
    const auto r = run_cli(render + name + "d.d", dir);
    EXPECT_EQ(r.status, 2) << r.err;  // was 1, "file name too long", from the kernel
    EXPECT_NE(r.err.find("has a name of 256 bytes; a file name holds at most 255 (NAME_MAX): give a shorter name"),
              std::string::npos)
        << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_TRUE(files_in(dir).empty()) << "nothing written, not even the figure";
}

/// A directory under `base` whose path relative to base has exactly `bytes` bytes (made from
/// base, as its absolute path may be longer than PATH_MAX).
std::string directory_of_length(const fs::path& base, std::size_t bytes) {
    std::string rel;
    while (bytes - rel.size() > 201) rel += std::string(200, 'd') + "/";
    rel += std::string(bytes - rel.size(), 'e');
    EXPECT_EQ(test_support::run_command("cd '" + base.string() + "' && mkdir -p " + rel).status, 0);
    return rel;
}

TEST(AttackOutputs, PathMaxAcceptedAndOneMoreRefused) {
    // The longest path written is the temporary's beside the file: DIR/ and 41 bytes of name.
    const auto base = temp_dir("attack-pathmax");
    const std::string ok_dir = directory_of_length(base, PATH_MAX - 1 - 42);
    const auto ok = run_cli(trajectory + "-f svg -o " + ok_dir, base);
    EXPECT_EQ(ok.status, 0) << ok.err;
    EXPECT_EQ(test_support::run_command("cd '" + base.string() + "' && test -f " + ok_dir + "/trajectory.svg").status, 0);

    const std::string one_more = directory_of_length(base, PATH_MAX - 1 - 42 + 1);
    const auto r = run_cli(trajectory + "-f svg -o " + one_more, base);
    EXPECT_EQ(r.status, 2) << r.err;  // was 1, "file name too long", from the kernel
    EXPECT_NE(r.err.find("has 4096 bytes; a path holds at most 4095 (PATH_MAX less its NUL): give a shorter output "
                         "directory"),
              std::string::npos)
        << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_EQ(test_support::run_command("cd '" + base.string() + "' && test -z \"$(ls -A " + one_more + ")\"").status, 0)
        << "nothing written";
}

TEST(AttackOutputs, LinksDirectoriesAndFifosAtTheTargetAreNeverWrittenThrough) {
    const auto dir = temp_dir("attack-targets");
    const auto outside = temp_dir("attack-targets-victim");
    write_file(outside / "victim.txt", "untouched");
    fs::create_directories(dir / "out");
    const auto out = dir / "out";
    const auto refused = [&](const std::string& what) {
        const auto r = run_cli(trajectory + "-f svg -o out", dir);
        EXPECT_EQ(r.status, 2) << what << ": " << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_EQ(slurp(outside / "victim.txt"), "untouched") << what;
        fs::remove(out / "trajectory.svg");
        EXPECT_TRUE(files_in(out).empty()) << what;
    };
    fs::create_symlink(outside / "victim.txt", out / "trajectory.svg");
    refused("a symbolic link");
    fs::create_symlink(outside / "new.svg", out / "trajectory.svg");
    refused("a dangling link");
    EXPECT_FALSE(fs::exists(outside / "new.svg"));
    fs::create_directory(out / "trajectory.svg");
    refused("a directory");
    ASSERT_EQ(::mkfifo((out / "trajectory.svg").c_str(), 0600), 0);
    refused("a FIFO");  // and it did not block
    // A hard link is a regular file: replaced by rename, the other name keeps its bytes.
    fs::create_hard_link(outside / "victim.txt", out / "trajectory.svg");
    const auto r = run_cli(trajectory + "-f svg -o out", dir);
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(slurp(outside / "victim.txt"), "untouched");
    EXPECT_NE(slurp(out / "trajectory.svg").find("<svg"), std::string::npos);
}

TEST(AttackOutputs, LinksAtTheTemporariesNamesAreNeitherFollowedNorRemoved) {
    const auto dir = temp_dir("attack-temporaries");
    const auto outside = temp_dir("attack-temporaries-victim");
    write_file(outside / "victim.txt", "untouched");
    const std::string stem = ".pendulum-figures-578218d50c3c3838-";  // trajectory.svg's temporaries (64-bit FNV-1a)
    // Links named as a killed run's temporaries, older than the hour after which those are removed.
    const struct timespec old[2] = {{1000000000, 0}, {1000000000, 0}};
    for (const std::string suffix : {"AAAAAA", "zzzzzz", "012345"}) {
        const auto link = dir / (stem + suffix);
        fs::create_symlink(outside / "victim.txt", link);
        ASSERT_EQ(::utimensat(AT_FDCWD, link.c_str(), old, AT_SYMLINK_NOFOLLOW), 0);
    }
    fs::create_symlink(outside / "made.txt", dir / (stem + "dangle"));
    const auto r = run_cli(trajectory + "-f svg", dir);
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(slurp(outside / "victim.txt"), "untouched");
    EXPECT_FALSE(fs::exists(outside / "made.txt"));
    for (const std::string suffix : {"AAAAAA", "zzzzzz", "012345", "dangle"}) {
        EXPECT_TRUE(fs::is_symlink(dir / (stem + suffix))) << "a link a user made stays: " << suffix;
    }
    EXPECT_EQ(files_in(outside), (std::set<std::string>{"victim.txt"}));
}

TEST(AttackOutputs, PaperFileNamesOutsideTheOutputDirectory) {
    const auto dir = temp_dir("attack-paper-file");
    fs::create_directories(dir / "out");
    for (const std::string name : {"../evil", "/tmp/evil", "a/b", "..", ".hidden", "-rf", "a\\nb", "a\\u202eb"}) {
        write_file(dir / "f.toml", "[[panel]]\nplot = \"period\"\nmethods = [\"exact\"]\npaper_file = \"" + name + "\"\n");
        const auto r = run_cli("render f.toml --paper-files -f svg -o out", dir);
        EXPECT_EQ(r.status, 2) << name << ": " << r.err;
        EXPECT_NE(r.err.find("'paper_file' "), std::string::npos) << r.err;
        expect_no_terminal_controls(r.err);
        EXPECT_TRUE(files_in(dir / "out").empty()) << name;
    }
    EXPECT_FALSE(fs::exists(dir / "evil.svg"));
}

TEST(AttackLists, DataFilesThatLeadOutOrBlock) {
    const auto dir = temp_dir("attack-data-files");
    write_file(dir / "ok.csv", "x,y\n1,2\n");
    fs::create_symlink("/etc/passwd", dir / "out.csv");
    ASSERT_EQ(::mkfifo((dir / "fifo.csv").c_str(), 0600), 0);
    const std::string period = "plot period --methods exact -f svg --name d --data ";
    const std::vector<std::pair<std::string, std::string>> refused = {
        {"out.csv:1,2", "'file' = \"out.csv\" leads out of the spec's directory (through a symbolic link); a spec's "
                        "style and data files stay inside it"},
        {"fifo.csv:1,2", "data file 'fifo.csv' is not a regular file (a device, FIFO or socket)"},
        {"/etc/passwd:1,2", "must be a path relative to the spec's directory, not an absolute path"},
        {"../x.csv:1,2", "must stay inside the spec's directory: no '..' leading out of it"},
        {"'ok.csv:x\xe2\x80\xae,y'", "'x' = \"x\\u{202e}\": no such column in the header"},
    };
    for (const auto& [data, message] : refused) {
        const auto r = test_support::run_command("cd '" + dir.string() + "' && timeout 20 '" + PENDULUM_EXE + "' " +
                                                 period + data);
        EXPECT_EQ(r.status, 2) << data << ": " << r.err;
        EXPECT_NE(r.err.find(message), std::string::npos) << data << ": " << r.err;
        expect_no_terminal_controls(r.err);
        EXPECT_FALSE(fs::exists(dir / "d.svg"));
    }
}

TEST(AttackOutputs, ReadOnlyDirectoryAndNamesOutsideIt) {
    const auto dir = temp_dir("attack-readonly");
    fs::create_directories(dir / "ro");
    // Read and enter for everyone, write for no one. Root writes anywhere: as root, the
    // program runs as nobody (setpriv), for whom the directory is read-only too.
    fs::permissions(dir, fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec |
                             fs::perms::others_read | fs::perms::others_exec);
    fs::permissions(dir / "ro", fs::perms::owner_read | fs::perms::owner_exec | fs::perms::group_read |
                                    fs::perms::group_exec | fs::perms::others_read | fs::perms::others_exec);
    const std::string as = ::geteuid() == 0 ? "setpriv --reuid=65534 --regid=65534 --clear-groups " : "";
    const auto r = test_support::run_command("cd '" + dir.string() + "' && " + as + "'" + std::string(PENDULUM_EXE) +
                                             "' " + trajectory + "-f svg -o ro");
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_NE(r.err.find("is not writable"), std::string::npos) << r.err;
    EXPECT_TRUE(files_in(dir / "ro").empty());
    fs::permissions(dir / "ro", fs::perms::owner_all);
    fs::remove_all(dir);
}

TEST(AttackOutputs, DepfileNamesThatMakeOrAShellWouldRun) {
    const auto dir = temp_dir("attack-depfile");
    const auto spec = run_cli("show trajectory-lowest").out;
    for (const std::string sub : {"nl\ndir", "a$(touch pwned)", "a`touch pwned`"}) {
        fs::create_directories(dir / sub);
        write_file(dir / sub / "f.toml", spec);
        fs::create_directories(dir / "out");
        const auto r = run_cli("render " + quoted(sub + "/f.toml") + " -o out -f svg --depfile out/f.d", dir);
        EXPECT_EQ(r.status, 2) << r.err;
        EXPECT_NE(r.err.find("so no dependency file can name it"), std::string::npos) << r.err;
        expect_no_terminal_controls(r.err);
        EXPECT_TRUE(files_in(dir / "out").empty()) << sub;
        for (const std::string target : {"a\nb", "a$(touch pwned)", "a`id`", "a;b", ".PHONY"}) {
            const auto t = run_cli("render trajectory-lowest -o out -f svg --depfile out/g.d --depfile-target " +
                                   quoted(target), dir);
            EXPECT_EQ(t.status, 2) << target << ": " << t.err;
            EXPECT_TRUE(files_in(dir / "out").empty()) << target;
        }
    }
    EXPECT_FALSE(fs::exists(dir / "pwned"));
    // What Make reads as a variable or a separator is escaped where it can be.
    fs::create_directories(dir / "sp ec$x");
    write_file(dir / "sp ec$x" / "f.toml", spec);
    const auto ok = run_cli("render 'sp ec$x/f.toml' -o out -f svg --depfile out/f.d", dir);
    EXPECT_EQ(ok.status, 0) << ok.err;
    EXPECT_NE(slurp(dir / "out" / "f.d").find("sp\\ ec$$x/f.toml"), std::string::npos) << slurp(dir / "out" / "f.d");
}

// ---- LaTeX overlays -----------------------------------------------------------------------

TEST(AttackLatex, CaretNotationCatcodesAndBracesNeverReachTexRaw) {
    const auto dir = temp_dir("attack-latex");
    for (const std::string label : {"^^5cinput{/etc/hostname}", "\\catcode`\\^=7 ^^5c", "a}b", "a{b",
                                    "\\write18{touch pwned}", "$^^5c$", "$^{^5c}$", "$\\mathrm{^}^5cinput$",
                                    "$^^M$", "x~#&%_"}) {
        fs::remove_all(dir / "trajectory.pdf_tex");
        const auto r = run_cli(trajectory + "-f pdf_tex --x-label " + quoted(label), dir);
        EXPECT_EQ(r.status, 0) << label << ": " << r.err;
        const std::string tex = slurp(dir / "trajectory.pdf_tex");
        const std::string body = tex.substr(tex.find("\\begin{picture}"));
        EXPECT_EQ(body.find("^^"), std::string::npos) << label << ":\n" << body;
        EXPECT_EQ(body.find("\\input"), std::string::npos) << label;
        EXPECT_EQ(body.find("\\write"), std::string::npos) << label;
        EXPECT_EQ(body.find("\\catcode"), std::string::npos) << label;
        // Braces balance in every line the labels are set in.
        for (std::size_t at = 0, end = 0; at < body.size(); at = end + 1) {
            end = body.find('\n', at);
            if (end == std::string::npos) end = body.size();
            int depth = 0;
            for (std::size_t i = at; i < end; ++i) {
                if (body[i] == '\\' && i + 1 < end) {
                    ++i;
                    continue;
                }
                depth += body[i] == '{' ? 1 : body[i] == '}' ? -1 : 0;
                ASSERT_GE(depth, 0) << label << ": " << body.substr(at, end - at);
            }
            EXPECT_EQ(depth, 0) << label << ": " << body.substr(at, end - at);
        }
    }
    for (const std::string label : {"$\\input{/etc/passwd}$", "$a}b$", "$x^^5c$", "$\\^^5c$"}) {
        const auto r = run_cli(trajectory + "-f pdf_tex --name refused --x-label " + quoted(label), dir);
        EXPECT_EQ(r.status, 2) << label << ": " << r.err;
        EXPECT_FALSE(fs::exists(dir / "refused.pdf_tex"));
        EXPECT_FALSE(fs::exists(dir / "refused.pdf"));
    }
}

// ---- the expression parser ----------------------------------------------------------------

TEST(AttackParser, NoSilentZeroBeyondTheExponentRange) {
    // Before: 1e-99999 was refused, 1e-9999999999 (past MPFR's exponent range) read as 0.
    for (const std::string v : {"1e-99999", "1e-323228496", "1e-323228497", "1e-9999999999", "1e-99999999999999999999",
                                "0.0001e-9223372036854775809", "2-2+1e-9999999999"}) {
        const auto r = run_cli("eval --theta0 0.5 --omega0 " + quoted(v));
        EXPECT_EQ(r.status, 2) << v << ": " << r.out;
        EXPECT_NE(r.err.find("below the smallest double, 4.9406564584124654e-324, and it is not 0"), std::string::npos)
            << r.err;
    }
    // A mantissa of zeros is 0 whatever its exponent, and the smallest double is held.
    for (const std::string v : {"0e-9999999999", "0.000e-99999999999999999999", "4.9406564584124654e-324"}) {
        const auto r = run_cli("eval --theta0 0.5 --omega0 " + quoted(v));
        EXPECT_EQ(r.status, 0) << v << ": " << r.err;
    }
}

TEST(AttackParser, ConfusablesNanInfAndHexAreRefusedByName) {
    for (const std::string v : {"\xe2\x88\x92" "1", "\xef\xbc\x91", "\xd9\xa3", "\xe2\x80\x8f" "1", "1\xe2\x80\xae",
                                "nan", "NaN", "inf", "-inf", "infinity", "0x1p-1", "0x1.8p0", "1d5", "1_000",
                                "2^10", "1e99999999999999999999"}) {
        const auto r = run_cli("eval --theta0 " + quoted(v));
        EXPECT_EQ(r.status, 2) << v << ": " << r.out;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        expect_no_terminal_controls(r.err);
        EXPECT_TRUE(r.out.empty());
    }
    // The Greek pi and the degree sign are read.
    EXPECT_EQ(run_cli("eval --theta0 '2\xcf\x80/3'").status, 0);
    EXPECT_EQ(run_cli("eval --theta0 '162\xc2\xb0'").status, 0);
}

TEST(AttackParser, NestingAndLengthAtTheirLimits) {
    const auto nested = [](int n) { return std::string(n, '(') + "1" + std::string(n, ')'); };
    EXPECT_EQ(run_cli("eval --theta0 '" + nested(250) + "'").status, 0);
    const auto r = run_cli("eval --theta0 '" + nested(251) + "'");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("nested too deeply (at most 250 levels"), std::string::npos) << r.err;
    const auto dir = temp_dir("attack-parser-files");
    write_file(dir / "deep.txt", std::string(500000, '(') + "1" + std::string(500000, ')') + "\n");
    write_file(dir / "signs.txt", std::string(1000000, '-') + "1\n");
    for (const std::string f : {"deep.txt", "signs.txt"}) {
        const auto big = run_cli("eval --theta0 @" + f, dir);
        EXPECT_EQ(big.status, 2) << big.err;
        EXPECT_NE(big.err.find("line 1 is longer than 65536 bytes"), std::string::npos) << big.err;
    }
}

// ---- plot --set, --range in seconds, --omega0 in rad/s --------------------------------------

TEST(AttackPlotValues, SetRangeAndRadiansPerSecond) {
    const auto dir = temp_dir("attack-plot-values");
    const std::vector<std::pair<std::string, std::string>> refused = {
        {"--set columns=99999999999999999999", "not a whole number"},
        {"--set columns=7", "'columns' = 7 is out of range; allowed 1 to 6"},
        {"--set columns=0", "'columns' = 0 is out of range; allowed 1 to 6"},
        {"--set legend=", "is not one of first, each, none"},
        {"--set title=x --title y", "--set title and --title both give the figure's title: give one"},
        {"--set title=" + std::string(1001, 'a'), "'title' has 1001 bytes; at most 1000"},
        {"--set 'title=a\xc2\x9b" "2J'", "has the control character U+009B"},
        {"--range 0,5s", "in seconds needs the pendulum's --length"},
        {"--range 0,1e6s --length 1", "a trajectory panel draws at most 100"},
        {"--range 0,5s --length 1 --time t/T", "in seconds goes with --time t/s (the default then) or t/T0"},
        {"--range 0,5s-1s --length 1", "unknown name 's'"},
        {"--range 0,1e308s --length 1", "must be finite and at most 1e6"},
        {"--omega0 2rad/s", "needs the pendulum's --length"},
        {"--omega0 '2 rad / s' --length 1", "unknown name 'rad'"},
        {"--omega0 2deg/s --length 1", "unknown name 'deg'"},
    };
    for (const auto& [options, message] : refused) {
        const auto r = run_cli(trajectory + "-f svg " + options, dir);
        EXPECT_EQ(r.status, 2) << options << ": " << r.err;
        EXPECT_NE(r.err.find(message), std::string::npos) << options << ": " << r.err;
        expect_no_terminal_controls(r.err);
    }
    EXPECT_TRUE(files_in(dir).empty());
    // A control character in a text option is named with the value it is in (was "control
    // character in an option", naming nothing).
    for (const std::string options : {"--set 'title=a\x1b]0;t\x07b'", "--title 'a\rb'", "--x-label 'a\tb'",
                                      "--panel-title 'a\nb'"}) {
        const auto r = run_cli(trajectory + "-f svg " + options, dir);
        EXPECT_EQ(r.status, 2) << options << ": " << r.err;
        EXPECT_NE(r.err.find("' has a control character: an option's text is one line of printable characters"),
                  std::string::npos)
            << r.err;
        EXPECT_NE(r.err.find("'a\\x"), std::string::npos) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    }
    EXPECT_TRUE(files_in(dir).empty());
    EXPECT_EQ(run_cli(trajectory + "-f svg --set columns=6 --set 'title=" + std::string(1000, 'a') + "'", dir).status, 0);
}

}  // namespace
