// SPDX-License-Identifier: GPL-3.0-or-later
// A user's formula as a method: the language, its bounds and messages, its values and
// period errors against mpmath (tests/data/make_formula_reference.py), and its use in specs,
// plot and eval.
#include "pendulum/exact.hpp"
#include "pendulum/formula.hpp"
#include "pendulum/methods.hpp"
#include "process.hpp"
#include "reference.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

using namespace pendulum;
using test_support::run_cli;
using test_support::slurp;
using test_support::temp_dir;

namespace {

/// The formulas of make_formula_reference.py, in its order.
const std::vector<std::string> reference_formulas = {
    "1/sqrt(cos(theta0/2))",
    "(sin(theta0/2)/(theta0/2))^(-3/4)",
    "sqrt(theta0/(2*besselj(1, theta0))) * (2*ellipe(sin(theta0/2)^2)/pi)^(-0.1) / agm(1, cos(theta0/2))^0.2",
};

/// The message parsing `text` throws, or "" where it parses.
std::string parse_error(const std::string& text) {
    try {
        formula f(text);
        return "";
    } catch (const domain_error& e) {
        return e.what();
    }
}

double value(const std::string& text, double theta0, double t = 0) { return formula(text).value(theta0, t); }

void write(const std::filesystem::path& p, const std::string& text) { std::ofstream(p) << text; }

}  // namespace

// ---- The language.

TEST(FormulaLanguage, ArithmeticAndPrecedence) {
    EXPECT_DOUBLE_EQ(value("1 + 2*3", 0), 7);
    EXPECT_DOUBLE_EQ(value("2^3^2", 0), 512);   // right-associative
    EXPECT_DOUBLE_EQ(value("-2^2", 0), -4);     // unary minus looser than ^
    EXPECT_DOUBLE_EQ(value("2^-1", 0), 0.5);
    EXPECT_DOUBLE_EQ(value("(-2)^2", 0), 4);
    EXPECT_DOUBLE_EQ(value("8/4/2", 0), 1);     // left-associative
    EXPECT_DOUBLE_EQ(value("9pi/10", 0), 0.9 * std::numbers::pi);
    EXPECT_DOUBLE_EQ(value("2\u03c0", 0), 2 * std::numbers::pi);
    EXPECT_DOUBLE_EQ(value("theta0*cos(t)", 0.5, 1.0), 0.5 * std::cos(1.0));
    EXPECT_DOUBLE_EQ(value("\u03b80^2", 3), 9);
    EXPECT_DOUBLE_EQ(value("abs(-3) + sqrt(4) + exp(0) + log(1)", 0), 6);
    EXPECT_NEAR(value("sinh(1) - cosh(1) + tanh(0) + asin(1) + acos(1) + atan(1)", 0),
                std::sinh(1.0) - std::cosh(1.0) + std::asin(1.0) + std::atan(1.0), 1e-15);
    EXPECT_NEAR(value("besselj(1, 2)", 0), jn(1, 2.0), 1e-16);
    EXPECT_NEAR(value("besselj(-3, 2)", 0), -jn(3, 2.0), 1e-16);
    EXPECT_NEAR(value("agm(1, 2)", 0), 1.4567910310469068692, 1e-15);
    // mpmath: ellipk(0.5), ellipe(0.5), ellipk(-1), ellipe(-1) (parameter m = k^2).
    EXPECT_NEAR(value("ellipk(0.5)", 0), 1.8540746773013719184, 1e-15);
    EXPECT_NEAR(value("ellipe(0.5)", 0), 1.3506438810476755025, 1e-15);
    EXPECT_NEAR(value("ellipk(-1)", 0), 1.3110287771460599052, 1e-15);
    EXPECT_NEAR(value("ellipe(-1)", 0), 1.9100988945138560089, 1e-15);
    EXPECT_EQ(value("ellipe(1)", 0), 1);
    EXPECT_TRUE(std::isinf(value("ellipk(1)", 0)));
    EXPECT_TRUE(std::isnan(value("ellipk(2)", 0)));
    EXPECT_TRUE(std::isnan(value("sqrt(-1)", 0)));
    EXPECT_FALSE(formula("1/sqrt(cos(theta0/2))").uses_t());
    EXPECT_TRUE(formula("theta0*cos(t)").uses_t());
}

