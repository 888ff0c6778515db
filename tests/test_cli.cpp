// SPDX-License-Identifier: GPL-3.0-or-later
// Tests of the command line: angle expressions, output tables and every kind of bad input.
#include "cli/depfile.hpp"
#include "cli/lists.hpp"
#include "pendulum/angle.hpp"
#include "cli/table.hpp"
#include "pendulum/approximants.hpp"
#include "pendulum/exact.hpp"
#include "pendulum/motion.hpp"
#include "process.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <charconv>
#include <filesystem>
#include <fstream>
#include <cmath>
#include <iomanip>
#include <filesystem>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <unistd.h>

using namespace pendulum;
using std::numbers::pi;
using test_support::run_cli;
using test_support::slurp;
namespace fs = std::filesystem;

TEST(Angle, ParsesWhatPhysicistsType) {
    EXPECT_EQ(pendulum::parse_angle("1.2"), 1.2);
    EXPECT_EQ(pendulum::parse_angle("pi/2"), pi / 2);
    EXPECT_EQ(pendulum::parse_angle("9pi/10"), 9 * pi / 10);
    EXPECT_EQ(pendulum::parse_angle("9*pi/10"), 9 * pi / 10);
    EXPECT_EQ(pendulum::parse_angle("0.9pi"), 0.9 * pi);
    EXPECT_EQ(pendulum::parse_angle("162deg"), 0.9 * pi);
    EXPECT_EQ(pendulum::parse_angle("90 deg"), pi / 2);
    EXPECT_EQ(pendulum::parse_angle("90\u00b0"), pi / 2);
    // Correctly rounded (50-digit mpmath), where pi / 3 in doubles is one ulp low.
    EXPECT_EQ(pendulum::parse_angle("\u03c0/3"), 1.0471975511965979);
    EXPECT_EQ(pendulum::parse_angle(" 3pi/4 "), 3 * pi / 4);
    EXPECT_EQ(pendulum::parse_angle("pi - 1e-9"), pi - 1e-9);
    EXPECT_EQ(pendulum::parse_angle("2(pi/3)"), 2.0943951023931957);
    EXPECT_EQ(pendulum::parse_angle("1e-8"), 1e-8);
    EXPECT_EQ(pendulum::parse_angle("1.5rad"), 1.5);
    EXPECT_EQ(pendulum::parse_angle("-pi/2"), -pi / 2);
}

TEST(Angle, RejectsWhatIsNotAnAngle) {
    for (const char* bad : {"", " ", "abc", "pi/0", "1e999", "inf", "nan", "1..2", "pi/", "(pi",
                            "2 3", "0x10", "1e", ".", "pideg deg", "1e308*10"}) {
        EXPECT_THROW(pendulum::parse_angle(bad), std::invalid_argument) << "'" << bad << "'";
    }
    try {
        pendulum::parse_angle("pi/0");
        FAIL();
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("'pi/0'"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("division by zero"), std::string::npos);
    }
}

TEST(Angle, SplitsLists) {
    EXPECT_EQ(cli::split_list("a,b"), (std::vector<std::string>{"a", "b"}));
    EXPECT_EQ(cli::split_list("a,"), (std::vector<std::string>{"a", ""}));
    EXPECT_EQ(cli::split_list(""), (std::vector<std::string>{""}));
}

TEST(Table, CsvAndJsonRoundTrip) {
    cli::table t{{"x", "y"}, {{0.1, 1.0 / 3.0}, {1e-300, -2.5}}};
    std::ostringstream csv;
    cli::write_table(csv, t, cli::table_format::csv);
    EXPECT_EQ(csv.str(), "x,y\n0.1,0.3333333333333333\n1e-300,-2.5\n");
    std::ostringstream json;
    cli::write_table(json, t, cli::table_format::json);
    EXPECT_EQ(json.str(), "[\n {\"x\": 0.1, \"y\": 0.3333333333333333},\n {\"x\": 1e-300, \"y\": -2.5}\n]\n");
    EXPECT_THROW(cli::parse_table_format("xml"), std::invalid_argument);
}

