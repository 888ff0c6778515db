// SPDX-License-Identifier: GPL-3.0-or-later
// The one parser of angles and formulas (expression_parser.hpp): each message of it in both
// languages, its limits at their boundary, hostile texts; and a new file's mode taken from
// the umask without the umask being set.
#include "pendulum/angle.hpp"
#include "pendulum/expression_parser.hpp"
#include "pendulum/formula.hpp"
#include "pendulum/mp_real.hpp"
#include "pendulum/written_mp.hpp"
#include "plot/output.hpp"
#include "grammar_errors.hpp"
#include "process.hpp"

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

namespace {

using test_support::angle_error;
using test_support::formula_error;

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

/// The angle's envelope: the value named, then what an angle may be.
void angle_says(const std::string& text, const std::string& shown, const std::string& why) {
    const std::string e = angle_error(text);
    EXPECT_EQ(e.rfind("invalid value '" + shown + "': " + why + "; expected a number, pi, or an expression such as", 0), 0u)
        << e;
    EXPECT_EQ(pendulum::grammar::invalid_utf8(e), e.size()) << e;
}

}  // namespace

// ---- One message each, in both languages: the value named, what to do.

TEST(Grammar, EachMessageInBothLanguages) {
    struct row {
        std::string text;
        std::string formula;  // the whole formula message
        std::string angle;    // the angle's reason
    };
    const std::vector<row> rows = {
        {"", "formula:1:1: empty formula; write T/T0 in theta0, e.g. 1/sqrt(cos(theta0/2))", "empty value"},
        {"1 +", "formula:1:4: incomplete formula: a number, a name or '(' is missing at the end",
         "incomplete expression: a number, a name or '(' is missing at the end"},
        {"1 + 2)", "formula:1:6: unmatched ')'", "unmatched ')'"},
        {"(1 + 2", "formula:1:7: missing ')' for the '(' at column 1", "missing ')' for the '(' at column 1"},
        {"(1 2)", "formula:1:4: expected ')' or an operator, not '2'", "expected ')' or an operator, not '2'"},
        {"1 $ 2", "formula:1:3: unexpected '$' after a complete expression", "unexpected '$' after a complete expression"},
        {"2 * \u00e9", "formula:1:5: unexpected '\u00e9'; expected a number, a name or '('",
         "unexpected '\u00e9'; expected a number, a name or '('"},
        {".e5", "formula:1:1: '.e5' is not a number", "'.e5' is not a number"},
        {"1e999", "formula:1:1: number 1e999 is beyond a double's range", "number 1e999 is beyond a double's range"},
        {"1 +\x07 2", "formula:1:4: control character \\x07 in a formula", "control character \\x07 in an expression"},
        {"1\x7f", "formula:1:2: control character \\x7f in a formula", "control character \\x7f in an expression"},
        {"1+\xff", "formula:1:3: byte \\xff is not UTF-8; write the formula in UTF-8",
         "byte \\xff is not UTF-8; write the expression in UTF-8"},
        {"1+\xce", "formula:1:3: byte \\xce is not UTF-8; write the formula in UTF-8",
         "byte \\xce is not UTF-8; write the expression in UTF-8"},
        {"\xed\xa0\x80", "formula:1:1: byte \\xed is not UTF-8; write the formula in UTF-8",
         "byte \\xed is not UTF-8; write the expression in UTF-8"},
    };
    for (const auto& r : rows) {
        EXPECT_EQ(formula_error(r.text), r.formula) << r.text;
        std::string shown;
        for (const char c : r.text) {
            const auto u = static_cast<unsigned char>(c);
            if (u < 0x20 || u == 0x7f || (u >= 0x80 && !has(r.text, "\u00e9"))) {
                constexpr char hex[] = "0123456789abcdef";
                shown += std::string("\\x") + hex[u >> 4] + hex[u & 15];
            } else {
                shown += c;
            }
        }
        angle_says(r.text, shown, r.angle);
    }
    // The core's evaluation of an angle, after the parser.
    angle_says("1/(pi-pi)", "1/(pi-pi)", "division by zero");
    angle_says("1e300*1e300", "1e300*1e300", "value is not finite");
}