TEST(FormulaLanguage, SyntaxErrorsNameTheirColumn) {
    EXPECT_EQ(parse_error("1/sqrt(cos(theta0/2))"), "");
    const std::string unknown = parse_error("1/sqr(cos(theta0/2))");
    EXPECT_EQ(unknown.rfind("formula:1:3: unknown name 'sqr'; did you mean 'sqrt'? (names: theta0", 0), 0u) << unknown;
    EXPECT_NE(unknown.find("functions: sqrt, exp, log, sin, cos, tan"), std::string::npos) << unknown;
    EXPECT_NE(unknown.find("besselj(n, x)"), std::string::npos) << unknown;
    EXPECT_NE(unknown.find("parameter m = k^2"), std::string::npos) << unknown;
    // A Greek letter counts as one column.
    EXPECT_EQ(parse_error("\u03b80 + sqr(1)").rfind("formula:1:6: unknown name 'sqr'", 0), 0u);
    EXPECT_EQ(parse_error("theta + 1").rfind("formula:1:1: unknown name 'theta'; did you mean 'theta0'?", 0), 0u);
    EXPECT_EQ(parse_error(""), "formula:1:1: empty formula; write T/T0 in theta0, e.g. 1/sqrt(cos(theta0/2))");
    EXPECT_EQ(parse_error("1 +"), "formula:1:4: incomplete formula: a number, a name or '(' is missing at the end");
    EXPECT_EQ(parse_error("(1 + 2"), "formula:1:7: missing ')' for the '(' at column 1");
    EXPECT_EQ(parse_error("1 + 2)"), "formula:1:6: unmatched ')'");
    EXPECT_EQ(parse_error("(1 2)"), "formula:1:4: expected ')' or an operator, not '2'");
    EXPECT_EQ(parse_error("1 $ 2"), "formula:1:3: unexpected '$' after a complete expression");
    EXPECT_EQ(parse_error("sqrt 2"), "formula:1:6: sqrt is a function: write sqrt(...)");
    EXPECT_EQ(parse_error("sqrt(1, 2)"), "formula:1:1: sqrt takes 1 argument, not 2");
    EXPECT_EQ(parse_error("agm(1)"), "formula:1:1: agm takes 2 arguments, not 1");
    EXPECT_EQ(parse_error("besselj(theta0, 1)"),
              "formula:1:9: besselj(n, x) needs n to be a constant whole number, not a formula in theta0 or t");
    EXPECT_EQ(parse_error("besselj(1.5, 1)"), "formula:1:9: besselj(n, x) takes a whole number n with |n| <= 1000, not 1.5");
    EXPECT_EQ(parse_error("1e999"), "formula:1:1: number 1e999 is beyond a double's range");
    EXPECT_EQ(parse_error("."), "formula:1:1: '.' is not a number");
    EXPECT_EQ(parse_error("2 * \u00e9"), "formula:1:5: unexpected '\u00e9'; expected a number, a name or '('");
}

// ---- The bounds: N accepted, N + 1 refused with its message.

TEST(FormulaLimits, Bytes) {
    const std::string ok = "1" + std::string(max_formula_bytes - 1, ' ');
    EXPECT_EQ(parse_error(ok), "");
    EXPECT_EQ(parse_error(ok + " "), "formula:1:1001: a formula takes at most 1000 bytes, this one has 1001");
}

