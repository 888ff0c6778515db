# SPDX-License-Identifier: GPL-3.0-or-later
# bash completion for pendulum-figures. The names of figures, methods, plot kinds, formats,
# themes, text sizes and --set keys come from the program's own tables
# (pendulum-figures complete WHAT); the commands and options are checked against --help by
# tests/completion_test.sh.

# Offers the words of `pendulum-figures complete WHAT` for the current word; in a
# comma-separated list (-f png,s), for the part after the last comma.
_pendulum_figures_words() {
    local words prefix="" last=$cur
    words=$("$1" complete "$2" 2>/dev/null) || return
    if [[ $3 == list && $cur == *,* ]]; then
        prefix=${cur%,*},
        last=${cur##*,}
    fi
    local IFS=$'\n'
    COMPREPLY=($(compgen -P "$prefix" -W "$words" -- "$last"))
    __ltrim_colon_completions "$cur"
    # order: and set-key= are not words yet.
    if [[ ${#COMPREPLY[@]} -eq 1 && ${COMPREPLY[0]} == *[:=] ]]; then
        compopt -o nospace
    fi
}

_pendulum_figures() {
    local cur prev words cword
    _init_completion -n := || return
    local exe=${words[0]}
    local commands="eval trajectory claims list show render plot data describe"
    if [[ $cword -eq 1 ]]; then
        COMPREPLY=($(compgen -W "$commands --help --help-all --version" -- "$cur"))
        return
    fi
    local command=${words[1]}
    case $prev in
        -f|--formats)
            if [[ $command == data ]]; then
                COMPREPLY=($(compgen -W "csv json" -- "$cur"))
            else
                _pendulum_figures_words "$exe" formats list
            fi
            return ;;
        --layout) COMPREPLY=($(compgen -W "long wide" -- "$cur")); return ;;
        --theme)
            _pendulum_figures_words "$exe" themes
            COMPREPLY+=($(compgen -f -X '!*.toml' -- "$cur"))
            return ;;
        -o|--output-dir) _filedir -d; return ;;
        --output|--depfile|--depfile-target) _filedir; return ;;
        --format) COMPREPLY=($(compgen -W "csv json" -- "$cur")); return ;;
        --check) COMPREPLY=($(compgen -W "aps aip ajp aps:1 aps:2 aip:1 aip:2 ajp:1 ajp:2" -- "$cur")); return ;;
        --tex-sizes) _pendulum_figures_words "$exe" tex-sizes; return ;;
        --set)
            if [[ $command == plot ]]; then
                _pendulum_figures_words "$exe" plot-set-keys
            else
                _pendulum_figures_words "$exe" set-keys
            fi
            return ;;
        --method)
            if [[ $command == trajectory ]]; then
                _pendulum_figures_words "$exe" motion-methods list
            else
                _pendulum_figures_words "$exe" methods list
            fi
            return ;;
        --methods) _pendulum_figures_words "$exe" methods list; return ;;
        --time) COMPREPLY=($(compgen -W "t/T t/T0 t/s" -- "$cur")); return ;;
        --y) COMPREPLY=($(compgen -W "value error-percent error-log residual" -- "$cur")); return ;;
        --x) COMPREPLY=($(compgen -W "amplitude energy" -- "$cur")); return ;;
        --angle-unit) COMPREPLY=($(compgen -W "rad deg" -- "$cur")); return ;;
        --separatrix|--clock) COMPREPLY=($(compgen -W "true false" -- "$cur")); return ;;
        --arrows) COMPREPLY=($(compgen -W "velocity acceleration velocity,acceleration" -- "$cur")); return ;;
        --legend) COMPREPLY=($(compgen -W "each first none" -- "$cur")); return ;;
        --loop) COMPREPLY=($(compgen -W "periods crossfade hold" -- "$cur")); return ;;
        --harmonics|--orders|--trail|--fps|--duration|--speed|--y-range|--x-label|--y-label|--panel-title|--title|--size) return ;;
        --theta0|--omega0|--energy|--at|--order|--dpi|--samples|--periods|--range|--frames|--name|--harmonic|--length|--g|--tex-font-size|--jobs|--columns) return ;;
    esac
    local options=""
    case $command in
        eval) options="--theta0 --omega0 --energy --order --method --length --g --format --columns --jobs --help --help-all" ;;
        trajectory) options="--theta0 --omega0 --energy --time --length --g --method --order --at --samples --periods --format --help --help-all" ;;
        claims) options="--format --help --help-all" ;;
        list) options="--markdown --help --help-all" ;;
        show) options="--theme --help --help-all" ;;
        render) options="--all -o --output-dir -f --formats --theme --set --dpi --size --theta0 --frames --at --force --tex-font-size --tex-sizes --paper-files --depfile --depfile-target --jobs --check --help --help-all" ;;
        plot) options="--theta0 --energy --omega0 --methods --range --time --harmonic --harmonics --orders --y --x --angle-unit --separatrix --trail --energy-bars --arrows --timer --apart --fps --periods --duration --speed --clock --loop --y-range --x-label --y-label --panel-title --title --legend --size --name -o --output-dir -f --formats --theme --set --dpi --jobs --data --length --g --help --help-all" ;;
        data) options="-o --output --theta0 -f --format --layout --jobs --help --help-all" ;;
        describe) options="--alt --help --help-all" ;;
    esac
    if [[ $cur == -* ]]; then
        COMPREPLY=($(compgen -W "$options" -- "$cur"))
        return
    fi
    # The positional arguments: figures (ids, aliases, spec files) and plot kinds.
    case $command in
        render)
            _pendulum_figures_words "$exe" ids
            COMPREPLY+=($(compgen -f -X '!*.toml' -- "$cur")) ;;
        data|show)
            if [[ $cword -eq 2 ]]; then
                _pendulum_figures_words "$exe" ids
                COMPREPLY+=($(compgen -f -X '!*.toml' -- "$cur"))
            fi ;;
        plot) [[ $cword -eq 2 ]] && _pendulum_figures_words "$exe" plots ;;
    esac
} &&
    complete -F _pendulum_figures pendulum-figures
