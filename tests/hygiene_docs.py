#!/usr/bin/env python3
"""hygiene.docs: README.md and docs/design.md name only what exists.

  hygiene_docs.py SOURCE_DIR TSIS_BINARY

Checks that every repository path they name (in `code` or a relative link)
is a file or folder of the tree, that every --option they name is one a tsis
command takes (its --help) or one of the other programs listed below, and
that design.md's method table (§4) lists exactly the methods tsis registers,
and that README's table of method options gives each the methods the
parameter table gives it (as `tsis render --help` prints them).
Prints one line per problem; exit 1 when there is any.
"""
import fnmatch
import os
import re
import subprocess
import sys

# Options of programs other than tsis that the docs name, by program.
OTHER_PROGRAMS = {
    "bench/run.sh and the bench programs": {"quick", "models", "truth", "seconds", "photons",
                                            "size", "repeat", "gl-floors", "side-by-side", "stages"},
    "cmake, ctest": {"build", "target", "output-on-failure", "preset", "install", "prefix"},
    "clang-format": {"dry-run", "Werror"},
    "duplicates": {"change", "base"},
}
# Top-level folders a path may start with; build outputs are not in the tree.
TREE_DIRS = ("host/", "kernels/", "tests/", "bench/", "docs/", "data/", "gl/", "cmake/",
             ".ci/", "python/")
BUILD_DIRS = ("build/", "build-bench/", "build-sanitize/")
SOURCE_EXT = re.compile(r"\.(h|cpp|cl|sh|py|md|cmake|txt|glsl|vert|frag|script|csv|\*)$")


def tracked_paths(root):
    try:
        files = subprocess.run(["git", "ls-files"], cwd=root, capture_output=True, text=True,
                               check=True).stdout.split("\n")
    except (OSError, subprocess.CalledProcessError):  # a source tree without git
        files = [os.path.relpath(os.path.join(d, f), root)
                 for d, dirs, names in os.walk(root)
                 if not os.path.relpath(d, root).startswith(("build", ".git"))
                 for f in names]
    paths = set(f for f in files if f)
    # Folders .gitignore names from the root hold what setup.sh makes there
    # (data/meshes/): the docs may name them.
    with open(os.path.join(root, ".gitignore"), encoding="utf-8") as f:
        paths |= set(line.strip().strip("/") for line in f
                     if line.startswith("/") and line.strip().endswith("/"))
    for f in list(paths):
        parts = f.split("/")
        for i in range(1, len(parts)):
            paths.add("/".join(parts[:i]))
    return paths


def path_candidates(text):
    """Backticked words and relative link targets that look like repository paths."""
    words = re.findall(r"`([^`\n]+)`", text)
    words += [m for m in re.findall(r"\]\(([^)\s]+)\)", text)
              if not re.match(r"[a-z]+:|#", m)]
    for w in words:
        w = w.split()[0] if w.split() else w
        w = w.split("#")[0]
        if w.startswith("./"):
            w = w[2:]
        if not re.fullmatch(r"[A-Za-z0-9_.<>*{}/-]+", w) or w.startswith(BUILD_DIRS):
            continue
        if w.startswith(TREE_DIRS) or ("/" in w and SOURCE_EXT.search(w.rstrip("/"))) or \
                re.fullmatch(r"[a-z0-9_]+\.(h|cpp|cl|sh)", w) or w == "setup.sh":
            yield w


def path_exists(word, paths, doc_dir):
    pattern = re.sub(r"<[^>]*>", "*", word.rstrip("/"))
    pattern = re.sub(r"\{([^}]*)\}", lambda m: "[" + "".join(
        sorted(set(c for c in m.group(1) if c != ","))) + "]*", pattern)
    candidates = [pattern, os.path.normpath(os.path.join(doc_dir, pattern))]
    for p in paths:
        for c in candidates:
            # A path may be given from its module down (render/profiles.h):
            # it must end the tracked path at a folder boundary.
            if fnmatch.fnmatchcase(p, c) or fnmatch.fnmatchcase(p, "*/" + c):
                return True
    return False