TEST(FormulaLimits, Depth) {
    const auto nested = [](int n) { return std::string(static_cast<std::size_t>(n), '(') + "1" + std::string(static_cast<std::size_t>(n), ')'); };
    EXPECT_EQ(parse_error(nested(64)), "");
    EXPECT_EQ(parse_error(nested(65)),
              "formula:1:65: nested too deeply (at most 64 levels of parentheses, calls, signs and exponents)");
    EXPECT_EQ(parse_error(std::string(64, '-') + "1"), "");
    EXPECT_EQ(parse_error(std::string(65, '-') + "1").rfind("formula:1:65: nested too deeply", 0), 0u);
    std::string powers = "1";
    for (int i = 0; i < 64; ++i) powers += "^1";
    EXPECT_EQ(parse_error(powers), "");
    EXPECT_EQ(parse_error(powers + "^1").rfind("formula:1:130: nested too deeply", 0), 0u);
    // Hostile: 499 parentheses deep within the byte limit; 1000 deep is over it.
    EXPECT_EQ(parse_error(nested(499)).rfind("formula:1:65: nested too deeply", 0), 0u);
    EXPECT_EQ(parse_error(nested(1000)).rfind("formula:1:1001: a formula takes at most 1000 bytes", 0), 0u);
}

TEST(FormulaLimits, Nodes) {
    // "1+1+...": n numbers and n - 1 additions.
    const auto sum = [](int numbers) {
        std::string s = "1";
        for (int i = 1; i < numbers; ++i) s += "+1";
        return s;
    };
    EXPECT_EQ(formula(sum(250)).nodes().size(), 499u);
    EXPECT_EQ(formula("-(" + sum(250) + ")").nodes().size(), 500u);
    const std::string over = parse_error(sum(251));   // 501 nodes
    EXPECT_EQ(over, "formula:1:502: a formula has at most 500 numbers, names and operations") << over;
}

TEST(FormulaLimits, BesselOrder) {
    EXPECT_EQ(parse_error("besselj(1000, theta0)"), "");
    EXPECT_EQ(parse_error("besselj(-1000, theta0)"), "");
    EXPECT_EQ(parse_error("besselj(1001, theta0)"), "formula:1:9: besselj(n, x) takes a whole number n with |n| <= 1000, not 1001");
    EXPECT_EQ(parse_error("besselj(-1001, theta0)"),
              "formula:1:9: besselj(n, x) takes a whole number n with |n| <= 1000, not -1001");
    EXPECT_EQ(parse_error("besselj(1e9, theta0)"), "formula:1:9: besselj(n, x) takes a whole number n with |n| <= 1000, not 1e+09");
}

// ---- Hostile text.

TEST(FormulaHostile, ControlCharacters) {
    EXPECT_EQ(parse_error(std::string("1 +\x07 2")), "formula:1:4: control character \\x07 in a formula");
    EXPECT_EQ(parse_error(std::string("1\n+ 2")), "formula:1:2: control character \\x0a in a formula");
    EXPECT_EQ(parse_error(std::string("1\x1b[31m", 7)), "formula:1:2: control character \\x1b in a formula");
    EXPECT_EQ(parse_error(std::string("1\0", 2)), "formula:1:2: control character \\x00 in a formula");
}

TEST(FormulaHostile, HugeExponentsAreInfiniteNotSlow) {
    const auto start = std::chrono::steady_clock::now();
    EXPECT_TRUE(std::isinf(value("10^10^10", 0)));
    const formula f("10^10^10 + theta0");
    EXPECT_TRUE(std::isinf(formula_period(f, 1.0)));
    EXPECT_EQ(formula_period_error(f, 1.0).what, period_error::kind::no_period);
    // 10^10^8 is within MPFR's range but not a double's: infinite, and sin of it is not
    // reduced at millions of bits.
    EXPECT_EQ(formula_period_error(formula("1 + sin(10^10^8)*theta0"), 1.0).what, period_error::kind::no_period);
    // J_1000 at 1e300 is conditioned like 1e300: its error needs more work than a point may
    // take, and is not computed (a gap); between |x| = 1e3 and n^2 MPFR's series would take
    // minutes, and is not tried.
    EXPECT_EQ(formula_period_error(formula("besselj(1000, 1e300*theta0) + 1"), 1.0).what, period_error::kind::not_computed);
    EXPECT_EQ(formula_period_error(formula("besselj(1000, 5e5*theta0) + 1"), 1.0).what, period_error::kind::not_computed);
    EXPECT_EQ(formula_period_error(formula("besselj(1000, 500*theta0) + 1"), 1.0).what, period_error::kind::value);
    EXPECT_LE(formula_error_seconds(formula("besselj(1000, 5e5*theta0) + 1")), 0.02);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_LT(seconds, 5.0);
}

