# SPDX-License-Identifier: GPL-3.0-or-later
# bash completion for pendulum-figures
_pendulum_figures() {
    local cur prev words cword
    _init_completion || return
    local commands="eval trajectory claims list show render plot data"
    if [[ $cword -eq 1 ]]; then
        COMPREPLY=($(compgen -W "$commands --help --version" -- "$cur"))
        return
    fi
    local command=${words[1]}
    case $prev in
        -f|--formats) COMPREPLY=($(compgen -W "png pdf svg eps gif pdf_tex eps_tex" -- "$cur")); return ;;
        --theme) COMPREPLY=($(compgen -W "paper slides slides-dark" -- "$cur") $(compgen -f -X '!*.toml' -- "$cur")); return ;;
        -o|--output-dir) [[ $command == data ]] && _filedir || _filedir -d; return ;;
        --output) _filedir; return ;;
        --format) COMPREPLY=($(compgen -W "csv json" -- "$cur")); return ;;
        --tex-sizes) COMPREPLY=($(compgen -W "relative absolute" -- "$cur")); return ;;
        --method|--methods)
            COMPREPLY=($(compgen -W "exact harmonic lowest first second polynomial order: kidd-fogg lima-arun ganley agm: denman series: log-asymptote" -- "$cur"))
            compopt -o nospace
            return ;;
        --theta0|--at|--order|--dpi|--samples|--periods|--range|--frames|--set|--name|--harmonic|--length|--g|--tex-font-size) return ;;
    esac
    local options=""
    case $command in
        eval) options="--theta0 --order --method --length --g --format --help --help-all" ;;
        trajectory) options="--theta0 --method --order --at --samples --periods --format --help --help-all" ;;
        claims) options="--format --help --help-all" ;;
        list) options="--markdown --help --help-all" ;;
        show) options="--theme --help --help-all" ;;
        render) options="--all -o --output-dir -f --formats --theme --set --dpi --theta0 --frames --at --force --tex-font-size --tex-sizes --paper-files --help --help-all" ;;
        plot) options="--theta0 --methods --range --time --harmonic --y --name -o --output-dir -f --formats --theme --set --dpi --help --help-all" ;;
        data) options="-o --output --theta0 --help --help-all" ;;
    esac
    if [[ $cur == -* ]]; then
        COMPREPLY=($(compgen -W "$options" -- "$cur"))
    elif [[ $command == render || $command == data || $command == show ]]; then
        local ids
        ids=$("${words[0]}" list 2>/dev/null | awk '/^  [a-z]/ { print $1 }')
        COMPREPLY=($(compgen -W "$ids fig1 fig2 fig3 fig4 fig5 fig6 fig7" -- "$cur") $(compgen -f -X '!*.toml' -- "$cur"))
    elif [[ $command == plot && $cword -eq 2 ]]; then
        COMPREPLY=($(compgen -W "trajectory phase period coefficient convergence spectrum pendulum" -- "$cur"))
    fi
} &&
    complete -F _pendulum_figures pendulum-figures
