// SPDX-License-Identifier: GPL-3.0-or-later
// A formula's tree written as TeX math, for the default label of a user's formula: the
// text stays the formula; this is only how it reads.
#include "pendulum/formula.hpp"

#include <string>

namespace pendulum {

namespace {

using op = formula_node::op;

/// How tightly a node binds, for the parentheses its parent needs around it.
enum class binding { sum = 1, product = 2, sign = 3, power = 4, atom = 5 };

binding binding_of(op what) {
    switch (what) {
        case op::add:
        case op::sub: return binding::sum;
        case op::mul:
        case op::div: return binding::product;
        case op::neg: return binding::sign;
        case op::pow: return binding::power;
        default: return binding::atom;
    }
}

/// The name TeX sets for a function of one argument in parentheses, or empty.
std::string function_name(op what) {
    switch (what) {
        case op::exp: return "\\exp";
        case op::log: return "\\ln";
        case op::sin: return "\\sin";
        case op::cos: return "\\cos";
        case op::tan: return "\\tan";
        case op::asin: return "\\arcsin";
        case op::acos: return "\\arccos";
        case op::atan: return "\\arctan";
        case op::sinh: return "\\sinh";
        case op::cosh: return "\\cosh";
        case op::tanh: return "\\tanh";
        case op::ellipk: return "K";
        case op::ellipe: return "E";
        default: return {};
    }
}

/// A number as written, its exponent as a power of ten: 1.5e-3 is 1.5 \times 10^{-3}.
std::string number_tex(const std::string& digits) {
    const auto e = digits.find_first_of("eE");
    if (e == std::string::npos) return digits;
    std::string exponent = digits.substr(e + 1);
    if (!exponent.empty() && exponent.front() == '+') exponent.erase(0, 1);
    return digits.substr(0, e) + " \\times 10^{" + exponent + "}";
}

class tex_writer {
public:
    explicit tex_writer(const std::vector<formula_node>& nodes) : nodes_(nodes) {}

    std::string of(int i) const {
        const formula_node& n = node(i);
        switch (n.what) {
            case op::number: return number_tex(n.digits);
            case op::pi: return "\\pi";
            case op::theta0: return "\\theta_0";
            case op::t: return "t";
            case op::add: return of(n.a) + " + " + operand(n.b, binding::product);
            case op::sub: return of(n.a) + " - " + operand(n.b, binding::product);
            case op::mul: return product(n);
            case op::div: return "\\frac{" + of(n.a) + "}{" + of(n.b) + "}";
            case op::neg: return "-" + operand(n.a, binding::power);
            case op::pow: return operand(n.a, binding::atom) + "^{" + of(n.b) + "}";
            case op::sqrt: return "\\sqrt{" + of(n.a) + "}";
            case op::abs: return "\\left|" + of(n.a) + "\\right|";
            case op::agm: return "\\mathrm{agm}(" + of(n.a) + ", " + of(n.b) + ")";
            case op::besselj: return "J_{" + std::to_string(n.order) + "}(" + of(n.a) + ")";
            default: return function_name(n.what) + "(" + of(n.a) + ")";
        }
    }

private:
    const formula_node& node(int i) const { return nodes_[static_cast<std::size_t>(i)]; }

    /// Node i in parentheses where it binds less tightly than `least`.
    std::string operand(int i, binding least) const {
        const std::string t = of(i);
        return binding_of(node(i).what) < least ? "(" + t + ")" : t;
    }

    /// a b with a thin space; a \cdot b where b starts with a digit or a sign (2 \cdot 3).
    std::string product(const formula_node& n) const {
        const std::string right = operand(n.b, binding::power);
        const char first = right.empty() ? ' ' : right.front();
        const bool dot = (first >= '0' && first <= '9') || first == '-' || first == '.';
        return operand(n.a, binding::product) + (dot ? " \\cdot " : "\\,") + right;
    }

    const std::vector<formula_node>& nodes_;
};

}  // namespace

std::string formula_tex(const formula& f) {
    if (f.nodes().empty()) return {};
    return tex_writer(f.nodes()).of(static_cast<int>(f.nodes().size()) - 1);
}

}  // namespace pendulum
