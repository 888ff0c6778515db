// SPDX-License-Identifier: GPL-3.0-or-later
#include "plot/math_layout.hpp"

#include <string_view>

namespace plot {

namespace {

/// The end of the element whose content starts at `from`: the position of its "</tag>",
/// past any element of the same tag nested in it (a subscript of a subscript).
std::size_t closing(const std::string& s, std::size_t from, const std::string& tag) {
    const std::string open = "<" + tag + ">";
    const std::string close = "</" + tag + ">";
    int depth = 0;
    for (std::size_t i = from; i < s.size();) {
        if (s.compare(i, open.size(), open) == 0) {
            ++depth;
            i += open.size();
        } else if (s.compare(i, close.size(), close) == 0) {
            if (depth == 0) return i;
            --depth;
            i += close.size();
        } else {
            ++i;
        }
    }
    return std::string::npos;
}

}  // namespace

namespace {

/// Builds the pieces of split_scripts: the depth of elements other than top-level scripts,
/// and whether the last thing read was a script.
class script_splitter {
public:
    explicit script_splitter(const std::string& markup) : markup_(markup) {}

    std::vector<math_piece> run() {
        while (i_ < markup_.size()) {
            if (markup_[i_] != '<') {
                base_text(markup_.substr(i_, 1));
                ++i_;
                continue;
            }
            const std::size_t end = markup_.find('>', i_);
            if (end == std::string::npos) {  // not markup; Pango reports it
                pieces_.back().base += markup_.substr(i_);
                break;
            }
            const std::string tag = markup_.substr(i_ + 1, end - i_ - 1);
            if (!script(tag, end)) element(tag, end);
        }
        return std::move(pieces_);
    }

private:
    /// Text (or a tag) on the baseline: after a script it starts a new piece.
    void base_text(const std::string& text) {
        if (after_script_) pieces_.emplace_back();
        after_script_ = false;
        pieces_.back().base += text;
    }

    /// A top-level <sup> or <sub> whose tag ends at `end`: true if taken as a script.
    bool script(const std::string& tag, std::size_t end) {
        if (depth_ != 0 || (tag != "sup" && tag != "sub")) return false;
        const std::size_t close = closing(markup_, end + 1, tag);
        if (close == std::string::npos) return false;
        const bool is_sup = tag == "sup";
        // A second script of the same kind starts a new piece with an empty base.
        if (after_script_ && (is_sup ? pieces_.back().has_sup : pieces_.back().has_sub)) pieces_.emplace_back();
        math_piece& p = pieces_.back();
        (is_sup ? p.sup : p.sub) = markup_.substr(end + 1, close - end - 1);
        (is_sup ? p.has_sup : p.has_sub) = true;
        after_script_ = true;
        i_ = close + tag.size() + 3;
        return true;
    }

    /// Any other element's tag, ending at `end`: part of the base, counted in the depth.
    void element(const std::string& tag, std::size_t end) {
        if (!tag.empty() && tag[0] == '/') {
            --depth_;
        } else if (tag.empty() || tag.back() != '/') {
            ++depth_;
        }
        base_text(markup_.substr(i_, end - i_ + 1));
        i_ = end + 1;
    }

    const std::string& markup_;
    std::vector<math_piece> pieces_ = std::vector<math_piece>(1);
    std::size_t i_ = 0;
    int depth_ = 0;  // open elements other than top-level scripts
    bool after_script_ = false;
};

}  // namespace

std::vector<math_piece> split_scripts(const std::string& markup) { return script_splitter(markup).run(); }

std::size_t combining_marks_at(const std::string& s, std::size_t pos) {
    std::size_t end = pos;
    for (;;) {
        const auto byte = [&](std::size_t k) { return end + k < s.size() ? static_cast<unsigned char>(s[end + k]) : 0; };
        if ((byte(0) == 0xcc && byte(1) >= 0x80 && byte(1) <= 0xbf) || (byte(0) == 0xcd && byte(1) >= 0x80 && byte(1) <= 0xaf)) {
            end += 2;
        } else if (byte(0) == 0xe2 && byte(1) == 0x83 && byte(2) >= 0x90 && byte(2) <= 0xbf) {
            end += 3;
        } else {
            return end - pos;
        }
    }
}

namespace {

/// Builds the pieces of split_accents: the elements open at the cursor, and the run so far.
class accent_splitter {
public:
    std::vector<accent_piece> run(const std::string& markup) {
        for (std::size_t i = 0; i < markup.size();) {
            i = markup[i] == '<' ? tag(markup, i) : character(markup, i);
        }
        // The rest as the markup leaves it: an element left open stays open, for Pango to report.
        if (has_text_) pieces_.push_back({text_, {}});
        return std::move(pieces_);
    }

private:
    /// An element's start or end at markup[i]; returns the position after it.
    std::size_t tag(const std::string& markup, std::size_t i) {
        const std::size_t end = markup.find('>', i);
        if (end == std::string::npos) {  // not markup; Pango reports it
            text_ += markup.substr(i);
            has_text_ = true;
            return markup.size();
        }
        const std::string whole = markup.substr(i, end - i + 1);
        text_ += whole;
        if (whole.size() > 2 && whole[1] == '/') {
            if (!open_.empty()) open_.pop_back();
        } else if (whole[whole.size() - 2] != '/') {
            open_.push_back(whole);
        }
        return end + 1;
    }

