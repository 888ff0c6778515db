// SPDX-License-Identifier: GPL-3.0-or-later
// Every figure's numbers out: data (long and wide CSV, JSON), trajectory with several
// methods, eval's error columns.
#include "figures/batch.hpp"
#include "figures/figure_data.hpp"
#include "pendulum/amplitude.hpp"
#include "pendulum/methods.hpp"
#include "process.hpp"

#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using test_support::run_cli;
using test_support::run_command;
using test_support::slurp;
using test_support::temp_dir;

/// Debian's Python, which has numpy and mpmath.
constexpr const char* python = "/usr/bin/python3";

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) out.push_back(line);
    return out;
}

std::vector<std::string> fields_of(const std::string& line) {
    std::vector<std::string> out;
    std::string field;
    std::istringstream in(line);
    while (std::getline(in, field, ',')) out.push_back(field);
    if (!line.empty() && line.back() == ',') out.emplace_back();
    return out;
}

void write_file(const fs::path& p, const std::string& text) {
    std::ofstream out(p, std::ios::binary);
    out << text;
}

/// Runs a Python script with Debian's python3; its output, and its status in `status`.
test_support::run_result run_python(const fs::path& dir, const std::string& script, const std::string& args = "") {
    write_file(dir / "check.py", script);
    return run_command(std::string(python) + " '" + (dir / "check.py").string() + "' " + args);
}

double number(const std::string& text) {
    if (text == "nan") return std::nan("");
    double v = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    EXPECT_TRUE(ec == std::errc() && end == text.data() + text.size()) << text;
    return v;
}

// --- ids ------------------------------------------------------------------------------

TEST(SeriesIds, UniqueValidAndStable) {
    plot::panel p;
    p.data.push_back(plot::series{.id = "exact"});
    p.data.push_back(plot::series{.id = "exact"});
    p.data.push_back(plot::series{.id = "order:6"});
    p.data.push_back(plot::series{.id = "order_6"});  // the same wide column as order:6
    p.data.push_back(plot::series{.id = "a b,\"c\"\n"});
    p.data.push_back(plot::series{});
    p.data.push_back(plot::series{.autoscale = false});
    p.data.push_back(plot::series{.id = "data:1"});
    p.data.push_back(plot::series{.id = "formula:1"});
    figures::give_series_ids(p);
    std::vector<std::string> ids;
    for (const auto& s : p.data) ids.push_back(s.id);
    EXPECT_EQ(ids, (std::vector<std::string>{"exact", "exact.2", "order:6", "order_6.2", "a_b__c__", "series:6",
                                             "line:1", "data:1", "formula:1"}));
    // Giving ids again changes nothing: they are stable.
    figures::give_series_ids(p);
    for (std::size_t i = 0; i < ids.size(); ++i) EXPECT_EQ(p.data[i].id, ids[i]);
}

TEST(SeriesIds, EveryFigureHasUniqueValidIdsPerPanel) {
    for (const char* id : {"period", "period-error", "convergence", "spectrum", "phase-portrait", "regimes",
                           "trajectory-first", "c1-lowest", "swing", "separatrix", "over-the-top"}) {
        const auto r = run_cli(std::string("data ") + id + " -f json");
        ASSERT_EQ(r.status, 0) << id << r.err;
        const fs::path dir = temp_dir("ids");
        write_file(dir / "d.json", r.out);
        const auto py = run_python(dir, R"(
import json, re, sys
d = json.load(open(sys.argv[1]))
for p in d["panels"]:
    ids = [s["id"] for s in p["series"]]
    assert len(ids) == len(set(ids)), ids
    cols = [s["columns"]["x"] for s in p["series"]]
    assert len(cols) == len(set(cols)), cols
    for i in ids:
        assert re.fullmatch(r"[A-Za-z0-9_:.-]+", i), i
    for s in p["series"]:
        assert re.fullmatch(r"[A-Za-z0-9_]+", s["columns"]["x"]), s["columns"]
print("ok")
)", "'" + (dir / "d.json").string() + "'");
        EXPECT_EQ(py.out, "ok\n") << id << py.err;
        fs::remove_all(dir);
    }
}

