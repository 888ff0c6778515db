// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What several commands parse and check alike: lists of values, amplitudes, orders,
// methods, the output directory and the theme.

#include "cli/lists.hpp"
#include "pendulum/angle.hpp"
#include "cli/errors.hpp"
#include "figures/spec.hpp"
#include "pendulum/amplitude.hpp"
#include "pendulum/methods.hpp"
#include "pendulum/motion.hpp"
#include "plot/theme.hpp"

#include <CLI/CLI.hpp>

#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <iostream>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace pendulum::cli {

/// What the help of the commands that take angles says about them.
extern const char* const angle_help;

/// Refuses an empty value (CLI11 validator): '' is never a figure, directory or amplitude.
extern const CLI::Validator non_empty;

/// The longest line of a list file (@FILE, -): far more than any list of amplitudes needs.
inline constexpr std::size_t max_list_line_bytes = 65536;

/// The most values a list option takes, from its text, @FILE or standard input (-): the
/// million amplitudes make bench evaluates, 8 MB of values. Reading stops at the next one.
inline constexpr std::size_t max_list_items = 1'000'000;

/// Refuses the item number `count` of a list option past max_list_items, and an item that
/// is not one line of printable UTF-8 of at most plot::max_label_bytes (titles show it).
void check_list_item(const std::string& option, const std::string& text, std::size_t count, std::string_view item);

/// Reads a list's lines a block of 1 MB at a time, each line a view into the block (valid
/// until the next one): no copy per line or item.
class line_reader {
public:
    /// Reads `in`.
    explicit line_reader(std::istream& in);
    /// The next line without its newline; one longer than max_list_line_bytes comes as its
    /// first max_list_line_bytes + 1 bytes (the caller refuses it), so that a file of no
    /// newlines, /dev/zero, takes no more time or memory than that. False at the end.
    bool next(std::string_view& line);

private:
    bool fill();  // reads more after the unread bytes; false at the end of the stream
    std::istream& in_;
    std::vector<char> buffer_;
    std::size_t begin_ = 0;  // the unread bytes are [begin_, end_)
    std::size_t end_ = 0;
    bool at_end_ = false;
};

/// The stream a list option reads, `text` being @FILE (opened into `file`) or - (standard
/// input); a directory or a file that cannot be read is a usage error.
std::istream& list_source(const std::string& text, const std::string& option, std::ifstream& file);

/// Calls take(item) for each comma-separated item of one line, trimmed, as split_list cuts
/// them (an empty one included).
template <class Take>
void for_each_line_item(std::string_view line, Take take) {
    for (std::string_view rest = line;;) {
        const auto comma = rest.find(',');
        std::string_view item = rest.substr(0, comma);
        const auto first = item.find_first_not_of(" \t\r");
        item = first == std::string_view::npos ? std::string_view()
                                               : item.substr(first, item.find_last_not_of(" \t\r") - first + 1);
        take(item);
        if (comma == std::string_view::npos) return;
        rest.remove_prefix(comma + 1);
    }
}

/// Calls take(item) for each item of a list option: its text, or the lines (each
/// comma-separated, # comments) of FILE for @FILE and of standard input for -, read as
/// they come, so that a million amplitudes need no more memory than their values. The item
/// is a std::string_view (valid during the call) where take accepts one, a std::string otherwise.
template <class Take>
void for_each_item(const std::string& text, const std::string& option, Take take) {
    const auto give = [&](std::string_view item) {
        if constexpr (std::is_invocable_v<Take&, std::string_view>) take(item);
        else take(std::string(item));
    };
    std::size_t count = 0;
    if (text != "-" && (text.empty() || text[0] != '@')) {
        for (const auto& item : split_list(text)) {
            check_list_item(option, text, ++count, item);
            give(item);
        }
        return;
    }
    std::ifstream file;
    line_reader lines(list_source(text, option, file));
    bool any = false;
    std::size_t number = 0;
    for (std::string_view line; lines.next(line);) {
        ++number;
        if (line.size() > max_list_line_bytes) {
            throw usage_error(option + " " + text + ": line " + std::to_string(number) + " is longer than " +
                              std::to_string(max_list_line_bytes) + " bytes");
        }
        line = line.substr(0, line.find('#'));
        if (line.find_first_not_of(" \t\r") == std::string_view::npos) continue;
        for_each_line_item(line, [&](std::string_view item) {
            check_list_item(option, text, ++count, item);
            give(item);
            any = true;
        });
    }
    if (!any) throw usage_error(option + " " + text + ": no values");
}

