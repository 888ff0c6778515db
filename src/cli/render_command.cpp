// SPDX-License-Identifier: GPL-3.0-or-later
// render: figures, built in or spec files, into files of the formats asked for.
#include "cli/commands.hpp"
#include "cli/depfile.hpp"
#include "cli/format_help.hpp"
#include "cli/options.hpp"
#include "cli/render_figures.hpp"
#include "cli/report.hpp"
#include "figures/animation.hpp"
#include "figures/plots.hpp"
#include "figures/render_plan.hpp"
#include "figures/themes.hpp"
#include "plot/output.hpp"
#include "plot/preflight.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <deque>
#include <iostream>
#include <filesystem>
#include <stdexcept>
#include <memory>
#include <optional>
#include <utility>

namespace pendulum::cli {

namespace {

/// Parses --frames a..b (1-based, inclusive) into 0-based indices; b may be left out.
std::pair<int, int> parse_frames(const std::string& text, int count) {
    const auto dots = text.find("..");
    const auto number = [&](const std::string& part, int fallback) {
        if (part.empty()) return fallback;
        std::size_t used = 0;
        long long v = -1;
        try {
            v = std::stoll(part, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (used != part.size() || v < 1 || v > count) {
            throw usage_error("--frames '" + text + "': frames are 1.." + std::to_string(count) + ", as A..B");
        }
        return static_cast<int>(v);
    };
    if (dots == std::string::npos) {
        const int one = number(text, 0);
        return {one - 1, one - 1};
    }
    const int a = number(text.substr(0, dots), 1);
    const int b = number(text.substr(dots + 2), count);
    if (a > b) throw usage_error("--frames '" + text + "': the first frame comes after the last");
    return {a - 1, b - 1};
}

/// The program's own file, as the kernel knows it: a new build of it is a new input.
std::string program_file() {
    std::error_code ec;
    const auto self = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (ec) throw std::runtime_error("cannot find the program's file for --depfile: " + ec.message());
    return self.string();
}

/// The files of a --depfile rule: the render's outputs (or --depfile-target) and what they
/// depend on.
struct dependencies {
    std::vector<std::string> targets;  ///< as given or as written, lexically normal
    std::vector<std::string> outputs;  ///< the files the render writes
    std::vector<std::string> inputs;   ///< spec files, style files, the program
};

/// Adds `file` to `files` unless it is there.
void add_once(std::vector<std::string>& files, const std::string& file) {
    if (std::find(files.begin(), files.end(), file) == files.end()) files.push_back(file);
}

/// The measured data files of the specs' panels ([[panel.data]]).
void add_data_files(std::vector<std::string>& files,
                    const std::vector<std::pair<std::string, std::vector<const figures::entry*>>>& groups) {
    for (const auto& g : groups) {
        for (const auto* e : g.second) {
            for (const auto& panel : e->spec.panels) {
                for (const auto& d : panel.data) {
                    if (!d.file.empty()) add_once(files, d.file);
                }
            }
        }
    }
}

/// The --depfile rule's files: every output of the render (or --depfile-target) depends on the
/// spec files, the style files used and the program.
dependencies dependency_files(const render_options& o,
                              const std::vector<std::pair<std::string, std::vector<const figures::entry*>>>& groups,
                              const std::vector<std::filesystem::path>& outputs) {
    dependencies d;
    // Spec files are the ids ending in .toml (as selected_figures reads them); built-in
    // figures are in the program.
    for (const auto& id : o.ids) {
        if (id.ends_with(".toml")) add_once(d.inputs, id);
    }
    if (o.theme.ends_with(".toml")) add_once(d.inputs, o.theme);
    for (const auto& g : groups) {
        if (!g.first.empty()) add_once(d.inputs, g.first);
    }
    add_data_files(d.inputs, groups);
    add_once(d.inputs, program_file());
    for (const auto& path : outputs) d.outputs.push_back(path.lexically_normal().string());
    d.targets = o.depfile_target.empty() ? d.outputs : std::vector<std::string>{o.depfile_target};
    return d;
}

/// True when a and b name one file: the same path, or the same existing file by another path.
bool same_file(const std::filesystem::path& a, const std::filesystem::path& b) {
    if (std::filesystem::absolute(a).lexically_normal() == std::filesystem::absolute(b).lexically_normal()) return true;
    std::error_code ec;
    return std::filesystem::equivalent(a, b, ec) && !ec;
}

/// The --depfile rule, after checking that the dependency file is none of the files it names
/// (a spec, a style, an output): refused before any work.
std::string dependency_rule(const render_options& o, const dependencies& d) {
    for (const auto* list : {&d.inputs, &d.outputs}) {
        for (const auto& file : *list) {
            if (same_file(o.depfile, file)) {
                throw usage_error("--depfile '" + shown_text(o.depfile) + "' is " +
                                  (list == &d.inputs ? "an input" : "an output") + " of the render (" +
                                  shown_text(file) + "); name another file");
            }
        }
    }
    try {
        return make_rule(d.targets, d.inputs);
    } catch (const std::invalid_argument& e) {
        throw usage_error(std::string("--depfile: ") + e.what());
    }
}

/// The figures grouped by their style file (one group, the command line's, with --theme).
using style_groups = std::vector<std::pair<std::string, std::vector<const figures::entry*>>>;

/// -f's formats, each once, refusing an overlay format with its drawing's (both write ID.pdf).
std::vector<std::string> chosen_formats(const render_options& o) {
    std::vector<std::string> formats;
    for (const auto& f : split_list(o.formats)) {
        plot::check_format(f);
        if (std::find(formats.begin(), formats.end(), f) == formats.end()) formats.push_back(f);
    }
    // An overlay format writes its drawing under the drawing format's name.
    for (const auto& row : plot::format_table()) {
        if (row.graphics.empty()) continue;
        const std::string overlay(row.name);
        const std::string graphics(row.graphics);
        if (std::count(formats.begin(), formats.end(), graphics) && std::count(formats.begin(), formats.end(), overlay)) {
            throw usage_error("-f " + o.formats + ": " + graphics + " and " + overlay + " both write ID." + graphics +
                              " (" + overlay + "'s without its text); render them into different directories");
        }
    }
    return formats;
}

/// What the LaTeX overlays need (--tex-sizes, --tex-font-size); dpi is set per theme.
plot::output_options overlay_options(const render_options& o) {
    plot::output_options overlay;
    try {
        overlay.tex_sizes = plot::find_tex_sizing(o.tex_sizes).value;
    } catch (const plot::bad_input& e) {
        throw usage_error(std::string("--tex-sizes: ") + e.what());
    }
    if (!o.tex_font_size) return overlay;
    if (!(*o.tex_font_size >= 5 && *o.tex_font_size <= 30)) {
        throw usage_error("--tex-font-size " + format_double(*o.tex_font_size) +
                          ": the document's font size in points, 5 to 30");
    }
    if (overlay.tex_sizes == plot::tex_sizing::absolute) {
        throw usage_error("--tex-font-size does nothing with --tex-sizes absolute: the text has the theme's "
                          "sizes in points (--set tick_font_pt=... changes them)");
    }
    overlay.tex_font_pt = *o.tex_font_size;
    return overlay;
}

/// --set, with --size as the style key size_px at the resolution of --dpi where one is given.
std::vector<std::string> style_sets(const render_options& o) {
    std::vector<std::string> sets = o.sets;
    if (!o.size.empty()) {
        if (o.dpi) sets.push_back("dpi=" + format_double(*o.dpi));
        sets.push_back("size_px=" + o.size);
    }
    return sets;
}

/// What the themes of every style share: --set, the overlays' options, the workers.
struct style_inputs {
    std::vector<std::string> sets;  ///< --set and --size
    plot::output_options overlay;   ///< the LaTeX overlays' options
    unsigned workers;               ///< worker threads
};

/// The themes of a style: --theme over the spec's style file over paper (slides for
/// animations), with --set on top.
figures::render_style style_for(const render_options& o, const style_inputs& in, const std::string& style_file) {
    const std::string still = !o.theme.empty() ? o.theme : !style_file.empty() ? style_file : "paper";
    const plot::theme theme = chosen_theme(still, in.sets);
    // Animations are for slides: theirs unless a theme or style file is asked for.
    const plot::theme moving_theme = still == "paper" && o.theme.empty() ? chosen_theme("slides", in.sets) : theme;
    const double dpi = o.dpi.value_or(theme.dpi);
    const double moving_dpi = o.dpi.value_or(moving_theme.dpi);
    for (const double d : {dpi, moving_dpi}) {
        if (!(d >= plot::min_dpi && d <= plot::max_dpi)) {
            throw usage_error("--dpi " + format_double(d) + ": must be between " + format_double(plot::min_dpi) +
                              " and " + format_double(plot::max_dpi));
        }
    }
    const plot::output_options& ov = in.overlay;
    return figures::render_style{theme, plot::output_options{dpi, o.force, ov.tex_font_pt, ov.tex_sizes, in.workers},
                                 moving_theme,
                                 plot::output_options{moving_dpi, o.force, ov.tex_font_pt, ov.tex_sizes, in.workers}};
}

/// The figures grouped by their style file (one group, the command line's, with --theme).
style_groups grouped_by_style(const std::vector<const figures::entry*>& chosen, const render_options& o) {
    style_groups groups;
    for (const auto* e : chosen) {
        const std::string style_file = o.theme.empty() ? e->spec.style : std::string();
        auto it = std::find_if(groups.begin(), groups.end(), [&](const auto& g) { return g.first == style_file; });
        if (it == groups.end()) it = groups.insert(groups.end(), {style_file, {}});
        it->second.push_back(e);
    }
    return groups;
}

/// Each group's style; a style file that cannot be read or has problems is the spec's to correct.
std::vector<figures::render_style> styles_of(const style_groups& groups, const render_options& o,
                                             const style_inputs& in) {
    std::vector<figures::render_style> styles;
    for (const auto& g : groups) {
        try {
            styles.push_back(style_for(o, in, g.first));
        } catch (const std::invalid_argument& e) {
            if (g.first.empty()) throw;
            throw usage_error("figure '" + g.second.front()->id + "' ([figure] style = " + g.first + "): " + e.what());
        }
    }
    return styles;
}

/// --theta0, for figures that take amplitudes.
figures::build_options build_options_of(const std::vector<const figures::entry*>& chosen, const render_options& o) {
    figures::build_options build;
    if (o.theta0.empty()) return build;
    if (std::none_of(chosen.begin(), chosen.end(), [](const auto* e) { return e->takes_amplitudes(); })) {
        throw usage_error("--theta0 applies to figures with " + figures::plot_names(true, "or") + " panels, "
                          "and none was chosen");
    }
    build.amplitudes = parse_amplitudes(o.theta0, figures::max_amplitudes_per_panel);
    return build;
}

/// --at in seconds (10s) as t/T of the one animation chosen, whose [pendulum] table gives
/// the seconds; with several animations or none with a length, a usage_error says what works.
double seconds_as_periods(const std::vector<const figures::entry*>& chosen, const render_options& o,
                          const figures::build_options& build, double seconds) {
    const figures::entry* moving = nullptr;
    for (const auto* e : chosen) {
        if (!e->spec.animation) continue;
        if (moving) throw usage_error("--at " + o.at + ": a time in seconds goes with one animation; give t/T for several");
        moving = e;
    }
    if (!moving->spec.pendulum) {
        throw usage_error("--at " + o.at + ": a time in seconds needs the animation's [pendulum] table (length_m, g); "
                          "'" + moving->id + "' has none: give t/T (e.g. --at 0.25)");
    }
    const figures::animation_plan plan = figures::plan_animation(*moving, build);
    return seconds / (plan.seconds_per_unit * plan.reference_period);
}

/// --at: one frame at time t/T, or in seconds (10s) with a [pendulum] table, or nothing;
/// --frames and --at for animations only, not both.
std::optional<double> frame_time(const std::vector<const figures::entry*>& chosen, const render_options& o,
                                 const figures::build_options& build) {
    if ((!o.frames.empty() || !o.at.empty()) &&
        std::none_of(chosen.begin(), chosen.end(), [](const auto* e) { return e->spec.animation.has_value(); })) {
        throw usage_error("--frames and --at apply to animations, and none was chosen (see 'list')");
    }
    if (!o.frames.empty() && !o.at.empty()) throw usage_error("give --frames or --at, not both");
    if (o.at.empty()) return std::nullopt;
    const given_time t = parse_time("--at", o.at);
    const double at = t.seconds && std::isfinite(t.value) ? seconds_as_periods(chosen, o, build, t.value) : t.value;
    // t/T is multiplied by the period: a huge one would be no time at all.
    if (!(std::fabs(at) <= 1e6)) {
        throw usage_error("--at " + o.at + ": a time t/T must be finite and at most 1e6 in size");
    }
    return at;
}

/// The files of every group, checked together before any work.
struct render_jobs {
    std::vector<std::vector<figures::figure_file>> stills;     ///< each group's still files
    std::vector<std::vector<figures::animation_job>> moving;   ///< each group's animations
    std::vector<figures::figure_file> all_stills;              ///< every group's still files
    std::vector<figures::animation_job> all_moving;            ///< every group's animations
};

/// --paper-files writes each still panel to a file sized as in the paper: no animations, no
/// whole-figure sizes.
void check_paper_files(const render_options& o, const plot::theme& theme, bool animations) {
    if (!o.paper_files) return;
    if (animations) throw usage_error("--paper-files applies to still figures, not to animations");
    for (const char* key : {"figure_width_cm", "figure_height_cm", "size_px"}) {
        if (theme.given.contains(key)) {
            throw usage_error(std::string(key) + " sizes a whole figure, and --paper-files writes each panel to a "
                              "file of its own, sized as in the paper's source: set panel_width_cm instead");
        }
    }
}

/// Plans one group's files: its animations' frames, its still files, its rasters' sizes.
void plan_group(render_jobs& jobs, std::size_t g, const style_groups& groups, const std::vector<std::string>& formats,
                const render_options& o, const figures::build_options& build,
                const std::vector<figures::render_style>& styles) {
    std::vector<const figures::entry*> stills;
    for (const auto* e : groups[g].second) {
        if (!e->spec.animation) {
            stills.push_back(e);
            continue;
        }
        const auto plan = figures::plan_animation(*e, build);
        const auto [first, last] = o.frames.empty() ? std::pair{0, plan.frames - 1} : parse_frames(o.frames, plan.frames);
        jobs.moving[g].push_back({e, plan, first, last});
    }
    check_paper_files(o, styles[g].still_theme, !jobs.moving[g].empty());
    jobs.stills[g] = figures::files_for(stills, formats, o.dir, o.paper_files, build);
    // Rasters too large for Cairo or for memory are refused before any work.
    figures::check_raster_sizes(groups[g].second, formats, build, styles[g]);
    jobs.all_stills.insert(jobs.all_stills.end(), jobs.stills[g].begin(), jobs.stills[g].end());
    jobs.all_moving.insert(jobs.all_moving.end(), jobs.moving[g].begin(), jobs.moving[g].end());
}

/// One still figure in one format, to standard output (-o -).
int render_to_stdout(const std::vector<const figures::entry*>& chosen, const std::vector<std::string>& formats,
                     const render_options& o, const figures::build_options& build,
                     const figures::render_style& style) {
    if (chosen.size() != 1 || formats.size() != 1 || o.paper_files || chosen.front()->spec.animation) {
        throw usage_error("-o - writes one still figure in one format to standard output");
    }
    if (!o.depfile.empty()) throw usage_error("--depfile names the files a render writes, and -o - writes none");
    return write_stdout(figures::render_one(*chosen.front(), build, style.still_theme, formats.front(),
                                            plot::output_options{style.still.dpi}));
}

/// --check: the options it cannot go with, refused before any work.
void check_check_options(const render_options& o) {
    if (o.dir == "-" || !o.depfile.empty() || o.paper_files) {
        throw usage_error("--check measures the figures and writes no file: drop -o -, --depfile and --paper-files");
    }
}

/// --check: refuses animations, and figures whose drawing would cost too much (as a PDF's
/// would), before any work.
void check_before_measuring(const std::vector<const figures::entry*>& chosen, const style_groups& groups,
                            const std::vector<figures::render_style>& styles, const figures::build_options& build,
                            const render_options& o) {
    for (const auto* e : chosen) {
        if (e->spec.animation) {
            throw usage_error("--check measures still figures, and '" + shown_text(e->id) +
                              "' is an animation (render a frame with --at and look at it)");
        }
    }
    const std::vector<std::string> pdf{"pdf"};
    render_jobs jobs{std::vector<std::vector<figures::figure_file>>(groups.size()),
                     std::vector<std::vector<figures::animation_job>>(groups.size()), {}, {}};
    for (std::size_t g = 0; g < groups.size(); ++g) plan_group(jobs, g, groups, pdf, o, build, styles);
    figures::check_render_cost(jobs.stills, jobs.moving, pdf, build, styles, false);
}

/// --check JOURNAL: each chosen figure drawn as its files would be and measured against the
/// journal's rules (plot::preflight_problems); one line per problem on standard output, and
/// exit status 1 when a figure breaks a rule. No file is written.
int check_figures(const std::vector<const figures::entry*>& chosen, const style_groups& groups,
                  const std::vector<figures::render_style>& styles, const figures::build_options& build,
                  const render_options& o, const plot::journal_check& journal) {
    check_before_measuring(chosen, groups, styles, build, o);
    const std::string name(journal.rules->name);
    int failed = 0;
    int count = 0;
    for (std::size_t g = 0; g < groups.size(); ++g) {
        const plot::theme& th = styles[g].still_theme;
        for (const auto* e : groups[g].second) {
            const plot::figure_measure m = plot::measure_figure(figures::build(*e, figures::sized_by(build, th)), th);
            const std::vector<std::string> problems = plot::preflight_problems(m, journal);
            ++count;
            failed += problems.empty() ? 0 : 1;
            for (const auto& p : problems) std::cout << shown_text(e->id) << ": " << shown_text(p) << '\n';
            if (problems.empty()) {
                const bool one = journal.span != plot::column_span::two &&
                                 m.width_cm <= journal.rules->column_cm + 1e-6;
                std::cout << shown_text(e->id) << ": keeps to " << name << "'s rules ("
                          << format_double(std::round(m.width_cm * 1000) / 1000) << " cm wide, "
                          << (one ? "one column" : "two columns") << ")\n";
                const std::string note = plot::scaling_note(m, journal);
                if (!note.empty()) std::cout << shown_text(e->id) << ": note: " << note << '\n';
            }
        }
    }
    if (failed > 0) {
        std::cerr << failed << " of " << count << (count == 1 ? " figure breaks " : " figures break ") << name
                  << "'s rules for figures (see above)\n";
    }
    return failed > 0 ? 1 : 0;
}

}  // namespace

int render_figures(const std::vector<const figures::entry*>& chosen, const render_options& o) {
    // The environment is input too: a bad SOURCE_DATE_EPOCH stops the run before any work.
    plot::pdf_creation_date();
    const std::optional<plot::journal_check> journal =
        o.check.empty() ? std::nullopt : std::optional(plot::find_journal(o.check));
    if (journal) check_check_options(o);
    const std::vector<std::string> formats = chosen_formats(o);
    const plot::output_options overlay = overlay_options(o);
    const style_inputs in{style_sets(o), overlay, chosen_jobs(o.jobs)};
    const style_groups groups = grouped_by_style(chosen, o);
    const std::vector<figures::render_style> styles = styles_of(groups, o, in);
    const figures::build_options build = build_options_of(chosen, o);
    if (journal) return check_figures(chosen, groups, styles, build, o, *journal);
    if (o.dir == "-") return render_to_stdout(chosen, formats, o, build, styles.front());
    check_output_dir(o.dir);
    const std::optional<double> at = frame_time(chosen, o, build);

    // Every group's files, checked together before any work.
    render_jobs jobs{std::vector<std::vector<figures::figure_file>>(groups.size()),
                     std::vector<std::vector<figures::animation_job>>(groups.size()), {}, {}};
    for (std::size_t g = 0; g < groups.size(); ++g) plan_group(jobs, g, groups, formats, o, build, styles);
    if (jobs.all_stills.empty() && jobs.all_moving.empty()) {
        throw usage_error("the chosen figures have no panels in the paper; drop --paper-files");
    }
    figures::check_distinct_outputs(jobs.all_stills, jobs.all_moving, formats, o.dir, at.has_value());
    // Every output, the depfile too, is a new file or replaces a regular one: checked before any work.
    std::vector<std::filesystem::path> outputs;
    for (const auto& output : figures::render_outputs(jobs.all_stills, jobs.all_moving, formats, o.dir, at.has_value())) {
        outputs.push_back(output.first);
    }
    plot::check_output_files(outputs);
    if (!o.depfile.empty()) plot::check_output_file(o.depfile);
    figures::check_render_cost(jobs.stills, jobs.moving, formats, build, styles, at.has_value());
    const std::string depfile = o.depfile.empty() ? std::string() : dependency_rule(o, dependency_files(o, groups, outputs));
    for (std::size_t g = 0; g < groups.size(); ++g) {
        figures::write_render(jobs.stills[g], jobs.moving[g], formats, o.dir, build, styles[g], at);
    }
    // Written last and always: its time is the time of the run, so make can use it as a stamp.
    if (!o.depfile.empty()) plot::write_atomically(o.depfile, depfile);
    return 0;
}

command add_render_command(CLI::App& app) {
    auto ro = std::make_shared<render_options>();
    auto* cmd = app.add_subcommand("render", "Draw figures (built-in or spec files) into files: " + format_list() + ".");
    cmd->add_option("ids", ro->ids, "Figure ids or aliases (see 'list'), or spec files NAME.toml")->type_name("ID");
    cmd->add_flag("--all", ro->all, "Render every built-in still figure (and the figures given with it); animations are rendered by name");
    cmd->add_option("-o,--output-dir", ro->dir, "Existing directory for the files (default: .); - writes one "
                                                  "figure in one format to standard output")->type_name("DIR")->check(non_empty);
    cmd->add_option("-f,--formats", ro->formats, "Comma-separated formats (default: pdf,png): " + format_help())
        ->type_name("LIST")->check(non_empty);
    cmd->add_option("--theme", ro->theme, figures::theme_help() + "; default paper, slides for animations")
        ->type_name("NAME")->check(non_empty);
    cmd->add_option("--set", ro->sets, "KEY=VALUE of a style file on top of the theme, e.g. tick_font_pt=9; "
                                         "repeatable ('show --theme paper' lists the keys)")
        ->type_name("KEY=VALUE")->check(non_empty);
    cmd->add_option("--size", ro->size, "A raster of WIDTHxHEIGHT pixels, e.g. 1920x1080: the figure is that size "
                                        "at the resolution (--dpi or the theme's) and laid out for it")
        ->type_name("WxH")
        ->check(non_empty);
    cmd->add_option("--dpi", ro->dpi, "Resolution of " + raster_formats() + " in dots per inch, 10..2400 (default: "
                                        "the theme's, 300 for paper)")
        ->type_name("N");
    cmd->add_option("--theta0", ro->theta0, "Amplitudes of the trajectory figures, a comma-separated LIST")
        ->type_name("LIST")->check(non_empty);
    cmd->add_option("--frames", ro->frames, "Animations: only frames A..B (from 1; A.. or ..B for the rest)")
        ->type_name("A..B")->check(non_empty);
    cmd->add_option("--at", ro->at, "Animations: one frame at time t/T (T the exact period of the first "
                                      "amplitude), or in seconds (10s) with the spec's [pendulum], in every format")
        ->type_name("T")->check(non_empty);
    cmd->add_flag("--force", ro->force, "Rewrite files that would not change (by default they are left alone, "
                                          "so their time stays and make does not rebuild)");
    cmd->add_option("--tex-font-size", ro->tex_font_size,
                       overlay_formats() + ": the document's font size in points, 5..30 (default 10); the figure's "
                       "text is set at sizes relative to it (\\footnotesize, \\small) and laid out to fit")
        ->type_name("PT");
    {
        std::string help = overlay_formats() + ": how the text is sized (default relative):";
        for (const auto& row : plot::tex_sizing_table()) {
            help += "\n  " + std::string(row.name) + ": " + std::string(row.description);
        }
        cmd->add_option("--tex-sizes", ro->tex_sizes, help)->type_name("HOW");
    }
    cmd->add_option("--depfile", ro->depfile, "Write a dependency FILE in Make syntax (as gcc -MD): the outputs "
                                                "depend on the spec files, the style files and the program; for "
                                                "make and ninja (see the README)")
        ->type_name("FILE")->check(non_empty);
    cmd->add_option("--depfile-target", ro->depfile_target, "The dependency file's target instead of the outputs "
                                                              "(as gcc -MT): a stamp file, for make")
        ->type_name("NAME")->check(non_empty)->needs("--depfile");
    cmd->add_flag("--paper-files", ro->paper_files,
                     "One file per panel, named and sized as in the paper's LaTeX source (Fig.C1.Lowest, ...)");
    cmd->add_option("--jobs", ro->jobs, jobs_help)->type_name("N");
    cmd->add_option("--check", ro->check,
                    "Write nothing: measure each figure as drawn against a JOURNAL's rules for figures (" +
                        plot::journal_names() + "; JOURNAL:1 one column, :2 two): every text's size, every "
                        "line's width, the figure's width, series that merge in greyscale; exit status 1 if any "
                        "breaks one")
        ->type_name("JOURNAL")
        ->check(non_empty);
    cmd->footer(std::string("\n") + angle_help +
                   "\n\nFiles are DIR/ID.EXT (or the paper's names with --paper-files). Each file is written "
                   "under a temporary name and renamed, so a failed run never leaves a partial figure. Set "
                   "SOURCE_DATE_EPOCH to stamp PDF and EPS files with that date; otherwise they carry none.\n\n"
                   "Examples:\n"
                   "  pendulum-figures render --all -o figures -f pdf,png\n"
                   "  pendulum-figures render fig2 --theta0 170deg --theme slides -f png --dpi 150\n"
                   "  pendulum-figures render --all --paper-files -f eps -o paper/\n"
                   "\nLaTeX sets the text: -f pdf_tex writes ID.pdf without text and ID.pdf_tex, which the document "
                   "reads with \\usepackage{graphicx} and \\input{ID.pdf_tex}: every label in the document's own "
                   "fonts, at \\footnotesize or \\small of its size (--tex-font-size), or at the theme's sizes in "
                   "points with --tex-sizes absolute (with Computer Modern: \\RequirePackage{fix-cm} first). "
                   "\\def\\figurewidth{8.6cm} "
                   "before \\input scales the drawing, not the text. eps_tex is the same for latex and dvips. Labels "
                   "are the specs' TeX, verbatim; a macro LaTeX lacks shows only when the document is compiled.\n"
                   "  pendulum-figures render fig2 -f pdf_tex -o figures --tex-font-size 10\n"
                   "  pendulum-figures render fig7 -f eps_tex --tex-sizes absolute --set tick_font_pt=8\n"
                   "\nAnimations (a spec with [animation]; built in: swing, separatrix, over-the-top) are written as " +
                   animation_help() + ". In Beamer: \\usepackage{animate} and "
                   "\\animategraphics[loop,autoplay]{25}{swing}{}{} (25: the spec's fps). A video: ffmpeg -framerate "
                   "25 -i swing-%04d.png -pix_fmt yuv420p swing.mp4\n"
                   "  pendulum-figures render swing --theme slides -f gif,pdf\n"
                   "  pendulum-figures render swing --at 0.25 -f svg");
    return {cmd, [ro] {
                std::deque<figures::entry> loaded;
                return render_figures(figures::selected_figures(ro->ids, ro->all, loaded), *ro);
            }};
}

}  // namespace pendulum::cli