// ---- Values and period errors against mpmath.

TEST(FormulaReference, PeriodsAndErrorsMatchMpmath) {
    const auto rows = test_support::read_reference("formula_reference.csv");
    ASSERT_GE(rows.size(), 3u * 26u);
    double smallest = 1;
    for (const auto& row : rows) {
        const formula f(reference_formulas[static_cast<std::size_t>(row[0])]);
        const double theta0 = row[1];
        SCOPED_TRACE(f.text() + " at " + format_double(theta0));
        EXPECT_NEAR(formula_period(f, theta0), row[2], 1e-13 * row[2]);
        const auto e = formula_period_error(f, theta0);
        ASSERT_EQ(e.what, period_error::kind::value);
        EXPECT_NEAR(e.value, row[3], 1e-12 * std::fabs(row[3]));
        smallest = std::min(smallest, std::fabs(row[3]));
    }
    EXPECT_LT(smallest, 1e-20);  // down to errors of 1e-20 and below
}

TEST(FormulaReference, ExactPeriodAsAFormulaHasNoError) {
    const formula exact("2*ellipk(sin(theta0/2)^2)/pi");
    const auto rows = test_support::read_reference("formula_reference.csv");
    for (const auto& row : rows) {
        if (row[0] != 0) continue;
        const auto e = formula_period_error(exact, row[1]);
        SCOPED_TRACE(format_double(row[1]));
        EXPECT_TRUE(e.what == period_error::kind::below_limit || (e.what == period_error::kind::value && std::fabs(e.value) < 1e-30));
    }
    // Close to pi from an expression: pi - 1e-12 exactly, not its double.
    const formula kidd_fogg("1/sqrt(cos(theta0/2))");
    const amplitude near = amplitude::from_pi(1e-12);
    EXPECT_NEAR(formula_period(kidd_fogg, near), 1 / std::sqrt(std::sin(0.5e-12)), 1e-12 * 1.5e6);
    EXPECT_EQ(formula_period_error(kidd_fogg, near).what, period_error::kind::value);
    const double built_in = method_period_error(parse_method("kidd-fogg"), near).value;
    EXPECT_NEAR(formula_period_error(kidd_fogg, near).value, built_in, 1e-12 * built_in);
}

TEST(FormulaReference, AgreesWithTheBuiltInFormulas) {
    // Kidd and Fogg is 1/sqrt(k'), Denman 1/(1 - theta0^2/16): the same errors as the built-ins.
    for (const double t : {1e-8, 1e-3, 0.5, 2.0, 3.0, std::numbers::pi - 1e-9}) {
        SCOPED_TRACE(format_double(t));
        const auto f = formula_period_error(formula("1/sqrt(cos(theta0/2))"), t);
        const auto b = method_period_error(parse_method("kidd-fogg"), t);
        ASSERT_EQ(f.what, b.what);
        EXPECT_NEAR(f.value, b.value, 1e-12 * std::fabs(b.value));
        const auto fd = formula_period_error(formula("1/(1 - theta0^2/16)"), t);
        const auto bd = method_period_error(parse_method("denman"), t);
        ASSERT_EQ(fd.what, bd.what);
        EXPECT_NEAR(fd.value, bd.value, 1e-12 * std::fabs(bd.value));
    }
}