/// One --theta0 item's amplitude; bad input (usage_error) names the item.
pendulum::amplitude amplitude_item(std::string_view item);

/// One --theta0 item, checked; take(text, value) receives it.
template <class Take>
void for_each_amplitude(const std::string& given, Take take) {
    for_each_item(given, "--theta0", [&](const std::string& item) { take(item, amplitude_item(item)); });
}

/// The values of --theta0, checked (a million of them take 8 MB), read in order and parsed
/// on every worker (plot::parallel_for); a bad one is refused as the first in the list.
std::vector<pendulum::amplitude> parse_amplitude_values(const std::string& given);

/// Amplitudes as typed and their values; figure titles show them as typed. More than
/// `most` is bad input (the reading stops there).
std::vector<figures::amplitude> parse_amplitudes(const std::string& given,
                                                 std::size_t most = std::numeric_limits<std::size_t>::max());

/// A start given on the command line, as typed, and its exact motion.
struct start_option {
    std::string text;        ///< "theta0 = 0, omega0 = 1.9" or "energy = 2.5"
    pendulum::motion motion; ///< the motion from it
};

/// What the help of the commands that take starts says about them.
extern const char* const start_help;

/// The starts of --theta0 ANGLE with --omega0 W (states, paired item by item; a single item on
/// either side goes with each item of the other) or of --energy E (launches from the bottom);
/// bad input, both or neither of --theta0 and --energy, is a usage_error saying what works.
std::vector<start_option> parse_starts(const std::string& theta0, const std::string& omega0, const std::string& energy);

/// What the help of --omega0 says: its unit, the natural frequency, and rad/s.
extern const char* const omega0_help;

/// A time as given: a number in the option's unit of time, or of seconds ("10s", "2.5 s").
struct given_time {
    double value = 0;      ///< the number
    bool seconds = false;  ///< true: seconds, which need the pendulum's length and g
};

/// Reads a time of `option`: an expression ("1/3", "0.25") in the option's unit, or one
/// followed by s in seconds; bad input names the option and the text.
given_time parse_time(const std::string& option, const std::string& text);

/// The items of a list option as one comma-separated text: `text` itself, or the items
/// of @FILE or of standard input (-), read once.
std::string listed_items(const std::string& text, const std::string& option);

/// The items of --omega0 in units of w0 = sqrt(g/L): an item as given, or one in rad/s
/// ("2.5rad/s") divided by w0 of `length` (metres) and `g` (m/s^2), rounded once; rad/s
/// without a length is a usage_error that says to give --length. A list from @FILE or -
/// is read here, its items converted alike.
std::string omega0_in_w0(const std::string& text, const std::optional<double>& length, double g);

/// Throws a usage_error unless `method` applies to the start: the paper's approximants and
/// the iteration describe librations only (E < 2).
void check_method_applies(const method_choice& method, const start_option& start);

/// Parses a method name (NAME or NAME:N) for the option `option`.
method_choice parse_method_option(const std::string& option, const std::string& text);

/// Parses an order N given as text, with a message that names it.
int parse_order(const std::string& text);

/// Parses --order items: orders N and ranges a..b, in the order given, each order once.
std::vector<int> parse_orders(const std::vector<std::string>& items);

/// A comma-separated option value as its items, empty ones kept so that they are reported.
std::vector<std::string> list_items(const std::vector<std::string>& values);

/// The theme of --theme and --set; a bad style file is bad input.
plot::theme chosen_theme(const std::string& name, const std::vector<std::string>& sets);

/// The environment variable that gives --jobs when the option is not given (for builds).
inline constexpr const char* jobs_variable = "PENDULUM_FIGURES_JOBS";

/// The help of --jobs.
extern const char* const jobs_help;

/// The largest accepted --jobs.
inline constexpr int max_jobs = 1024;

/// The workers --jobs asks for, or PENDULUM_FIGURES_JOBS when the option is not given; 0
/// (one per CPU the process may use) when neither is. Bad input names the option or variable.
unsigned chosen_jobs(const std::optional<int>& given);

/// Checks that dir exists and can be written to, naming it otherwise.
void check_output_dir(const std::string& dir);

}  // namespace pendulum::cli
