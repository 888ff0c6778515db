// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Reads the CSV reference tables written by tests/data/make_reference.py.

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace test_support {

/// Rows of a reference CSV file (comment lines and the header skipped), parsed as doubles.
inline std::vector<std::vector<double>> read_reference(const std::string& name) {
    const std::string path = std::string(PENDULUM_TEST_DATA) + "/" + name;
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot open " + path);
    std::vector<std::vector<double>> rows;
    std::string line;
    bool header = true;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        if (header) {
            header = false;
            continue;
        }
        std::vector<double> row;
        std::stringstream fields(line);
        std::string field;
        while (std::getline(fields, field, ',')) row.push_back(std::stod(field));
        rows.push_back(row);
    }
    if (rows.empty()) throw std::runtime_error("no rows in " + path);
    return rows;
}

}  // namespace test_support
