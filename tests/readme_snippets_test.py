#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Runs every code block of README.md, in order, in one scratch directory, as a reader would.

Usage: readme_snippets_test.py PENDULUM_FIGURES BUILD_DIR SOURCE_DIR

Blocks are fenced, with a language:
- sh: run with bash -e. A block of `$ COMMAND` lines with output runs each command and
  compares the output shown, if any: `...` stands for any text within a line, and a line
  `...` alone for the rest of the output.
- toml, cpp, cmake, make, ninja: written to the file named by `<!-- snippet: file NAME -->` on the line
  before the block; a toml spec (one with [[panel]]) is also read by `pendulum-figures data`,
  and a block whose file is one of examples/ must be that file.
- latex: a whole document, written to the file named as above (default readme.tex) and
  compiled with pdflatex (after the blocks before it ran).
A block that cannot run here (sudo, make recursing into the project, a synopsis) carries
`<!-- not run: REASON -->` on the line before it; such blocks are counted and listed.
The installed core library (cmake --install --component dev) is on PKG_CONFIG_PATH and
CMAKE_PREFIX_PATH, and pendulum-figures on PATH and at build/pendulum-figures.
"""
import fnmatch
import os
import re
import shutil
import subprocess
import sys
import tempfile

exe, build_dir, source_dir = (os.path.abspath(a) for a in sys.argv[1:4])
readme = open(os.path.join(source_dir, "README.md"), encoding="utf-8").read().split("\n")

MARKER = re.compile(r"^\s*<!-- (snippet: file (?P<file>\S+)|not run: (?P<reason>.+?)) -->\s*$")
FENCE = re.compile(r"^(?P<indent>\s*)```(?P<lang>\S*)\s*$")
LANGS = {"sh", "toml", "cpp", "cmake", "latex", "make", "ninja"}


def blocks():
    """(line number, language, text, marker match or None) of each fenced block."""
    i = 0
    while i < len(readme):
        m = FENCE.match(readme[i])
        if not m:
            # An indented code block (four spaces or more after a blank line) would escape
            # the test: every block is fenced.
            if readme[i].startswith("    ") and i > 0 and readme[i - 1].strip() == "":
                yield i + 1, "indented", readme[i], None
            i += 1
            continue
        indent, lang, start = len(m.group("indent")), m.group("lang"), i
        body = []
        i += 1
        while not readme[i].strip().startswith("```"):
            body.append(readme[i][indent:])
            i += 1
        j = start - 1
        while j >= 0 and readme[j].strip() == "":
            j -= 1
        marker = MARKER.match(readme[j]) if j >= 0 else None
        yield start + 1, lang, "\n".join(body) + "\n", marker
        i += 1


def matches(shown, got):
    """The output shown in the README against the output of the command."""
    if not shown:
        return True  # a command shown without its output
    got_lines = got.rstrip("\n").split("\n") if got.strip() else []
    for k, line in enumerate(shown):
        if line == "...":
            return True
        pattern = fnmatch.translate(line.replace("[", "[[]").replace("...", "*"))
        if k >= len(got_lines) or not re.match(pattern, got_lines[k]):
            return False
    return len(got_lines) == len(shown)


work = tempfile.mkdtemp(prefix="readme-snippets-")
failures, ran, not_run = [], 0, []
try:
    prefix = os.path.join(work, "prefix")
    subprocess.run(["cmake", "--install", build_dir, "--prefix", prefix, "--component", "dev"],
                   check=True, stdout=subprocess.DEVNULL)
    pc_dirs = [root for root, _, files in os.walk(prefix) if "pendulum.pc" in files]
    bin_dir = os.path.join(work, "bin")
    os.makedirs(bin_dir)
    os.symlink(exe, os.path.join(bin_dir, "pendulum-figures"))
    run_dir = os.path.join(work, "run")
    os.makedirs(os.path.join(run_dir, "build"))
    os.symlink(exe, os.path.join(run_dir, "build", "pendulum-figures"))
    env = dict(os.environ, PATH=bin_dir + os.pathsep + os.environ["PATH"], PKG_CONFIG_PATH=pc_dirs[0],
               CMAKE_PREFIX_PATH=prefix, LC_ALL="C.UTF-8", HOME=work)
    env.pop("SOURCE_DATE_EPOCH", None)
    # The snippets are what a user types at a shell, not a sub-make of make test:
    # without this, make prints "Entering directory" and make[1] prefixes.
    for name in ("MAKELEVEL", "MAKEFLAGS", "MFLAGS", "MAKEOVERRIDES", "MAKE_TERMOUT", "MAKE_TERMERR"):
        env.pop(name, None)

    def run(args, **kw):
        return subprocess.run(args, cwd=run_dir, env=env, capture_output=True, text=True, timeout=600, **kw)

    for line, lang, text, marker in blocks():
        where = f"README.md:{line}"
        if lang == "indented":
            failures.append(f"{where}: an indented code block; fence it with a language")
            continue
        if lang not in LANGS:
            failures.append(f"{where}: a block of language '{lang}'; the test runs {sorted(LANGS)}")
            continue
        if marker and marker.group("reason"):
            not_run.append(f"{where} ({lang}): {marker.group('reason')}")
            continue
        ran += 1
        file = marker.group("file") if marker else None
        if lang == "sh":
            lines = text.rstrip("\n").split("\n")
            if lines[0].startswith("$ "):
                commands, k = [], 0
                while k < len(lines):
                    command, shown = lines[k][2:], []
                    k += 1
                    while k < len(lines) and not lines[k].startswith("$ "):
                        shown.append(lines[k])
                        k += 1
                    r = run(["bash", "-e", "-c", command])
                    if r.returncode != 0:
                        failures.append(f"{where}: '{command}' exits {r.returncode}: {r.stderr.strip()}")
                    elif not matches(shown, r.stdout):
                        failures.append(f"{where}: '{command}' prints\n{r.stdout[:2000]}\nnot what the README shows:\n"
                                        + "\n".join(shown))
            else:
                r = run(["bash", "-e", "-c", text])
                if r.returncode != 0:
                    failures.append(f"{where}: the block exits {r.returncode}:\n{text}{r.stdout[-2000:]}{r.stderr[-2000:]}")
        elif lang == "latex":
            tex = file or "readme.tex"
            with open(os.path.join(run_dir, tex), "w", encoding="utf-8") as f:
                f.write(text)
            r = run(["pdflatex", "-interaction=nonstopmode", "-halt-on-error", "-no-shell-escape", tex])
            if r.returncode != 0:
                failures.append(f"{where}: pdflatex fails:\n{r.stdout[-3000:]}")
        else:
            if not file:
                failures.append(f"{where}: a {lang} block needs <!-- snippet: file NAME --> before it")
                continue
            os.makedirs(os.path.dirname(os.path.join(run_dir, file)), exist_ok=True)
            with open(os.path.join(run_dir, file), "w", encoding="utf-8") as f:
                f.write(text)
            example = os.path.join(source_dir, "examples", file)
            if os.path.exists(example) and open(example, encoding="utf-8").read() != text:
                failures.append(f"{where}: the block differs from examples/{file}")
            if lang == "toml" and re.search(r"^\[\[panel\]\]", text, re.M):
                r = run(["pendulum-figures", "data", file])
                if r.returncode != 0:
                    failures.append(f"{where}: pendulum-figures data {file} exits {r.returncode}: {r.stderr.strip()}")
finally:
    shutil.rmtree(work, ignore_errors=True)

for f in failures:
    print("FAIL:", f)
print(f"{ran} README blocks run, {len(not_run)} not run:")
for n in not_run:
    print("  ", n)
sys.exit(1 if failures or ran == 0 else 0)