TEST(SeriesIds, MethodsAndAmplitudesAndLines) {
    const auto period = run_cli("data period -f json");
    ASSERT_EQ(period.status, 0) << period.err;
    for (const char* id : {"\"exact\"", "\"lowest\"", "\"first\"", "\"second\""}) {
        EXPECT_NE(period.out.find(std::string("{\"id\":") + id), std::string::npos) << id;
    }
    const auto convergence = run_cli("data convergence -f json");
    ASSERT_EQ(convergence.status, 0) << convergence.err;
    EXPECT_NE(convergence.out.find("{\"id\":\"theta0:2\""), std::string::npos);
    const auto lines = run_cli("data period-error -f json");
    ASSERT_EQ(lines.status, 0) << lines.err;
    EXPECT_NE(lines.out.find("{\"id\":\"line:1\""), std::string::npos);
}

// --- long CSV ---------------------------------------------------------------------------

TEST(DataLong, HeaderIdColumnAndCurveSamples) {
    const auto r = run_cli("data period");
    ASSERT_EQ(r.status, 0) << r.err;
    const auto rows = lines_of(r.out);
    ASSERT_FALSE(rows.empty());
    EXPECT_EQ(rows[0], "panel,series,x,y,id");
    std::map<std::string, std::size_t> per_series;
    for (std::size_t i = 1; i < rows.size(); ++i) {
        const auto f = fields_of(rows[i]);
        ASSERT_EQ(f.size(), 5u) << rows[i];
        ++per_series[f[0] + "/" + f[4]];
    }
    // The curves are their adaptive samples (from theta0 = pi/1000, where the curves start),
    // not the 23 markers of exact.
    EXPECT_EQ(per_series["a/exact"], 23u);
    EXPECT_GT(per_series["a/lowest"], 30u);
    EXPECT_GT(per_series["b/second"], 30u);
    EXPECT_NE(r.out.find("\na,lowest order,0.0031415926535897933,"), std::string::npos);
}

TEST(DataLong, ReferenceLinesAreTwoEndsWithinThePanel) {
    const auto r = run_cli("data period-error -f json");
    ASSERT_EQ(r.status, 0) << r.err;
    const fs::path dir = temp_dir("lines");
    write_file(dir / "d.json", r.out);
    const auto py = run_python(dir, R"(
import json, sys
d = json.load(open(sys.argv[1]))
n = 0
for p in d["panels"]:
    for s in p["series"]:
        if s["kind"] != "line":
            continue
        n += 1
        assert s["id"].startswith("line:"), s["id"]
        assert len(s["x"]) == 2 and len(s["y"]) == 2
        lo, hi = sorted([p["x"]["min"], p["x"]["max"]])
        assert all(lo <= x <= hi for x in s["x"]), (s["x"], lo, hi)
        lo, hi = sorted([p["y"]["min"], p["y"]["max"]])
        assert all(lo <= y <= hi for y in s["y"]), (s["y"], lo, hi)
print(n)
)", "'" + (dir / "d.json").string() + "'");
    EXPECT_EQ(py.status, 0) << py.err;
    EXPECT_NE(py.out, "0\n");
    fs::remove_all(dir);
}

TEST(DataLong, SamplesLieOnTheExactCurve) {
    // The period figure's curves are drawn from their functions: every sample is the
    // core's value at the same amplitude (panel a is T/T0 against theta0 in radians).
    const auto r = run_cli("data period");
    ASSERT_EQ(r.status, 0) << r.err;
    std::size_t checked = 0;
    for (const auto& row : lines_of(r.out)) {
        const auto f = fields_of(row);
        if (f.size() != 5 || f[0] != "a" || f[3] == "nan") continue;
        const std::string& id = f[4];
        if (id != "exact" && id != "lowest" && id != "first" && id != "second") continue;
        const double x = number(f[2]);
        const double y = number(f[3]);
        if (!(x > 0 && x < M_PI)) continue;
        const double want = pendulum::method_period(pendulum::parse_method(id), pendulum::amplitude(x));
        EXPECT_NEAR(y, want, 1e-12 * std::fabs(want)) << id << " at " << f[2];
        ++checked;
    }
    // 140 samples in the three approximants and 23 exact markers at the paper's 4.2-cm panel
    // whose axes keep the data off the frame (146 before the axes gave the markers room).
    EXPECT_GE(checked, 140u);
}