TEST(Grammar, UnknownNamesAreNamedWithASuggestionAndTheLanguagesNames) {
    EXPECT_EQ(formula_error("1 + sqr(2)").rfind("formula:1:5: unknown name 'sqr'; did you mean 'sqrt'? (names: theta0 or "
                                                "\u03b80, t, pi or \u03c0; functions: sqrt, ",
                                                0),
              0u);
    EXPECT_TRUE(has(formula_error("1 + sqr(2)"), "besselj(n, x) (ellipk and ellipe take the parameter m = k^2))"));
    angle_says("2pj", "2pj", "unknown name 'pj'; did you mean 'pi'? (names: pi or \u03c0; units at the end: deg or \u00b0, rad)");
    angle_says("90 dge", "90 dge", "unknown name 'dge'; did you mean 'deg'? (names: pi or \u03c0; units at the end: deg or \u00b0, rad)");
    // A unit is an angle's, not an expression's nor a formula's.
    EXPECT_EQ(pendulum::parse_angle("180deg"), pendulum::parse_angle("pi"));
    EXPECT_TRUE(has(formula_error("180deg"), "formula:1:4: unknown name 'deg'"));
    EXPECT_TRUE(has([] {
        try {
            (void)pendulum::parse_expression("180deg");
        } catch (const pendulum::domain_error& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    }(), "unknown name 'deg' (names: pi or \u03c0)"));
    // A name that is a control sequence is shown escaped (it never reaches the name check).
    EXPECT_EQ(formula_error("sqrt\x1b[2J(1)"), "formula:1:5: control character \\x1b in a formula");
}

// ---- The rows: what each language reads, through the one parser.

TEST(Grammar, BothLanguagesReadTheirRowsAlike) {
    for (const char* text : {"2pi/3", "-pi/2", "9pi/10", "0.99pi", "pi - 1e-9", "2*(1+3)/4", "--1", "+-+1", "2 (3)"}) {
        EXPECT_DOUBLE_EQ(pendulum::parse_expression(text), pendulum::formula(text).value(0)) << text;  // doubles round each step
    }
    EXPECT_DOUBLE_EQ(pendulum::parse_angle("120deg"), 2 * pendulum::parse_angle("pi") / 3);
    EXPECT_EQ(pendulum::parse_angle("\u03c0rad"), pendulum::parse_angle("pi"));
    EXPECT_EQ(pendulum::parse_angle("180\u00b0"), pendulum::parse_angle("pi"));
    // ^ is the formula's row only: right-associative, tighter than a sign.
    EXPECT_EQ(pendulum::formula("2^3^2").value(0), 512.0);
    EXPECT_EQ(pendulum::formula("-2^2").value(0), -4.0);
    EXPECT_EQ(pendulum::formula("2^-1*4").value(0), 2.0);
    EXPECT_TRUE(has(angle_error("2^3"), "unexpected '^' after a complete expression"));
    EXPECT_EQ(pendulum::formula("\u03c0\u03b80").value(2), 2 * pendulum::parse_angle("pi"));
}

TEST(Grammar, AnglePiecesAreTheParsersLexemes) {
    using k = pendulum::angle_token::kind;
    const auto t = pendulum::angle_tokens("-(2.50e-03 + pi) * 3/\u03c0 deg");
    const std::vector<k> want = {k::sign_minus, k::open, k::number, k::plus, k::pi, k::close,
                                 k::times, k::number, k::divide, k::pi, k::degrees};
    ASSERT_EQ(t.size(), want.size());
    for (std::size_t i = 0; i < want.size(); ++i) EXPECT_EQ(t[i].type, want[i]) << i;
    EXPECT_EQ(t[2].mantissa, "2.50");
    EXPECT_EQ(t[2].exponent, "3");
    EXPECT_TRUE(t[2].negative_exponent);
    EXPECT_EQ(pendulum::angle_tokens("2pi rad").back().type, k::radians);
    EXPECT_THROW(pendulum::angle_tokens("1/(pi-pi)"), pendulum::domain_error);
}

TEST(Grammar, WrittenNumbersKeepEveryDigit) {
    // pi - 1e-300 reaches the core as written: its distance from pi is 1e-300, not 0.
    const auto w = pendulum::written_number::angle("pi-1e-300");
    const mpfr_prec_t bits = 2048;
    const auto d = pendulum::mp::pi(bits) - pendulum::evaluate_written(w, bits);
    EXPECT_EQ(d.to_double(), 1e-300);
    EXPECT_FALSE(w.exact_double());
    EXPECT_TRUE(pendulum::written_number::expression("2/2").exact_double());
    const auto a = pendulum::parse_amplitude("pi - 1e-300");
    EXPECT_EQ(a.from_pi(), 1e-300);
}

// ---- The limits: N accepted, N + 1 refused with its message.

TEST(Grammar, AngleDepthAtItsBoundary) {
    const int n = pendulum::grammar::max_angle_depth;
    const auto nested = [](int depth) {
        return std::string(static_cast<std::size_t>(depth), '(') + "1" + std::string(static_cast<std::size_t>(depth), ')');
    };
    EXPECT_EQ(pendulum::parse_angle(nested(n)), 1.0);
    EXPECT_TRUE(has(angle_error(nested(n + 1)), "nested too deeply (at most 250 levels of parentheses and signs)"))
        << angle_error(nested(n + 1)).substr(0, 200);
    EXPECT_EQ(pendulum::parse_angle(std::string(static_cast<std::size_t>(n), '-') + "1"), 1.0);
    EXPECT_TRUE(has(angle_error(std::string(static_cast<std::size_t>(n + 1), '-') + "1"), "nested too deeply"));
    // Levels are counted alike in a formula.
    EXPECT_EQ(formula_error(std::string(pendulum::max_formula_depth, '-') + "1"), "accepted");
    EXPECT_EQ(formula_error(std::string(pendulum::max_formula_depth + 1, '-') + "1"),
              "formula:1:65: nested too deeply (at most 64 levels of parentheses, calls, signs and exponents)");
}

TEST(Grammar, OneMebibyteTexts) {
    const std::size_t mib = 1 << 20;
    // A sum of a mebibyte is evaluated without recursion (the tree is read as a stack machine).
    std::string sum = "1";
    while (sum.size() + 2 <= mib) sum += "+1";
    const auto start = std::chrono::steady_clock::now();
    EXPECT_EQ(pendulum::parse_expression(sum), static_cast<double>(sum.size() / 2 + 1));
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 20.0);
    // Nesting of a mebibyte stops at the bound, and the message shows the value by its ends.
    const std::string deep = std::string(mib / 2, '(') + "1" + std::string(mib / 2, ')');
    const std::string e = angle_error(deep);
    EXPECT_TRUE(has(e, "nested too deeply")) << e.substr(0, 200);
    EXPECT_LT(e.size(), 400u);
    // A formula takes at most its bytes.
    EXPECT_EQ(formula_error(sum).rfind("formula:1:1001: a formula takes at most 1000 bytes, this one has 1048575", 0), 0u);
    // A mebibyte of digits is one number.
    EXPECT_EQ(pendulum::parse_expression("0." + std::string(mib, '3')), 1.0 / 3);
}

