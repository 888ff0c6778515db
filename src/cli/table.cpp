// SPDX-License-Identifier: GPL-3.0-or-later
#include "cli/table.hpp"

#include "cli/errors.hpp"
#include "pendulum/amplitude.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string_view>

namespace pendulum::cli {

table_format parse_table_format(std::string_view text) {
    if (text == "csv") return table_format::csv;
    if (text == "json") return table_format::json;
    throw usage_error("unknown format '" + std::string(text) + "'; use csv or json");
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

/// A number as a field: a value that does not exist (the iteration's breakdown) is an empty
/// CSV field or JSON null.
std::string cell(double v, table_format format) {
    if (std::isfinite(v)) return format_double(v);
    return format == table_format::json ? "null" : "";
}

std::string cell(const field& v, table_format format) {
    if (const auto* text = std::get_if<std::string>(&v)) {
        // A text a spreadsheet would take for a formula gets a single quote before it.
        const bool formula = !text->empty() && std::string_view("=+-@\t\r").find(text->front()) != std::string_view::npos;
        return format == table_format::csv ? csv_quoted(formula ? "'" + *text : *text) : json_quoted(*text);
    }
    return cell(std::get<double>(v), format);
}

}  // namespace

table_writer::table_writer(std::ostream& out, std::vector<std::string> columns, table_format format)
    : out_(out), format_(format) {
    if (format_ == table_format::csv) {
        for (std::size_t i = 0; i < columns.size(); ++i) out_ << (i ? "," : "") << csv_quoted(columns[i]);
        out_ << '\n';
    } else {
        for (const auto& c : columns) keys_.push_back(json_quoted(c) + ": ");
        out_ << "[";
    }
}

template <class Value>
void table_writer::write_row(const std::vector<Value>& values) {
    if (format_ == table_format::csv) {
        for (std::size_t i = 0; i < values.size(); ++i) out_ << (i ? "," : "") << cell(values[i], format_);
        out_ << '\n';
    } else {
        out_ << (rows_ ? ",\n " : "\n ") << "{";
        for (std::size_t i = 0; i < keys_.size() && i < values.size(); ++i) {
            out_ << (i ? ", " : "") << keys_[i] << cell(values[i], format_);
        }
        out_ << "}";
    }
    ++rows_;
}

void table_writer::row(const std::vector<double>& values) { write_row(values); }

void table_writer::record(const std::vector<field>& values) { write_row(values); }

void table_writer::finish() {
    if (format_ == table_format::json) out_ << (rows_ ? "\n]\n" : "]\n");
}

void write_table(std::ostream& out, const table& t, table_format format) {
    table_writer w(out, t.columns, format);
    for (const auto& row : t.rows) w.row(row);
    w.finish();
}

void write_records(std::ostream& out, const std::vector<std::string>& columns,
                   const std::vector<std::vector<field>>& rows, table_format format) {
    table_writer w(out, columns, format);
    for (const auto& row : rows) w.record(row);
    w.finish();
}

}  // namespace pendulum::cli