TEST(DataLong, HostileLabelsAreQuotedAndEscaped) {
    // A label from a spec with quotes, commas, a backslash and a leading = reaches CSV quoted
    // (RFC 4180, a ' before a formula's =) and JSON escaped. (A control character in a spec
    // is refused by the spec's reader: see HostileDataAndFormulaLabels for \u escapes.)
    const fs::path dir = temp_dir("hostile");
    write_file(dir / "h.toml",
               "[figure]\n[[panel]]\nplot = \"period\"\n"
               "methods = [{ method = \"exact\", label = '=a, \"b\" \\\\' }, \"lowest\"]\n"
               "[[panel.line]]\ny = 2\nlabel = '-line, \"q\"'\n");
    const auto csv = run_cli("data h.toml", dir);
    ASSERT_EQ(csv.status, 0) << csv.err;
    const auto rows = lines_of(csv.out);
    std::set<std::string> labels;
    for (std::size_t i = 1; i < rows.size(); ++i) labels.insert(rows[i].substr(0, rows[i].find(",0") + 1));
    EXPECT_TRUE(labels.contains("a,\"'=a, \"\"b\"\" \\\",")) << csv.out.substr(0, 400);
    EXPECT_NE(csv.out.find("\na,\"'-line, \"\"q\"\"\","), std::string::npos) << csv.out;
    const auto json = run_cli("data h.toml -f json", dir);
    ASSERT_EQ(json.status, 0) << json.err;
    write_file(dir / "d.json", json.out);
    const auto py = run_python(dir, R"(
import json, sys
d = json.load(open(sys.argv[1]))
for s in d["panels"][0]["series"]:
    print(s["id"], repr(s["label"]))
)", "'" + (dir / "d.json").string() + "'");
    EXPECT_NE(py.out.find("exact '=a, \"b\" \\\\'\n"), std::string::npos) << py.out << py.err;
    EXPECT_NE(py.out.find("line:1 '-line, \"q\"'\n"), std::string::npos) << py.out << py.err;
    fs::remove_all(dir);
}

TEST(DataLong, HostileDataAndFormulaLabels) {
    // Data series and user formulas (ids data:N, formula:N) take the same writers.
    plot::figure f;
    plot::panel p;
    p.data.push_back(plot::series{.label = "x,\"y\"\x02", .id = "data:1", .x = {1, 2}, .y = {0.5, 0.25}});
    p.data.push_back(plot::series{.label = "@f\x1f", .id = "formula:1", .x = {3}, .y = {0.1}});
    f.panels = {p};
    EXPECT_EQ(figures::figure_csv(f),
              "panel,series,x,y,id\n"
              "a,\"x,\"\"y\"\"\x02\",1,0.5,data:1\na,\"x,\"\"y\"\"\x02\",2,0.25,data:1\n"
              "a,'@f\x1f,3,0.1,formula:1\n");
    const std::string json = figures::numbers_json(figures::numbers_of(f));
    EXPECT_NE(json.find("{\"id\":\"data:1\",\"label\":\"x,\\\"y\\\"\\u0002\""), std::string::npos) << json;
    EXPECT_NE(json.find("{\"id\":\"formula:1\",\"label\":\"@f\\u001f\""), std::string::npos) << json;
    EXPECT_EQ(figures::json_string("\x7f\t\n"), "\"\\u007f\\u0009\\u000a\"");
}

TEST(DataLong, LegendsTooLargeForThePngAreLeftOutAndSaid) {
    // 32 amplitudes' legend leaves no room for the axes at the PNG's size: the numbers are
    // still written, sampled on axes without legends, and a note says so.
    const fs::path dir = temp_dir("legends");
    std::string list;
    for (int i = 1; i <= 32; ++i) list += std::string(list.empty() ? "" : ", ") + "\"" + std::to_string(i * 0.09) + "\"";
    write_file(dir / "many.toml", "[figure]\n[[panel]]\nplot = \"phase\"\nmethods = [\"exact\"]\ntheta0 = [" + list + "]\n");
    const auto r = run_cli("data many.toml", dir);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("note: figure 'many' leaves no room for its axes with its legends"), std::string::npos) << r.err;
    EXPECT_NE(r.out.find(",theta0:32\n"), std::string::npos);
    const auto fits = run_cli("data period");
    EXPECT_EQ(fits.err, "");
    fs::remove_all(dir);
}

// --- wide CSV ---------------------------------------------------------------------------

