// SPDX-License-Identifier: GPL-3.0-or-later
#include "figures/toml_reader.hpp"

#include "figures/input_file.hpp"

#include <algorithm>
#include <sstream>

namespace figures {

namespace {

/// Measures how deep the keys of TOML text nest, without parsing it: a key's depth is the
/// depth of the table it is in ([header], or the inline tables and lists around it) plus its
/// dotted parts. Strings (a quoted key's dots) and comments are skipped. Text that is not
/// TOML is only scanned, never refused: toml++ reports it.
class depth_scan {
public:
    depth_scan(std::string_view text, std::size_t most) : t_(text), most_(most) {}

    /// The line and column of the first key nested deeper than the bound, if any.
    std::optional<std::pair<std::size_t, std::size_t>> run() {
        while (pos_ < t_.size() && !deep_ && stack_.size() <= most_) {
            const char c = t_[pos_];
            if (c == '\n') {
                newline();
            } else if (c == '"' || c == '\'') {
                if (key_mode_) start_key();
                skip_string(c);
            } else if (c == '#') {
                while (pos_ < t_.size() && t_[pos_] != '\n') ++pos_;
            } else {
                if (key_mode_) {
                    key_character(c);
                } else {
                    value_character(c);
                }
                ++pos_;
            }
        }
        if (!deep_) return std::nullopt;
        return std::pair{key_line_, key_column_};
    }

private:
    /// An open inline table (keys inside) or list, and the depth of the value it is.
    struct frame {
        bool table;
        std::size_t depth;
    };

    std::size_t base() const {
        if (header_) return 0;
        return stack_.empty() ? table_depth_ : stack_.back().depth;
    }

    void newline() {
        ++pos_;
        ++line_;
        line_start_ = pos_;
        if (!stack_.empty()) return;  // a list goes on over lines
        key_mode_ = true;
        header_ = false;
        line_has_key_ = false;
        begin_key();
    }

    void begin_key() {
        dots_ = 0;
        key_started_ = false;
    }

    void start_key() {
        if (key_started_) return;
        key_started_ = true;
        line_has_key_ = true;
        key_line_ = line_;
        key_column_ = pos_ - line_start_ + 1;
    }

    /// The key read so far is base() + dots + 1 deep.
    std::size_t key_depth() {
        const std::size_t depth = base() + dots_ + 1;
        if (depth > most_) deep_ = true;
        return depth;
    }

    void key_character(char c) {
        switch (c) {
            case ' ': case '\t': case '\r': break;
            case '.': ++dots_; key_depth(); break;
            case '[':
                if (stack_.empty() && !key_started_ && !line_has_key_) {
                    header_ = true;
                    line_has_key_ = true;
                    if (pos_ + 1 < t_.size() && t_[pos_ + 1] == '[') ++pos_;
                    begin_key();
                }
                break;
            case ']':
                if (header_) {
                    table_depth_ = key_depth();
                    header_ = false;
                    begin_key();
                    key_started_ = true;  // the rest of the line holds no key
                }
                break;
            case '=': value_depth_ = key_depth(); key_mode_ = false; break;
            case '}': close('}'); break;
            case ',': begin_key(); break;
            default: start_key();
        }
    }

    void value_character(char c) {
        switch (c) {
            case '[':
                stack_.push_back({false, value_depth_});
                ++value_depth_;
                break;
            case '{':
                stack_.push_back({true, value_depth_});
                key_mode_ = true;
                begin_key();
                break;
            case ']': case '}': close(c); break;
            case ',':
                if (stack_.empty()) break;
                if (stack_.back().table) {
                    key_mode_ = true;
                    begin_key();
                } else {
                    value_depth_ = stack_.back().depth + 1;
                }
                break;
            default: break;
        }
    }

    /// The end of a list (]) or inline table (}): a value of the enclosing list or table.
    void close(char c) {
        if (stack_.empty() || stack_.back().table != (c == '}')) return;
        value_depth_ = stack_.back().depth;
        stack_.pop_back();
        key_mode_ = false;
    }

