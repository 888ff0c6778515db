#!/bin/bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The core library keeps no process-wide state of its host: neither libpendulum.a nor a
# program that links only it refers to GSL's error handler or to any other process-wide
# setting (MPFR's defaults and exponent range, the umask, the locale, signals, the
# environment, the working directory, the terminate handler), and that program runs.
# Usage: library_state_test.sh LIBRARY PROBE
set -euo pipefail
library=$1
probe=$2
# One name per line: symbols that change a setting of the whole process.
forbidden='^(gsl_set_error_handler|gsl_set_error_handler_off|gsl_set_stream_handler|gsl_set_stream|mpfr_set_default_prec|mpfr_set_default_rounding_mode|mpfr_set_emin|mpfr_set_emax|umask|setlocale|signal|sigaction|putenv|setenv|unsetenv|chdir|_ZSt13set_terminatePFvvE)$'
status=0
check() {  # check WHAT SYMBOL-LIST
    local found
    found=$(printf '%s\n' "$2" | grep -E "$forbidden" | sort -u || true)
    if [ -n "$found" ]; then
        echo "$1 refers to process-wide settings: $found"
        status=1
    fi
}
names() { awk '{print $NF}' | sed 's/@.*//'; }
[ -s "$library" ] || { echo "no library at $library"; exit 1; }
check "the library $library" "$(nm "$library" 2>/dev/null | names)"
check "the program $probe (nm)" "$(nm "$probe" 2>/dev/null | names)"
check "the program $probe (nm -D)" "$(nm -D "$probe" | names)"
# The check itself sees a reference where there is one.
planted=$(printf 'U gsl_set_error_handler_off\n' | names)
if [ -z "$(printf '%s\n' "$planted" | grep -E "$forbidden")" ]; then
    echo "the check misses a planted reference"
    status=1
fi
"$probe" >/dev/null || { echo "$probe failed"; status=1; }
[ "$status" = 0 ] && echo "1 passed, 0 failed" || echo "0 passed, 1 failed"
exit "$status"
