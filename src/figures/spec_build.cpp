// SPDX-License-Identifier: GPL-3.0-or-later
#include "figures/spec_build.hpp"

#include "figures/describe.hpp"
#include "figures/errors.hpp"
#include "figures/figure_data.hpp"
#include "figures/panel_support.hpp"
#include "pendulum/formula.hpp"
#include "plot/tex_markup.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <mutex>
#include <stdexcept>

namespace figures {

namespace {

std::string panel_letter(std::size_t i) {
    // Appended, not "(" + name: GCC 12 warns wrongly (-Wrestrict) on a literal plus a temporary.
    std::string letter(1, '(');
    letter += panel_name(i);
    letter += ')';
    return letter;
}

}  // namespace

namespace {

/// A panel that takes one amplitude and becomes one panel per amplitude.
bool per_amplitude(const panel_spec& p) { return p.plot->amplitudes == amplitude_policy::one_per_panel; }

/// The panels per amplitude, in place of the spec's first such panel: the spec's i-th such
/// panel for the i-th amplitude, or copies of the first (without its paper file) past them.
void add_amplitude_panels(std::vector<panel_spec>& out, const figure_spec& spec, const panel_spec& first,
                          const build_options& o) {
    std::vector<const panel_spec*> trajectories;
    for (const auto& p : spec.panels) {
        if (per_amplitude(p)) trajectories.push_back(&p);
    }
    for (std::size_t i = 0; i < o.amplitudes.size(); ++i) {
        panel_spec q = i < trajectories.size() ? *trajectories[i] : first;
        if (i >= trajectories.size()) q.paper_file.clear();
        q.theta0 = {o.amplitudes[i]};
        q.starts.clear();
        q.title.reset();
        out.push_back(std::move(q));
    }
}

/// A panel of another kind with --theta0's amplitudes, as many as it takes.
panel_spec with_amplitudes(const panel_spec& p, const build_options& o) {
    panel_spec q = p;
    if (p.plot->amplitudes != amplitude_policy::none) q.starts.clear();
    if (p.plot->amplitudes == amplitude_policy::list) {
        q.theta0 = o.amplitudes;
    } else if (p.plot->amplitudes == amplitude_policy::one) {
        q.theta0 = {o.amplitudes.front()};
    }
    return q;
}

}  // namespace

std::vector<panel_spec> panels_with(const figure_spec& spec, const build_options& o) {
    if (o.amplitudes.empty()) return spec.panels;
    std::vector<panel_spec> out;
    const auto first_trajectory = std::find_if(spec.panels.begin(), spec.panels.end(), per_amplitude);
    for (const auto& p : spec.panels) {
        if (!per_amplitude(p)) {
            out.push_back(with_amplitudes(p, o));
        } else if (&p == &*first_trajectory) {
            add_amplitude_panels(out, spec, p, o);
        }
    }
    return out;
}

void add_frame_state(plot::figure& f, const figure_spec& spec, const std::vector<panel_spec>& panels, double w0_t,
                     double frame_step, double history) {
    const panel_context c{spec, f.panel_width_cm, true, frame_step, history};
    for (std::size_t i = 0; i < panels.size() && i < f.panels.size(); ++i) {
        const panel_spec& p = panels[i];
        if (!p.plot->add_frame) continue;
        plot::panel& panel = f.panels[i];
        const std::size_t still = panel.data.size();
        p.plot->add_frame(panel, c, p, w0_t);
        // Everything added here moves: the overlay pass of a frame draws it.
        for (std::size_t k = still; k < panel.data.size(); ++k) panel.data[k].overlay = true;
    }
}

std::string panel_name(std::size_t i) {
    std::string letters;
    for (std::size_t n = i + 1; n > 0; n = (n - 1) / 26) letters.insert(letters.begin(), static_cast<char>('a' + (n - 1) % 26));
    return letters;
}

plot::label method_label(const pendulum::method_choice& m) {
    if (m.user) {
        // A user's formula reads as math (sqrt as a root, theta0 as a subscripted theta);
        // one whose TeX is past a label's bounds (bytes, nesting) reads as its text.
        const std::string tex = "$" + pendulum::formula_tex(*m.user) + "$";
        try {
            if (tex.size() <= plot::max_label_bytes) return plot::tex_label(tex);
        } catch (const std::invalid_argument&) {
        }
    }
    return plot::tex_label(m.label());
}

plot::figure figure_grid(const figure_spec& spec, const build_options& options) {
    const int n = static_cast<int>(panels_with(spec, options).size());
    if (n == 0) throw bad_input("figure '" + spec.id + "' has no panels");
    if (n > max_panels) {
        throw bad_input("figure '" + spec.id + "' would have " + std::to_string(n) +
                        " panels (one per --theta0 amplitude); a figure has at most " + std::to_string(max_panels));
    }
    plot::figure f;
    f.cols = std::min(spec.columns.value_or(3), n);
    f.rows = (n + f.cols - 1) / f.cols;
    f.panel_width_cm = options.panel_width_given ? options.panel_width_cm
                                                 : spec.panel_width_cm.value_or(options.panel_width_cm);
    f.panel_aspect = options.panel_aspect_given ? options.panel_aspect : spec.panel_aspect.value_or(options.panel_aspect);
    f.shared_legend = spec.legend == legend_mode::first;
    if (!spec.title.empty()) f.title = plot::tex_label(spec.title);
    return f;
}

namespace {

/// A series of the panel's methods with no value at all (a scheme without a period there)
/// would be a legend entry over nothing: refused, naming the series and the amplitudes. A
/// series of no points at all is a legend key (a drawing's, for the rods its frames draw).
void require_values(const plot::panel& panel, const panel_spec& p, std::size_t index) {
    for (const auto& s : panel.data) {
        if (s.label.empty() || s.overlay || s.x.empty()) continue;
        if (std::any_of(s.y.begin(), s.y.end(), [](double v) { return std::isfinite(v); })) continue;
        std::string at;
        for (const auto& a : p.theta0) at += (at.empty() ? "" : ", ") + a.text;
        throw bad_input("panel " + std::to_string(index + 1) + " (" + std::string(p.plot->name) +
                        (at.empty() ? "" : ", theta0 = " + at) + "): '" + plain_text(s.label.markup) +
                        "' has no value there (a scheme without a period at that amplitude); choose another "
                        "method or order, or amplitudes further from pi");
    }
}

}  // namespace

namespace {

/// The extent of an axis a reference line crosses: from limit to limit, or past the data by
/// the widest margin an axis adds where the axis has no limit, so the line meets the frame.
std::array<double, 2> line_extent(const plot::panel& panel, const plot::axis& a, bool horizontal) {
    double lo = a.min.value_or(std::numeric_limits<double>::infinity());
    double hi = a.max.value_or(-std::numeric_limits<double>::infinity());
    for (const auto& d : panel.data) {
        for (double v : horizontal ? d.x : d.y) {
            if (!std::isfinite(v) || !d.autoscale) continue;
            if (!a.min) lo = std::min(lo, v);
            if (!a.max) hi = std::max(hi, v);
        }
    }
    const double pad = a.kind == plot::scale::log ? 0.0 : (hi - lo);
    return std::array<double, 2>{a.min ? lo : lo - pad, a.max ? hi : hi + pad};
}

/// A reference line's series: it crosses the whole panel, from limit to limit of the other
/// axis (its data range when the axis has no limits), and leaves the limits alone.
plot::series line_series(const plot::panel& panel, const reference_line& line, std::size_t number) {
    plot::series s;
    s.id = "line:" + std::to_string(number);
    if (!line.label.empty()) s.label = plot::tex_label(line.label);
    s.line = line.style;
    s.autoscale = false;
    if (line.span) {
        const auto& [from, to] = *line.span;
        s.x = line.y ? std::vector<double>{from, to} : std::vector<double>{*line.x, *line.x};
        s.y = line.y ? std::vector<double>{*line.y, *line.y} : std::vector<double>{from, to};
    } else if (line.y) {
        const auto x = line_extent(panel, panel.x, true);
        s.x = {x[0], x[1]};
        s.y = {*line.y, *line.y};
    } else {
        const auto y = line_extent(panel, panel.y, false);
        s.x = {*line.x, *line.x};
        s.y = {y[0], y[1]};
    }
    return s;
}

/// The spec's y range, axis labels and title: "(a)" before a panel's own title where the
/// figure has several panels.
void label_panel(plot::panel& panel, const panel_spec& p, std::size_t i, std::size_t count) {
    if (p.y_range) {
        panel.y.min = (*p.y_range)[0];
        panel.y.max = (*p.y_range)[1];
        panel.y.exact_range = true;
    }
    if (p.paper_y_range) panel.y.paper_range = std::pair{(*p.paper_y_range)[0], (*p.paper_y_range)[1]};
    if (p.x_label) panel.x.label = plot::tex_label(*p.x_label);
    if (p.y_label) panel.y.label = plot::tex_label(*p.y_label);
    const std::string letter = count > 1 ? panel_letter(i) : "";
    if (p.title) {
        panel.label = plot::tex_label(*p.title);
    } else if (p.plot->amplitudes == amplitude_policy::one_per_panel || !panel.label.empty()) {
        // A panel that names its one start (a trajectory's amplitude, a drawing's start).
        if (!letter.empty()) panel.label = plot::join(plot::label(letter + " "), panel.label);
    } else {
        panel.label = letter;
    }
}

/// The figure in words travels with it, into the files that can hold them; found when
/// first asked for, once, from the figure as built (and the layout of the first file's
/// drawing, where it is the one the words speak of).
void attach_words(plot::figure& f, const figure_spec& spec, const build_options& options) {
    struct found {
        std::once_flag once;
        plot::figure_words words;
    };
    f.words = [whole = std::make_shared<const plot::figure>(f), memo = std::make_shared<found>(), spec,
               options](const plot::drawing* drawn) {
        std::call_once(memo->once, [&] {
            const figure_description d = describe(spec, *whole, options, drawn);
            memo->words = {d.alt, d.text};
        });
        return memo->words;
    };
}

}  // namespace

plot::figure build_figure(const figure_spec& spec, const build_options& options) {
    const auto panels = panels_with(spec, options);
    plot::figure f = figure_grid(spec, options);
    const panel_context c{spec, f.panel_width_cm, options.animated, 0.0};
    for (std::size_t i = 0; i < panels.size(); ++i) {
        const auto& p = panels[i];
        plot::panel panel = p.plot->build(c, p);
        require_values(panel, p, i);
        label_panel(panel, p, i, panels.size());
        if (spec.legend == legend_mode::none) panel.legend = plot::legend_place::none;
        for (std::size_t l = 0; l < p.lines.size(); ++l) panel.data.push_back(line_series(panel, p.lines[l], l + 1));
        give_series_ids(panel);
        f.panels.push_back(std::move(panel));
    }
    attach_words(f, spec, options);
    return f;
}

}  // namespace figures