TEST(Table, LongTablesAsEachNumberAlone) {
    // Rows are gathered and written in blocks: the text is that of each number formatted on
    // its own (format_double), past many blocks, and a row needs no flush to be complete.
    std::ostringstream csv;
    std::string expected = "a,b\n";
    {
        cli::table_writer w(csv, {"a", "b"}, cli::table_format::csv);
        for (int i = 0; i < 20000; ++i) {
            const double a = std::ldexp(1.0 + i / 7.0, i % 600 - 300);
            const double b = i % 97 == 0 ? std::nan("") : -1.0 / (i + 1);
            w.row({a, b});
            expected += pendulum::format_double(a) + "," + (std::isnan(b) ? "" : pendulum::format_double(b)) + "\n";
        }
        w.finish();
    }
    EXPECT_GT(csv.str().size(), 300000u);
    EXPECT_TRUE(csv.str() == expected);
}

TEST(Cli, TablesAreTheTextTheyWere) {
    // eval and trajectory write numbers straight into a buffer; the text is the one the
    // streams wrote (tests/data/tables, written before), breakdowns near pi included.
    const fs::path data = fs::path(PENDULUM_TEST_DATA) / "tables";
    const std::string eval = "eval --theta0 'pi/3,1e-3,pi/2,9pi/10,pi-1e-6,0.3' --order 6,8 --method agm:2,kidd-fogg --length 0.5";
    EXPECT_EQ(run_cli(eval).out, slurp(data / "eval.csv"));
    EXPECT_EQ(run_cli(eval + " --format json").out, slurp(data / "eval.json"));
    const std::string trajectory = "trajectory --theta0 170deg --samples 50 --periods 2";
    EXPECT_EQ(run_cli(trajectory).out, slurp(data / "trajectory.csv"));
    EXPECT_EQ(run_cli(trajectory + " --format json").out, slurp(data / "trajectory.json"));
}

TEST(Cli, EvalColumnsWritesOnlyThose) {
    // --columns keeps the columns asked for, in the table's order, with the values of the
    // whole table; T_s needs --length, and an unknown column is bad input.
    const std::string amplitudes = "eval --theta0 'pi/3,1e-3,pi-1e-6' --length 0.5 --order 6";
    const auto all = run_cli(amplitudes);
    ASSERT_EQ(all.status, 0);
    std::string expected;
    std::istringstream in(all.out);
    for (std::string line; std::getline(in, line);) {
        std::vector<std::string> fields;
        std::istringstream cells(line);
        for (std::string f; std::getline(cells, f, ',');) fields.push_back(f);
        if (line.back() == ',') fields.emplace_back();
        // period_exact, c3_first, then period_order6 and T_s, the last two.
        expected += fields[1] + "," + fields[10] + "," + fields[fields.size() - 2] + "," + fields.back() + "\n";
    }
    const auto some = run_cli(amplitudes + " --columns T_s,c3_first,period_exact");
    EXPECT_EQ(some.status, 0);
    EXPECT_EQ(some.out, expected);
    auto r = run_cli("eval --theta0 1 --columns period_exact,bogus");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("unknown column 'bogus'; the columns are theta0, period_exact"), std::string::npos) << r.err;
    r = run_cli("eval --theta0 1 --columns T_s");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("needs --length"), std::string::npos) << r.err;
}

namespace {

std::vector<std::string> lines(const std::string& s) {
    std::vector<std::string> out;
    std::istringstream in(s);
    std::string line;
    while (std::getline(in, line)) out.push_back(line);
    return out;
}

std::vector<double> numbers(const std::string& line) {
    std::vector<double> v;
    std::istringstream in(line);
    std::string field;
    while (std::getline(in, field, ',')) v.push_back(std::stod(field));
    return v;
}

/// One record of a JSON table: its keys and values in order, null as NaN.
using json_record = std::vector<std::pair<std::string, double>>;

/// Reads the whole of a JSON table as eval writes it: an array of objects whose values are
/// numbers or null. Anything else, trailing text included, throws std::runtime_error.
std::vector<json_record> parse_json_table(const std::string& s) {
    std::size_t i = 0;
    const auto fail = [&](const std::string& what) {
        throw std::runtime_error(what + " at byte " + std::to_string(i) + ": '" + s.substr(i, 20) + "'");
    };
    const auto space = [&] {
        while (i < s.size() && (s[i] == ' ' || s[i] == '\n' || s[i] == '\t' || s[i] == '\r')) ++i;
    };
    const auto accept = [&](char c) {
        space();
        if (i < s.size() && s[i] == c) {
            ++i;
            return true;
        }
        return false;
    };
    const auto expect = [&](char c) {
        if (!accept(c)) fail(std::string("expected '") + c + "'");
    };
    const auto string = [&] {
        expect('"');
        const auto end = s.find('"', i);
        if (end == std::string::npos) fail("unterminated string");
        std::string out = s.substr(i, end - i);
        if (out.find('\\') != std::string::npos) fail("escape in a key");
        i = end + 1;
        return out;
    };
    const auto number = [&] {
        space();
        if (s.compare(i, 4, "null") == 0) {
            i += 4;
            return std::nan("");
        }
        const auto end = s.find_first_not_of("-+0123456789.eE", i);
        double v = 0;
        const auto [ptr, ec] = std::from_chars(s.data() + i, s.data() + (end == std::string::npos ? s.size() : end), v);
        if (ec != std::errc() || ptr == s.data() + i || ptr != s.data() + (end == std::string::npos ? s.size() : end)) {
            fail("not a JSON number");
        }
        i = static_cast<std::size_t>(ptr - s.data());
        return v;
    };
    std::vector<json_record> table;
    expect('[');
    if (!accept(']')) {
        do {
            json_record record;
            expect('{');
            do {
                std::string key = string();
                expect(':');
                record.emplace_back(std::move(key), number());
            } while (accept(','));
            expect('}');
            table.push_back(std::move(record));
        } while (accept(','));
        expect(']');
    }
    space();
    if (i != s.size()) fail("text after the table");
    return table;
}

}  // namespace

