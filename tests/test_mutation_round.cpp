// SPDX-License-Identifier: GPL-3.0-or-later
// Tests for the mutants of last round's new code that no other test killed (the table is
// tests/data/mutations_round.md): UTF-8's boundaries in the one expression parser, columns
// and names in its messages, the Jacobi branch next to m = 1 against mpmath, the modes and
// leftovers of output temporaries, the angle-notation rule's texts, and tick marks that
// start on a marker's keep-out circle.
#include "pendulum/angle.hpp"
#include "pendulum/exact.hpp"
#include "pendulum/expression_parser.hpp"
#include "pendulum/formula.hpp"
#include "pendulum/motion.hpp"
#include "plot/figure.hpp"
#include "plot/legend.hpp"
#include "plot/output.hpp"
#include "plot/preflight.hpp"
#include "plot/strokes.hpp"
#include "plot/text.hpp"
#include "grammar_errors.hpp"
#include "process.hpp"
#include "reference_rows.hpp"

#include <gtest/gtest.h>

#include <fontconfig/fontconfig.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using test_support::slurp;
using test_support::temp_dir;

namespace {

using test_support::angle_error;
using test_support::formula_error;

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

/// The mode bits of a path.
unsigned mode_of(const fs::path& p) {
    struct stat st {};
    if (::stat(p.c_str(), &st) != 0) return 0xffffffffu;
    return st.st_mode & 07777;
}

/// Sets the umask for its life, and puts the old one back.
class umask_for_test {
public:
    explicit umask_for_test(mode_t m) : old_(::umask(m)) {}
    ~umask_for_test() { ::umask(old_); }
    umask_for_test(const umask_for_test&) = delete;
    umask_for_test& operator=(const umask_for_test&) = delete;

private:
    mode_t old_;
};

}  // namespace

// ---- UTF-8 in the one parser: each lead byte's range and each second byte's at its boundary.

TEST(MutationRound, Utf8LeadAndSecondBytesAtTheirBoundaries) {
    using pendulum::grammar::invalid_utf8;
    struct row {
        std::string text;
        bool valid;
    };
    const std::vector<row> rows = {
        {"\xc1\xbf", false},          {"\xc2\x80", true},          // overlong 2-byte | U+0080
        {"\xdf\xbf", true},           {"\xe0\x9f\xbf", false},     // U+07FF | overlong 3-byte
        {"\xe0\xa0\x80", true},       {"\xed\x9f\xbf", true},      // U+0800 | U+D7FF
        {"\xed\xa0\x80", false},      {"\xef\xbf\xbf", true},      // surrogate U+D800 | U+FFFF
        {"\xf0\x8f\xbf\xbf", false},  {"\xf0\x90\x80\x80", true},  // overlong 4-byte | U+10000
        {"\xf4\x8f\xbf\xbf", true},   {"\xf4\x90\x80\x80", false}, // U+10FFFF | beyond it
        {"\xf5\x80\x80\x80", false},  {"\xf7\xbf\xbf\xbf", false}, // no code point starts so
        {"\xc0\x80", false},          {"\x80", false},             // overlong NUL | a lone continuation
    };
    for (const auto& r : rows) {
        EXPECT_EQ(invalid_utf8(r.text), r.valid ? r.text.size() : 0u) << r.text.size() << " bytes";
    }
    // Through the parser, the byte named (both hex digits its own).
    EXPECT_EQ(formula_error("1+\xc1\xbf"), "formula:1:3: byte \\xc1 is not UTF-8; write the formula in UTF-8");
    EXPECT_EQ(formula_error("1+\xf5\x80\x80\x80"), "formula:1:3: byte \\xf5 is not UTF-8; write the formula in UTF-8");
    EXPECT_TRUE(has(angle_error("\xc0\x80"), "byte \\xc0 is not UTF-8; write the expression in UTF-8"));
}

