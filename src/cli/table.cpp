// SPDX-License-Identifier: GPL-3.0-or-later
#include "cli/table.hpp"

#include "cli/errors.hpp"
#include "pendulum/amplitude.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>
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

/// Appends a number as a field: the shortest form that reads back to the same double; a
/// value that does not exist (the iteration's breakdown) is an empty CSV field or JSON null.
void append_cell(std::string& out, double v, table_format format) {
    if (!std::isfinite(v)) {
        if (format == table_format::json) out += "null";
        return;
    }
    char buf[32];
    const auto end = std::to_chars(buf, buf + sizeof buf, v).ptr;
    out.append(buf, end);
}

void append_cell(std::string& out, const field& v, table_format format) {
    if (const auto* text = std::get_if<std::string>(&v)) {
        // A text a spreadsheet would take for a formula gets a single quote before it.
        const bool formula = !text->empty() && std::string_view("=+-@\t\r").find(text->front()) != std::string_view::npos;
        out += format == table_format::csv ? csv_quoted(formula ? "'" + *text : *text) : json_quoted(*text);
        return;
    }
    append_cell(out, std::get<double>(v), format);
}

/// Rows are gathered into this many bytes before they go to the stream together.
constexpr std::size_t flush_bytes = 1 << 16;

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
    buffer_.reserve(flush_bytes + 4096);
}

namespace {

/// The number of a field, or NaN for text.
double number_of(double v) { return v; }
double number_of(const field& v) {
    const double* x = std::get_if<double>(&v);
    return x ? *x : std::numeric_limits<double>::quiet_NaN();
}
bool is_number(double) { return true; }
bool is_number(const field& v) { return std::holds_alternative<double>(v); }

}  // namespace

double table_writer::first_empty_at(std::size_t column) const {
    return column < first_empty_.size() ? first_empty_[column] : std::numeric_limits<double>::quiet_NaN();
}

template <class Value>
void table_writer::write_row(const std::vector<Value>& values) {
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (!is_number(values[i]) || std::isfinite(number_of(values[i]))) continue;
        if (empty_.size() < values.size()) {
            empty_.resize(values.size(), 0);
            first_empty_.resize(values.size(), std::numeric_limits<double>::quiet_NaN());
        }
        if (empty_[i]++ == 0) first_empty_[i] = number_of(values.front());
    }
    append_row(buffer_, values, rows_ == 0);
    ++rows_;
    if (buffer_.size() >= flush_bytes) flush();
}

template <class Value>
void table_writer::append_row(std::string& out, const std::vector<Value>& values, bool first) const {
    if (format_ == table_format::csv) {
        for (std::size_t i = 0; i < values.size(); ++i) {
            if (i) out += ',';
            append_cell(out, values[i], format_);
        }
        out += '\n';
    } else {
        out += first ? "\n {" : ",\n {";
        for (std::size_t i = 0; i < keys_.size() && i < values.size(); ++i) {
            if (i) out += ", ";
            out += keys_[i];
            append_cell(out, values[i], format_);
        }
        out += '}';
    }
}

void table_writer::row(const std::vector<double>& values) { write_row(values); }

void table_writer::record(const std::vector<field>& values) { write_row(values); }

void table_writer::format(std::string& out, const std::vector<field>& values, bool first) const {
    append_row(out, values, first);
}

void table_writer::write_formatted(std::string_view text, std::size_t rows) {
    buffer_ += text;
    rows_ += rows;
    if (buffer_.size() >= flush_bytes) flush();
}

void table_writer::flush() {
    out_.write(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
    buffer_.clear();
}

void table_writer::finish() {
    if (format_ == table_format::json) buffer_ += rows_ ? "\n]\n" : "]\n";
    flush();
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