TEST(Cli, EvalPrintsTheDocumentedColumns) {
    const auto r = run_cli("eval --theta0 'pi/2,162deg' --order 3 --order 12");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err, "");
    const auto l = lines(r.out);
    ASSERT_EQ(l.size(), 3u);
    EXPECT_EQ(l[0],
              "theta0,period_exact,period_lowest,period_first,period_second,c1_exact,c3_exact,"
              "c5_exact,c1_lowest,c1_first,c3_first,c1_second,c3_second,c5_second,c1_poly,c3_poly,"
              "c5_poly,period_order3,period_order12");
    const auto row = numbers(l[1]);
    ASSERT_EQ(row.size(), 19u);
    EXPECT_EQ(row[0], pi / 2);
    const exact_solution e(pi / 2);
    EXPECT_EQ(row[1], e.period_ratio());  // round-trips exactly
    EXPECT_EQ(row[5], e.coefficient(0));
    EXPECT_EQ(row[4], second_order(pi / 2).period_ratio());
    EXPECT_EQ(row[18], iterated(pi / 2, 12).period_ratio());
    EXPECT_EQ(numbers(l[2])[0], 0.9 * pi);
}

TEST(Cli, EvalJson) {
    // One object per amplitude, the CSV's columns as keys in the same order, every value
    // the core library's, and null where the iteration breaks down (order 6 at pi - 1e-6).
    const std::string args = "eval --theta0 '1,pi-1e-6' --order 6";
    const auto csv = run_cli(args);
    ASSERT_EQ(csv.status, 0) << csv.err;
    const auto r = run_cli(args + " --format json");
    ASSERT_EQ(r.status, 0) << r.err;
    std::vector<json_record> table;
    ASSERT_NO_THROW(table = parse_json_table(r.out)) << r.out;
    ASSERT_EQ(table.size(), 2u) << r.out;
    std::vector<std::string> header;
    {
        std::istringstream in(lines(csv.out).at(0));
        for (std::string key; std::getline(in, key, ',');) header.push_back(key);
    }
    // The amplitudes as eval reads them: pi - 1e-6 keeps its distance from pi exactly.
    for (const amplitude t0 : {parse_amplitude("1"), parse_amplitude("pi-1e-6")}) {
        const auto& record = table[t0.radians() == 1.0 ? 0 : 1];
        const exact_solution e(t0);
        const auto first = first_order(t0);
        const auto second = second_order(t0);
        const auto poly = polynomial(t0);
        const std::vector<std::pair<std::string, double>> want = {
            {"theta0", t0.radians()},
            {"period_exact", e.period_ratio()},
            {"period_lowest", lowest_order(t0).period_ratio()},
            {"period_first", first.period_ratio()},
            {"period_second", second.period_ratio()},
            {"c1_exact", e.coefficient(0)},
            {"c3_exact", e.coefficient(1)},
            {"c5_exact", e.coefficient(2)},
            {"c1_lowest", lowest_order(t0).coefficients.at(0)},
            {"c1_first", first.coefficients.at(0)},
            {"c3_first", first.coefficients.at(1)},
            {"c1_second", second.coefficients.at(0)},
            {"c3_second", second.coefficients.at(1)},
            {"c5_second", second.coefficients.at(2)},
            {"c1_poly", poly.coefficients.at(0)},
            {"c3_poly", poly.coefficients.at(1)},
            {"c5_poly", poly.coefficients.at(2)},
            {"period_order6", t0.radians() == 1.0 ? iterated(1.0, 6).period_ratio() : std::nan("")},
        };
        ASSERT_EQ(record.size(), want.size()) << r.out;
        for (std::size_t k = 0; k < want.size(); ++k) {
            EXPECT_EQ(record[k].first, want[k].first) << t0.radians();
            EXPECT_EQ(record[k].first, header.at(k)) << "JSON keys and CSV columns differ";
            if (std::isnan(want[k].second)) {
                EXPECT_TRUE(std::isnan(record[k].second)) << want[k].first << " at " << t0.radians() << " is not null";
            } else {
                EXPECT_EQ(record[k].second, want[k].second) << want[k].first << " at " << t0.radians();
            }
        }
    }
    EXPECT_THROW(parse_json_table(r.out + "]"), std::runtime_error);
}

