// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One reader for the core's two expression languages: an angle (angle.cpp: numbers, pi,
// + - * /, a unit at the end) and a formula (formula.cpp: names, functions and ^ besides).
// What a language allows is rows of its table (names, functions, operators, units, limits);
// the parser is one precedence climber over those rows, so a new operator, function or unit
// is one row. The grammar, for every language (lowest binding first):
//   text    = expr [ unit ]
//   expr    = operand { operator expr' }        (each operator row binds as its row says)
//   operand = sign operand | primary { primary } (a primary right after one multiplies: "2pi")
//   primary = number | name | function "(" expr { "," expr } ")" | "(" expr ")"
// "-2^2" is -(2^2) as in maths; "^" is right-associative. For the core only, not installed.

#include "pendulum/formula.hpp"

#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace pendulum::grammar {

using op = formula_node::op;

/// The most levels of parentheses and signs an angle or expression nests (deeper is no angle
/// anyone types, and would only exhaust the stack).
inline constexpr int max_angle_depth = 250;

/// A variable or constant a language knows by name.
struct name_row {
    std::string_view name;  ///< as written
    op what;                ///< the leaf it reads as
};

/// A function a language may call.
struct function_row {
    std::string_view name;     ///< as written
    op what;                   ///< the node it reads as
    int arguments;             ///< how many it takes
    std::string_view shown;    ///< its arguments as help writes them ("(n, x)"), or empty
    bool order_first = false;  ///< the first argument is a constant whole order (besselj)
};

/// A binary operator: higher binding binds tighter; a sign binds at sign_binding.
struct operator_row {
    char symbol;  ///< as written
    op what;      ///< the node it reads as
    int binding;  ///< its precedence
    bool right;   ///< right-associative (^)
};

/// The binding of a sign (unary + and -): tighter than * and /, looser than ^.
inline constexpr int sign_binding = 3;
/// The binding of a product without a sign ("2pi", "3(x)"), as * has.
inline constexpr int implicit_binding = 2;

/// What a unit at the end of a text stands for.
enum class unit { none, degrees, radians };

/// A unit that may end a text.
struct unit_row {
    std::string_view name;  ///< as written
    unit what;              ///< what it stands for
};

/// A language: its rows, its limits and the words of its messages.
struct language {
    std::span<const name_row> names;          ///< variables and constants
    std::span<const function_row> functions;  ///< functions
    std::span<const operator_row> operators;  ///< binary operators
    std::span<const unit_row> units;          ///< units that may end the text
    std::size_t max_bytes;                    ///< the text's length
    int max_depth;                            ///< nesting of parentheses, calls, signs and powers
    std::size_t max_nodes;                    ///< numbers, names, operations and calls
    int max_order;                            ///< |n| of an order_first argument
    std::string_view noun;                    ///< "formula", "expression"
    std::string_view a_noun;                  ///< with its article: "a formula", "an expression"
    std::string_view nesting;                 ///< what a level of nesting is, for the message
    std::string_view empty;                   ///< the message for an empty text
    std::string_view functions_note;          ///< said after the list of functions, or empty
    /// The whole message for `why` at byte `at` of `text`, which the parser throws as a domain_error.
    std::string (*message)(std::string_view text, std::size_t at, const std::string& why);
    /// The double value of a constant node (an order_first argument); null where no row needs it.
    double (*constant)(const std::vector<formula_node>& nodes, int i);
};

/// One piece of a text as the parser reads it, in order.
struct lexeme {
    /// What the piece is.
    enum class kind { number, name, unit, binary, sign, open, close, comma };
    kind type;              ///< what it is
    std::string_view text;  ///< the piece as written
};

/// A text read: its tree (children before parents, root last), its unit and whether it uses t.
struct tree {
    std::vector<formula_node> nodes;  ///< the tree, root last
    unit what = unit::none;           ///< the unit at the end, if any
    bool uses_t = false;              ///< a name reading as op::t occurs
};

/// Reads `text` in `lang`; throws domain_error with lang.message. Where `lexemes` is given,
/// the pieces are recorded there in order.
tree parse(std::string_view text, const language& lang, std::vector<lexeme>* lexemes = nullptr);

/// The names a language knows, for a message: "theta0 or θ0, t, pi or π" (rows reading as
/// the same leaf joined by "or").
std::string names_of(const language& lang);

/// The units a language knows, for a message: "deg or °, rad".
std::string units_of(const language& lang);

/// The functions a language knows, for a message: "sqrt, exp, ..., besselj(n, x)".
std::string functions_of(const language& lang);

/// The first byte that is not valid UTF-8 in text, or text.size().
std::size_t invalid_utf8(std::string_view text);

}  // namespace pendulum::grammar
