#!/usr/bin/env python3
"""hygiene.docs: README.md and docs/**/*.md name only what exists.

  hygiene_docs.py SOURCE_DIR TSIS_BINARY

Checks, in README.md and every Markdown file under docs/ (the design, the
user guide docs/guide/, the Python page), that every repository path they
name in `code` is a file or folder of the tree; that every relative link
(and image) leads, from the file's own folder, to a file or folder of the
tree, and its #anchor, if any, to a heading of the Markdown file it names
(GitHub's heading ids); that every --option they name is one a tsis command
takes (its --help) or one of the other programs listed below; that
design.md's method table (§4) lists exactly the methods tsis registers; and
that the guide's table of method options (docs/guide/rendering.md) gives each
the methods the parameter table gives it (as `tsis render --help` prints
them). Prints one line per problem; exit 1 when there is any.
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
    "ray start (docs/guide/distributed.md)": {"head", "address", "port", "num-cpus",
                                               "temp-dir"},
}
# Top-level folders a path may start with; build outputs are not in the tree.
TREE_DIRS = ("host/", "kernels/", "tests/", "bench/", "docs/", "data/", "gl/", "cmake/",
             ".ci/", "python/")
BUILD_DIRS = ("build/", "build-bench/", "build-sanitize/")
SOURCE_EXT = re.compile(r"\.(h|cpp|cl|sh|py|md|cmake|txt|glsl|vert|frag|script|csv|\*)$")


# The guide's page that holds the table of method options.
METHOD_OPTIONS_DOC = "docs/guide/rendering.md"


def tracked_paths(root):
    # Tracked files and new ones not yet added (not what .gitignore ignores).
    try:
        files = subprocess.run(["git", "ls-files", "--cached", "--others", "--exclude-standard"],
                               cwd=root, capture_output=True, text=True,
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


def doc_files(root):
    """README.md and every Markdown file under docs/, as paths from the root."""
    docs = ["README.md"]
    for d, dirs, names in os.walk(os.path.join(root, "docs")):
        dirs.sort()
        docs += sorted(os.path.relpath(os.path.join(d, n), root) for n in names
                       if n.endswith(".md"))
    return docs


def without_code_blocks(text):
    """The text with fenced code blocks blanked (their lines kept, emptied)."""
    out, fence = [], None
    for line in text.split("\n"):
        m = re.match(r"^ {0,3}(`{3,}|~{3,})", line)
        if fence is None and m:
            fence = m.group(1)
            out.append("")
        elif fence is not None:
            if re.match(r"^ {0,3}" + re.escape(fence[0]) + "{%d,}\\s*$" % len(fence), line):
                fence = None
            out.append("")
        else:
            out.append(line)
    return "\n".join(out)


def heading_ids(text):
    """The ids GitHub gives a Markdown file's headings (github-slugger)."""
    ids, seen = set(), {}
    for m in re.finditer(r"^ {0,3}#{1,6}[ \t]+(.*?)(?:[ \t]+#+)?[ \t]*$",
                         without_code_blocks(text), re.M):
        title = re.sub(r"!?\[([^\]]*)\]\([^)]*\)", r"\1", m.group(1))  # links: their text
        title = re.sub(r"<[^>]+>", "", title).replace("`", "").replace("**", "")
        slug = re.sub(r"[^\w\- ]", "", title.strip().lower()).replace(" ", "-")
        n = seen.get(slug, 0)
        seen[slug] = n + 1
        ids.add(slug if n == 0 else f"{slug}-{n}")
    return ids


def link_targets(text):
    """Relative link and image targets outside code: (path or '', anchor or '')."""
    prose = re.sub(r"`[^`\n]*`", "", without_code_blocks(text))
    for target in re.findall(r"\]\(<?([^)\s>]+)>?(?:\s+\"[^\"]*\")?\)", prose):
        if re.match(r"[a-z][a-z0-9+.-]*:", target):  # a URL (https:, mailto:)
            continue
        path, _, anchor = target.partition("#")
        yield path, anchor


def check_links(root, doc, text, paths, problems):
    doc_dir = os.path.dirname(doc)
    for path, anchor in sorted(set(link_targets(text))):
        shown = path + ("#" + anchor if anchor else "")
        target = os.path.normpath(os.path.join(doc_dir, path)) if path else doc
        if target.startswith("..") or os.path.isabs(path):
            problems.append(f"{doc}: links to '{shown}', outside the tree")
            continue
        if target.rstrip("/") not in paths:
            problems.append(f"{doc}: links to '{shown}', which is not in the tree")
            continue
        if anchor and target.endswith(".md"):
            with open(os.path.join(root, target), encoding="utf-8") as f:
                ids = heading_ids(f.read())
            if anchor not in ids:
                problems.append(f"{doc}: links to '{shown}': {target} has no heading "
                                f"with the id '{anchor}'")


def path_candidates(text):
    """Backticked words that look like repository paths."""
    words = re.findall(r"`([^`\n]+)`", text)
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


def doc_parameter_methods(doc, registry):
    """The guide's table of method options: option → the methods its row names."""
    section = re.search(r"^Options of some methods.*?\n\n(\|.*?)\n\n", doc, re.M | re.S)
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
    for doc in doc_files(root):
        text = open(os.path.join(root, doc), encoding="utf-8").read()
        doc_dir = os.path.dirname(doc)
        for w in sorted(set(path_candidates(text))):
            if not path_exists(w, paths, doc_dir):
                problems.append(f"{doc}: names '{w}', which is not in the tree")
        check_links(root, doc, text, paths, problems)
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
    # The guide's method column says what the parameter table says.
    doc = METHOD_OPTIONS_DOC
    owners = parameter_methods(tsis, registry)
    rows = doc_parameter_methods(open(os.path.join(root, doc), encoding="utf-8").read(), registry)
    if not rows:
        problems.append(f"{doc}: no table of method options found")
    for name, methods in sorted(rows.items()):
        if owners.get(name) != methods:
            problems.append(f"{doc}: --{name} is for {sorted(methods)}; tsis render --help "
                            f"says {sorted(owners.get(name, set()))}")
    for name in sorted(set(owners) - set(rows)):
        problems.append(f"{doc}: the table of method options lacks --{name}")
    for p in problems:
        print("hygiene.docs: " + p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
