// SPDX-License-Identifier: GPL-3.0-or-later
// Hostile input: deep nesting, malformed numbers, control characters, a bad
// SOURCE_DATE_EPOCH, an unwritable standard output, many panels, too many amplitudes.
#include "cli/lists.hpp"
#include "pendulum/angle.hpp"
#include "process.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <set>
#include <stdexcept>
#include <string>

namespace {

namespace fs = std::filesystem;
using test_support::files_in;
using test_support::run_cli;
using test_support::run_command;
using test_support::temp_dir;

std::string why(const std::string& text) {
    try {
        pendulum::parse_angle(text);
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "accepted";
}

TEST(Hardening, DeepNestingIsAnErrorNotACrash) {
    for (const std::string& text : {std::string(50000, '(') + "1" + std::string(50000, ')'),
                                    std::string(30000, '(') + "1", std::string(30000, '-') + "1",
                                    std::string(300, '(') + "1" + std::string(300, ')')}) {
        EXPECT_NE(why(text).find("nested too deeply"), std::string::npos) << text.size();
        EXPECT_LT(why(text).size(), 300u);  // the value is shown by its ends
    }
    EXPECT_EQ(pendulum::parse_angle(std::string(100, '(') + "1" + std::string(100, ')')), 1.0);
    // Within the command line's 1000 bytes a list item may have, far past the depth bound.
    const auto r = run_cli("eval --theta0 '" + std::string(900, '(') + "1'");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("nested too deeply"), std::string::npos);
}

TEST(Hardening, NumbersNeedADigit) {
    for (const char* text : {".e5", "1+.e5", ".", "-.e-3", "2*.E1"}) {
        EXPECT_NE(why(text).find("is not a number"), std::string::npos) << text << ": " << why(text);
    }
    EXPECT_EQ(pendulum::parse_angle("1.e-1"), 0.1);
    EXPECT_EQ(pendulum::parse_angle(".5e1"), 5.0);
}

TEST(Hardening, ControlCharactersAreShownEscaped) {
    const auto s = run_command("'" + std::string(PENDULUM_EXE) + "' eval --theta0 \"$(printf '\\033[2J1\\r')\"");
    EXPECT_EQ(s.status, 2);
    EXPECT_EQ(s.err.find('\x1b'), std::string::npos) << s.err;
    EXPECT_EQ(s.err.find('\r'), std::string::npos);
    EXPECT_NE(s.err.find("\\x1b[2J1\\x0d"), std::string::npos) << s.err;
}

TEST(Hardening, SourceDateEpochMustBeValid) {
    const auto dir = temp_dir("epoch");
    for (const char* bad : {"garbage", "-1", "1.5", "0x10", "253402300800", " 5"}) {
        const auto r = run_command("SOURCE_DATE_EPOCH='" + std::string(bad) + "' '" + PENDULUM_EXE +
                                   "' render fig1 -f pdf -o '" + dir.string() + "'");
        EXPECT_EQ(r.status, 2) << bad;
        EXPECT_NE(r.err.find("SOURCE_DATE_EPOCH"), std::string::npos) << r.err;
    }
    EXPECT_TRUE(files_in(dir).empty());
    const auto good = run_command("SOURCE_DATE_EPOCH=253402300799 '" + std::string(PENDULUM_EXE) +
                                  "' render fig1 -f pdf -o '" + dir.string() + "'");
    EXPECT_EQ(good.status, 0) << good.err;
    EXPECT_NE(test_support::slurp(dir / "c1-lowest.pdf").find("99991231235959"), std::string::npos);
    fs::remove_all(dir);
}

TEST(Hardening, UnwritableStandardOutputIsAnError) {
    for (const char* args : {"--help", "render --help", "--version", "list", "eval --theta0 1", "data fig1"}) {
        const auto r = run_command("'" + std::string(PENDULUM_EXE) + "' " + args + " > /dev/full");
        EXPECT_EQ(r.status, 1) << args;
        EXPECT_NE(r.err.find("cannot write"), std::string::npos) << args << ": " << r.err;
    }
}

TEST(Hardening, ManyPanelsAreLetteredInPlainAscii) {
    const auto amplitudes = [](int n) {
        std::string list;
        for (int i = 1; i <= n; ++i) list += (i > 1 ? "," : "") + std::to_string(i * 0.1);
        return list;
    };
    // One trajectory panel per amplitude, (a) to (z): the most a figure has.
    const auto r = run_cli("data fig2 --theta0 '" + amplitudes(26) + "'");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("\nz,"), std::string::npos);
    for (const char c : r.out) EXPECT_LT(static_cast<unsigned char>(c), 0x80u);
    // More is bad input, named, before any work.
    const auto more = run_cli("data fig2 --theta0 '" + amplitudes(27) + "'");
    EXPECT_EQ(more.status, 2);
    EXPECT_NE(more.err.find("would have 27 panels (one per --theta0 amplitude); a figure has at most 26"),
              std::string::npos)
        << more.err;
    EXPECT_EQ(more.out, "");
}

