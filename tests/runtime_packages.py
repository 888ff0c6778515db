# SPDX-License-Identifier: GPL-3.0-or-later
"""The runtime package list suffices: every library the program and its video module load
(ldd) and every font the built-in themes name (fc-match) comes from a package that
packaging/packages/build.list installs, itself or through its dependencies.

Usage: runtime_packages.py SOURCE_DIR PROGRAM MODULE
Prints each file whose package the list does not bring, and exits 1 if there is one."""
import os
import re
import subprocess
import sys


def listed(path):
    """The package names of a list file, comments left out."""
    with open(path, encoding="utf-8") as f:
        return [w for line in f for w in line.split("#", 1)[0].split()]


def installed_graph():
    """Installed package -> the installed packages it depends on (Depends, Pre-Depends, any
    alternative; a virtual package's providers)."""
    out = subprocess.run(["dpkg-query", "-W", "-f", "${Package}\t${Provides}\t${Depends}, ${Pre-Depends}\t${db:Status-Abbrev}\n"],
                         check=True, capture_output=True, text=True).stdout
    depends, providers = {}, {}
    for line in out.splitlines():
        name, provides, deps, status = line.split("\t")
        if not status.startswith("ii"):
            continue
        depends[name] = [re.sub(r"[ (:].*", "", alt.strip()) for alt in re.split(r"[,|]", deps) if alt.strip()]
        for p in provides.split(","):
            if p.strip():
                providers.setdefault(re.sub(r"[ (].*", "", p.strip()), []).append(name)
    return depends, providers


def closure(roots, depends, providers):
    """The packages roots bring, themselves included."""
    seen, todo = set(), list(roots)
    while todo:
        p = todo.pop()
        for q in [p] + providers.get(p, []):
            if q in depends and q not in seen:
                seen.add(q)
                todo.extend(depends[q])
    return seen


def loaded_files(program, module):
    """The shared libraries the program and the module load, resolved."""
    files = set()
    for binary in (program, module):
        out = subprocess.run(["ldd", binary], check=True, capture_output=True, text=True).stdout
        files.update(m.group(1) for m in re.finditer(r"=> (/\S+)", out))
    return files


def theme_fonts():
    """The font files the built-in themes' families resolve to."""
    families = ["CMU Serif", "CMU Sans Serif", "DejaVu Math TeX Gyre", "DejaVu Sans"]
    return {subprocess.run(["fc-match", "-f", "%{file}", f], check=True, capture_output=True, text=True).stdout
            for f in families}


def owners(paths):
    """path -> the package that installed it (one dpkg -S for all), trying each path as given
    and resolved (/usr-merged libraries are listed under /lib)."""
    spellings = {}
    for path in paths:
        real = os.path.realpath(path)
        for p in (path, real, re.sub(r"^/usr/lib/", "/lib/", real)):
            spellings.setdefault(p, path)
    out = subprocess.run(["dpkg", "-S"] + sorted(spellings), capture_output=True, text=True).stdout
    found = {}
    for line in out.splitlines():
        package, _, file = line.partition(": ")
        if file in spellings:
            found.setdefault(spellings[file], package.split(",")[0].split(":")[0].strip())
    return found


def main():
    source, program, module = sys.argv[1:4]
    depends, providers = installed_graph()
    brought = closure(listed(f"{source}/packaging/packages/build.list"), depends, providers)
    missing = []
    files = loaded_files(program, module) | theme_fonts()
    found = owners(files)
    for f in sorted(files):
        p = found.get(f)
        if p not in brought:
            missing.append(f"{f} (package {p})")
    for m in missing:
        print(f"not brought by packaging/packages/build.list: {m}")
    print(f"{len(brought)} packages brought by build.list")
    return 1 if missing else 0


if __name__ == "__main__":
    sys.exit(main())