    void skip_string(char quote) {
        const bool basic = quote == '"';
        if (t_.substr(pos_, 3) == std::string(3, quote)) {
            pos_ += 3;
            while (pos_ < t_.size()) {
                if (t_.substr(pos_, 3) == std::string(3, quote)) {
                    pos_ += 3;
                    for (int extra = 0; extra < 2 && pos_ < t_.size() && t_[pos_] == quote; ++extra) ++pos_;
                    return;
                }
                if (t_[pos_] == '\n') {
                    ++line_;
                    line_start_ = pos_ + 1;
                }
                pos_ += basic && t_[pos_] == '\\' && pos_ + 1 < t_.size() && t_[pos_ + 1] != '\n' ? 2 : 1;
            }
            return;
        }
        for (++pos_; pos_ < t_.size() && t_[pos_] != '\n'; ++pos_) {
            if (t_[pos_] == quote) {
                ++pos_;
                return;
            }
            if (basic && t_[pos_] == '\\' && pos_ + 1 < t_.size() && t_[pos_ + 1] != '\n') ++pos_;
        }
    }

    std::string_view t_;
    std::size_t most_;
    std::size_t pos_ = 0;
    std::size_t line_ = 1;
    std::size_t line_start_ = 0;
    bool key_mode_ = true;
    bool header_ = false;
    bool line_has_key_ = false;
    bool key_started_ = false;
    bool deep_ = false;
    std::size_t dots_ = 0;
    std::size_t table_depth_ = 0;
    std::size_t value_depth_ = 0;
    std::size_t key_line_ = 0;
    std::size_t key_column_ = 0;
    std::vector<frame> stack_;
};

source_position position_of(const std::string& file, const toml::source_region& r) {
    return {file, static_cast<int>(r.begin.line), static_cast<int>(r.begin.column)};
}

/// Checks every key and string under `n` (the value of `key`) with plot::text_problem.
void check_texts(const toml::node& n, const std::string& key, const std::string& file,
                 std::vector<spec_problem>& problems) {
    if (const auto* t = n.as_table()) {
        for (const auto& [k, v] : *t) {
            // Keys are only quoted shortened, so they may be long (a message shows their ends).
            const std::string why = plot::text_problem(k.str(), max_input_file_bytes);
            if (!why.empty()) problems.push_back({position_of(file, k.source()), "a key " + why});
            check_texts(v, why.empty() ? std::string(k.str()) : std::string("a key"), file, problems);
        }
    } else if (const auto* a = n.as_array()) {
        for (const auto& e : *a) check_texts(e, key, file, problems);
    } else if (const auto* s = n.as_string()) {
        if (const std::string why = plot::text_problem(s->get()); !why.empty()) {
            problems.push_back({position_of(file, n.source()), "'" + key + "' " + why});
        }
    }
}

}  // namespace

toml::table parse_toml(std::string_view text, const std::string& file) {
    if (const auto deep = depth_scan(text, max_toml_depth).run()) {
        throw spec_error({{{file, static_cast<int>(deep->first), static_cast<int>(deep->second)},
                           "keys nested more than " + std::to_string(max_toml_depth) +
                               " deep (dotted keys and [table] headers, with the inline tables and lists "
                               "around them)"}});
    }
    toml::table doc = toml::parse(text, file);
    std::vector<spec_problem> problems;
    check_texts(doc, {}, file, problems);
    if (!problems.empty()) {
        std::stable_sort(problems.begin(), problems.end(), [](const spec_problem& a, const spec_problem& b) {
            return std::pair(a.where.line, a.where.column) < std::pair(b.where.line, b.where.column);
        });
        throw spec_error(std::move(problems));
    }
    return doc;
}

std::vector<std::string> words(std::string_view text) {
    std::vector<std::string> out;
    std::istringstream in{std::string(text)};
    for (std::string w; in >> w;) out.push_back(w);
    return out;
}

bool contains(const std::vector<std::string>& names, std::string_view name) {
    return std::find(names.begin(), names.end(), name) != names.end();
}

std::string listed(const std::vector<std::string>& names) {
    std::string out;
    for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
    return out;
}

std::optional<plot::rgb> parse_color(std::string_view text) {
    if (text.size() != 7 || text[0] != '#') return std::nullopt;
    double v[3];
    for (int i = 0; i < 3; ++i) {
        int x = 0;
        for (int j = 1; j <= 2; ++j) {
            const char c = text[static_cast<std::size_t>(2 * i + j)];
            const int d = c >= '0' && c <= '9' ? c - '0' : c >= 'a' && c <= 'f' ? c - 'a' + 10 : c >= 'A' && c <= 'F' ? c - 'A' + 10 : -1;
            if (d < 0) return std::nullopt;
            x = 16 * x + d;
        }
        v[i] = x / 255.0;
    }
    return plot::rgb{v[0], v[1], v[2]};
}

}  // namespace figures