    /// A character (or entity) at markup[i] and the combining marks after it.
    std::size_t character(const std::string& markup, std::size_t i) {
        std::size_t end = i + 1;
        if (markup[i] == '&') {
            const std::size_t semicolon = markup.find(';', i);
            end = semicolon == std::string::npos ? markup.size() : semicolon + 1;
        } else {
            while (end < markup.size() && (static_cast<unsigned char>(markup[end]) & 0xc0) == 0x80) ++end;
        }
        const std::size_t marks = combining_marks_at(markup, end);
        if (marks == 0 || (end - i == 1 && markup[i] == ' ')) {
            text_ += markup.substr(i, end + marks - i);
            has_text_ = true;
            return end + marks;
        }
        cut();
        text_ = opened() + markup.substr(i, end - i);
        has_text_ = true;
        cut(markup.substr(end, marks));
        return end + marks;
    }

    std::string opened() const {
        std::string out;
        for (const auto& t : open_) out += t;
        return out;
    }

    std::string closed() const {
        std::string out;
        for (auto it = open_.rbegin(); it != open_.rend(); ++it) {
            const std::size_t name_end = it->find_first_of(" >");
            out += "</" + it->substr(1, name_end - 1) + ">";
        }
        return out;
    }

    /// Ends the current piece (kept if it has text) and starts the next inside the open elements.
    void cut(const std::string& mark = {}) {
        if (has_text_) pieces_.push_back({text_ + closed(), mark});
        text_ = opened();
        has_text_ = false;
    }

