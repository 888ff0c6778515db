// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <ostream>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace pendulum::cli {

/// A table of numbers with named columns, printed as CSV or JSON.
struct table {
    std::vector<std::string> columns;       ///< column names
    std::vector<std::vector<double>> rows;  ///< one value per column in each row
};

/// Output formats for tables.
enum class table_format { csv, json };

/// Parses "csv" or "json"; throws std::invalid_argument naming the text otherwise.
table_format parse_table_format(std::string_view text);

/// A field of a record: text or a number.
using field = std::variant<std::string, double>;

/// Writes a table row by row as it is computed, so that long tables need no memory (rows go
/// out in blocks of 64 kB, and at finish()). Numbers
/// use the shortest form that reads back to the same double, NaN an empty field / null;
/// text is quoted as RFC 4180 asks (CSV) or escaped (JSON). A CSV text field that a
/// spreadsheet would take for a formula (=, +, -, @, tab or CR first) gets a ' before it.
class table_writer {
public:
    /// Writes the header (CSV) or the opening bracket (JSON).
    table_writer(std::ostream& out, std::vector<std::string> columns, table_format format);
    /// Writes one row of numbers, one per column.
    void row(const std::vector<double>& values);
    /// Writes one row of text and numbers, one per column.
    void record(const std::vector<field>& values);
    /// Appends one row of text and numbers to `out` as record() writes it, `first` where it is
    /// the table's first row, without writing it (workers format rows apart; not counted in
    /// empty_fields).
    void format(std::string& out, const std::vector<field>& values, bool first) const;
    /// Writes `rows` rows that format() made, in order.
    void write_formatted(std::string_view text, std::size_t rows);
    /// Ends the table (JSON's closing bracket) and writes what is gathered.
    void finish();
    /// Writes the rows gathered so far to the stream.
    void flush();
    /// How many number fields of a column were left empty (not finite: NaN or beyond the
    /// largest double), so that the command can say why on standard error.
    std::size_t empty_fields(std::size_t column) const { return column < empty_.size() ? empty_[column] : 0; }
    /// The first column's number in the first row where `column` was left empty (NaN if none).
    double first_empty_at(std::size_t column) const;

private:
    template <class Value>
    void write_row(const std::vector<Value>& values);
    template <class Value>
    void append_row(std::string& out, const std::vector<Value>& values, bool first) const;

    std::ostream& out_;
    std::vector<std::string> keys_;  // JSON: each column's quoted name and ": "
    table_format format_;
    std::size_t rows_ = 0;
    std::string buffer_;  // rows not yet written: numbers go straight into it (std::to_chars)
    std::vector<std::size_t> empty_;  // per column: number fields left empty
    std::vector<double> first_empty_;  // per column: the first column's number where one first was
};

/// Writes the table: CSV with a header line, or JSON as an array of objects. Numbers use
/// the shortest form that reads back to the same double; NaN is an empty field / null.
void write_table(std::ostream& out, const table& t, table_format format);

/// Writes records of text and numbers, as table_writer does.
void write_records(std::ostream& out, const std::vector<std::string>& columns,
                   const std::vector<std::vector<field>>& rows, table_format format);

}  // namespace pendulum::cli