// ---- Messages: columns count characters, and a name may start with "_".

TEST(MutationRound, ColumnsCountCharactersNotBytes) {
    // θ is two bytes and one column: the '(' is the fourth character.
    EXPECT_TRUE(has(formula_error("\u03b80*(1"), "missing ')' for the '(' at column 4")) << formula_error("\u03b80*(1");
    EXPECT_TRUE(has(formula_error("\u03b80*\u03c0*(1"), "missing ')' for the '(' at column 6"));
}

TEST(MutationRound, AnUnderscoreStartsAName) {
    EXPECT_TRUE(has(formula_error("2*_x"), "unknown name '_x'")) << formula_error("2*_x");
    EXPECT_TRUE(has(angle_error("_pi"), "unknown name '_pi'")) << angle_error("_pi");
}

// ---- Jacobi's functions next to m = 1: the branch below k' = 1e-9 and its first-order term,
// against mpmath (tests/data/make_jacobi_near_one.py, jacobi_near_one.csv).

TEST(MutationRound, JacobiNextToOneAgreesWithMpmath) {
    std::ifstream in(std::string(PENDULUM_TEST_DATA) + "/jacobi_near_one.csv");
    ASSERT_TRUE(in) << "jacobi_near_one.csv";
    std::string line;
    std::getline(in, line);  // header
    int rows = 0;
    while (std::getline(in, line)) {
        const auto f = test_support::rows::split_at(line, ',');
        ASSERT_EQ(f.size(), 5u) << line;
        const double kp = test_support::rows::number(f[0]);
        const double u = test_support::rows::number(f[1]);
        const pendulum::jacobi_values v = pendulum::jacobi(u, kp);
        const double want[3] = {test_support::rows::number(f[2]), test_support::rows::number(f[3]), test_support::rows::number(f[4])};
        const double got[3] = {v.sn, v.cn, v.dn};
        for (int i = 0; i < 3; ++i) {
            // cn and dn are ~1e-5 here; the first-order term is ~2e-12 of them, 2e4 ulp.
            EXPECT_LE(std::fabs(got[i] - want[i]), 4 * test_support::rows::ulp(want[i]))
                << "kp " << f[0] << " u " << f[1] << " value " << i << ": " << got[i] << " vs " << f[2 + i];
        }
        ++rows;
    }
    EXPECT_EQ(rows, 6);
}

// ---- Output temporaries: their modes, and which leftovers go.

TEST(MutationRound, NewFilesTakeTheUmaskFrom0666) {
    const auto dir = temp_dir("mut-umask");
    {
        const umask_for_test mask(002);
        plot::write_atomically(dir / "a.svg", "a");
    }
    EXPECT_EQ(mode_of(dir / "a.svg"), 0664u);
    {
        const umask_for_test mask(0);
        plot::write_atomically(dir / "b.svg", "b");
    }
    EXPECT_EQ(mode_of(dir / "b.svg"), 0666u);
    fs::remove_all(dir);
}

TEST(MutationRound, AReplacingTemporaryIsPrivateUntilItTakesTheName) {
    const auto dir = temp_dir("mut-private");
    std::ofstream(dir / "f.pdf") << "old";
    ASSERT_EQ(::chmod((dir / "f.pdf").c_str(), 0644), 0);
    const umask_for_test mask(022);
    unsigned while_written = 0;
    plot::write_atomically_by(dir / "f.pdf", [&](const fs::path& temp) {
        while_written = mode_of(temp);
        std::ofstream(temp) << "new";
    });
    EXPECT_EQ(while_written, 0600u);
    EXPECT_EQ(mode_of(dir / "f.pdf"), 0644u);
    EXPECT_EQ(slurp(dir / "f.pdf"), "new");
    // A new file's temporary has the new file's mode from the start.
    plot::write_atomically_by(dir / "g.pdf", [&](const fs::path& temp) {
        while_written = mode_of(temp);
        std::ofstream(temp) << "g";
    });
    EXPECT_EQ(while_written, 0644u);
    fs::remove_all(dir);
}