// ---- A new file's mode: 0666 less the umask, the umask never set to read it.

TEST(GrammarUmask, NewFilesFollowTheUmaskAsItIsNow) {
    const auto dir = test_support::temp_dir("grammar_umask");
    const mode_t before = ::umask(077);
    plot::write_atomically(dir / "a.txt", "a");
    ::umask(027);
    plot::write_atomically(dir / "b.txt", "b");
    ::umask(before);
    struct stat st {};
    ASSERT_EQ(::stat((dir / "a.txt").c_str(), &st), 0);
    EXPECT_EQ(st.st_mode & 0777, 0600u);
    ASSERT_EQ(::stat((dir / "b.txt").c_str(), &st), 0);
    EXPECT_EQ(st.st_mode & 0777, 0640u);
    // A file that is replaced keeps its mode.
    ASSERT_EQ(::chmod((dir / "a.txt").c_str(), 0604), 0);
    plot::write_atomically(dir / "a.txt", "again");
    ASSERT_EQ(::stat((dir / "a.txt").c_str(), &st), 0);
    EXPECT_EQ(st.st_mode & 0777, 0604u);
}

TEST(GrammarUmask, AnotherThreadsFilesKeepTheirUmask) {
    const auto dir = test_support::temp_dir("grammar_umask_threads");
    const mode_t before = ::umask(077);
    std::atomic<bool> done{false};
    std::atomic<int> wrong{0};
    std::thread other([&] {
        for (int i = 0; !done.load() || i < 200; ++i) {
            const auto p = dir / ("other" + std::to_string(i % 50));
            const int fd = ::open(p.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0666);
            if (fd < 0) continue;
            struct stat st {};
            if (::fstat(fd, &st) == 0 && (st.st_mode & 0777) != 0600) ++wrong;
            ::close(fd);
            ::unlink(p.c_str());
        }
    });
    for (int i = 0; i < 200; ++i) plot::write_atomically(dir / ("mine" + std::to_string(i)), "x");
    done = true;
    other.join();
    ::umask(before);
    EXPECT_EQ(wrong.load(), 0);
}

// ---- An input that cannot be read is bad input (exit 2), named, without a catch to convert it.

TEST(GrammarRethrow, AnUnreadableSpecOrStyleIsBadInput) {
    // /proc/self/mem is a regular file whose first byte cannot be read (EIO), even by root.
    const auto dir = test_support::temp_dir("grammar_unreadable");
    std::filesystem::create_symlink("/proc/self/mem", dir / "mem.toml");
    const auto spec = test_support::run_cli("render '" + (dir / "mem.toml").string() + "' -o '" + dir.string() + "'");
    EXPECT_EQ(spec.status, 2) << spec.err;
    EXPECT_TRUE(has(spec.err, "cannot read spec file '" + (dir / "mem.toml").string() + "'")) << spec.err;
    const auto style = test_support::run_cli("render c1-lowest --theme '" + (dir / "mem.toml").string() + "' -o '" +
                                             dir.string() + "'");
    EXPECT_EQ(style.status, 2) << style.err;
    EXPECT_TRUE(has(style.err, "cannot read style file")) << style.err;
    EXPECT_TRUE(test_support::files_in(dir).size() == 1u);  // nothing written but the link
}
