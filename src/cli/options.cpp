// SPDX-License-Identifier: GPL-3.0-or-later
#include "cli/options.hpp"

#include "figures/themes.hpp"
#include "plot/tex_markup.hpp"
#include "plot/workers.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <functional>
#include <utility>
#include <unistd.h>

namespace pendulum::cli {

const char* const angle_help =
    "Angles are expressions in radians: 1.2, pi/2, 9pi/10, 9*pi/10, 0.9pi, pi-1e-6, or degrees "
    "with deg: 162deg. A LIST is comma-separated: --theta0 'pi/3,pi/2,162deg'; --theta0 @FILE reads it from a "
    "file and --theta0 - from standard input (values comma-separated or one a line, # comments), and so do "
    "--omega0 and --energy.";

const CLI::Validator non_empty(
    [](std::string& value) { return value.empty() ? std::string("empty value") : std::string(); }, "", "NON-EMPTY");

const char* const jobs_help =
    "Worker threads, 1..1024 (default: PENDULUM_FIGURES_JOBS, else one per CPU this process may use, "
    "as taskset and cpusets allow); the files are the same for any number";

unsigned chosen_jobs(const std::optional<int>& given) {
    const auto check = [](long long n, const std::string& what) {
        if (n < 1 || n > max_jobs) {
            throw usage_error(what + ": the number of workers, 1 to " + std::to_string(max_jobs));
        }
        return static_cast<unsigned>(n);
    };
    if (given) return check(*given, "--jobs " + std::to_string(*given));
    const char* text = std::getenv(jobs_variable);
    if (!text || !*text) return 0;
    const std::string value = text;
    std::size_t used = 0;
    long long n = 0;
    try {
        n = std::stoll(value, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    const std::string what = std::string(jobs_variable) + "='" + shown_text(value) + "'";
    if (used != value.size()) check(0, what);
    return check(n, what);
}

pendulum::amplitude amplitude_item(std::string_view item) {
    try {
        return pendulum::parse_amplitude(item);
    } catch (const std::invalid_argument& e) {
        const std::string shown = shown_text(
            item.size() <= 80 ? std::string(item)
                              : std::string(item.substr(0, 40)) + "..." + std::string(item.substr(item.size() - 20)));
        throw usage_error("--theta0 '" + shown + "': " + e.what());
    }
}

namespace {

/// Items read before they are parsed together: 16384 of them, their bytes in one string.
constexpr std::size_t items_per_block = std::size_t{1} << 14;
/// Items one worker parses at a time.
constexpr std::size_t items_per_task = 256;

/// Items of a list held together: their bytes one after another, and where each ends.
struct item_block {
    std::string bytes;
    std::vector<std::size_t> ends;
    std::size_t size() const { return ends.size(); }
    std::string_view operator[](std::size_t i) const {
        const std::size_t begin = i ? ends[i - 1] : 0;
        return std::string_view(bytes).substr(begin, ends[i] - begin);
    }
    void add(std::string_view item) {
        bytes += item;
        ends.push_back(bytes.size());
    }
    void clear() {
        bytes.clear();
        ends.clear();
    }
};

/// Parses `items` on every worker and appends their amplitudes to `values` in order; the
/// first bad item's error is thrown, whichever worker met it.
void parse_items(const item_block& items, std::vector<pendulum::amplitude>& values) {
    std::vector<std::optional<pendulum::amplitude>> parsed(items.size());
    std::vector<std::exception_ptr> errors(items.size());
    plot::parallel_for_each(items.size(), items_per_task, [&](std::size_t i) {
        try {
            parsed[i] = amplitude_item(items[i]);
        } catch (...) {
            errors[i] = std::current_exception();
        }
    });
    for (std::size_t i = 0; i < items.size(); ++i) {
        if (errors[i]) std::rethrow_exception(errors[i]);
        values.push_back(*parsed[i]);
    }
}

}  // namespace

std::vector<pendulum::amplitude> parse_amplitude_values(const std::string& given) {
    std::vector<pendulum::amplitude> values;
    item_block items;
    for_each_item(given, "--theta0", [&](std::string_view item) {
        items.add(item);
        if (items.size() < items_per_block) return;
        parse_items(items, values);
        items.clear();
    });
    parse_items(items, values);
    return values;
}

std::vector<figures::amplitude> parse_amplitudes(const std::string& given, std::size_t most) {
    std::vector<figures::amplitude> values;
    for_each_amplitude(given, [&](const std::string& item, const pendulum::amplitude& v) {
        if (values.size() == most) {
            throw usage_error("--theta0: more than " + std::to_string(most) + " amplitudes; a figure's panel takes at most " +
                              std::to_string(most));
        }
        values.push_back({item, v.radians(), v});
    });
    return values;
}

void check_list_item(const std::string& option, const std::string& text, std::size_t count, std::string_view item) {
    if (count > max_list_items) {
        throw usage_error(option + " " + (text.size() <= 80 ? shown_text(text) : std::string("LIST")) + ": more than " +
                          std::to_string(max_list_items) + " values; a list takes at most " +
                          std::to_string(max_list_items));
    }
    // Printable ASCII of at most max_label_bytes, as numbers are, has nothing text_problem refuses.
    bool printable = item.size() <= plot::max_label_bytes;
    for (const char c : item) printable &= static_cast<unsigned char>(c - ' ') <= '~' - ' ';
    if (printable) return;
    if (const std::string why = plot::text_problem(item); !why.empty()) {
        const std::string shown = shown_text(item.size() <= 80 ? std::string(item)
                                                               : std::string(item.substr(0, 40)) + "..." +
                                                                     std::string(item.substr(item.size() - 20)));
        throw usage_error(option + " '" + shown + "' " + why);
    }
}

std::istream& list_source(const std::string& text, const std::string& option, std::ifstream& file) {
    if (text == "-") return std::cin;
    std::error_code ec;
    const auto status = std::filesystem::status(text.substr(1), ec);  // through symbolic links
    if (std::filesystem::is_directory(status)) {
        throw usage_error(option + " " + text + ": '" + text.substr(1) + "' is a directory, not a list");
    }
    // As spec and style files: a FIFO or device could block or never end; standard input can be either (-).
    if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status)) {
        throw usage_error(option + " " + text + ": '" + text.substr(1) +
                          "' is not a regular file (a device, FIFO or socket); give a file, or - and redirect it");
    }
    file.open(text.substr(1), std::ios::binary);
    if (!file) throw usage_error(option + " " + shown_text(text) + ": cannot read '" + shown_text(text.substr(1)) + "'");
    return file;
}

/// The bytes a line reader holds: a block read at a time, and room for the longest line kept.
constexpr std::size_t line_block_bytes = std::size_t{1} << 20;

line_reader::line_reader(std::istream& in) : in_(in), buffer_(line_block_bytes + max_list_line_bytes + 1) {}

bool line_reader::fill() {
    if (at_end_) return false;
    // The unread bytes (the start of a line, at most max_list_line_bytes) go to the front.
    std::copy(buffer_.begin() + static_cast<std::ptrdiff_t>(begin_), buffer_.begin() + static_cast<std::ptrdiff_t>(end_),
              buffer_.begin());
    end_ -= begin_;
    begin_ = 0;
    in_.read(buffer_.data() + end_, static_cast<std::streamsize>(buffer_.size() - end_));
    const auto count = static_cast<std::size_t>(in_.gcount());
    end_ += count;
    if (!in_) at_end_ = true;
    return count > 0;
}

bool line_reader::next(std::string_view& line) {
    for (std::size_t searched = begin_;;) {
        const char* data = buffer_.data();
        const void* newline = std::memchr(data + searched, '\n', end_ - searched);
        if (newline) {
            const auto at = static_cast<std::size_t>(static_cast<const char*>(newline) - data);
            line = std::string_view(data + begin_, at - begin_);
            begin_ = at + 1;
            return true;
        }
        if (end_ - begin_ > max_list_line_bytes) {  // too long: the caller refuses it
            line = std::string_view(data + begin_, max_list_line_bytes + 1);
            begin_ = end_;
            return true;
        }
        searched = end_ - begin_;
        if (!fill()) {
            if (begin_ == end_) return false;
            line = std::string_view(buffer_.data() + begin_, end_ - begin_);  // the last line, no newline
            begin_ = end_;
            return true;
        }
    }
}

const char* const start_help =
    "A start is an amplitude (--theta0 alone: released at rest), a state (--theta0 ANGLE with --omega0 W, the "
    "initial velocity theta'/w0, any angle and either sign) or an energy (--energy E in units of m g L from the "
    "bottom, launched from the bottom forwards). E < 2 is a libration, E = 2 the separatrix (the top is reached "
    "only as t -> infinity: no period), E > 2 a rotation over the top (its period is one revolution, T_rev). "
    "Angles, velocities and energies are taken as written (2pi/3, 2-1e-20, pi-1e-300): the energy and 2 - E come "
    "from those exact numbers, so 2pi/3 with omega0 = 1 is the separatrix and 2-1e-20 a libration; a start whose "
    "2 - E vanishes at 32768 and 65536 bits (the precision is doubled from 128 up to 65536) is the separatrix, "
    "one that only 65536 bits can tell from it is refused, and so is one within 2 k' < 2.2e-308 of the top. "
    "A state at rest at an angle in (0, pi] is that amplitude (pi itself is refused).";

const char* const omega0_help =
    "The launch velocity --omega0 is theta'(0) in units of w0 = sqrt(g/L), the natural frequency (the "
    "small-amplitude angular frequency, the same w0 as on a phase portrait's axis): --omega0 2 at the bottom "
    "reaches the top (E = 2). With --length (and --g) it may be given in rad/s, --omega0 2.5rad/s.";

namespace {

/// The text without `suffix` and the blanks before it, or empty if it does not end so.
std::string without_suffix(const std::string& text, std::string_view suffix) {
    if (text.size() <= suffix.size() || !text.ends_with(suffix)) return "";
    std::string rest = text.substr(0, text.size() - suffix.size());
    while (!rest.empty() && (rest.back() == ' ' || rest.back() == '\t')) rest.pop_back();
    return rest;
}

}  // namespace

given_time parse_time(const std::string& option, const std::string& text) {
    const std::string seconds = without_suffix(text, "s");
    try {
        if (!seconds.empty()) return {parse_expression(seconds), true};
        return {parse_expression(text), false};
    } catch (const std::invalid_argument& e) {
        throw usage_error(option + " '" + shown_text(text.substr(0, 80)) + "': " + e.what() +
                          " (a time is a number in the option's unit, or seconds such as 10s)");
    }
}

std::string listed_items(const std::string& text, const std::string& option) {
    if (text != "-" && !text.starts_with("@")) return text;
    std::string out;
    for_each_item(text, option, [&](const std::string& item) { out += (out.empty() ? "" : ",") + item; });
    return out;
}

std::string omega0_in_w0(const std::string& text, const std::optional<double>& length, double g) {
    if (text.empty()) return text;
    // The items as given, or read from @FILE or standard input (-): each converted alike.
    std::string out;
    for_each_item(text, "--omega0", [&](const std::string& item) {
        std::string value = item;
        if (const std::string number = without_suffix(item, "rad/s"); !number.empty()) {
            if (!length) {
                throw usage_error("--omega0 '" + shown_text(item.substr(0, 80)) +
                                  "': a velocity in rad/s needs the pendulum's --length in metres (and --g, default "
                                  "9.80665); without them give it in units of w0 = sqrt(g/L), e.g. --omega0 1.9");
            }
            double v = 0;
            try {
                v = parse_expression(number);
            } catch (const std::invalid_argument& e) {
                throw usage_error("--omega0 '" + shown_text(item.substr(0, 80)) + "': " + e.what());
            }
            if (!(*length > 0) || !(g > 0)) {
                throw usage_error("--omega0 '" + shown_text(item.substr(0, 80)) + "': --length and --g must be above 0");
            }
            value = format_double(v / std::sqrt(g / *length));
        }
        out += (out.empty() ? "" : ",") + value;
    });
    return out;
}

namespace {

/// The values of a list option of expressions (angles, with deg, or plain numbers), as typed
/// and as written: each keeps every digit its text has.
std::vector<std::pair<std::string, written_number>> parse_values(const std::string& given, const std::string& option,
                                                                 bool angle) {
    std::vector<std::pair<std::string, written_number>> values;
    for_each_item(given, option, [&](const std::string& item) {
        try {
            values.emplace_back(item, angle ? written_number::angle(item) : written_number::expression(item));
        } catch (const std::invalid_argument& e) {
            throw usage_error(option + " '" + shown_text(item.substr(0, 80)) + "': " + e.what());
        }
    });
    return values;
}

start_option start_of(const std::string& text, const std::function<pendulum::motion()>& make) {
    try {
        return {text, make()};
    } catch (const domain_error& e) {
        // The core's message names the start already where it can.
        const std::string why = e.what();
        throw usage_error(shown_text(why.starts_with(text) ? why : text + ": " + why));
    }
}

}  // namespace

std::vector<start_option> parse_starts(const std::string& theta0, const std::string& omega0, const std::string& energy) {
    if (!energy.empty() && (!theta0.empty() || !omega0.empty())) {
        throw usage_error("--energy launches from the bottom: give either --energy E or --theta0 ANGLE (with --omega0 W "
                          "for a state), not both");
    }
    if (energy.empty() && theta0.empty()) {
        throw usage_error(omega0.empty() ? "give --theta0 (an amplitude, or with --omega0 a state) or --energy"
                                         : "--omega0 needs the start angle --theta0 too (--theta0 0 launches from the bottom)");
    }
    std::vector<start_option> starts;
    if (!energy.empty()) {
        for (const auto& [text, e] : parse_values(energy, "--energy", false)) {
            starts.push_back(start_of("energy = " + text, [&e = e] { return pendulum::motion::from_energy(e); }));
        }
        return starts;
    }
    if (omega0.empty()) {
        for_each_amplitude(theta0, [&](const std::string& item, const pendulum::amplitude& a) {
            starts.push_back({"--theta0 " + shown_text(item), pendulum::motion::from_amplitude(a)});
        });
        return starts;
    }
    const auto angles = parse_values(theta0, "--theta0", true);
    const auto speeds = parse_values(omega0, "--omega0", false);
    if (angles.size() != speeds.size() && angles.size() != 1 && speeds.size() != 1) {
        throw usage_error("--theta0 has " + std::to_string(angles.size()) + " values and --omega0 " +
                          std::to_string(speeds.size()) + ": give as many of each, or one of either");
    }
    const std::size_t count = std::max(angles.size(), speeds.size());
    for (std::size_t i = 0; i < count; ++i) {
        const auto& [angle_text, angle] = angles[angles.size() == 1 ? 0 : i];
        const auto& [speed_text, speed] = speeds[speeds.size() == 1 ? 0 : i];
        starts.push_back(start_of("theta0 = " + angle_text + ", omega0 = " + speed_text, [&angle = angle, &speed = speed] {
            return pendulum::motion::from_state(angle, speed);
        }));
    }
    return starts;
}

void check_method_applies(const method_choice& method, const start_option& start) {
    const auto kind = start.motion.kind();
    if (method.is_exact() || kind == regime::libration) return;
    const auto& row = row_of(kind);
    throw usage_error("--method " + method.text() + " describes librations only (E < 2), but " + start.text +
                      " is a " + std::string(row.name) + " (E = " + format_double(start.motion.energy()) +
                      "): use --method exact, or a start with E < 2");
}

method_choice parse_method_option(const std::string& option, const std::string& text) {
    try {
        return parse_method(text);
    } catch (const domain_error& e) {
        throw usage_error(option + " '" + shown_text(text) + "': " + e.what());
    }
}

namespace {

void check_order(int order) {
    if (order < 0 || order > max_order) {
        throw usage_error("--order " + std::to_string(order) + ": order must be between 0 and " +
                          std::to_string(max_order));
    }
}

}  // namespace

int parse_order(const std::string& text) {
    // Spaces around the number are allowed on both sides, as in angles.
    const auto first = text.find_first_not_of(" \t");
    const auto last = text.find_last_not_of(" \t");
    const std::string digits = first == std::string::npos ? "" : text.substr(first, last - first + 1);
    if (digits.empty()) throw usage_error("--order: empty value; orders are 0.." + std::to_string(max_order));
    if (digits.find_first_not_of("0123456789") != std::string::npos) {
        throw usage_error("--order '" + text + "': not a whole number; orders are 0.." + std::to_string(max_order));
    }
    if (digits.size() > 9) {
        throw usage_error("--order " + digits + ": order must be between 0 and " + std::to_string(max_order));
    }
    const int order = std::stoi(digits);
    check_order(order);
    return order;
}

std::vector<int> parse_orders(const std::vector<std::string>& items) {
    std::vector<int> orders;
    const auto add = [&](int n) {
        if (std::find(orders.begin(), orders.end(), n) == orders.end()) orders.push_back(n);
    };
    for (const auto& text : items) {
        const auto dots = text.find("..");
        if (dots == std::string::npos) {
            add(parse_order(text));
            continue;
        }
        const int from = parse_order(text.substr(0, dots));
        const int to = parse_order(text.substr(dots + 2));
        if (from > to) {
            throw usage_error("--order '" + text + "': a range a..b needs a <= b, e.g. 0.." + std::to_string(max_order));
        }
        for (int n = from; n <= to; ++n) add(n);
    }
    return orders;
}

std::vector<std::string> list_items(const std::vector<std::string>& values) {
    std::vector<std::string> items;
    for (const auto& v : values) {
        for (auto& item : split_list(v)) items.push_back(std::move(item));
    }
    return items;
}

plot::theme chosen_theme(const std::string& name, const std::vector<std::string>& sets) {
    try {
        return figures::load_theme(name, sets);
    } catch (const figures::spec_error& e) {
        // The message names the theme (or the style file and line), the key and what to change.
        throw usage_error(e.what());
    }
}

void check_output_dir(const std::string& dir) {
    std::error_code ec;
    const std::string shown = shown_text(dir.size() <= 100 ? dir : dir.substr(0, 40) + "..." + dir.substr(dir.size() - 40));
    const bool exists = std::filesystem::exists(dir, ec);
    if (ec) throw usage_error("output directory '" + shown + "' cannot be reached: " + ec.message());
    if (!exists) throw usage_error("output directory '" + shown + "' does not exist");
    if (!std::filesystem::is_directory(dir, ec)) throw usage_error("output path '" + dir + "' is not a directory");
    if (::access(dir.c_str(), W_OK | X_OK) != 0) {
        throw usage_error("output directory '" + dir + "' is not writable");
    }
}

}  // namespace pendulum::cli