TEST(MutationRound, AReplacedFileKeepsItsSpecialModeBits) {
    const auto dir = temp_dir("mut-special");
    std::ofstream(dir / "f.png") << "old";
    ASSERT_EQ(::chmod((dir / "f.png").c_str(), 01640), 0);
    if (mode_of(dir / "f.png") != 01640u) GTEST_SKIP() << "the file system does not keep the sticky bit";
    plot::write_atomically(dir / "f.png", "new");
    EXPECT_EQ(mode_of(dir / "f.png"), 01640u);
    fs::remove_all(dir);
}

TEST(MutationRound, OnlyTemporariesOlderThanAnHourGo) {
    const auto dir = temp_dir("mut-stale");
    const std::string ours = ".pendulum-figures-b2664dce40f08f91-";  // f.svg's temporaries (64-bit FNV-1a of its name)
    const auto now = fs::file_time_type::clock::now();
    const struct {
        std::string suffix;
        std::chrono::minutes age;
        bool stays;
    } rows[] = {
        {"Min002", std::chrono::minutes(2), true},     // another run's, still writing
        {"Min055", std::chrono::minutes(55), true},    // under the hour
        {"Min065", std::chrono::minutes(65), false},   // a killed run's
        {"Min999x", std::chrono::minutes(999), true},  // seven characters: not a name the writer makes
    };
    for (const auto& r : rows) {
        std::ofstream(dir / (ours + r.suffix)) << "x";
        fs::last_write_time(dir / (ours + r.suffix), now - r.age);
    }
    plot::write_atomically(dir / "f.svg", "svg");
    for (const auto& r : rows) EXPECT_EQ(fs::exists(dir / (ours + r.suffix)), r.stays) << r.suffix;
    fs::remove_all(dir);
}

// ---- The angle-notation rule: every label's text, ".5π" a decimal too.

namespace {

plot::figure figure_with(const std::string& title, const std::string& axis, const std::string& series_label,
                         const std::string& peer_label) {
    plot::figure fig;
    fig.title = title;
    plot::panel p;
    p.x.label = axis;
    plot::series s;
    s.label = series_label;
    p.data.push_back(s);
    fig.panels.push_back(p);
    if (!peer_label.empty()) {
        plot::panel peer;
        peer.label = peer_label;
        fig.peers.push_back(peer);
    }
    return fig;
}

}  // namespace

TEST(MutationRound, AngleNotationReadsEveryLabel) {
    using plot::angle_notation_problem;
    // One way alone is quiet, however many labels.
    EXPECT_EQ(angle_notation_problem(figure_with("\u03c0/2", "9\u03c0/10", "", "")), "");
    EXPECT_EQ(angle_notation_problem(figure_with("0.5\u03c0", "", "0.9\u03c0", "")), "");
    // Two ways, wherever the second is: a series' legend label, a peer panel's label.
    EXPECT_TRUE(has(angle_notation_problem(figure_with("\u03c0/2", "", "0.9\u03c0", "")), "0.9\u03c0 (a decimal)"));
    EXPECT_TRUE(has(angle_notation_problem(figure_with("\u03c0/2", "", "", "0.9\u03c0")), "\u03c0/2 (a fraction"));
    // A decimal without its leading zero is a decimal.
    const std::string bare = angle_notation_problem(figure_with("\u03c0/2", ".5\u03c0", "", ""));
    EXPECT_TRUE(has(bare, ".5\u03c0 (a decimal)")) << bare;
}

// ---- Tick marks: one that starts on a marker's keep-out circle is not drawn, whichever way it goes.

