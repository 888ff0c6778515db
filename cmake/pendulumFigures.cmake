# SPDX-License-Identifier: GPL-3.0-or-later
# pendulum_add_figures: figures for CMake-built documentation, rendered by pendulum-figures
# with its dependency file, so that an edited spec or style file (or a new program) renders
# them again.
#
#   pendulum_add_figures(TARGET docs-figures [ALL]
#                        SPECS a.toml b.toml [period ...]
#                        [FORMATS pdf svg ...] [OUTPUT_DIR dir] [THEME name|file.toml]
#                        [OPTIONS --set tick_font_pt=8 ...] [JOBS n] [OUTPUTS_VARIABLE var])
#
# SPECS are spec files (relative to the current source directory) or built-in figure ids as
# `pendulum-figures list` prints them (not the aliases fig1 ...); FORMATS default to pdf;
# OUTPUT_DIR defaults to figures/ in the current binary directory. Each spec is one render:
# OUTPUT_DIR/NAME.FORMAT for every format, NAME the spec file's name without .toml (a
# LaTeX overlay format, pdf_tex or eps_tex, writes its drawing NAME.pdf or NAME.eps too).
# OUTPUTS_VARIABLE receives the list of files, for a document's DEPENDS. The program is
# PENDULUM_FIGURES_EXECUTABLE: the one installed with this package (or the build tree's, for
# -Dpendulum_DIR=<build directory>), or found on PATH.
#
# Each render runs with JOBS workers (--jobs, default 1): the build runs renders in parallel
# as it runs compiles (ninja -jN, make -jN), and a render's own default, one worker per CPU,
# would run N times as many workers as the build was given.
#
# With Ninja, a figure whose bytes did not change is left untouched and CMake's restat
# keeps what depends on it from rebuilding; Makefile generators have no restat, so there
# the files are always rewritten (--force) and the build is up to date after one run.

function(pendulum_add_figures)
    cmake_parse_arguments(PARSE_ARGV 0 arg "ALL" "TARGET;OUTPUT_DIR;THEME;JOBS;OUTPUTS_VARIABLE"
                          "SPECS;FORMATS;OPTIONS")
    if(arg_UNPARSED_ARGUMENTS)
        message(FATAL_ERROR "pendulum_add_figures: unknown arguments ${arg_UNPARSED_ARGUMENTS}; it takes TARGET, "
                            "ALL, SPECS, FORMATS, OUTPUT_DIR, THEME, OPTIONS, JOBS and OUTPUTS_VARIABLE")
    endif()
    if(NOT arg_TARGET OR NOT arg_SPECS)
        message(FATAL_ERROR "pendulum_add_figures: give TARGET name and SPECS file.toml ...")
    endif()
    if(NOT arg_FORMATS)
        set(arg_FORMATS pdf)
    endif()
    if(NOT DEFINED arg_JOBS)
        set(arg_JOBS 1)
    elseif(NOT arg_JOBS MATCHES "^[1-9][0-9]*$")
        message(FATAL_ERROR "pendulum_add_figures: JOBS ${arg_JOBS}: the number of workers of each render, 1 or more")
    endif()
    foreach(option IN LISTS arg_OPTIONS)
        if(option MATCHES "^--jobs")
            message(FATAL_ERROR "pendulum_add_figures: OPTIONS ${option}: give the workers of each render as JOBS n")
        endif()
    endforeach()
    if(NOT arg_OUTPUT_DIR)
        set(arg_OUTPUT_DIR "${CMAKE_CURRENT_BINARY_DIR}/figures")
    endif()
    get_filename_component(out_dir "${arg_OUTPUT_DIR}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_BINARY_DIR}")
    if(NOT PENDULUM_FIGURES_EXECUTABLE)
        find_program(PENDULUM_FIGURES_EXECUTABLE pendulum-figures HINTS "${PENDULUM_FIGURES_BINDIR}"
                     DOC "pendulum-figures, for pendulum_add_figures")
    endif()
    if(NOT PENDULUM_FIGURES_EXECUTABLE)
        message(FATAL_ERROR "pendulum_add_figures: pendulum-figures not found (install the package "
                            "pendulum-figures, or set PENDULUM_FIGURES_EXECUTABLE)")
    endif()
    foreach(format IN LISTS arg_FORMATS)
        if(format MATCHES "^(.+)_tex$" AND CMAKE_MATCH_1 IN_LIST arg_FORMATS)
            message(FATAL_ERROR "pendulum_add_figures: FORMATS ${CMAKE_MATCH_1} and ${format} both write "
                                "NAME.${CMAKE_MATCH_1} (${format}'s without its text); call it twice, with "
                                "different OUTPUT_DIRs")
        endif()
    endforeach()
    list(JOIN arg_FORMATS "," formats)
    set(theme_args "")
    set(theme_depends "")
    if(arg_THEME)
        if(arg_THEME MATCHES "\\.toml$")
            get_filename_component(theme_file "${arg_THEME}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_SOURCE_DIR}")
            set(theme_args --theme "${theme_file}")
            set(theme_depends "${theme_file}")
        else()
            set(theme_args --theme "${arg_THEME}")
        endif()
    endif()
    set(force "")
    if(NOT CMAKE_GENERATOR MATCHES "Ninja")
        set(force --force)
    endif()
    set(all_outputs "")
    foreach(spec IN LISTS arg_SPECS)
        if(spec MATCHES "\\.toml$")
            get_filename_component(input "${spec}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_SOURCE_DIR}")
            get_filename_component(name "${spec}" NAME_WE)
            set(depends "${input}")
        else()
            set(input "${spec}")
            set(name "${spec}")
            set(depends "")
        endif()
        set(outputs "")
        foreach(format IN LISTS arg_FORMATS)
            list(APPEND outputs "${out_dir}/${name}.${format}")
            # An overlay (pdf_tex, eps_tex) writes its drawing under the drawing format's name.
            if(format MATCHES "^(.+)_tex$")
                list(APPEND outputs "${out_dir}/${name}.${CMAKE_MATCH_1}")
            endif()
        endforeach()
        set(depfile "${out_dir}/${name}.d")
        add_custom_command(
            OUTPUT ${outputs}
            COMMAND "${CMAKE_COMMAND}" -E make_directory "${out_dir}"
            COMMAND "${PENDULUM_FIGURES_EXECUTABLE}" render "${input}" -f "${formats}" -o "${out_dir}"
                    --depfile "${depfile}" --jobs ${arg_JOBS} ${theme_args} ${force} ${arg_OPTIONS}
            DEPENDS ${depends} ${theme_depends} "${PENDULUM_FIGURES_EXECUTABLE}"
            DEPFILE "${depfile}"
            COMMENT "Rendering figure ${name} (${formats})"
            VERBATIM)
        list(APPEND all_outputs ${outputs})
    endforeach()
    set(all "")
    if(arg_ALL)
        set(all ALL)
    endif()
    add_custom_target(${arg_TARGET} ${all} DEPENDS ${all_outputs})
    if(arg_OUTPUTS_VARIABLE)
        set(${arg_OUTPUTS_VARIABLE} "${all_outputs}" PARENT_SCOPE)
    endif()
endfunction()