TEST(FormulaReference, RoundingNoiseIsNeverAnError) {
    // theta0 + 1e100 - 1e100 loses theta0 at 128 and 256 bits alike (the same wrong zero
    // twice): the lost bits are counted, and the error is theta0's.
    const auto e = formula_period_error(formula("(theta0 + 1e100) - 1e100"), 1.0);
    ASSERT_EQ(e.what, period_error::kind::value);
    const double expected = 1.0 / period_ratio(1.0) - 1;
    EXPECT_NEAR(e.value, expected, 1e-12 * std::fabs(expected));
    // log(1 + theta0^2) at theta0 = 1e-30: 1 + 1e-60 is 1 at 128 bits.
    const auto g = formula_period_error(formula("1 + log(1 + theta0^2)"), 1e-30);
    ASSERT_EQ(g.what, period_error::kind::value);
    EXPECT_NEAR(g.value, 1e-60 - 1e-60 / 16, 1e-12 * 1e-60);
    // Zero by cancellation everywhere: never resolved, never drawn.
    EXPECT_EQ(formula_period_error(formula("1 + (theta0 - theta0)"), 1.0).what, period_error::kind::value);
    EXPECT_EQ(formula_period_error(formula("sqrt(-1) + theta0"), 1.0).what, period_error::kind::no_period);
}

TEST(FormulaMethod, ParsedAsAMethod) {
    const auto m = parse_method("formula:1/sqrt(cos(theta0/2))");
    EXPECT_EQ(m.text(), "formula:1");
    EXPECT_FALSE(m.has_motion());
    EXPECT_EQ(m.label(), "1/sqrt(cos(theta0/2))");
    EXPECT_EQ(method_period(m, 1.0), 1 / std::sqrt(std::cos(0.5)));
    const auto motion = parse_method("formula:theta0*cos(t)");
    EXPECT_TRUE(motion.has_motion());
    EXPECT_THROW(method_period(motion, 1.0), domain_error);
    EXPECT_THROW(parse_method("formula:sqr(2)"), domain_error);
    EXPECT_NE(method_names().find("formula:EXPR"), std::string::npos);
}

// ---- Through the program.

TEST(FormulaCli, EvalWritesPeriodAndError) {
    const auto r = run_cli("eval --theta0 1e-6,2 --method 'formula:1/sqrt(cos(theta0/2))' "
                           "--method 'formula:2*ellipk(sin(theta0/2)^2)/pi' --columns theta0,period_exact");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.out.substr(0, r.out.find('\n')),
              "theta0,period_exact,period_formula:1,period_formula:2,err:formula:1,err:formula:2");
    EXPECT_NE(r.out.find("9.765625000000812e-28,below_limit"), std::string::npos) << r.out;
}

TEST(FormulaCli, EvalRefusesBadFormulasWithExit2) {
    const auto r = run_cli("eval --theta0 1 --method 'formula:1/sqr(2)'");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("--method 'formula:1/sqr(2)': formula:1:3: unknown name 'sqr'; did you mean 'sqrt'?"), std::string::npos)
        << r.err;
    const auto t = run_cli("eval --theta0 1 --method 'formula:theta0*cos(t)'");
    EXPECT_EQ(t.status, 2);
    EXPECT_NE(t.err.find("the formula uses t"), std::string::npos) << t.err;
    // A comma inside a call does not split the list.
    const auto b = run_cli("eval --theta0 1 --method 'formula:sqrt(theta0/(2*besselj(1, theta0)))'");
    EXPECT_EQ(b.status, 0) << b.err;
}

TEST(FormulaSpec, PeriodPanelWithTwoFormulas) {
    const auto dir = temp_dir("formula_spec");
    write(dir / "f.toml",
          "[[panel]]\nplot = \"period\"\ny = \"error-log\"\n"
          "methods = [\"exact\", { formula = \"1/sqrt(cos(theta0/2))\", label = \"$\\\\cos(\\\\theta_0/2)^{-1/2}$\" },\n"
          "           { formula = \"(sin(theta0/2)/(theta0/2))^(-3/4)\" }, \"lowest\"]\n");
    const auto r = run_cli("render f.toml -f svg", dir);
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string svg = slurp(dir / "f.svg");
    EXPECT_GT(svg.size(), 1000u);
}

