// SPDX-License-Identifier: GPL-3.0-or-later
// claims: every quantitative statement of the paper, what the tool measures, and a verdict.
#include "cli/commands.hpp"
#include "cli/report.hpp"
#include "cli/table.hpp"
#include "pendulum/claims.hpp"

#include <CLI/CLI.hpp>

#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace pendulum::cli {

command add_claims_command(CLI::App& app) {
    auto format = std::make_shared<std::string>("csv");
    auto* cmd = app.add_subcommand(
        "claims", "Print every quantitative statement of the paper, where it is made, what the tool measures, and "
                  "a verdict.");
    cmd->add_option("--format", *format, "Output format: csv (default) or json")->type_name("csv|json");
    cmd->footer("\nColumns: claim (a short id), where (the paper's section or figure), statement, quantity (what "
                   "is measured), value, unit (%, rad, deg, or empty for orders), verdict. Periods are compared with "
                   "the exact one; deviations of theta are the largest over one exact period.\n\n"
                   "Examples:\n"
                   "  pendulum-figures claims\n"
                   "  pendulum-figures claims --format json");

    return {cmd, [format] {
                const auto table = parse_table_format(*format);
                std::vector<std::vector<field>> rows;
                for (const auto& c : paper_claims()) {
                    rows.push_back({c.claim, c.where, c.statement, c.quantity, c.value, c.unit, c.verdict});
                }
                std::ostringstream out;
                write_records(out, {"claim", "where", "statement", "quantity", "value", "unit", "verdict"}, rows, table);
                return write_stdout(out.str());
            }};
}

}  // namespace pendulum::cli
