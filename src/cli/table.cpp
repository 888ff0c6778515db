// SPDX-License-Identifier: GPL-3.0-or-later
#include "cli/table.hpp"

#include "pendulum/amplitude.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace pendulum::cli {

table_format parse_table_format(std::string_view text) {
    if (text == "csv") return table_format::csv;
    if (text == "json") return table_format::json;
    throw std::invalid_argument("unknown format '" + std::string(text) + "'; use csv or json");
}

table_writer::table_writer(std::ostream& out, std::vector<std::string> columns, table_format format)
    : out_(out), columns_(std::move(columns)), format_(format) {
    if (format_ == table_format::csv) {
        for (std::size_t i = 0; i < columns_.size(); ++i) out_ << (i ? "," : "") << columns_[i];
        out_ << '\n';
    } else {
        out_ << "[";
    }
}

void table_writer::row(const std::vector<double>& values) {
    if (format_ == table_format::csv) {
        // A value that does not exist (the iteration's breakdown) is an empty field.
        for (std::size_t i = 0; i < values.size(); ++i) {
            out_ << (i ? "," : "") << (std::isfinite(values[i]) ? format_double(values[i]) : "");
        }
        out_ << '\n';
    } else {
        out_ << (rows_ ? ",\n " : "\n ") << "{";
        for (std::size_t i = 0; i < columns_.size() && i < values.size(); ++i) {
            const double v = values[i];
            out_ << (i ? ", " : "") << '"' << columns_[i] << "\": " << (std::isfinite(v) ? format_double(v) : "null");
        }
        out_ << "}";
    }
    ++rows_;
}

void table_writer::finish() {
    if (format_ == table_format::json) out_ << (rows_ ? "\n]\n" : "]\n");
}

void write_table(std::ostream& out, const table& t, table_format format) {
    table_writer w(out, t.columns, format);
    for (const auto& row : t.rows) w.row(row);
    w.finish();
}

namespace {

std::string csv_quoted(const std::string& text) {
    if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
    std::string out = "\"";
    for (const char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
}

std::string json_quoted(const std::string& text) {
    std::string out = "\"";
    for (const char c : text) {
        if (c == '"' || c == '\\') {
            out += '\\';
            out += c;
        } else if (static_cast<unsigned char>(c) < 0x20) {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned char>(c));
            out += buf;
        } else {
            out += c;
        }
    }
    return out + "\"";
}

std::string number_text(double v, table_format format) {
    if (std::isfinite(v)) return format_double(v);
    return format == table_format::json ? "null" : "";
}

}  // namespace

void write_records(std::ostream& out, const std::vector<std::string>& columns,
                   const std::vector<std::vector<field>>& rows, table_format format) {
    if (format == table_format::csv) {
        for (std::size_t i = 0; i < columns.size(); ++i) out << (i ? "," : "") << csv_quoted(columns[i]);
        out << '\n';
        for (const auto& row : rows) {
            for (std::size_t i = 0; i < row.size(); ++i) {
                out << (i ? "," : "");
                if (const auto* text = std::get_if<std::string>(&row[i])) {
                    out << csv_quoted(*text);
                } else {
                    out << number_text(std::get<double>(row[i]), format);
                }
            }
            out << '\n';
        }
        return;
    }
    out << "[";
    for (std::size_t r = 0; r < rows.size(); ++r) {
        out << (r ? ",\n " : "\n ") << "{";
        for (std::size_t i = 0; i < columns.size() && i < rows[r].size(); ++i) {
            out << (i ? ", " : "") << json_quoted(columns[i]) << ": ";
            if (const auto* text = std::get_if<std::string>(&rows[r][i])) {
                out << json_quoted(*text);
            } else {
                out << number_text(std::get<double>(rows[r][i]), format);
            }
        }
        out << "}";
    }
    out << (rows.empty() ? "]\n" : "\n]\n");
}

}  // namespace pendulum::cli