TEST(FormulaSpec, RefusedWithExit2) {
    const auto dir = temp_dir("formula_spec_bad");
    const auto refused = [&](const std::string& methods, const std::string& plot, const std::string& expected) {
        write(dir / "b.toml", "[[panel]]\nplot = \"" + plot + "\"\n" + (plot == "trajectory" ? "theta0 = 1.0\n" : "") +
                                  "methods = " + methods + "\n");
        const auto r = run_cli("render b.toml -f svg", dir);
        EXPECT_EQ(r.status, 2) << methods;
        EXPECT_NE(r.err.find(expected), std::string::npos) << r.err;
    };
    refused("[{ formula = \"1/sqr(2)\" }]", "period", "formula:1:3: unknown name 'sqr'; did you mean 'sqrt'?");
    refused("[{ formula = \"theta0*cos(t)\" }]", "period", "uses t: it is a law of motion theta(t), whose period is not defined");
    refused("[{ formula = \"1\", method = \"exact\" }]", "period", "method = \"NAME\" or formula = \"EXPR\", not both");
    refused("[{ formula = 3 }]", "period", "formula = \"EXPR\" takes a string");
    refused("[{ formula = \"sqrt(-1 - theta0)\" }]", "period", "is not finite anywhere on the panel's axis");
    refused("[{ formula = \"1/sqrt(cos(theta0/2))\" }]", "trajectory", "is a period T/T0 in theta0; use it in a period panel");
    // Every string of a spec is at most 1000 bytes: a formula of 1000 is read, one of 1001 refused.
    refused("[{ formula = \"1" + std::string(999, ' ') + "\" }, { formula = \"sqrt(-1)\" }]", "period", "formula:2 = 'sqrt(-1)'");
    refused("[{ formula = \"1" + std::string(1000, ' ') + "\" }]", "period", "has 1001 bytes; at most 1000");
}

TEST(FormulaCli, PlotTakesFormulas) {
    const auto dir = temp_dir("formula_plot");
    const auto r = run_cli("plot period --methods 'exact,formula:1/sqrt(cos(theta0/2)),formula:agm(1, 1)' --y error-log -f svg -o .",
                           dir);
    EXPECT_EQ(r.status, 0) << r.err;
    const auto bad = run_cli("plot period --methods 'formula:sqrt(-1 - theta0)' -f svg -o .", dir);
    EXPECT_EQ(bad.status, 2) << bad.err;
}

TEST(FormulaTrajectory, CommandWritesTheLaw) {
    const auto r = run_cli("trajectory --theta0 1 --method 'formula:theta0*cos(t)' --at 0,0.5 --time t/T0");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.out, "t_over_T0,theta\n0,1\n0.5," + format_double(std::cos(std::numbers::pi)) + "\n");
    const auto state = run_cli("trajectory --theta0 1 --omega0 0.1 --method 'formula:theta0*cos(t)' --samples 3");
    EXPECT_EQ(state.status, 2);
    EXPECT_NE(state.err.find("starts at rest at its amplitude: give --theta0 alone"), std::string::npos) << state.err;
    const auto period = run_cli("trajectory --theta0 1 --method 'formula:1/sqrt(cos(theta0/2))' --samples 3");
    EXPECT_EQ(period.status, 2);
    EXPECT_NE(period.err.find("gives a period only, not a law of motion"), std::string::npos) << period.err;
    const auto nowhere = run_cli("trajectory --theta0 1 --method 'formula:sqrt(-1)*t' --samples 3");
    EXPECT_EQ(nowhere.status, 2);
    EXPECT_NE(nowhere.err.find("is not finite at any of the times asked for"), std::string::npos) << nowhere.err;
    EXPECT_EQ(nowhere.out, "");  // nothing partial
}

TEST(FormulaEval, AFormulasErrorColumnComesWithItsMethod) {
    const auto with = run_cli("eval --theta0 1 --method 'formula:1/sqrt(cos(theta0/2))' --columns theta0,err:lowest");
    ASSERT_EQ(with.status, 0) << with.err;
    EXPECT_EQ(with.out.substr(0, with.out.find('\n')), "theta0,period_formula:1,err:lowest,err:formula:1");
    // Written in --columns it would be numbered apart from the --method formulas: refused.
    const auto alone = run_cli("eval --theta0 1 --columns 'theta0,err:formula:1/sqrt(cos(theta0/2))'");
    EXPECT_EQ(alone.status, 2);
    EXPECT_NE(alone.err.find("--columns 'err:formula:1/sqrt(cos(theta0/2))': give the formula with --method"),
              std::string::npos) << alone.err;
    EXPECT_TRUE(alone.out.empty()) << alone.out;
}

