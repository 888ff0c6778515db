// SPDX-License-Identifier: GPL-3.0-or-later
// Specs, styles and names from strangers: see the tests below.
#include "process.hpp"

#include "figures/plots.hpp"
#include "figures/spec.hpp"
#include "figures/themes.hpp"
#include "figures/toml_reader.hpp"
#include "plot/tex_markup.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using test_support::files_in;
using test_support::run_cli;
using test_support::run_command;
using test_support::temp_dir;

const std::string period_panel = "[[panel]]\nplot = \"period\"\nmethods = [\"exact\"]\n";

/// The problems parse_spec reports for `text` (as "fuzz.toml"), or "accepted".
std::string problems_of(const std::string& text) {
    try {
        figures::parse_spec(text, "fuzz.toml");
    } catch (const figures::spec_error& e) {
        return e.what();
    }
    return "accepted";
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

void write(const fs::path& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

/// "a.a.a" with `n` parts, joined by `dot`.
std::string dotted(int n, const std::string& part = "a", const std::string& dot = ".") {
    std::string out = part;
    for (int i = 1; i < n; ++i) out += dot + part;
    return out;
}

const std::string too_deep = "keys nested more than 256 deep";

// 1. Keys nested deeper than toml++ bounds values overflowed the stack: the pre-scan bounds
// them at 256, as toml++ bounds values, in every form a key nests.
TEST(HostileInputs, KeyDepthIsBoundedAt256) {
    const int n = static_cast<int>(figures::max_toml_depth);
    ASSERT_EQ(n, 256);
    struct form {
        const char* name;
        std::string (*text)(int depth);
        const char* where;  // where the refusal points
    };
    const form forms[] = {
        {"header", [](int d) { return "[" + dotted(d) + "]\n" + period_panel; }, "fuzz.toml:1:2:"},
        {"array header", [](int d) { return "[[" + dotted(d) + "]]\n" + period_panel; }, "fuzz.toml:1:3:"},
        {"dotted key", [](int d) { return dotted(d) + " = 1\n" + period_panel; }, "fuzz.toml:1:1:"},
        {"spaced dots", [](int d) { return dotted(d, "a", " . ") + " = 1\n" + period_panel; }, "fuzz.toml:1:1:"},
        {"quoted parts", [](int d) { return dotted(d, "\"x\"", ".") + " = 1\n" + period_panel; }, "fuzz.toml:1:1:"},
        {"under [[panel]]", [](int d) { return period_panel + dotted(d - 1) + " = 1\n"; }, "fuzz.toml:4:1:"},
        {"header and key", [](int d) { return "[" + dotted(100) + "]\n" + dotted(d - 100) + " = 1\n" + period_panel; },
         "fuzz.toml:2:1:"},
        {"inline table", [](int d) { return "x = { " + dotted(d - 1) + " = 1 }\n" + period_panel; }, "fuzz.toml:1:7:"},
        {"list of inline tables", [](int d) { return "x = [ 1, { " + dotted(d - 2) + " = 1 } ]\n" + period_panel; },
         "fuzz.toml:1:12:"},
    };
    for (const auto& f : forms) {
        const std::string ok = problems_of(f.text(n));
        EXPECT_FALSE(has(ok, too_deep)) << f.name << ": " << ok.substr(0, 300);
        const std::string refused = problems_of(f.text(n + 1));
        EXPECT_TRUE(has(refused, std::string(f.where) + " " + too_deep)) << f.name << ": " << refused.substr(0, 300);
    }
    // Dots in quoted keys, strings, multi-line strings and comments are not key parts.
    const std::string quoted_dots = dotted(300, ".");
    for (const std::string& text :
         {period_panel + "\"" + quoted_dots + "\" = 1\n", period_panel + "'" + quoted_dots + "' = 1\n",
          "[figure]\ndescription = \"" + quoted_dots + "\"\n" + period_panel,
          "[figure]\ndescription = '''\n" + quoted_dots + "'''\n" + period_panel,
          "[figure]\ndescription = \"\"\"a\\\"\"\"\n" + quoted_dots + "\"\"\"\n" + period_panel,
          "# " + quoted_dots + "\n" + period_panel, period_panel + "range = [0.1, 1.5] # " + quoted_dots + "\n"}) {
        EXPECT_FALSE(has(problems_of(text), too_deep)) << text.substr(0, 200);
    }
    // The fuzzers' finding, 50,000 deep in 100 KB: refused, not a stack overflow.
    EXPECT_TRUE(has(problems_of("[" + dotted(50000) + "]\n"), "fuzz.toml:1:2: " + too_deep));
    EXPECT_TRUE(has(problems_of(dotted(50000) + " = 1\n"), "fuzz.toml:1:1: " + too_deep));
}

// 1. Every command that reads TOML: render, data and describe a spec, --theme, a spec's
// [figure] style, and --set.
TEST(HostileInputs, DeepKeysAreExitTwoInEveryCommand) {
    const auto dir = temp_dir("deep-keys");
    const std::string deep = "[" + dotted(50000) + "]\n";
    write(dir / "deep.toml", deep + period_panel);
    write(dir / "style.toml", deep);
    write(dir / "styled.toml", "[figure]\nstyle = \"style.toml\"\n" + period_panel);
    write(dir / "fine.toml", period_panel);
    fs::create_directories(dir / "out");
    const std::string out = " -f svg -o '" + (dir / "out").string() + "'";
    const std::pair<std::string, std::string> runs[] = {
        {"render deep.toml" + out, "deep.toml:1:2: " + too_deep},
        {"data deep.toml", "deep.toml:1:2: " + too_deep},
        {"describe deep.toml", "deep.toml:1:2: " + too_deep},
        {"render fine.toml --theme style.toml" + out, "style.toml:1:2: " + too_deep},
        {"render styled.toml" + out, "style.toml:1:2: " + too_deep},
        {"render fine.toml --set " + dotted(50000) + "=1" + out, too_deep},
    };
    for (const auto& [args, want] : runs) {
        const auto r = run_cli(args, dir);
        EXPECT_EQ(r.status, 2) << args.substr(0, 80) << "\n" << r.err.substr(0, 400);
        EXPECT_TRUE(has(r.err, want)) << args.substr(0, 80) << "\n" << r.err.substr(0, 400);
    }
    EXPECT_TRUE(files_in(dir / "out").empty());
    fs::remove_all(dir);
}

// 2. An empty list in any key of any panel kind is refused where the spec is read, naming
// the key at its line: the builders take a list's first item.
TEST(HostileInputs, EmptyListsAreRefusedInEveryPanelKey) {
    int checked = 0;
    for (const auto& row : figures::plot_table()) {
        std::string keys = "plot title x_label y_label y_range paper_file " + std::string(row.keys);
        std::istringstream words(keys);
        for (std::string key; words >> key;) {
            if (key == "plot") continue;
            const std::string text = "[[panel]]\nplot = \"" + std::string(row.name) + "\"\n" + key + " = []\n";
            const std::string got = problems_of(text);
            EXPECT_TRUE(has(got, "fuzz.toml:3:" + std::to_string(key.size() + 4) + ": '" + key + "' is an empty list"))
                << row.name << " " << key << ": " << got;
            ++checked;
        }
        // With the keys it needs given, the empty list is still the one problem.
        const std::string line = "[[panel]]\nplot = \"" + std::string(row.name) + "\"\n[[panel.line]]\ny = 1\nspan = []\n";
        EXPECT_TRUE(has(problems_of(line), "fuzz.toml:5:8: 'span' is an empty list")) << problems_of(line);
    }
    EXPECT_GT(checked, 30);
    // The reproductions: each crashed render, data and describe.
    const auto dir = temp_dir("empty-lists");
    fs::create_directories(dir / "out");
    const std::pair<std::string, std::string> specs[] = {
        {"energy = []\n", "'energy' is an empty list"},
        {"omega0 = []\ntheta0 = 0\n", "'omega0' is an empty list"},
        {"theta0 = []\nomega0 = 1\n", "'theta0' is an empty list"},
    };
    for (const auto& [keys, want] : specs) {
        write(dir / "empty.toml", "[[panel]]\nplot = \"trajectory\"\n" + keys);
        for (const char* command : {"render empty.toml -f svg -o out", "data empty.toml", "describe empty.toml"}) {
            const auto r = run_cli(command, dir);
            EXPECT_EQ(r.status, 2) << command << " " << keys << r.err;
            EXPECT_TRUE(has(r.err, "empty.toml:3:")) << r.err;
            EXPECT_TRUE(has(r.err, want)) << r.err;
        }
    }
    EXPECT_TRUE(files_in(dir / "out").empty());
    fs::remove_all(dir);
}

// 3. A spec's style file stays inside the spec's directory tree, links resolved; the
// command line's --theme may name any file.
TEST(HostileInputs, StylePathsStayInsideTheSpecsTree) {
    const auto dir = temp_dir("style-paths");
    const auto tree = dir / "tree";
    fs::create_directories(tree / "sub");
    fs::create_directories(dir / "outside");
    write(dir / "outside" / "secret.toml", "tick_font_pt = 9\n");
    write(tree / "sub" / "inner.toml", "tick_font_pt = 9\n");
    fs::create_symlink(dir / "outside" / "secret.toml", tree / "link-out.toml");
    fs::create_symlink(tree / "sub" / "inner.toml", tree / "link-in.toml");
    fs::create_symlink(dir / "outside", tree / "dir-out");
    const auto load = [&](const std::string& style) -> std::string {
        write(tree / "spec.toml", "[figure]\nstyle = \"" + style + "\"\n" + period_panel);
        try {
            return figures::load_spec(tree / "spec.toml").style;
        } catch (const figures::spec_error& e) {
            return e.what();
        }
    };
    const std::string at = (tree / "spec.toml").string() + ":2:9: 'style' ";
    for (const std::string& style : {(dir / "outside" / "secret.toml").string(), std::string("/etc/x.toml")}) {
        EXPECT_TRUE(has(load(style), at + "must be a path relative to the spec's directory")) << load(style);
    }
    for (const char* style : {"../outside/secret.toml", "sub/../../outside/secret.toml", "..//x.toml"}) {
        EXPECT_TRUE(has(load(style), at + "must stay inside the spec's directory")) << load(style);
    }
    for (const char* style : {"link-out.toml", "dir-out/secret.toml"}) {
        EXPECT_TRUE(has(load(style), "leads out of the spec's directory")) << style << ": " << load(style);
    }
    EXPECT_EQ(load("sub/inner.toml"), (tree / "sub" / "inner.toml").string());
    EXPECT_EQ(load("sub/../sub/inner.toml"), (tree / "sub" / "inner.toml").string());
    EXPECT_EQ(load("link-in.toml"), (tree / "link-in.toml").string());
    // render: refused before anything is read or written, the secret's keys never shown.
    fs::create_directories(dir / "out");
    write(dir / "outside" / "secret.toml", "password = \"hunter2\"\n");
    write(tree / "spec.toml", "[figure]\nstyle = \"link-out.toml\"\n" + period_panel);
    const auto r = run_cli("render tree/spec.toml -f svg -o out", dir);
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_TRUE(has(r.err, "tree/spec.toml:2:9: 'style'")) << r.err;
    EXPECT_FALSE(has(r.err, "password")) << r.err;
    EXPECT_TRUE(files_in(dir / "out").empty());
    // The command line names what it likes.
    write(dir / "outside" / "secret.toml", "tick_font_pt = 9\n");
    write(tree / "spec.toml", period_panel);
    const auto ok = run_cli("render tree/spec.toml --theme '" + (dir / "outside" / "secret.toml").string() +
                                "' -f svg -o out",
                            dir);
    EXPECT_EQ(ok.status, 0) << ok.err;
    fs::remove_all(dir);
}

// 4. One check for every text: printable ASCII passes, every other single byte is refused.
TEST(HostileInputs, TextCheckTakesEveryByteValue) {
    for (int b = 0; b < 256; ++b) {
        const std::string text(1, static_cast<char>(b));
        const std::string why = plot::text_problem(text);
        if (b >= 0x20 && b < 0x7f) {
            EXPECT_EQ(why, "") << b;
        } else if (b < 0x80) {
            EXPECT_TRUE(has(why, "control character")) << b << ": " << why;
        } else {
            EXPECT_TRUE(has(why, "not valid UTF-8")) << b << ": " << why;
        }
    }
    const auto utf8 = [](char32_t c) {
        std::string s;
        if (c < 0x80) {
            s += static_cast<char>(c);
        } else if (c < 0x800) {
            s += static_cast<char>(0xc0 | (c >> 6));
            s += static_cast<char>(0x80 | (c & 0x3f));
        } else if (c < 0x10000) {
            s += static_cast<char>(0xe0 | (c >> 12));
            s += static_cast<char>(0x80 | ((c >> 6) & 0x3f));
            s += static_cast<char>(0x80 | (c & 0x3f));
        } else {
            s += static_cast<char>(0xf0 | (c >> 18));
            s += static_cast<char>(0x80 | ((c >> 12) & 0x3f));
            s += static_cast<char>(0x80 | ((c >> 6) & 0x3f));
            s += static_cast<char>(0x80 | (c & 0x3f));
        }
        return s;
    };
    for (char32_t c = 0x80; c <= 0x9f; ++c) EXPECT_TRUE(has(plot::text_problem(utf8(c)), "control character")) << unsigned(c);
    for (char32_t c = 0xfdd0; c <= 0xfdef; ++c) EXPECT_TRUE(has(plot::text_problem(utf8(c)), "noncharacter")) << unsigned(c);
    for (char32_t plane = 0; plane <= 0x10; ++plane) {
        for (char32_t low : {0xfffe, 0xffff}) {
            const char32_t c = plane << 16 | low;
            char code[16];
            std::snprintf(code, sizeof code, "U+%04X", static_cast<unsigned>(c));
            EXPECT_TRUE(has(plot::text_problem("a" + utf8(c)), std::string("noncharacter ") + code)) << code;
        }
    }
    for (char32_t c : {0xa0, 0xfdcf, 0xfdf0, 0xfffd, 0x3d1, 0x1f600, 0x10fffd}) {
        EXPECT_EQ(plot::text_problem(utf8(c)), "") << unsigned(c);
    }
    // Surrogates, overlong forms, past U+10FFFF, cut short.
    for (const char* bad : {"\xed\xa0\x80", "\xc0\x80", "\xe0\x80\xaf", "\xf4\x90\x80\x80", "\xe2\x82", "\xf8\x88\x80\x80\x80"}) {
        EXPECT_TRUE(has(plot::text_problem(bad), "not valid UTF-8")) << bad;
    }
    EXPECT_EQ(plot::text_problem(std::string(1000, 'x')), "");
    EXPECT_EQ(plot::text_problem(std::string(1001, 'x')), "has 1001 bytes; at most 1000");
}

/// A spec with one text of `value` (TOML string content) at `key` of its kind.
std::vector<std::pair<std::string, std::string>> texts_at(const std::string& value) {
    const std::string q = "\"" + value + "\"";
    return {
        {"title", "[figure]\ntitle = " + q + "\n" + period_panel},
        {"description", "[figure]\ndescription = " + q + "\n" + period_panel},
        {"title", period_panel + "title = " + q + "\n"},
        {"x_label", period_panel + "x_label = " + q + "\n"},
        {"y_label", period_panel + "y_label = " + q + "\n"},
        {"label", "[[panel]]\nplot = \"period\"\nmethods = [{method = \"exact\", label = " + q + "}]\n"},
        {"label", period_panel + "[[panel.line]]\ny = 1\nlabel = " + q + "\n"},
        {"theta0", "[[panel]]\nplot = \"trajectory\"\nmethods = [\"exact\"]\ntheta0 = " + q + "\n"},
        {"energy", "[[panel]]\nplot = \"trajectory\"\nenergy = [1, " + q + "]\n"},
        {"plot", "[[panel]]\nplot = " + q + "\n"},
        {"paper_file", period_panel + "paper_file = " + q + "\n"},
    };
}

TEST(HostileInputs, EveryTextOfASpecIsChecked) {
    for (const char* escape : {"\\u0000", "\\u0007", "\\u001b[2J", "\\t", "\\n", "\\u007f", "\\u0085", "\\u009b",
                               "\\ufffe", "\\uffff", "\\ufdd0", "\\U0001FFFF", "\\U0010FFFF"}) {
        for (const auto& [key, text] : texts_at(std::string("a") + escape + "b")) {
            const std::string got = problems_of(text);
            EXPECT_TRUE(has(got, "fuzz.toml:") && has(got, "'" + key + "' has the")) << key << " " << escape << ": " << got;
            EXPECT_EQ(got.find('\x1b'), std::string::npos);
        }
    }
    // Every byte value raw in a string: printable ASCII is text, anything else refused (by
    // toml++ as not TOML, or as text).
    for (int b = 0; b < 256; ++b) {
        if (b == '"' || b == '\\') continue;
        const std::string text = "[figure]\ndescription = \"a" + std::string(1, static_cast<char>(b)) + "b\"\n" + period_panel;
        const std::string got = problems_of(text);
        if (b >= 0x20 && b < 0x7f) {
            EXPECT_EQ(got, "accepted") << b;
        } else {
            EXPECT_TRUE(has(got, "fuzz.toml:2:")) << b << ": " << got;
        }
    }
    // Keys too: they are shown in messages.
    EXPECT_TRUE(has(problems_of(period_panel + "\"a\\u001bb\" = 1\n"), "fuzz.toml:4:1: a key has the control character U+001B"));
    // The byte limit, every text: 1000 bytes pass the check, 1001 do not.
    for (const auto& [key, text] : texts_at(std::string(1001, '1'))) {
        EXPECT_TRUE(has(problems_of(text), "'" + key + "' has 1001 bytes; at most 1000")) << key;
    }
    std::string expression = " 1";
    while (expression.size() < 1000) expression += "+0";
    ASSERT_EQ(expression.size(), 1000u);
    const std::string theta0 = "[[panel]]\nplot = \"trajectory\"\nmethods = [\"exact\"]\ntheta0 = \"" + expression + "\"\n";
    EXPECT_EQ(problems_of(theta0), "accepted");
    EXPECT_EQ(problems_of("[figure]\ndescription = \"" + std::string(1000, 'd') + "\"\n" + period_panel), "accepted");
}

TEST(HostileInputs, TextsAreExitTwoOnTheCommandLine) {
    const auto dir = temp_dir("texts");
    fs::create_directories(dir / "out");
    write(dir / "escape.toml", "[figure]\ndescription = \"\\u001b[2J\\u0000\"\n" + period_panel);
    write(dir / "nonchar.toml", period_panel + "y_label = \"\\uFFFE\"\n");
    const std::string long_theta0 = "1" + std::string(2000, ' ');
    const std::pair<std::string, std::string> runs[] = {
        {"describe escape.toml", "escape.toml:2:15: 'description' has the control character U+001B"},
        {"render nonchar.toml -f svg -o out", "nonchar.toml:4:11: 'y_label' has the noncharacter U+FFFE"},
        {"render nonchar.toml -f pdf -o out", "nonchar.toml:4:11: 'y_label' has the noncharacter U+FFFE"},
        {"render trajectory-first --theta0 \"$(printf '1\\033[2J')\" -f svg -o out",
         "--theta0 '1\\x1b[2J' has the control character U+001B"},
        {"render trajectory-first --theta0 \"$(printf '1\\357\\277\\276')\" -f svg -o out",
         "has the noncharacter U+FFFE"},
        {"render trajectory-first --theta0 '" + long_theta0 + "' -f svg -o out", "has 2001 bytes; at most 1000"},
        {"eval --theta0 \"$(printf '1\\302\\205')\"", "has the control character U+0085"},
        {"render fig1 --set \"font_family=$(printf 'DejaVu\\033]0;x\\007')\" -f svg -o out",
         "--set font_family: the value has the control character U+001B"},
    };
    for (const auto& [args, want] : runs) {
        const auto r = run_cli(args, dir);
        EXPECT_EQ(r.status, 2) << args.substr(0, 100) << "\n" << r.err;
        EXPECT_TRUE(has(r.err, want)) << args.substr(0, 100) << "\n" << r.err;
        EXPECT_EQ(r.err.find('\x1b'), std::string::npos) << args.substr(0, 100);
        EXPECT_EQ(r.out.find('\x1b'), std::string::npos) << args.substr(0, 100);
    }
    EXPECT_TRUE(files_in(dir / "out").empty());
    fs::remove_all(dir);
}

// 5. A list from standard input or @FILE is bounded by its count of values, before memory grows.
TEST(HostileInputs, ListsFromStandardInputAreBounded) {
    const auto dir = temp_dir("lists");
    const std::string exe = std::string("'") + PENDULUM_EXE + "'";
    const auto endless = run_command("yes 1 | " + exe + " eval --theta0 - --method exact");
    EXPECT_EQ(endless.status, 2) << endless.err;
    EXPECT_TRUE(has(endless.err, "--theta0 -: more than 1000000 values; a list takes at most 1000000")) << endless.err;
    // A million pass, one more does not (@FILE as -).
    {
        std::ofstream list(dir / "million");
        for (int i = 0; i < 1'000'000; ++i) list << "1\n";
    }
    const auto million = run_command(exe + " eval --theta0 @'" + (dir / "million").string() +
                                     "' --method exact --columns theta0 | tail -n 1");
    EXPECT_EQ(million.status, 0) << million.err;
    std::ofstream(dir / "million", std::ios::app) << "1\n";
    const auto more = run_command(exe + " eval --theta0 @'" + (dir / "million").string() + "' --method exact");
    EXPECT_EQ(more.status, 2);
    EXPECT_TRUE(has(more.err, "more than 1000000 values")) << more.err;
    fs::remove_all(dir);
}

TEST(HostileInputs, SizeMessagesSayWhatIsWrong) {
    const auto why = [](const std::string& size) {
        try {
            figures::load_theme("paper", {"size_px=" + size});
        } catch (const figures::spec_error& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    EXPECT_TRUE(has(why("0x10"), "'size_px' = \"0x10\": the width 0 is out of range; each side is 16 to 20000 pixels"))
        << why("0x10");
    EXPECT_TRUE(has(why("16x15"), "the height 15 is out of range")) << why("16x15");
    EXPECT_TRUE(has(why("20001x16"), "the width 20001 is out of range"));
    EXPECT_EQ(why("16x16"), "accepted");
    EXPECT_EQ(why("20000x20000"), "accepted");
    for (const char* bad : {"16", "x16", "16x", "-16x16", "16x16x16", "1e3x16", "0x1A"}) {
        EXPECT_TRUE(has(why(bad), "not WIDTHxHEIGHT")) << bad << ": " << why(bad);
    }
    const auto dir = temp_dir("size");
    const auto r = run_cli("render fig1 --size 0x10 -f png -o '" + dir.string() + "'");
    EXPECT_EQ(r.status, 2);
    EXPECT_TRUE(has(r.err, "the width 0 is out of range")) << r.err;
    fs::remove_all(dir);
}

TEST(HostileInputs, FontconfigFileMustBeARegularFile) {
    const auto dir = temp_dir("fontconfig");
    const std::string exe = std::string("'") + PENDULUM_EXE + "'";
    const std::string render = " render fig1 -f svg -o '" + dir.string() + "'";
    for (const char* file : {"/dev/zero", "/tmp"}) {
        const auto r = run_command(std::string("FONTCONFIG_FILE=") + file + " timeout 60 " + exe + render);
        EXPECT_EQ(r.status, 2) << file << ": " << r.err;
        EXPECT_TRUE(has(r.err, std::string("FONTCONFIG_FILE='") + file + "' is not a regular file")) << r.err;
    }
    EXPECT_TRUE(files_in(dir).empty());
    const auto fine = run_command("FONTCONFIG_FILE=/etc/fonts/fonts.conf " + exe + render);
    EXPECT_EQ(fine.status, 0) << fine.err;
    fs::remove_all(dir);
}

}  // namespace