TEST(DataWide, ColumnsPaddedWithNan) {
    const auto r = run_cli("data period --layout wide");
    ASSERT_EQ(r.status, 0) << r.err;
    const auto rows = lines_of(r.out);
    ASSERT_GT(rows.size(), 2u);
    const auto header = fields_of(rows[0]);
    EXPECT_EQ(header[0], "a_exact_x");
    EXPECT_EQ(header[1], "a_exact_y");
    for (const auto& row : rows) EXPECT_EQ(fields_of(row).size(), header.size());
    // The markers of exact are fewer than the samples: their columns end in nan.
    EXPECT_EQ(fields_of(rows.back())[0], "nan");
}

TEST(DataWide, NumpyReadsItAndTheColumnsMatchTheJson) {
    const fs::path dir = temp_dir("numpy");
    for (const char* id : {"period", "period-error", "convergence"}) {
        ASSERT_EQ(run_cli(std::string("data ") + id + " --layout wide -o '" + (dir / "w.csv").string() + "'").status, 0);
        ASSERT_EQ(run_cli(std::string("data ") + id + " -f json -o '" + (dir / "d.json").string() + "'").status, 0);
        ASSERT_EQ(run_cli(std::string("data ") + id + " -o '" + (dir / "l.csv").string() + "'").status, 0);
        const auto py = run_python(dir, R"(
import csv, json, math, sys, numpy
d = numpy.genfromtxt(sys.argv[1], names=True, delimiter=',')
j = json.load(open(sys.argv[2]))
cols = 0
for p in j["panels"]:
    for s in p["series"]:
        for axis in "xy":
            name = s["columns"][axis]
            got = d[name]
            want = s[axis]
            assert len(got) >= len(want), name
            for a, b in zip(got, want):
                assert (b is None and math.isnan(a)) or a == b, (name, a, b)
            assert all(math.isnan(a) for a in got[len(want):]), name
            cols += 1
assert cols == len(d.dtype.names), (cols, d.dtype.names)
# The long CSV holds the same numbers, in text that reads back to the same doubles.
rows = list(csv.reader(open(sys.argv[3])))
assert rows[0] == ["panel", "series", "x", "y", "id"]
k = 0
for p in j["panels"]:
    for s in p["series"]:
        for x, y in zip(s["x"], s["y"]):
            r = rows[1 + k]
            k += 1
            assert r[0] == p["name"] and r[1] == s["label"] and r[4] == s["id"], r
            assert (x is None and r[2] == "nan") or float(r[2]) == x, (r, x)
            assert (y is None and r[3] == "nan") or float(r[3]) == y, (r, y)
assert k == len(rows) - 1
print("ok")
)", "'" + (dir / "w.csv").string() + "' '" + (dir / "d.json").string() + "' '" + (dir / "l.csv").string() + "'");
        EXPECT_EQ(py.out, "ok\n") << id << py.err;
    }
    fs::remove_all(dir);
}

TEST(DataWide, PgfplotsDrawsFig7WithoutARowFilter) {
    const bool ci = std::getenv("CI") && std::string(std::getenv("CI")) == "true";
    if (run_command("command -v pdflatex").status != 0) {
        if (ci) FAIL() << "pdflatex is missing under CI";
        GTEST_SKIP() << "pdflatex is missing";
    }
    const fs::path dir = temp_dir("pgfplots");
    ASSERT_EQ(run_cli("data period --layout wide -o '" + (dir / "fig7.csv").string() + "'").status, 0);
    // Every series of the file, each panel an axis, as a reader of the header would write it.
    std::string plots;
    const auto header = fields_of(lines_of(slurp(dir / "fig7.csv")).at(0));
    for (const std::string panel : {"a", "b"}) {
        plots += "\\begin{tikzpicture}\\begin{axis}[unbounded coords=jump]\n";
        for (const auto& name : header) {
            if (!name.starts_with(panel + "_") || !name.ends_with("_x")) continue;
            const std::string series = name.substr(0, name.size() - 2);
            plots += "\\addplot table[x=" + series + "_x, y=" + series + "_y, col sep=comma] {fig7.csv};\n";
        }
        plots += "\\end{axis}\\end{tikzpicture}\n";
    }
    EXPECT_NE(plots.find("x=b_second_x, y=b_second_y"), std::string::npos) << plots;
    write_file(dir / "fig7.tex", "\\documentclass{article}\\usepackage{pgfplots}\\pgfplotsset{compat=1.16}\n"
                                 "\\begin{document}\n" + plots + "\\end{document}\n");
    const auto r = run_command("cd '" + dir.string() + "' && pdflatex -interaction=nonstopmode -halt-on-error fig7.tex");
    EXPECT_EQ(r.status, 0) << r.out.substr(r.out.size() > 3000 ? r.out.size() - 3000 : 0);
    EXPECT_TRUE(fs::exists(dir / "fig7.pdf"));
    fs::remove_all(dir);
}