TEST(MutationRound, ATickStartingOnTheKeepOutCircleIsNotDrawn) {
    const std::vector<plot::keep_out> disc = {{0.0, 0.0, 1.0}};
    // (1.5, 0) is exactly on the circle of radius 1 + 0.5: outwards, inwards, along it.
    EXPECT_EQ(plot::tick_length_clear(1.5, 0.0, 1.0, 0.0, 4.0, disc, 0.5), 0.0);
    EXPECT_EQ(plot::tick_length_clear(1.5, 0.0, -1.0, 0.0, 4.0, disc, 0.5), 0.0);
    EXPECT_EQ(plot::tick_length_clear(1.5, 0.0, 0.0, 1.0, 4.0, disc, 0.5), 0.0);
    // Just outside it, heading away: the whole length.
    EXPECT_EQ(plot::tick_length_clear(1.5000001, 0.0, 1.0, 0.0, 4.0, disc, 0.5), 4.0);
}

// ---- The scan of fontconfig's files follows fontconfig's rules: a relative
// XDG_CONFIG_HOME is not a directory (fontconfig takes ~/.config then), and <reset-dirs/>
// drops the directories listed before it.

namespace {

/// A font outside fontconfig's directories (one of TeX Live's) and its family; empty if none.
std::pair<std::string, std::string> font_unknown_to_fontconfig() {
    const auto script = temp_dir("mut-font-find") / "find.sh";
    std::ofstream(script) << (
        "known=$(fc-list : family); find /usr/share/texlive /usr/share/texmf -name '*.otf' 2>/dev/null | sort | "
        "while read -r f; do fam=$(fc-scan --format '%{family[0]}\\n' \"$f\" 2>/dev/null | sed -n 1p); "
        "if [ -n \"$fam\" ] && ! grep -qxF \"$fam\" <<<\"$known\" && ! grep -q '[,\"&<]' <<<\"$fam\"; then "
        "echo \"$f\"; echo \"$fam\"; break; fi; done\n");
    const auto r = test_support::run_command("bash " + script.string());
    fs::remove_all(script.parent_path());
    const auto nl = r.out.find('\n');
    if (nl == std::string::npos) return {};
    std::string family = r.out.substr(nl + 1);
    while (!family.empty() && family.back() == '\n') family.pop_back();
    return {r.out.substr(0, nl), family};
}

/// Renders fig1 as SVG with the family first, in `home` (HOME and the working directory) and
/// with XDG_CONFIG_HOME as given.
test_support::run_result render_in(const fs::path& home, const std::string& xdg_config_home, const std::string& family) {
    return test_support::run_command(
        "cd '" + home.string() + "' && env -u FONTCONFIG_FILE -u FONTCONFIG_PATH -u XDG_DATA_HOME HOME='" + home.string() +
        "' XDG_CONFIG_HOME='" + xdg_config_home + "' XDG_CACHE_HOME='" + (home / "cache").string() + "' timeout 120 " +
        PENDULUM_EXE + " render fig1 -f svg --force -o '" + home.string() + "' --set 'font_family=" + family +
        ", DejaVu Sans'");
}

void write_text(const fs::path& p, const std::string& text) {
    fs::create_directories(p.parent_path());
    std::ofstream(p) << text;
}

}  // namespace

TEST(MutationRound, FontScanTakesFontconfigsXdgAndResetRules) {
    const auto [font, family] = font_unknown_to_fontconfig();
    if (font.empty()) GTEST_SKIP() << "no font outside fontconfig's directories";
    const auto home = temp_dir("mut-fonts");
    fs::create_directories(home / "fonts");
    fs::copy_file(font, home / "fonts" / fs::path(font).filename());
    const std::string conf = "<fontconfig><dir>" + (home / "fonts").string() + "</dir></fontconfig>";
    // A relative XDG_CONFIG_HOME: fontconfig reads ~/.config, not ./config.
    write_text(home / "config/fontconfig/fonts.conf", conf);
    auto r = render_in(home, "config", family);
    EXPECT_EQ(r.status, 2) << "relative XDG_CONFIG_HOME read: " << r.err;
    write_text(home / ".config/fontconfig/fonts.conf", conf);
    r = render_in(home, "config", family);
    EXPECT_EQ(r.status, 0) << "~/.config not read: " << r.err;
    // <reset-dirs/> after the font's directory: fontconfig drops it, so the family is unknown.
    write_text(home / ".config/fontconfig/fonts.conf",
               "<fontconfig><dir>" + (home / "fonts").string() + "</dir><reset-dirs/></fontconfig>");
    r = render_in(home, (home / ".config").string(), family);
    EXPECT_EQ(r.status, 2) << "<reset-dirs/> not followed: " << r.err;
    fs::remove_all(home);
}