/// The lines of a command's table, checked: exit 0, the header and `rows` rows (else empty).
std::vector<std::string> table_lines(const std::string& args, const std::string& header, std::size_t rows) {
    const auto r = run_cli(args);
    EXPECT_EQ(r.status, 0) << args << ": " << r.err;
    auto l = lines(r.out);
    EXPECT_EQ(l.size(), rows + 1) << args;
    if (l.size() != rows + 1) return {};
    EXPECT_EQ(l[0], header) << args;
    return l;
}

TEST(Cli, TrajectoryMethodsAtTheSamePhysicalTime) {
    const auto l = table_lines("trajectory --theta0 9pi/10 --method second --at 0,0.25,0.5", "t_over_T,theta", 3);
    ASSERT_FALSE(l.empty());
    const exact_solution e(parse_amplitude("9pi/10"));
    const auto s = second_order(9 * pi / 10);
    // The command forms the phase from the approximant's own frequency ratio (not the
    // double w/w0 times the double time): the same value to an ulp of the phase, which next
    // to a zero crossing is a few 1e-16 of theta0.
    EXPECT_NEAR(numbers(l[2])[1], s.theta(0.25 * 4 * e.quarter_period()), 2e-15 * (9 * pi / 10))
        << std::setprecision(17) << numbers(l[2])[1] - s.theta(0.25 * 4 * e.quarter_period());

    const auto x = run_cli("trajectory --theta0 9pi/10 --samples 5 --periods 2");
    ASSERT_EQ(x.status, 0) << x.err;
    const auto xl = lines(x.out);
    ASSERT_EQ(xl.size(), 6u);
    EXPECT_EQ(numbers(xl[3]), (std::vector<double>{1.0, 9 * pi / 10}));
    EXPECT_EQ(numbers(xl[2]), (std::vector<double>{0.5, -9 * pi / 10}));

    for (const char* m : {"exact", "harmonic", "lowest", "first", "second", "polynomial"}) {
        const auto y = run_cli(std::string("trajectory --theta0 1 --samples 3 --method ") + m);
        EXPECT_EQ(y.status, 0) << m << y.err;
        EXPECT_EQ(lines(y.out).size(), 4u);
    }
    const auto o = run_cli("trajectory --theta0 1 --method order --order 6 --at 0.1 --format json");
    EXPECT_EQ(o.status, 0) << o.err;
    EXPECT_NE(o.out.find("\"t_over_T\": 0.1"), std::string::npos);
}

