#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The bash and zsh completions know every command, every option of each command's --help,
# and every value of the tables they complete (formats, themes, methods, plot kinds).
# Usage: completion_test.sh PENDULUM_FIGURES SOURCE_DIR
set -euo pipefail
exe=$1
bash_file=$2/completion/pendulum-figures.bash
zsh_file=$2/completion/_pendulum-figures
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

# The values of each table the completions offer.
markdown=$("$exe" list --markdown)
column() { echo "$markdown" | awk -v h="| $1 |" 'index($0, h) == 1 { on = 1; next } on && /^\| `/ { print } on && /^$/ { on = 0 }' |
           sed -n 's/^| `\([^`:]*\).*/\1/p'; }
bash_line() { grep -E -- "$1" "$bash_file"; }
for f in $(column format); do
    [[ $(bash_line '-f\|--formats\)') == *[\"\ ]"$f"[\ \"]* ]] || fail "bash: format $f"
    [[ $(grep "local formats=" "$zsh_file") == *[\(\ ]"$f"[\ \)]* ]] || fail "zsh: format $f"
done
for t in $(column theme); do
    [[ $(bash_line '--theme\)') == *[\"\ ]"$t"[\ \"]* ]] || fail "bash: theme $t"
    [[ $(grep "themes=" "$zsh_file") == *[\(\ ]"$t"[\ \)]* ]] || fail "zsh: theme $t"
done
for m in $(column method); do
    [[ $(grep -A1 -E -- '--method\|--methods\)' "$bash_file" | tail -1) == *[\"\ ]"$m"[:\ \"]* ]] || fail "bash: method $m"
done
for p in $(column plot); do
    [[ $(grep -A2 'command == plot' "$bash_file") == *[\"\ ]"$p"[\ \"]* ]] || fail "bash: plot kind $p"
    [[ $(grep "1:kind:" "$zsh_file") == *[\(\ ]"$p"[\ \)]* ]] || fail "zsh: plot kind $p"
done
for s in $(column 'text sizes'); do
    [[ $(bash_line '--tex-sizes\)') == *[\"\ ]"$s"[\ \"]* ]] || fail "bash: --tex-sizes $s"
    [[ $(grep -- "--tex-sizes" "$zsh_file") == *[\(\ ]"$s"[\ \)]* ]] || fail "zsh: --tex-sizes $s"
done
[ "$failures" -eq 0 ] || exit 1
echo "ok: completions know $(echo "$commands" | wc -w) commands, their options and the tables' values"
