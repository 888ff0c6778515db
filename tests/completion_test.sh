#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The bash and zsh completions know every command and every option of each command's --help,
# and bash offers what the tables hold (figures, formats, themes, methods, plot kinds, --set
# keys), after a comma too, and nothing else.
# Usage: completion_test.sh PENDULUM_FIGURES SOURCE_DIR
set -euo pipefail
exe=$1
bash_file=$2/completion/pendulum-figures.bash
zsh_file=$2/completion/_pendulum-figures
# In an empty directory: spec files (*.toml) in the current directory are offered too.
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
cd "$scratch"
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

commands=$("$exe" --help | awk '/^Subcommands:/ { on = 1; next } on && /^  [a-z]/ { print $1 } on && /^$/ { on = 0 }')
[ "$(echo "$commands" | wc -w)" -ge 8 ] || fail "too few commands in --help: $commands"
bash_commands=$(sed -n 's/^ *local commands="\(.*\)"$/\1/p' "$bash_file")
for c in $commands; do
    [[ " $bash_commands " == *" $c "* ]] || fail "bash: command $c"
    grep -q "^ *'$c:" "$zsh_file" || fail "zsh: command $c"
    options=$("$exe" "$c" --help | grep -oE '^ +(-[a-z],)?--[a-z0-9-]+' | grep -oE -- '--[a-z0-9-]+' | grep -v '^--help')
    bash_options=$(sed -n "s/^ *$c) options=\"\\(.*\\)\" ;;\$/\\1/p" "$bash_file")
    zsh_block=$(awk -v c="$c)" '$1 == c { on = 1 } on { print } on && /;;/ { exit }' "$zsh_file")
    [ -n "$zsh_block" ] || [ -z "$options" ] || fail "zsh: no block for $c"
    for o in $options; do
        [[ " $bash_options " == *" $o "* ]] || fail "bash: $c $o"
        [[ $zsh_block == *"$o"* ]] || fail "zsh: $c $o"
    done
done

# What bash offers, from the tables of list --markdown (the README's): the completion function
# runs as bash-completion runs it, on the words typed so far ("" for a word not begun).
complete_bash() {
    bash -c 'source /usr/share/bash-completion/bash_completion
             source "$1"; shift
             compopt() { :; }  # outside readline; what it sets is not looked at here
             COMP_WORDS=("$@"); COMP_CWORD=$((${#COMP_WORDS[@]} - 1))
             COMP_LINE="$*"; COMP_POINT=${#COMP_LINE}
             _pendulum_figures
             printf "%s\n" "${COMPREPLY[@]}"' _ "$bash_file" "$exe" "$@" | sort -u
}
markdown=$("$exe" list --markdown)
column() { echo "$markdown" | awk -v h="| $1 |" 'index($0, h) == 1 { on = 1; next } on && /^\| `/ { print } on && /^$/ { on = 0 }' |
           sed -n 's/^| `\([^`:]*\).*/\1/p'; }
expect() {  # EXPECTED_WORDS -- WORDS...: bash offers exactly EXPECTED_WORDS (sorted, one a line)
    local expected=$1
    shift 2
    local got
    got=$(complete_bash "$@")
    [ "$got" = "$(printf '%s\n' $expected | sort -u)" ] ||
        fail "bash: pendulum-figures $* <TAB> offers [$(echo $got)], not [$(echo $expected)]"
}
figures=$(echo "$markdown" | awk '/^\| figure/ { on = 1; next } on && /^\| `/ { print } on && /^$/ { on = 0 }' |
          grep -oE '`[^`]+`' | tr -d '`')
methods=$(echo "$markdown" | awk '/^\| method/ { on = 1; next } on && /^\| `/ { print } on && /^$/ { on = 0 }' |
          sed -n 's/^| `\([^`]*\)`.*/\1/p' | sed 's/:N$/:/')
motion=$(echo "$markdown" | awk '/^\| method/ { on = 1; next } on && /^\| `.*\| motion \|/ { print } on && /^$/ { on = 0 }' |
         sed -n 's/^| `\([^`]*\)`.*/\1/p' | sed 's/:N$/:/')
[ "$(echo "$figures" | wc -w)" -ge 14 ] || fail "too few figures in list --markdown: $figures"
expect "$figures" -- render ''
expect "$figures" -- data ''
expect "$(column plot)" -- plot ''
expect "$(column format)" -- render -f ''
expect "$(column format)" -- plot --formats ''
expect "png,svg" -- render -f png,s
expect "pdf,png,eps pdf,png,eps_tex" -- render -f pdf,png,eps
expect "$(column theme)" -- render --theme ''
expect "$(column 'text sizes')" -- render --tex-sizes ''
expect "$methods" -- eval --method ''
expect "exact,harmonic" -- plot --methods exact,h
expect "exact,order:" -- plot --methods exact,ord
expect "$motion" -- trajectory --method ''
expect "" -- trajectory --method kidd
expect "tick_font_pt= tick_length_pt=" -- render --set tick_
expect "dpi=" -- plot --set dp
# Every key of a style file, as show --theme paper prints them.
expect "$("$exe" show --theme paper | sed -n '/^\[/q; s/^\([a-z_]*\) =.*/\1=/p')" -- render --set ''
# plot --help names every plot kind.
for p in $(column plot); do
    "$exe" plot --help | grep "\b$p\b" >/dev/null || fail "plot --help does not name plot kind $p"
done
# The zsh completion reads the same tables.
for what in ids formats themes methods motion-methods plots tex-sizes set-keys; do
    grep -q "complete $what\|_pendulum_figures_words $what\|_pendulum_figures_list $what" "$zsh_file" ||
        fail "zsh: does not complete $what from the program"
done
zsh -n "$zsh_file" 2>/dev/null || ! command -v zsh >/dev/null || fail "zsh: syntax"
[ "$failures" -eq 0 ] || exit 1
echo "ok: completions know $(echo "$commands" | wc -w) commands, their options and the tables' values"