// ---- The separatrix has lost no bits: its gap is 0 by decision, not by cancellation.

TEST(MutationRound, TheSeparatrixReportsNoCancelledBits) {
    using pendulum::written_number;
    const auto top = pendulum::motion::from_energy(written_number::expression("2"));
    EXPECT_EQ(top.kind(), pendulum::regime::separatrix);
    EXPECT_EQ(top.cancelled_bits(), 0);
    const auto state = pendulum::motion::from_state(written_number::angle("2pi/3"), written_number::expression("1"));
    EXPECT_EQ(state.kind(), pendulum::regime::separatrix);
    EXPECT_EQ(state.cancelled_bits(), 0);
    // Next to it, the bits the gap lost are counted (2 - E = 1e-20: about 66 of them).
    const auto near = pendulum::motion::from_energy(written_number::expression("2-1e-20"));
    EXPECT_EQ(near.kind(), pendulum::regime::libration);
    EXPECT_GE(near.cancelled_bits(), 60);
}

// ---- Legends: a band's line holds entries that fill it exactly, and what an animation
// moves (an overlay) never counts against a legend's place.

TEST(MutationRound, ALegendLineHoldsEntriesThatFillItExactly) {
    plot::theme th;
    th.padding_pt = 1.0;
    plot::legend_layout l;
    l.entries = {0, 1};
    l.text_ws = {8.0, 8.0};
    l.sample_w = 10.0;
    l.row_h = 5.0;
    // Each entry is 10 + 1 + 8 = 19 wide, the gap between them 2: 40 in all.
    EXPECT_EQ(plot::legend_lines(l, th, 40.0).size(), 1u);
    EXPECT_EQ(plot::legend_lines(l, th, 39.75).size(), 2u);
    EXPECT_EQ(plot::legend_band_height(l, th, 40.0), 5.5);
    EXPECT_EQ(plot::legend_band_height(l, th, 39.75), 10.5);
}

TEST(MutationRound, AnOverlayDoesNotCountAgainstALegend) {
    const plot::rect box{0.0, 0.0, 10.0, 10.0};
    plot::series line;
    line.line = plot::line_style::solid;
    line.marker = plot::marker_style::filled_circle;
    plot::device_series through;
    through.x = {-5.0, 5.0, 15.0};
    through.y = {5.0, 5.0, 5.0};
    EXPECT_EQ(plot::overlap(box, {line}, {through}, 1.0), 3);  // two segments and one marker
    line.overlay = true;
    EXPECT_EQ(plot::overlap(box, {line}, {through}, 1.0), 0);
}

// ---- The scan reads a directory of configuration files in name order, as fontconfig does:
// the font directories keep fontconfig's order (which file of a family is found first).

