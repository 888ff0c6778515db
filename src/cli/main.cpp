// pendulum-figures: the command line. Parsing and validation only; the work is in the libraries.
#include "cli/angle.hpp"
#include "cli/table.hpp"
#include "figures/batch.hpp"
#include "figures/catalog.hpp"
#include "plot/output.hpp"
#include "plot/theme.hpp"
#include "pendulum/amplitude.hpp"
#include "pendulum/approximants.hpp"
#include "pendulum/exact.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <unistd.h>
#include <vector>

namespace {

using namespace pendulum;

/// Bad input from the user: reported in one line, exit code 2.
class usage_error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

constexpr int max_samples = 10'000'000;
constexpr double max_periods = 1e6;

std::vector<double> parse_amplitudes(const std::string& text) {
    std::vector<double> values;
    for (const auto& item : cli::split_list(text)) {
        try {
            const double v = cli::parse_angle(item);
            check_amplitude(v);
            values.push_back(v);
        } catch (const std::invalid_argument& e) {
            throw usage_error("--theta0 '" + item + "': " + e.what());
        }
    }
    return values;
}

void check_order(int order) {
    if (order < 0 || order > max_order) {
        throw usage_error("--order " + std::to_string(order) + ": order must be between 0 and " +
                          std::to_string(max_order));
    }
}

/// Parses an order N given as text, with a message that names it.
int parse_order(const std::string& text) {
    std::size_t used = 0;
    int order = -1;
    try {
        order = std::stoi(text, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used == 0 || used != text.size()) {
        throw usage_error("--order '" + text + "': not a whole number; orders are 0.." +
                          std::to_string(max_order));
    }
    check_order(order);
    return order;
}

/// CLI11's messages, lowercased at the start to match ours.
std::string lowercase_first(std::string s) {
    if (!s.empty() && s[0] >= 'A' && s[0] <= 'Z' && !(s.size() > 1 && s[1] >= 'A' && s[1] <= 'Z')) {
        s[0] = static_cast<char>(s[0] - 'A' + 'a');
    }
    return s;
}

struct eval_options {
    std::string theta0;
    std::vector<std::string> orders;
    std::string format = "csv";
};

cli::table eval_table(const eval_options& o) {
    const auto amplitudes = parse_amplitudes(o.theta0);
    std::vector<int> orders;
    for (const auto& text : o.orders) orders.push_back(parse_order(text));
    cli::table t;
    t.columns = {"theta0",    "period_exact", "period_lowest", "period_first", "period_second",
                 "c1_exact",  "c3_exact",     "c5_exact",      "c1_lowest",    "c1_first",
                 "c3_first",  "c1_second",    "c3_second",     "c5_second",    "c1_poly",
                 "c3_poly",   "c5_poly"};
    for (int n : orders) t.columns.push_back("period_order" + std::to_string(n));
    for (double theta0 : amplitudes) {
        const exact_solution exact(theta0);
        const auto low = lowest_order(theta0);
        const auto first = first_order(theta0);
        const auto second = second_order(theta0);
        const auto poly = polynomial(theta0);
        std::vector<double> row = {theta0,
                                   exact.period_ratio(),
                                   low.period_ratio(),
                                   first.period_ratio(),
                                   second.period_ratio(),
                                   exact.coefficient(0),
                                   exact.coefficient(1),
                                   exact.coefficient(2),
                                   low.coefficients[0],
                                   first.coefficients[0],
                                   first.coefficients[1],
                                   second.coefficients[0],
                                   second.coefficients[1],
                                   second.coefficients[2],
                                   poly.coefficients[0],
                                   poly.coefficients[1],
                                   poly.coefficients[2]};
        for (int n : orders) row.push_back(iterated(theta0, n).period_ratio());
        t.rows.push_back(std::move(row));
    }
    return t;
}

struct trajectory_options {
    std::string theta0;
    std::string method = "exact";
    std::string order;
    std::string at;
    int samples = 0;
    double periods = 1.0;
    std::string format = "csv";
};

const std::vector<std::string> method_names = {"exact",  "harmonic",   "lowest", "first",
                                               "second", "polynomial", "order"};

cli::table trajectory_table(const trajectory_options& o, bool order_given, bool periods_given) {
    const auto amplitudes = parse_amplitudes(o.theta0);
    if (amplitudes.size() != 1) throw usage_error("--theta0 takes one amplitude for trajectory");
    const double theta0 = amplitudes.front();
    int order = -1;
    if (o.method == "order") {
        if (!order_given) throw usage_error("--method order needs --order N");
        order = parse_order(o.order);
    } else if (order_given) {
        throw usage_error("--order is only used with --method order, not --method " + o.method);
    }
    if (o.at.empty() == (o.samples == 0)) {
        throw usage_error("give either --at LIST or --samples N (with --periods P)");
    }
    std::vector<double> times;
    if (!o.at.empty()) {
        if (periods_given) throw usage_error("--periods goes with --samples, not with --at");
        for (const auto& item : cli::split_list(o.at)) {
            try {
                times.push_back(cli::parse_expression(item));
            } catch (const std::invalid_argument& e) {
                throw usage_error(std::string("--at '") + item + "': " + e.what());
            }
        }
    } else {
        if (o.samples < 2 || o.samples > max_samples) {
            throw usage_error("--samples " + std::to_string(o.samples) + ": must be between 2 and " +
                              std::to_string(max_samples));
        }
        if (!(o.periods > 0.0) || !(o.periods <= max_periods)) {
            throw usage_error("--periods " + format_double(o.periods) +
                              ": must be greater than 0 and at most " + format_double(max_periods));
        }
        for (int i = 0; i < o.samples; ++i) times.push_back(o.periods * i / (o.samples - 1));
    }

    const exact_solution exact(theta0);
    fourier_solution approx;
    if (o.method == "harmonic") approx = harmonic(theta0);
    if (o.method == "lowest") approx = lowest_order(theta0);
    if (o.method == "first") approx = first_order(theta0);
    if (o.method == "second") approx = second_order(theta0);
    if (o.method == "polynomial") approx = polynomial(theta0);
    if (o.method == "order") approx = iterated(theta0, order);

    cli::table t;
    t.columns = {"t_over_T", "theta"};
    const double period = 4.0 * exact.quarter_period();  // exact T in units of 1/w0
    for (double s : times) {
        const double theta = o.method == "exact" ? exact.theta_at_fraction(s) : approx.theta(s * period);
        t.rows.push_back({s, theta});
    }
    return t;
}

struct render_options {
    std::vector<std::string> ids;
    bool all = false;
    std::string dir = ".";
    std::string formats = "pdf,png";
    std::string theme = "paper";
    double dpi = 300;
    std::string theta0;
    bool paper_files = false;
};

/// Checks that dir exists and can be written to, naming it otherwise.
void check_output_dir(const std::string& dir) {
    std::error_code ec;
    if (!std::filesystem::exists(dir, ec)) throw usage_error("output directory '" + dir + "' does not exist");
    if (!std::filesystem::is_directory(dir, ec)) throw usage_error("output path '" + dir + "' is not a directory");
    if (::access(dir.c_str(), W_OK | X_OK) != 0) {
        throw usage_error("output directory '" + dir + "' is not writable");
    }
}

std::vector<const figures::entry*> selected_figures(const std::vector<std::string>& ids, bool all) {
    if (all && !ids.empty()) throw usage_error("give figure ids or --all, not both");
    if (!all && ids.empty()) throw usage_error("name the figures to render, or use --all (see 'list')");
    std::vector<const figures::entry*> chosen;
    if (all) {
        for (const auto& e : figures::catalog()) chosen.push_back(&e);
        return chosen;
    }
    for (const auto& id : ids) {
        const auto* e = &figures::find(id);
        if (std::find(chosen.begin(), chosen.end(), e) == chosen.end()) chosen.push_back(e);
    }
    return chosen;
}

int run_render(const render_options& o) {
    const auto chosen = selected_figures(o.ids, o.all);
    std::vector<std::string> formats;
    for (const auto& f : cli::split_list(o.formats)) {
        plot::check_format(f);
        if (std::find(formats.begin(), formats.end(), f) == formats.end()) formats.push_back(f);
    }
    const plot::theme theme = plot::theme_by_name(o.theme);
    if (!(o.dpi >= plot::min_dpi && o.dpi <= plot::max_dpi)) {
        throw usage_error("--dpi " + format_double(o.dpi) + ": must be between " + format_double(plot::min_dpi) +
                          " and " + format_double(plot::max_dpi));
    }
    figures::build_options build;
    if (!o.theta0.empty()) {
        if (std::none_of(chosen.begin(), chosen.end(), [](const auto* e) { return e->takes_amplitudes; })) {
            throw usage_error("--theta0 applies to trajectory figures, and none was chosen");
        }
        build.amplitudes = parse_amplitudes(o.theta0);
    }
    check_output_dir(o.dir);

    const auto jobs = figures::files_for(chosen, formats, o.dir, o.paper_files);
    if (jobs.empty()) throw usage_error("the chosen figures have no panels in the paper; drop --paper-files");

    try {
        figures::write_figures(jobs, build, theme, plot::output_options{o.dpi});
    } catch (const std::exception& e) {
        std::cerr << "pendulum-figures: error: " << e.what() << "\n";
        return 1;
    }
    return 0;
}

std::string list_text() {
    std::ostringstream out;
    for (const auto& e : figures::catalog()) {
        std::string id = e.id + (e.alias.empty() ? "" : " (" + e.alias + ")");
        out << id << std::string(id.size() < 28 ? 28 - id.size() : 1, ' ') << e.paper_figure
            << std::string(e.paper_figure.size() < 8 ? 8 - e.paper_figure.size() : 1, ' ') << e.description << "\n";
    }
    return out.str();
}

std::string figure_data(const std::string& id, const std::string& theta0) {
    const auto& e = figures::find(id);
    figures::build_options build;
    if (!theta0.empty()) {
        if (!e.takes_amplitudes) throw usage_error("--theta0 applies to trajectory figures, not to " + e.id);
        build.amplitudes = parse_amplitudes(theta0);
    }
    return figures::figure_csv(figures::build(e, build));
}

const char* const angle_help =
    "Angles are expressions in radians: 1.2, pi/2, 9pi/10, 9*pi/10, 0.9pi, pi-1e-6, or degrees "
    "with deg: 162deg. A LIST is comma-separated: --theta0 'pi/3,pi/2,162deg'.";

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{
        "pendulum-figures: the simple pendulum solved exactly (Jacobi elliptic functions) and "
        "through the Fourier/Bessel approximants of R. Borghi, arXiv:1303.5023."};
    app.name("pendulum-figures");
    app.set_version_flag("--version", std::string("pendulum-figures ") + "0.1.0");
    app.require_subcommand(1);
    app.footer(std::string("\n") + angle_help +
               "\n\nExamples:\n"
               "  pendulum-figures eval --theta0 pi/2\n"
               "  pendulum-figures eval --theta0 'pi/3,pi/2,9pi/10' --order 4 --order 12 --format json\n"
               "  pendulum-figures trajectory --theta0 162deg --method first --samples 101\n"
               "  pendulum-figures list\n"
               "  pendulum-figures render --all -o figures -f pdf,png\n"
               "\nRun 'pendulum-figures COMMAND --help' for the options of each command.");

    eval_options ev;
    auto* eval = app.add_subcommand(
        "eval", "Print periods T/T0 and Fourier coefficients, exact and approximate, per amplitude.");
    eval->add_option("--theta0", ev.theta0, "Amplitudes, a comma-separated LIST of angles")
        ->required()
        ->type_name("LIST");
    eval->add_option("--order", ev.orders,
                     "Add a column period_orderN for the iteration to order N (0.." +
                         std::to_string(max_order) + "); repeatable")
        ->type_name("N")
        ->take_all()
        ->delimiter(',');
    eval->add_option("--format", ev.format, "Output format: csv (default) or json")
        ->type_name("csv|json");
    eval->footer(std::string("\n") + angle_help +
                 "\n\nColumns: theta0, period_exact, period_lowest, period_first, period_second "
                 "(all T/T0), c1_exact, c3_exact, c5_exact, c1_lowest, c1_first, c3_first, "
                 "c1_second, c3_second, c5_second, c1_poly, c3_poly, c5_poly, then period_orderN "
                 "for each --order N. Numbers round-trip a double.\n\n"
                 "Example:\n  pendulum-figures eval --theta0 'pi/2,9pi/10' --order 12");

    trajectory_options tr;
    auto* traj = app.add_subcommand(
        "trajectory", "Print theta(t) for one amplitude, exact or approximate, at times t/T.");
    traj->add_option("--theta0", tr.theta0, "Amplitude, one angle")->required()->type_name("ANGLE");
    traj->add_option("--method", tr.method,
                     "exact (default), harmonic, lowest, first, second, polynomial, or order "
                     "(with --order N)")
        ->type_name("METHOD");
    auto* order_opt = traj->add_option("--order", tr.order, "Order N of --method order (0.." +
                                                                std::to_string(max_order) + ")")
                          ->type_name("N");
    traj->add_option("--at", tr.at, "Times t/T, a comma-separated list (T is the exact period)")
        ->type_name("LIST");
    traj->add_option("--samples", tr.samples, "Number of equally spaced times from 0 to --periods")
        ->type_name("N");
    auto* periods_opt =
        traj->add_option("--periods", tr.periods, "Time span in exact periods T (default 1)")
            ->type_name("P");
    traj->add_option("--format", tr.format, "Output format: csv (default) or json")
        ->type_name("csv|json");
    traj->footer(std::string("\n") + angle_help +
                 "\n\nColumns: t_over_T, theta (radians). Every method is evaluated at the same "
                 "physical time t = (t/T) T, with T the exact period.\n\n"
                 "Examples:\n"
                 "  pendulum-figures trajectory --theta0 9pi/10 --method second --samples 201 --periods 2\n"
                 "  pendulum-figures trajectory --theta0 pi/2 --method order --order 8 --at 0,0.125,0.25");

    render_options ro;
    auto* render = app.add_subcommand("render", "Draw figures of the catalog into files (PNG, PDF, SVG, EPS).");
    render->add_option("ids", ro.ids, "Figure ids or aliases (see 'list'), e.g. period fig2")->type_name("ID");
    render->add_flag("--all", ro.all, "Render every figure of the catalog");
    render->add_option("-o,--output-dir", ro.dir, "Existing directory for the files (default: .)")->type_name("DIR");
    render->add_option("-f,--formats", ro.formats, "Comma-separated formats: png, pdf, svg, eps (default: pdf,png)")
        ->type_name("LIST");
    render->add_option("--theme", ro.theme, "paper (default: black and white, serif, paper sizes) or slides (16:9, "
                                            "large text, colour-blind-safe colours)")
        ->type_name("NAME");
    render->add_option("--dpi", ro.dpi, "PNG resolution in dots per inch, 10..2400 (default: 300)")->type_name("N");
    render->add_option("--theta0", ro.theta0, "Amplitudes of the trajectory figures, a comma-separated LIST")
        ->type_name("LIST");
    render->add_flag("--paper-files", ro.paper_files,
                     "One file per panel, named and sized as in the paper's LaTeX source (Fig.C1.Lowest, ...)");
    render->footer(std::string("\n") + angle_help +
                   "\n\nFiles are DIR/ID.EXT (or the paper's names with --paper-files). Each file is written "
                   "under a temporary name and renamed, so a failed run never leaves a partial figure. Set "
                   "SOURCE_DATE_EPOCH to stamp PDF and EPS files with that date; otherwise they carry none.\n\n"
                   "Examples:\n"
                   "  pendulum-figures render --all -o figures -f pdf,png\n"
                   "  pendulum-figures render fig2 --theta0 170deg --theme slides -f png --dpi 150\n"
                   "  pendulum-figures render --all --paper-files -f eps -o paper/");

    auto* list = app.add_subcommand("list", "List the figures: id, figure of the paper, description.");
    list->footer("\nExample:\n  pendulum-figures list\n  pendulum-figures render fig7 -f pdf");

    std::string data_id;
    std::string data_file;
    std::string data_theta0;
    auto* data = app.add_subcommand("data", "Print the data of a figure as CSV: panel,series,x,y.");
    data->add_option("id", data_id, "Figure id or alias (see 'list')")->required()->type_name("ID");
    data->add_option("-o,--output", data_file, "Write to FILE instead of standard output")->type_name("FILE");
    data->add_option("--theta0", data_theta0, "Amplitudes of a trajectory figure, a comma-separated LIST")
        ->type_name("LIST");
    data->footer("\nOne row per plotted point; panels are a, b, c, ... as in the paper's captions.\n\n"
                 "Example:\n  pendulum-figures data period -o period.csv");

    try {
        app.parse(argc, argv);
        std::ostringstream out;
        if (*render) return run_render(ro);
        if (*list) {
            out << list_text();
        } else if (*data) {
            const std::string csv = figure_data(data_id, data_theta0);
            if (!data_file.empty()) {
                plot::write_atomically(data_file, csv);
                return 0;
            }
            out << csv;
        } else if (*eval) {
            cli::write_table(out, eval_table(ev), cli::parse_table_format(ev.format));
        } else if (*traj) {
            if (std::find(method_names.begin(), method_names.end(), tr.method) == method_names.end()) {
                throw usage_error("--method '" + tr.method +
                                  "': unknown method; use exact, harmonic, lowest, first, second, "
                                  "polynomial or order");
            }
            const auto format = cli::parse_table_format(tr.format);
            cli::write_table(out, trajectory_table(tr, order_opt->count() > 0, periods_opt->count() > 0),
                             format);
        }
        std::cout << out.str() << std::flush;
        if (!std::cout) {
            std::cerr << "pendulum-figures: error: cannot write to standard output\n";
            return 1;
        }
        return 0;
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::string message = lowercase_first(e.what());
        if (app.get_subcommands().empty()) {
            // No command, or an unknown word where the command should be.
            if (argc < 2) {
                message = "a command is required: eval, trajectory, list, render or data (see --help)";
            } else if (argv[1][0] != '-') {
                message = std::string("unknown command '") + argv[1] +
                          "'; commands: eval, trajectory, list, render, data (see --help)";
            }
        }
        std::cerr << "pendulum-figures: error: " << message << "\n";
        return 2;
    } catch (const usage_error& e) {
        std::cerr << "pendulum-figures: error: " << e.what() << "\n";
        return 2;
    } catch (const std::invalid_argument& e) {
        std::cerr << "pendulum-figures: error: " << e.what() << "\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "pendulum-figures: error: " << e.what() << "\n";
        return 1;
    }
}