TEST(Cli, StatesAndEnergiesInAllRegimes) {
    const auto l = table_lines("eval --theta0 0 --omega0 1.9,2,2.2",
                               "theta0,omega0,energy,regime,amplitude,period_exact,revolution_period", 3);
    ASSERT_FALSE(l.empty());
    // The velocities as written: 1.9 and 2.2 are those decimals, not their doubles (E = 2.42).
    const auto written = [](const char* w) { return motion::from_state(written_number(0.0), written_number::expression(w)); };
    const auto lib = written("1.9");
    EXPECT_EQ(l[1], "0,1.9,1.805,libration," + format_double(lib.amplitude().radians()) + "," +
                        format_double(lib.period_ratio()) + ",");
    EXPECT_EQ(l[2], "0,2,2,separatrix,,,");
    EXPECT_EQ(l[3], "0,2.2,2.42,rotation,,," + format_double(written("2.2").period_ratio()));

    const auto m = run_cli("eval --energy 'pi/2' --method second");
    ASSERT_EQ(m.status, 0) << m.err;
    EXPECT_NE(m.out.find(",libration,"), std::string::npos) << m.out;

    const auto bad = run_cli("eval --energy 2.5 --method second");
    EXPECT_NE(bad.err.find("librations only"), std::string::npos) << bad.err;
    EXPECT_NE(bad.err.find("--method exact"), std::string::npos) << bad.err;
    const auto negative = run_cli("eval --energy -0.5");
    EXPECT_NE(negative.err.find("must be > 0"), std::string::npos) << negative.err;

    // A rotation's angle rises by 2 pi per revolution; the start is the state as given.
    const auto tl = table_lines("trajectory --theta0 0 --omega0 2.2 --at 0,1,2", "t_over_T,theta,omega", 3);
    ASSERT_FALSE(tl.empty());
    EXPECT_EQ(numbers(tl[1]), (std::vector<double>{0, 0, 2.2}));
    EXPECT_NEAR(numbers(tl[2])[1], 2 * pi, 1e-14);
    EXPECT_NEAR(numbers(tl[3])[1], 4 * pi, 1e-14);

    const auto sep = run_cli("trajectory --energy 2 --time t/T0 --at 1");
    ASSERT_EQ(sep.status, 0) << sep.err;
    EXPECT_EQ(lines(sep.out)[0], "t_over_T0,theta,omega");
    EXPECT_NEAR(numbers(lines(sep.out)[1])[1], 4 * std::atan(std::exp(2 * pi)) - pi, 1e-15);
    const auto nosep = run_cli("trajectory --energy 2 --at 1");
    EXPECT_NE(nosep.err.find("--time t/T0"), std::string::npos) << nosep.err;

    const auto sec = run_cli("trajectory --theta0 0 --omega0 1 --time t/s --length 9.80665 --at 6.283185307179586");
    ASSERT_EQ(sec.status, 0) << sec.err;
    EXPECT_NEAR(numbers(lines(sec.out)[1])[1], motion::from_state({0.0, 1.0}).theta(2 * pi), 1e-14);
}

TEST(Cli, HelpTeaches) {
    for (const char* args : {"--help", "eval --help", "trajectory --help"}) {
        const auto r = run_cli(args);
        EXPECT_EQ(r.status, 0) << args;
        EXPECT_NE(r.out.find("Example"), std::string::npos) << args;
        EXPECT_NE(r.out.find("9pi/10"), std::string::npos) << args;
    }
}

TEST(Cli, BadInputFailsWithOneLineAndNoOutput) {
    const char* cases[] = {
        "eval --theta0 0",
        "eval --theta0 -1",
        "eval --theta0 pi",
        "eval --theta0 4",
        "eval --theta0 nan",
        "eval --theta0 inf",
        "eval --theta0 ''",
        "eval --theta0 abc",
        "eval --theta0 pi/0",
        "eval --theta0 1e999",
        "eval --theta0 '1,,2'",
        "eval --theta0 1 --order -1",
        "eval --theta0 1 --order 201",
        "eval --theta0 1 --order x",
        "eval --theta0 1 --format xml",
        "eval",
        "eval --theta0 1 --bogus",
        "frobnicate",
        "",
        "trajectory --theta0 1 --method fancy --samples 3",
        "trajectory --theta0 1 --method order --samples 3",
        "trajectory --theta0 1 --method order --order 999 --samples 3",
        "trajectory --theta0 1 --method first --order 3 --samples 3",
        "trajectory --theta0 1 --samples 1",
        "trajectory --theta0 1 --samples 0",
        "trajectory --theta0 1 --samples 100000000",
        "trajectory --theta0 1 --samples 3 --periods 0",
        "trajectory --theta0 1 --samples 3 --periods -1",
        "trajectory --theta0 1 --samples 3 --periods nan",
        "trajectory --theta0 1 --at 0.1,abc",
        "trajectory --theta0 1 --at ''",
        "trajectory --theta0 1",
        "trajectory --theta0 1 --at 0.1 --samples 3",
        "trajectory --theta0 1,2 --at 0.1",
        "trajectory --theta0 pi --at 0.1",
        "eval --energy -1",
        "eval --energy 0",
        "eval --energy 1 --theta0 1",
        "eval --omega0 1",
        "eval --theta0 0 --omega0 0",
        "eval --theta0 0,1 --omega0 1,2,3",
        "eval --energy 2.5 --method second",
        "eval --energy 2 --order 3",
        "trajectory --theta0 0 --omega0 2.2 --method second --at 0.1",
        "trajectory --energy 2 --at 0.1",
        "trajectory --energy 1 --time t/x --at 0.1",
        "trajectory --energy 1 --time t/s --at 0.1",
        "trajectory --energy 1 --length 1 --at 0.1",
        "trajectory --theta0 0 --omega0 1,2 --at 0.1",
    };
    for (const char* args : cases) {
        const auto r = run_cli(args);
        EXPECT_EQ(r.status, 2) << args;  // bad input: 2, as --help says
        EXPECT_EQ(r.out, "") << args;
        const auto l = lines(r.err);
        ASSERT_EQ(l.size(), 1u) << args << "\n" << r.err;
        EXPECT_EQ(l[0].rfind("pendulum-figures: error: ", 0), 0u) << l[0];
    }
    const auto r = run_cli("eval --theta0 pi/0");
    EXPECT_NE(r.err.find("'pi/0'"), std::string::npos) << r.err;
    const auto p = run_cli("eval --theta0 3.5");
    EXPECT_NE(p.err.find("between 0 and pi"), std::string::npos) << p.err;
    EXPECT_NE(p.err.find("3.5"), std::string::npos) << p.err;
}