TEST(FormulaTrajectory, AFormulaGoesAloneInTheMethodList) {
    // A comma inside the formula's parentheses is its own: one method.
    const auto one = run_cli("trajectory --theta0 1 --method 'formula:besselj(0, t)*theta0' --at 0");
    EXPECT_EQ(one.status, 0) << one.err;
    EXPECT_EQ(one.out, "t_over_T,theta\n0,1\n");
    // Beside another method, before or after it, it is refused, never dropped.
    for (const std::string list : {"exact,formula:theta0*cos(t)", "formula:theta0*cos(t),exact"}) {
        const auto r = run_cli("trajectory --theta0 1 --method '" + list + "' --at 0");
        EXPECT_EQ(r.status, 2) << list;
        EXPECT_NE(r.err.find("a formula goes alone"), std::string::npos) << r.err;
        EXPECT_TRUE(r.out.empty()) << r.out;
    }
}

TEST(FormulaTrajectory, PanelDrawsTheLaw) {
    const auto dir = temp_dir("formula_trajectory");
    write(dir / "t.toml",
          "[[panel]]\nplot = \"trajectory\"\ntheta0 = \"0.9pi\"\n"
          "methods = [\"exact\", { formula = \"theta0*cos(t)\", label = \"harmonic, as a formula\" }]\n");
    const auto r = run_cli("render t.toml -f svg", dir);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(slurp(dir / "t.svg").find("harmonic, as a formula"), std::string::npos);
    write(dir / "s.toml",
          "[[panel]]\nplot = \"trajectory\"\nenergy = [1.0]\nmethods = [\"exact\", { formula = \"theta0*cos(t)\" }]\n");
    const auto s = run_cli("render s.toml -f svg", dir);
    EXPECT_EQ(s.status, 2);
    EXPECT_NE(s.err.find("starts at rest at its amplitude: give the panel theta0"), std::string::npos) << s.err;
    write(dir / "n.toml", "[[panel]]\nplot = \"trajectory\"\ntheta0 = 1.0\nmethods = [{ formula = \"log(-1 - t^2)\" }]\n");
    const auto n = run_cli("render n.toml -f svg", dir);
    EXPECT_EQ(n.status, 2);
    EXPECT_NE(n.err.find("is not finite anywhere on the panel's axis"), std::string::npos) << n.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "n.svg"));
}

TEST(FormulaSpec, NotFiniteSomewhereBreaksTheCurve) {
    const auto dir = temp_dir("formula_partly");
    write(dir / "p.toml",
          "[[panel]]\nplot = \"period\"\nmethods = [\"exact\", { formula = \"1/sqrt(1 - theta0/2)\" }]\n"
          "[[panel]]\nplot = \"period\"\ny = \"error-log\"\nmethods = [{ formula = \"1/sqrt(1 - theta0/2)\" }]\n");
    const auto r = run_cli("render p.toml -f svg", dir);
    EXPECT_EQ(r.status, 0) << r.err;
    // eval: no period where the formula has none (an empty field), and its error empty too.
    const auto e = run_cli("eval --theta0 1,3 --method 'formula:1/sqrt(1 - theta0/2)' --columns theta0");
    ASSERT_EQ(e.status, 0) << e.err;
    const double at_one = 1 / std::sqrt(0.5);
    EXPECT_EQ(e.out.substr(e.out.find('\n') + 1, 2), "1,");
    EXPECT_NE(e.out.find("1," + format_double(at_one) + ","), std::string::npos) << e.out;
    EXPECT_NE(e.out.find("\n3,,\n"), std::string::npos) << e.out;
}