// --- JSON -------------------------------------------------------------------------------

TEST(DataJson, PanelsAxesSeriesAndPeriods) {
    const fs::path dir = temp_dir("json");
    ASSERT_EQ(run_cli("data fig6 -f json -o '" + (dir / "d.json").string() + "'").status, 0);
    const auto py = run_python(dir, R"(
import json, sys
d = json.load(open(sys.argv[1]))
p = d["panels"][0]
assert p["name"] == "a" and p["x"]["scale"] == "linear", p["x"]
assert p["y"]["unit"] == "rad", p["y"]
s = [s for s in p["series"] if s["id"] == "second"][0]
print(s["method"], s["theta0"]["text"], s["theta0"]["radians"], s["period"]["T_over_T0"])
)", "'" + (dir / "d.json").string() + "'");
    ASSERT_EQ(py.status, 0) << py.err;
    std::istringstream in(py.out);
    std::string method, text, radians, period;
    in >> method >> text >> radians >> period;
    EXPECT_EQ(method, "second");
    EXPECT_EQ(text, "9pi/10");
    const double theta0 = number(radians);
    EXPECT_EQ(number(period), pendulum::method_period(pendulum::parse_method("second"), pendulum::amplitude(theta0)));
    fs::remove_all(dir);
}

TEST(DataJson, NumbersRoundTripExactly) {
    const auto json = run_cli("data period -f json");
    ASSERT_EQ(json.status, 0);
    const auto csv = run_cli("data period");
    ASSERT_EQ(csv.status, 0);
    // Every number of the long CSV appears in the JSON as the same text: to_chars' shortest
    // round trip, in both.
    std::set<std::string> in_csv;
    for (const auto& row : lines_of(csv.out)) {
        const auto f = fields_of(row);
        if (f.size() == 5 && f[2] != "x") {
            in_csv.insert(f[2]);
            if (f[3] != "nan") in_csv.insert(f[3]);
        }
    }
    std::size_t found = 0;
    for (const auto& n : in_csv) {
        found += json.out.find("," + n + ",") != std::string::npos || json.out.find("[" + n + ",") != std::string::npos ||
                 json.out.find("," + n + "]") != std::string::npos || json.out.find("[" + n + "]") != std::string::npos;
        double v = number(n);
        EXPECT_EQ(pendulum::format_double(v), n);
    }
    EXPECT_EQ(found, in_csv.size());
}

TEST(DataOptions, LayoutAndFormatAreChecked) {
    const auto wide_json = run_cli("data period -f json --layout wide");
    EXPECT_EQ(wide_json.status, 2);
    EXPECT_NE(wide_json.err.find("--layout wide is for CSV"), std::string::npos) << wide_json.err;
    const auto bad = run_cli("data period --layout tall");
    EXPECT_EQ(bad.status, 2);
    EXPECT_NE(bad.err.find("tall"), std::string::npos) << bad.err;
    const auto fmt = run_cli("data period -f xml");
    EXPECT_EQ(fmt.status, 2);
    EXPECT_NE(fmt.err.find("xml"), std::string::npos) << fmt.err;
    const auto help = run_cli("data --help");
    EXPECT_NE(help.out.find("\\addplot table[x=a_exact_x"), std::string::npos);
    EXPECT_NE(help.out.find("numpy.genfromtxt"), std::string::npos);
}

// --- trajectory ---------------------------------------------------------------------------

/// The column `c` of a CSV table (header excluded).
std::vector<std::string> column(const std::string& csv, std::size_t c) {
    std::vector<std::string> out;
    const auto rows = lines_of(csv);
    for (std::size_t i = 1; i < rows.size(); ++i) out.push_back(fields_of(rows[i]).at(c));
    return out;
}