def tsis_options(tsis):
    top = subprocess.run([tsis, "help"], capture_output=True, text=True).stdout
    commands = re.findall(r"^  ([a-z]+) ", top, re.M)
    options = {"help"}
    for c in commands:
        out = subprocess.run([tsis, c, "--help"], capture_output=True, text=True).stdout
        options |= set(re.findall(r"--([a-z][a-z0-9-]*)", out))
    return commands, options


def registered_methods(tsis):
    err = subprocess.run([tsis, "render", "--method", "?"], capture_output=True, text=True).stderr
    m = re.search(r"available: (.*)", err)
    return m.group(1).split(", ") if m else []


def parameter_methods(tsis, registry):
    """Option → the methods `tsis render --help` says read it (its table's column)."""
    out = subprocess.run([tsis, "render", "--help"], capture_output=True, text=True).stdout
    owners = {}
    for name, line in re.findall(r"^  --([a-z-]+) +(.*)$", out, re.M):
        # "METAVAR  methods: help", or a flag's "methods: help".
        m = re.match(r"([a-z, ]+): ", line) or re.match(r"\S+ +([a-z, ]+): ", line)
        names = m.group(1).split(", ") if m else []
        if names and all(n in registry for n in names):
            owners[name] = set(names)
    return owners


def readme_parameter_methods(readme, registry):
    """README's table of method options: option → the methods its row names."""
    section = re.search(r"^Options of some methods.*?\n\n(\|.*?)\n\n", readme, re.M | re.S)
    rows = {}
    for line in (section.group(1).split("\n") if section else [])[2:]:
        cells = [c.strip() for c in line.strip("|").split("|")]
        but = re.fullmatch(r"all but ([a-z]+)", cells[1])
        methods = set(registry) - {but.group(1)} if but else set(cells[1].split(", "))
        for name in re.findall(r"`--([a-z-]+)", cells[0]):
            rows[name] = methods
    return rows


def design_methods(design):
    section = re.search(r"^## 4\..*?(?=^## )", design, re.M | re.S)
    return re.findall(r"^\| `([a-z]+)`", section.group(0), re.M) if section else []


def main():
    root, tsis = sys.argv[1], sys.argv[2]
    paths = tracked_paths(root)
    commands, options = tsis_options(tsis)
    known = set(options)
    for names in OTHER_PROGRAMS.values():
        known |= names
    problems = []
    if len(commands) < 5:
        problems.append(f"tsis help lists {commands}: not the command list expected")
    for doc in ("README.md", "docs/design.md"):
        text = open(os.path.join(root, doc), encoding="utf-8").read()
        doc_dir = os.path.dirname(doc)
        for w in sorted(set(path_candidates(text))):
            if not path_exists(w, paths, doc_dir):
                problems.append(f"{doc}: names '{w}', which is not in the tree")
        # Options in prose and code alike; a word like "--" or "---" is not one.
        for o in sorted(set(re.findall(r"(?<![\w-])--([a-z][a-z0-9-]*[a-z0-9])", text))):
            if o not in known:
                problems.append(f"{doc}: names --{o}, which no tsis command takes")
    design = open(os.path.join(root, "docs/design.md"), encoding="utf-8").read()
    table, registry = design_methods(design), registered_methods(tsis)
    if not registry:
        problems.append("tsis render --method '?' did not list the methods")
    elif sorted(table) != sorted(registry):
        problems.append(f"docs/design.md §4 lists methods {table}; tsis registers {registry}")
    # README's method column says what the parameter table says.
    readme = open(os.path.join(root, "README.md"), encoding="utf-8").read()
    owners = parameter_methods(tsis, registry)
    rows = readme_parameter_methods(readme, registry)
    if not rows:
        problems.append("README.md: no table of method options found")
    for name, methods in sorted(rows.items()):
        if owners.get(name) != methods:
            problems.append(f"README.md: --{name} is for {sorted(methods)}; tsis render --help "
                            f"says {sorted(owners.get(name, set()))}")
    for name in sorted(set(owners) - set(rows)):
        problems.append(f"README.md: the table of method options lacks --{name}")
    for p in problems:
        print("hygiene.docs: " + p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