TEST(MutationRound, FontDirectoriesKeepFontconfigsOrder) {
    const auto home = temp_dir("mut-font-order");
    fs::create_directories(home / "userfonts");
    write_text(home / "config/fontconfig/fonts.conf",
               "<fontconfig><dir>" + (home / "userfonts").string() + "</dir></fontconfig>");
    int fds[2];
    ASSERT_EQ(::pipe(fds), 0);
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        // A process of its own: the private configuration is built once a process.
        ::close(fds[0]);
        ::setenv("HOME", home.c_str(), 1);
        ::setenv("XDG_CONFIG_HOME", (home / "config").c_str(), 1);
        for (const char* v : {"FONTCONFIG_FILE", "FONTCONFIG_PATH", "FONTCONFIG_SYSROOT", "XDG_DATA_HOME"}) ::unsetenv(v);
        std::vector<std::string> own;
        if (FcConfig* c = FcInitLoadConfig()) {
            FcStrList* dirs = FcConfigGetFontDirs(c);
            while (const FcChar8* d = FcStrListNext(dirs)) own.emplace_back(reinterpret_cast<const char*>(d));
            FcStrListDone(dirs);
            FcConfigDestroy(c);
        }
        const auto ours = plot::private_font_directories();
        // Each list as far as the other has it, first places only.
        const auto common = [](const std::vector<std::string>& a, const std::vector<std::string>& b) {
            std::vector<std::string> out;
            for (const auto& d : a) {
                if (std::find(b.begin(), b.end(), d) != b.end() && std::find(out.begin(), out.end(), d) == out.end()) {
                    out.push_back(d);
                }
            }
            return out;
        };
        std::string report;
        for (const auto& d : common(own, ours)) report += d + "\n";
        report += "--\n";
        for (const auto& d : common(ours, own)) report += d + "\n";
        (void)!::write(fds[1], report.data(), report.size());
        ::_exit(0);
    }
    ::close(fds[1]);
    std::string report;
    char buffer[4096];
    for (ssize_t n; (n = ::read(fds[0], buffer, sizeof buffer)) > 0;) report.append(buffer, static_cast<std::size_t>(n));
    ::close(fds[0]);
    int status = 0;
    ::waitpid(child, &status, 0);
    ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
    const auto cut = report.find("--\n");
    ASSERT_NE(cut, std::string::npos) << report;
    EXPECT_TRUE(has(report, (home / "userfonts").string())) << report;
    EXPECT_EQ(report.substr(0, cut), report.substr(cut + 3)) << report;
    fs::remove_all(home);
}

// ---- Seconds and rad/s read with --length: the same figure or numbers as the value in the
// command's own unit, converted with T0 = 2 pi sqrt(L/g) and w0 = sqrt(g/L) (g = 9.80665).

namespace {

std::string seventeen_digits(double v) {
    char text[40];
    std::snprintf(text, sizeof text, "%.17g", v);
    return text;
}

}  // namespace

TEST(MutationRound, SecondsOnAT0AxisAreConvertedByThePeriod) {
    const auto dir = temp_dir("mut-range-t0");
    const double t0 = 2 * M_PI * std::sqrt(1.0 / 9.80665);  // seconds
    const std::string common = "plot trajectory --methods exact --theta0 170deg --length 1 --time t/T0 -f svg ";
    auto r = test_support::run_cli(common + "--range 0,5s --name s", dir);
    ASSERT_EQ(r.status, 0) << r.err;
    r = test_support::run_cli(common + "--range 0," + seventeen_digits(5 / t0) + " --name t", dir);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_TRUE(slurp(dir / "s.svg") == slurp(dir / "t.svg")) << "5 s is " << 5 / t0 << " T0";
    fs::remove_all(dir);
}

TEST(MutationRound, RadPerSecondIsDividedByW0) {
    const double w0 = std::sqrt(9.80665 / 2.0);  // 1/s, L = 2 m
    const auto given = test_support::run_cli("eval --theta0 0 --length 2 --omega0 1.5rad/s");
    ASSERT_EQ(given.status, 0) << given.err;
    const auto plain = test_support::run_cli("eval --theta0 0 --length 2 --omega0 " + seventeen_digits(1.5 / w0));
    ASSERT_EQ(plain.status, 0) << plain.err;
    EXPECT_EQ(given.out, plain.out);
}