TEST(TrajectoryMethods, SeveralMethodsMatchSingleRunsByteForByte) {
    struct start {
        std::string args;
        bool state;
    };
    const std::vector<start> starts = {
        {"--theta0 9pi/10 --samples 9 --periods 3", false},
        {"--theta0 170deg --at 0,0.1,1e6,-2.5", false},
        {"--theta0 0.3 --omega0 1.2 --samples 7", true},
        {"--theta0 2 --time t/s --length 0.5 --samples 5 --periods 7", false},
    };
    const std::vector<std::string> methods = {"exact", "harmonic", "lowest", "first", "second", "polynomial", "order:6"};
    std::string list;
    for (const auto& m : methods) list += (list.empty() ? "" : ",") + m;
    for (const auto& s : starts) {
        const auto all = run_cli("trajectory " + s.args + " --method " + list);
        ASSERT_EQ(all.status, 0) << s.args << all.err;
        const auto header = fields_of(lines_of(all.out).at(0));
        const std::size_t per = s.state ? 2 : 1;
        ASSERT_EQ(header.size(), 1 + per * methods.size());
        for (std::size_t i = 0; i < methods.size(); ++i) {
            EXPECT_EQ(header[1 + per * i], "theta:" + methods[i]);
            if (s.state) {
                EXPECT_EQ(header[2 + per * i], "omega:" + methods[i]);
            }
            const auto one = run_cli("trajectory " + s.args + " --method " + methods[i]);
            ASSERT_EQ(one.status, 0) << one.err;
            EXPECT_EQ(column(all.out, 0), column(one.out, 0));
            for (std::size_t k = 0; k < per; ++k) {
                EXPECT_EQ(column(all.out, 1 + per * i + k), column(one.out, 1 + k)) << s.args << " " << methods[i];
            }
        }
    }
}

TEST(TrajectoryMethods, EightAcceptedNineRefusedTwiceRefused) {
    const std::string eight = "exact,harmonic,lowest,first,second,polynomial,order:1,order:2";
    const auto ok = run_cli("trajectory --theta0 1 --samples 2 --method " + eight);
    EXPECT_EQ(ok.status, 0) << ok.err;
    const auto nine = run_cli("trajectory --theta0 1 --samples 2 --method " + eight + ",order:3");
    EXPECT_EQ(nine.status, 2);
    EXPECT_NE(nine.err.find("9 methods; at most 8 in one table"), std::string::npos) << nine.err;
    const auto twice = run_cli("trajectory --theta0 1 --samples 2 --method exact,lowest,exact");
    EXPECT_EQ(twice.status, 2);
    EXPECT_NE(twice.err.find("exact is listed twice"), std::string::npos) << twice.err;
    const auto order = run_cli("trajectory --theta0 1 --samples 2 --method exact,order --order 6");
    EXPECT_EQ(order.status, 0) << order.err;
    EXPECT_NE(order.out.find("theta:order:6"), std::string::npos);
    const auto period_only = run_cli("trajectory --theta0 1 --samples 2 --method exact,kidd-fogg");
    EXPECT_EQ(period_only.status, 2);
    EXPECT_NE(period_only.err.find("kidd-fogg gives a period only"), std::string::npos) << period_only.err;
}

TEST(TrajectoryMethods, JsonOfSeveralMethods) {
    const fs::path dir = temp_dir("trajectory-json");
    const auto r = run_cli("trajectory --theta0 9pi/10 --method exact,lowest --at 0,0.25 --format json");
    ASSERT_EQ(r.status, 0) << r.err;
    write_file(dir / "t.json", r.out);
    const auto py = run_python(dir, R"(
import json, sys
d = json.load(open(sys.argv[1]))
assert d["time"] == {"column": "t_over_T", "unit": "t/T"}, d["time"]
m = {x["id"]: x for x in d["methods"]}
assert m["exact"]["theta_column"] == "theta:exact"
assert m["lowest"]["units"] == {"theta": "rad"}
assert d["rows"][1]["t_over_T"] == 0.25
assert d["theta0"]["text"] == "9pi/10"
print(repr(d["theta0"]["radians"]), repr(m["exact"]["period"]["T_over_T0"]), repr(m["lowest"]["period"]["T_over_T0"]))
)", "'" + (dir / "t.json").string() + "'");
    ASSERT_EQ(py.status, 0) << py.err;
    std::istringstream in(py.out);
    std::string theta0, exact, lowest;
    in >> theta0 >> exact >> lowest;
    const pendulum::amplitude a(number(theta0));
    EXPECT_EQ(number(exact), pendulum::method_period(pendulum::parse_method("exact"), a));
    EXPECT_EQ(number(lowest), pendulum::method_period(pendulum::parse_method("lowest"), a));
    fs::remove_all(dir);
}