TEST(Hardening, AFigureTooSmallForItsTextIsBadInput) {
    const auto dir = temp_dir("too-small");
    const auto r = run_cli("render fig2 --theme slides --set figure_width_cm=10.8 --set figure_height_cm=6.5 -f png -o '" +
                           dir.string() + "'");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("trajectory-lowest.png: a figure of 10.8 x 6.5 cm leaves panel 1 of 4 axes of"), std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("too small for 14 pt text"), std::string::npos) << r.err;
    EXPECT_TRUE(files_in(dir).empty());
    fs::remove_all(dir);
}

TEST(Hardening, TooManyAmplitudesForThePaperFilesIsCheckedFirst) {
    const auto dir = temp_dir("paper-files");
    const auto r = run_cli("render fig2 --paper-files --theta0 0.5,1,1.5,2,2.5 -f pdf -o '" + dir.string() + "'");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("no paper file name"), std::string::npos) << r.err;
    EXPECT_TRUE(files_in(dir).empty());
    fs::remove_all(dir);
}

}  // namespace

namespace {

TEST(Hardening, EmptyValuesAndOrdersAreReported) {
    const std::pair<const char*, const char*> cases[] = {
        {"eval --theta0 ''", "--theta0: empty value"},
        {"render fig1 --theta0 ''", "--theta0: empty value"},
        {"render fig1 -o ''", "--output-dir: empty value"},
        {"data fig1 -o ''", "--output: empty value"},
        {"eval --theta0 1 --order 1,,2", "--order: empty value"},
        {"eval --theta0 1 --order 2147483648", "order must be between 0 and 200"},
        {"eval --theta0 1 --order 5x", "not a whole number"},
        {"data fig1 -o /", "is a directory; give a file name"},
        {"data fig1 -o /nonexistent-dir/x.csv", "does not exist"},
    };
    for (const auto& [args, message] : cases) {
        const auto r = run_cli(args);
        EXPECT_EQ(r.status, 2) << args;
        EXPECT_NE(r.err.find(message), std::string::npos) << args << ": " << r.err;
    }
    // Spaces on either side of an order, and repeated orders give one column.
    const auto r = run_cli("eval --theta0 1 --order ' 5 ' --order 5,5");
    ASSERT_EQ(r.status, 0) << r.err;
    const auto header = r.out.substr(0, r.out.find('\n'));
    EXPECT_EQ(header.find("period_order5"), header.rfind("period_order5"));
}

}  // namespace

namespace {

TEST(Hardening, HugeRastersAreRefusedBeforeAnyWork) {
    const auto dir = temp_dir("huge");
    auto r = run_cli("render --all -f pdf,png --dpi 2400 --theme slides -o '" + dir.string() + "'");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("24000 x 13500 pixels is too large"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("--dpi 1333 is the most"), std::string::npos) << r.err;
    EXPECT_TRUE(files_in(dir).empty());  // not even the PDFs
    r = run_cli("render swing -f gif --dpi 2400 -o '" + dir.string() + "'");
    EXPECT_EQ(r.status, 2);
    EXPECT_TRUE(files_in(dir).empty());
    fs::remove_all(dir);
}

}  // namespace