TEST(Depfile, MakeEscapesWhatMakeAndNinjaRead) {
    EXPECT_EQ(cli::make_escaped("figures/c1.pdf"), "figures/c1.pdf");
    EXPECT_EQ(cli::make_escaped("my figs/a#1$.pdf"), "my\\ figs/a\\#1$$.pdf");
    for (const char* bad : {"a\nb", "a\\ b", "a\\", "a\\b"}) EXPECT_THROW(cli::make_escaped(bad), std::invalid_argument) << bad;
    EXPECT_EQ(cli::make_rule({"a b", "c"}, {"d", "e"}), "a\\ b \\\n c: \\\n  d \\\n  e\n\nd:\n\ne:\n");
}

TEST(Depfile, ListsEveryOutputAndInputAndFollowsTheSpecsStyle) {
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / ("pendulum-depfile-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir / "specs" / "out dir");
    // The style file inside the spec's directory: a spec's inputs stay in its tree.
    std::ofstream(dir / "specs" / "house.toml") << "# a house style\nbase = \"slides\"\n";
    std::ofstream(dir / "specs" / "a.toml") << "[figure]\nstyle = \"house.toml\"\n[[panel]]\nplot = \"period\"\nmethods = [\"exact\"]\n";
    auto r = run_cli("render specs/a.toml fig1 -f svg,pdf_tex -o 'specs/out dir' --depfile 'specs/out dir/a.d'", dir);
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string rule = test_support::slurp(dir / "specs" / "out dir" / "a.d");
    const std::string head = rule.substr(0, rule.find(':'));
    for (const char* target : {"specs/out\\ dir/a.svg", "specs/out\\ dir/a.pdf_tex", "specs/out\\ dir/a.pdf",
                               "specs/out\\ dir/c1-lowest.svg", "specs/out\\ dir/c1-lowest.pdf_tex"}) {
        EXPECT_NE(head.find(target), std::string::npos) << target << " not a target of\n" << rule;
    }
    for (const char* input : {"  specs/a.toml", "  specs/house.toml", "/pendulum-figures"}) {
        EXPECT_NE(rule.find(input), std::string::npos) << input << " not an input of\n" << rule;
    }
    // The spec's style file draws it (slides' sans serif), the built-in figure keeps paper's.
    const std::string styled = test_support::slurp(dir / "specs" / "out dir" / "a.svg");
    auto same = run_cli("render specs/a.toml -f svg -o - --theme specs/house.toml", dir);
    EXPECT_EQ(same.out, styled);
    auto paper = run_cli("render specs/a.toml -f svg -o - --theme paper", dir);
    EXPECT_NE(paper.out, styled);
    // --depfile-target names the stamp; a missing style file is bad input naming the spec's key.
    r = run_cli("render specs/a.toml -f svg -o 'specs/out dir' --depfile s.d --depfile-target s.d", dir);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(test_support::slurp(dir / "s.d").substr(0, 5), "s.d: ");
    fs::remove(dir / "specs" / "house.toml");
    r = run_cli("render specs/a.toml -f svg -o 'specs/out dir'", dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("[figure] style = specs/house.toml"), std::string::npos) << r.err;
    EXPECT_EQ(run_cli("render fig1 -o - -f svg --depfile x.d", dir).status, 2);
    fs::remove_all(dir);
}