// --- eval's error columns -------------------------------------------------------------------

TEST(EvalErrorColumns, MatchTheMpmathReference) {
    // tests/data/period_errors.csv: T_m/T - 1 at 900 digits (make_period_errors.py).
    std::map<std::string, std::vector<std::pair<std::string, std::string>>> by_method;
    for (const auto& row : lines_of(slurp(fs::path(PENDULUM_TEST_DATA) / "period_errors.csv"))) {
        const auto f = fields_of(row);
        if (f.size() != 3 || f[0] == "theta0" || row[0] == '#') continue;
        by_method[f[1]].emplace_back(f[0], f[2]);
    }
    std::size_t checked = 0;
    for (const auto& [method, rows] : by_method) {
        std::string list;
        for (const auto& r : rows) list += (list.empty() ? "" : ",") + r.first;
        const auto out = run_cli("eval --theta0 '" + list + "' --columns theta0,err:" + method);
        ASSERT_EQ(out.status, 0) << method << out.err;
        const auto got = lines_of(out.out);
        ASSERT_EQ(got.size(), rows.size() + 1) << method;
        EXPECT_EQ(got[0], "theta0,err:" + method);
        for (std::size_t i = 0; i < rows.size(); ++i) {
            const std::string value = fields_of(got[i + 1]).at(1);
            if (rows[i].second == "below") {  // |T_m/T - 1| < 1e-300 is said, as for a formula's column
                EXPECT_EQ(value, "below_limit") << method << " at " << rows[i].first;
                continue;
            }
            const double want = std::strtod(rows[i].second.c_str(), nullptr);
            EXPECT_NEAR(number(value), want, 1e-12 * std::fabs(want)) << method << " at " << rows[i].first;
            ++checked;
        }
    }
    EXPECT_GT(checked, 300u);
}

TEST(EvalErrorColumns, IterationMatchesTheMpmathReference) {
    // tests/data/iteration.csv: the iteration in 45-digit arithmetic (make_iteration.py),
    // its error T_N/T - 1 empty where the order has no period.
    std::size_t checked = 0;
    for (const auto& row : lines_of(slurp(fs::path(PENDULUM_TEST_DATA) / "iteration.csv"))) {
        const auto f = fields_of(row);
        if (f.size() != 6 || row[0] == '#' || f[0] == "theta0") continue;
        const int order = std::stoi(f[2]);
        if (order != 0 && order != 1 && order != 2 && order != 6 && order != 17 && order != 40) continue;
        const auto out = run_cli("eval --theta0 '" + f[0] + "' --columns err:order:" + f[2]);
        ASSERT_EQ(out.status, 0) << row << out.err;
        const auto got = lines_of(out.out);
        ASSERT_EQ(got.size(), 2u);
        EXPECT_EQ(got[0], "err:order:" + f[2]);
        if (f[5].empty()) {
            EXPECT_EQ(got[1], "") << row;
            continue;
        }
        const double want = std::strtod(f[5].c_str(), nullptr);
        // 45 digits: the reference is right to 1e-12 relative down to errors of 1e-30.
        if (std::fabs(want) < 1e-30) continue;
        EXPECT_NEAR(number(got[1]), want, 1e-12 * std::fabs(want)) << row;
        ++checked;
    }
    EXPECT_GT(checked, 25u);
}

TEST(EvalErrorColumns, NoPeriodIsEmptyAndUnknownMethodRefused) {
    const auto r = run_cli("eval --theta0 'pi-1e-6,1' --columns theta0,err:order:6,err:exact");
    ASSERT_EQ(r.status, 0) << r.err;
    const auto rows = lines_of(r.out);
    ASSERT_EQ(rows.size(), 3u);
    EXPECT_EQ(rows[0], "theta0,err:order:6,err:exact");
    EXPECT_EQ(fields_of(rows[1]).at(1), "");  // the iteration has no period there, and says so
    EXPECT_NE(r.err.find("no period at order 6"), std::string::npos) << r.err;
    EXPECT_EQ(fields_of(rows[2]).at(2), "0");
    const auto bad = run_cli("eval --theta0 1 --columns theta0,err:nosuch");
    EXPECT_EQ(bad.status, 2);
    EXPECT_NE(bad.err.find("--columns 'err:nosuch'"), std::string::npos) << bad.err;
}

}  // namespace