    std::vector<accent_piece> pieces_;
    std::vector<std::string> open_;  // the start tags of the elements open here
    std::string text_;
    bool has_text_ = false;
};

}  // namespace

std::vector<accent_piece> split_accents(const std::string& markup) { return accent_splitter().run(markup); }

namespace {

/// The end of the element whose start tag ends just before `from`: the position of the end
/// tag that closes it, past the elements nested in it; npos if it is not closed.
std::size_t element_end(const std::string& s, std::size_t from) {
    int depth = 0;
    for (std::size_t i = s.find('<', from); i != std::string::npos; i = s.find('<', i + 1)) {
        const std::size_t end = s.find('>', i);
        if (end == std::string::npos) return std::string::npos;
        if (s[i + 1] == '/') {
            if (depth == 0) return i;
            --depth;
        } else if (s[end - 1] != '/') {
            ++depth;
        }
        i = end;
    }
    return std::string::npos;
}

/// A fraction's parts as tex_to_markup writes them: <frac> or <dfrac>, then <num> (<pnum>
/// for a part that needs parentheses in line) and <den> (<pden>).
struct fraction_element {
    std::string num, den;
    bool num_paren = false, den_paren = false, display = false;
    std::size_t end = std::string::npos;  // past the closing tag; npos: not a fraction
};

/// One part of a fraction starting at s[i]: its tag's name is `name` or "p" + `name`.
bool fraction_part(const std::string& s, std::size_t& i, const std::string& name, std::string& text, bool& paren) {
    paren = s.compare(i, name.size() + 3, "<p" + name + ">") == 0;
    const std::string open = paren ? "<p" + name + ">" : "<" + name + ">";
    if (s.compare(i, open.size(), open) != 0) return false;
    const std::size_t close = element_end(s, i + open.size());
    if (close == std::string::npos || s.compare(close, open.size() + 1, "</" + open.substr(1)) != 0) return false;
    text = s.substr(i + open.size(), close - i - open.size());
    i = close + open.size() + 1;
    return true;
}

fraction_element fraction_at(const std::string& s, std::size_t i) {
    fraction_element f;
    f.display = s.compare(i, 7, "<dfrac>") == 0;
    if (!f.display && s.compare(i, 6, "<frac>") != 0) return f;
    const std::string close = f.display ? "</dfrac>" : "</frac>";
    std::size_t at = i + close.size() - 1;
    if (!fraction_part(s, at, "num", f.num, f.num_paren) || !fraction_part(s, at, "den", f.den, f.den_paren) ||
        s.compare(at, close.size(), close) != 0) {
        return f;
    }
    f.end = at + close.size();
    return f;
}

constexpr std::string_view overline_tag = "<span overline=\"single\">";
constexpr std::string_view root_sign = "\u221a";

/// A radical (\u221a and an overlined span) or an overline alone at markup[i]: the piece,
/// and the position past it; npos if there is none.
std::size_t radical_at(const std::string& markup, std::size_t i, box_piece& piece) {
    const bool sign = markup.compare(i, root_sign.size(), root_sign) == 0;
    const std::size_t tag = sign ? i + root_sign.size() : i;
    if (markup.compare(tag, overline_tag.size(), overline_tag) != 0) return std::string::npos;
    const std::size_t from = tag + overline_tag.size();
    const std::size_t close = element_end(markup, from);
    if (close == std::string::npos) return std::string::npos;
    piece = box_piece{};
    piece.type = box_piece::kind::radical;
    piece.text = markup.substr(from, close - from);
    piece.sign = sign;
    return close + std::string_view("</span>").size();
}

}  // namespace

std::vector<box_piece> split_boxes(const std::string& markup) {
    std::vector<box_piece> out;
    std::string run;
    box_piece radical;
    int depth = 0;
    const auto flush = [&] {
        if (run.empty()) return;
        box_piece p;
        p.text = run;
        out.push_back(std::move(p));
        run.clear();
    };
    for (std::size_t i = 0; i < markup.size();) {
        if (depth == 0) {
            if (const fraction_element f = fraction_at(markup, i); f.end != std::string::npos) {
                flush();
                box_piece p;
                p.type = box_piece::kind::fraction;
                p.num = f.num;
                p.den = f.den;
                p.display = f.display;
                out.push_back(std::move(p));
                i = f.end;
                continue;
            }
            if (const std::size_t end = radical_at(markup, i, radical); end != std::string::npos) {
                flush();
                out.push_back(std::move(radical));
                i = end;
                continue;
            }
        }
        if (markup[i] == '<') {
            const std::size_t end = markup.find('>', i);
            if (end == std::string::npos) {  // not markup; Pango reports it
                run += markup.substr(i);
                break;
            }
            if (markup[i + 1] == '/') {
                --depth;
            } else if (markup[end - 1] != '/') {
                ++depth;
            }
            run += markup.substr(i, end - i + 1);
            i = end + 1;
            continue;
        }
        run += markup[i++];
    }
    flush();
    return out;
}

std::string inline_fractions(const std::string& markup) {
    if (markup.find("frac>") == std::string::npos) return markup;
    std::string out;
    for (std::size_t i = 0; i < markup.size();) {
        const fraction_element f = markup[i] == '<' ? fraction_at(markup, i) : fraction_element{};
        if (f.end == std::string::npos) {
            out += markup[i++];
            continue;
        }
        const auto part = [](const std::string& s, bool paren) {
            const std::string in = inline_fractions(s);
            return paren ? "(" + in + ")" : in;
        };
        out += part(f.num, f.num_paren) + "/" + part(f.den, f.den_paren);
        i = f.end;
    }
    return out;
}

std::size_t italic_after_slash(const std::string& markup) {
    int depth = 0;
    for (std::size_t i = 0; i < markup.size(); ++i) {
        if (markup[i] == '/' && depth == 0 && markup.compare(i + 1, 3, "<i>") == 0) return i + 1;
        if (markup[i] != '<') continue;
        const std::size_t end = markup.find('>', i);
        if (end == std::string::npos) return std::string::npos;
        if (markup[i + 1] == '/') {
            --depth;
        } else if (markup[end - 1] != '/') {
            ++depth;
        }
        i = end;
    }
    return std::string::npos;
}

bool has_boxes(const std::string& markup) {
    return markup.find("frac>") != std::string::npos || markup.find(overline_tag) != std::string::npos;
}

bool only_primes(const std::string& markup) {
    if (markup.empty()) return false;
    for (std::size_t i = 0; i < markup.size();) {
        if (markup.compare(i, 2, "\u02b9") == 0) {
            i += 2;
        } else if (markup.compare(i, 3, "\u2032") == 0 || markup.compare(i, 3, "\u2033") == 0 ||
                   markup.compare(i, 3, "\u2034") == 0) {
            i += 3;
        } else {
            return false;
        }
    }
    return true;
}

}  // namespace plot
