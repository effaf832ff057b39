#!/usr/bin/env python3
"""Fails if a citation of the docs points nowhere, or if a page names in backticks code that is
not there (CONTRIBUTING: a move of a file or a heading is then mechanical, a reader who follows
a comment finds the text it means, and a name a page gives is one the code has).

Citations. A citation is a path under docs/ named in the code, the scripts, the build files or
the docs themselves, optionally followed by a section and a heading:

    docs/reference/conventions.md            the file exists
    docs/reference/conventions.md §2         it has a heading "§2 ..." or "2. ..."
    docs/reference/guarantees.md, "Nothing finished is lost"
                                             it has a heading or a bold run-in title (of a
                                             paragraph or a list item)
    docs/reference/conventions.md §1, "Matrix algebras"    ... inside §1

as comments wrap them (across comment leaders). A title matches when it is the cited text, or
begins with it followed by ":", ".", "," or " (" (backticks ignored): "Run folders" names
"Run folders: one writer, `--overwrite`". A path in backticks, as the docs write it, counts
as well.

Names in backticks. The inline code of every markdown page (the README, CONTRIBUTING.md, the
pages of docs/guide/, docs/reference/ and docs/design/, a folder's README.md), but not of
docs/results/ (records, each naming the code of its commit), CHANGELOG.md (it names removed
code) or fenced code blocks (tests/api/ compiles the guide's: check_public_names.py), must name
what the tree has. "The code" is the tree's sources (.h, .cc, .cu, .cuh, .py) without their
comments and Python's docstrings, with their strings (a Python name is a string of the
bindings), its CMake files and its scripts, outside docs/ and build*/.

    `relax()`, `ddb::Relaxation`, `G::hat`    each name of two letters or more is a word of
    `relax(method, system, μ₀, h₀, ...)`      the code (pzgemm when the code has pzgemm_),
    `void apply(PhaseFunction f, ...) const`  and of X::y or X.y one file of the code has both
    `OPENBLAS_NUM_THREADS=1`                  the variable is a word of the code
    `ddb-cay`, `sddb-*`, `fluid-relax`        a hyphenated word of the code, a glob of one,
                                              or one that it composes ("-hamiltonian")
    `ddb_distributed_FOUND`                   or a name that CMake composes
                                              (ddb_${ddb_component}_FOUND)
    `core/matrix_backend.h`, `examples/distributed/`
                                              a path from a top-level folder of the tree exists
    `reference.h`, `ddbConfigVersion.cmake`   a source file of that name exists, or the build
                                              writes it

Not checked: flags (`--n 4`), output files (`summary.json`, `<method>.csv`), commands with
arguments, formulas, names under other libraries' namespaces (`std::`, `Eigen::`, `np.`) and
the few other programs' names in FOREIGN_NAMES and Python's built-ins.

    python3 tests/checks/check_citations.py <source tree>
    python3 tests/checks/check_citations.py --self-test    runs the check on a small tree with
                                                           wrong names, which it must find
"""
import builtins
import os
import pathlib
import re
import sys

SCANNED_SUFFIXES = {".h", ".cc", ".cu", ".cuh", ".py", ".md", ".cmake", ".sh", ".txt", ".in", ".yml"}
SKIPPED_DIRS = {".git", "docs/html", "docs/data", "docs/figures"}
# Build folders at the top (.gitignore's build*/: build, build-sanitize, ...): a check running
# beside this one writes its scratch builds there.
SKIPPED_PREFIX = "build"
COMMENT_LEADER = re.compile(r"\n[ \t]*(?:///?|#+|\*|>)?[ \t]*")
CITATION = re.compile(
    r"docs/([A-Za-z0-9_./-]+?)(\.md|\.png|\.jsonl|\.html)?(?![A-Za-z0-9_/-])"
    r"`?(?:\s+§(\d+))?(?:,\s+\"([^\"\n]+)\")?"
)
HEADING = re.compile(r"^#+\s+(.*?)\s*$", re.M)
RUN_IN_TITLE = re.compile(r"^(?:[*-][ \t]+)?\*\*(.+?)\*\*", re.M)
SECTION = re.compile(r"^#+\s+(?:§(\d+)\b|(\d+)\.\s)", re.M)


def plain(title):
    return title.replace("`", "").strip()


def titles(text):
    """The headings and bold run-in titles of a markdown text, with their offsets."""
    out = []
    for m in HEADING.finditer(text):
        out.append((m.start(), plain(re.sub(r"^(?:§\d+|\d+\.)\s+", "", m.group(1)))))
    for m in RUN_IN_TITLE.finditer(text):
        out.append((m.start(), plain(m.group(1))))
    return out


def section_span(text, number):
    """The offsets of section §number of a markdown text, or None."""
    starts = [(m.start(), m.group(1) or m.group(2)) for m in SECTION.finditer(text)]
    for i, (start, n) in enumerate(starts):
        if n == number:
            end = starts[i + 1][0] if i + 1 < len(starts) else len(text)
            return start, end
    return None


def names(title, cited):
    if title == cited or title.rstrip(".") == cited:
        return True
    return any(title.startswith(cited + sep) for sep in (":", ".", ",", " ("))


def tree_paths(root):
    """The tree's files and folders, sorted, never entering the build folders at the top nor
    .git: a check running beside this one creates and removes its scratch trees there, and a
    walk that entered one could find a folder gone under it."""
    found = []
    for folder, subfolders, files in os.walk(root):
        if pathlib.Path(folder) == root:
            subfolders[:] = [d for d in subfolders
                             if not (d.startswith(SKIPPED_PREFIX) or d == ".git")]
        found += [pathlib.Path(folder) / name for name in subfolders + files]
    return sorted(found)


def scanned_files(root):
    for path in tree_paths(root):
        rel = path.relative_to(root).as_posix()
        if (not path.is_file() or any(rel == d or rel.startswith(d + "/") for d in SKIPPED_DIRS)):
            continue
        if path.suffix in SCANNED_SUFFIXES or path.name == "CMakeLists.txt":
            yield path, rel


# --- Names in backticks -----------------------------------------------------------------------

# The pages whose inline code is read for names: every markdown page but the records of
# docs/results/ (each names the code of its own commit) and CHANGELOG.md (it names removed code).
NAMES_SKIPPED = {"CHANGELOG.md", "docs/results"}
# The code the names must be in: sources, with their comments removed, and the build files
# and scripts (an app's name, a CMake option, an environment variable).
CODE_SUFFIXES = {".h", ".cc", ".cu", ".cuh", ".py"}
BUILD_SUFFIXES = {".cmake", ".in", ".sh", ".sbatch"}
# A file name of these kinds is checked against the tree's files; other extensions name outputs.
SOURCE_EXTENSIONS = {"h", "cc", "cu", "cuh", "py", "cmake", "sh", "sbatch"}
FILE_EXTENSIONS = SOURCE_EXTENSIONS | {
    "json", "jsonl", "csv", "md", "png", "mp4", "gif", "hdf5", "h5", "ddb", "partial", "lock",
    "txt", "a", "so", "in", "yml", "html", "npy", "npz", "out", "err", "log"}
# Namespaces and modules of other libraries: a name under them is theirs.
FOREIGN_ROOTS = {"std", "Eigen", "boost", "ceres", "np", "numpy", "h5py", "quflow", "matplotlib",
                 "plt", "os", "sys", "cuda", "thrust", "pybind11", "py", "benchmark", "testing"}
# Names of other programs the pages name where they say what the code does or did: a routine of
# ScaLAPACK that a record of docs/design/ measured before the code stopped calling it, tools,
# C's macros, quflow's functions, h5py's arguments. Python's built-in names are added below.
FOREIGN_NAMES = {"pztranc_", "zmmtcadd_", "pzgetri_", "perf", "cmp", "LC_ALL", "LC_NUMERIC",
                 "NDEBUG", "mat2shr", "QuData", "swmr"}
PYTHON_BUILTINS = set(dir(builtins))
IDENT = r"[A-Za-z_][A-Za-z0-9_]*"
DECLARATION_WORDS = {"template", "typename", "class", "struct", "const", "constexpr", "static",
                     "inline", "virtual", "override", "final", "noexcept", "void", "bool", "int",
                     "long", "double", "float", "auto", "unsigned", "&", "*", "&&"}
QUALIFIED = re.compile(rf"^~?({IDENT}(?:(?:::|\.|->)~?{IDENT})*)$", re.A)
ENV_ASSIGNMENT = re.compile(r"^([A-Z][A-Z0-9_]*)=\S*$")
HYPHENATED = re.compile(r"^[a-z0-9]+(?:-[a-z0-9]+)*-(?:[a-z0-9]+|\*)$")
PATH = re.compile(r"^[A-Za-z0-9_.][A-Za-z0-9_./-]*$")
FILE_NAME = re.compile(r"^[A-Za-z0-9_][A-Za-z0-9_.-]*\.([A-Za-z0-9]+)$")
WORD = re.compile(IDENT, re.A)
HYPHEN_WORD = re.compile(r"-?[A-Za-z0-9_]+(?:-[A-Za-z0-9_]+)*", re.A)
FILE_WORD = re.compile(r"[A-Za-z0-9_][A-Za-z0-9_.-]*\.[A-Za-z0-9]+", re.A)
# A name CMake composes, ddb_${ddb_component}_FOUND, matches ddb_distributed_FOUND.
COMPOSED = re.compile(r"[A-Za-z0-9_]*(?:\$\{[A-Za-z0-9_]+\}[A-Za-z0-9_]*)+", re.A)
C_LIKE_COMMENT = re.compile(r'("(?:\\.|[^"\\\n])*"|//[^\n]*|/\*.*?\*/)', re.S)
HASH_COMMENT = re.compile(r'("(?:\\.|[^"\\\n])*"|\'(?:\\.|[^\'\\\n])*\'|#[^\n]*)')
DOCSTRING = re.compile(r'"""(?:\\.|[^\\])*?"""|\'\'\'(?:\\.|[^\\])*?\'\'\'')


def without_comments(text, suffix):
    """The text with its comments (and Python's docstrings) blanked out, its strings kept (a
    Python name is a string of the bindings, an app's output a string of its writer)."""
    pattern = C_LIKE_COMMENT if suffix in {".h", ".cc", ".cu", ".cuh"} else HASH_COMMENT
    if suffix == ".py":  # docstrings are prose
        text = DOCSTRING.sub(" ", text)
    return pattern.sub(lambda m: m.group(1) if m.group(1)[0] in "\"'" else " ", text)


class CodeIndex:
    """The words, hyphenated words ("ddb-cay", "-hamiltonian"), file names and composed names
    of the tree's code and build files, with comments removed, and the tree's files."""

    def __init__(self, root):
        self.words, self.hyphenated, self.file_words = set(), set(), set()
        self.files, self.basenames, composed = set(), set(), set()
        self.where = {}  # word -> the files whose code has it
        for path, rel in code_files(root):
            self.files.add(rel)
            if not path.is_file():
                continue
            self.basenames.add(path.name)
            if path.suffix in CODE_SUFFIXES | BUILD_SUFFIXES or path.name == "CMakeLists.txt":
                suffix = path.suffix if path.suffix in CODE_SUFFIXES else ".sh"
                text = without_comments(path.read_text(encoding="utf-8", errors="replace"), suffix)
                file_words = set(WORD.findall(text))
                self.words |= file_words
                for word in file_words:
                    self.where.setdefault(word, set()).add(rel)
                self.hyphenated |= set(HYPHEN_WORD.findall(text))
                self.file_words |= set(FILE_WORD.findall(text))
                if suffix == ".sh":
                    composed |= {c for c in COMPOSED.findall(text) if len(c.split("${")[0]) > 1}
        self.composed = [re.compile("^" + re.sub(r"\\\$\\\{[A-Za-z0-9_]+\\\}", "[A-Za-z0-9_]+",
                                                 re.escape(c)) + "$") for c in composed]
        self.top_level = {f for f in self.files if "/" not in f and (root / f).is_dir()}

    def has_name(self, name):
        """A word of the code (ScaLAPACK's pzgemm is called as pzgemm_), a foreign name, or
        one CMake composes."""
        return (name in self.words or name + "_" in self.words or name in FOREIGN_NAMES
                or name in PYTHON_BUILTINS or any(c.match(name) for c in self.composed))

    def has_member(self, qualified):
        """X::y or X.y: one file of the code has both (a member where its class is)."""
        outer, inner = re.split(r"::|\.|->", qualified)
        if inner in FOREIGN_NAMES or inner in PYTHON_BUILTINS:
            return True
        return bool(self.where.get(outer, set()) & self.where.get(inner, set()))

    def has_hyphenated(self, name):
        """A name in the code, a glob of one (sddb-*), or one the code composes of a name and
        a suffix ("ddb-cay" + "-hamiltonian")."""
        if name.endswith("*"):
            return any(w.startswith(name[:-1]) for w in self.hyphenated)
        if name in self.hyphenated:
            return True
        cuts = [i for i, c in enumerate(name) if c == "-"]
        return any(name[:i] in self.hyphenated and name[i:] in self.hyphenated for i in cuts)


def code_files(root):
    for path in tree_paths(root):
        rel = path.relative_to(root).as_posix()
        if rel.split("/")[0] != "docs":
            yield path, rel


def bare(span):
    """The span without its strings, template arguments and call arguments:
    `template <class W> void setWeights(const W& w)` -> `template void setWeights`."""
    span = re.sub(r'"(?:\\.|[^"\\])*"|\'(?:\\.|[^\'\\])*\'', "", span)
    previous = None
    while previous != span:
        previous, span = span, re.sub(r"<[^<>]*>|\([^()]*\)", "", span)
    return span.strip()


def wanted(span, top_level):
    """What an inline code span names: [("name", word), ...], [("hyphenated", word)],
    [("path", path)], [("file", basename)], or [] for what is not a name of the code (a flag,
    an output file, a command with arguments, a formula, prose)."""
    span = span.strip()
    if not span or span[0] in "-_<*":
        return []  # a flag, a part of a name (_np4, *_SKIP_MPICXX), a placeholder (<method>.csv)
    m = ENV_ASSIGNMENT.match(span)
    if m:
        return [("name", m.group(1))]
    if "/" in span:
        first = span.split("/")[0]
        if PATH.match(span) and first in top_level and "*" not in span:
            return [("path", span.rstrip("/"))]
        return []
    m = FILE_NAME.match(span)
    if m and m.group(1) in FILE_EXTENSIONS:
        return [("file", span)] if m.group(1) in SOURCE_EXTENSIONS else []
    if HYPHENATED.match(span):
        return [("hyphenated", span)]
    # Code: a name, qualified (ddb::relax, G::hat, ddb.methods, stats().residual), called with
    # any arguments (relax(method, ...)), or a declaration (void apply(PhaseFunction f, ...)
    # const); words with spaces and no call are prose or a command line.
    code = bare(span).lstrip(".")
    if "..." in code or "…" in code or not code.isascii():
        return []
    tokens = [t for t in re.split(r"\s+|\s*=\s*", code) if t and t not in DECLARATION_WORDS]
    if len(tokens) > 1 and "(" not in span and "=" not in span:
        return []
    out = []
    for token in tokens:
        m = QUALIFIED.match(token.strip("&*"))
        if not m:
            return []
        parts = re.split(r"::|\.|->", m.group(1).replace("~", ""))
        if parts[0] in FOREIGN_ROOTS:
            continue
        # A one-letter part is a template parameter or a variable of the example (G::hat, X).
        named = [p for p in parts if len(p) > 1 and p != "ddb"]
        out += [("name", p) for p in named]
        out += [("member", f"{a}::{b}") for a, b in zip(parts, parts[1:])
                if a in named and b in named]
    return out


def inline_code(text):
    """The inline code spans of a markdown text outside its fenced blocks, with their lines."""
    fenced = re.compile(r"^[ \t]*(```|~~~).*?^[ \t]*\1[ \t]*$", re.M | re.S)
    text = fenced.sub(lambda m: "\n" * m.group(0).count("\n"), text)
    for m in re.finditer(r"(`+)(?!`)(.+?)(?<!`)\1(?!`)", text, re.S):
        if "\n\n" not in m.group(2):
            yield text.count("\n", 0, m.start()) + 1, " ".join(m.group(2).split())


def check_names(root):
    """(errors, number of names checked) for the names in backticks of the tree's pages."""
    code = CodeIndex(root)
    errors = []
    count = 0
    for path, rel in scanned_files(root):
        if path.suffix != ".md" or any(rel == d or rel.startswith(d + "/") for d in NAMES_SKIPPED):
            continue
        for line, span in inline_code(path.read_text(encoding="utf-8", errors="replace")):
            for kind, name in wanted(span, code.top_level):
                count += kind != "member"
                if kind == "name":
                    ok = code.has_name(name)
                elif kind == "member":
                    ok = code.has_name(name.split("::")[0]) and code.has_name(name.split("::")[1])
                    if not ok:
                        continue  # said above, name by name
                    ok = code.has_member(name)
                elif kind == "hyphenated":
                    ok = code.has_hyphenated(name)
                elif kind == "path":
                    ok = name in code.files
                else:  # a file of the tree, or one the build writes (ddbConfigVersion.cmake)
                    ok = name in code.basenames or name in code.file_words
                if not ok:
                    what = {"name": f"no {name} in the code", "hyphenated": "not in the code",
                            "member": "no file of the code has both "
                                      + " and ".join(name.split("::")),
                            "path": "no such file or folder",
                            "file": "no such file in the tree"}[kind]
                    errors.append(f"{rel}:{line}: `{span}`: {what}")
    return errors, count


# --- The check -----------------------------------------------------------------------------------

def check(root, min_citations=200):
    """(errors, a one-line summary) for the source tree at root."""
    docs = {}
    errors = []
    count = with_heading = 0
    for path, rel in scanned_files(root):
        text = path.read_text(encoding="utf-8", errors="replace")
        joined = COMMENT_LEADER.sub(" ", text)
        for m in CITATION.finditer(joined):
            stem, suffix, section, heading = m.groups()
            if stem.startswith("html/"):  # Doxygen's output, made by the build
                continue
            if suffix is None:
                if stem.endswith("/"):  # a folder: docs/figures/
                    if not (root / "docs" / stem).is_dir():
                        errors.append(f"{rel}: docs/{stem}: no such folder")
                continue
            target = "docs/" + stem + suffix
            count += 1
            if not (root / target).is_file():
                errors.append(f"{rel}: {target}: no such file")
                continue
            if suffix != ".md" or (section is None and heading is None):
                continue
            if target not in docs:
                docs[target] = (root / target).read_text(encoding="utf-8")
            doc = docs[target]
            span = (0, len(doc))
            if section is not None:
                span = section_span(doc, section)
                if span is None:
                    errors.append(f"{rel}: {target} §{section}: no such section")
                    continue
            if heading is not None:
                with_heading += 1
                cited = plain(heading)
                if not any(span[0] <= at < span[1] and names(title, cited) for at, title in titles(doc)):
                    where = f" §{section}" if section else ""
                    errors.append(f'{rel}: {target}{where}, "{heading}": no such heading')
    if count < min_citations:
        errors.append(f"found only {count} citations: is {root} the source tree?")
    name_errors, name_count = check_names(root)
    errors += name_errors
    summary = (f"check_citations: {count} citations of docs/, {with_heading} by heading, "
               f"{name_count} names in backticks; {len(errors)} pointing nowhere")
    return errors, summary


# --- Its own test --------------------------------------------------------------------------------

# The tree of the self-test. DOCS/ stands for the docs' folder, so that the check of this tree
# does not take these for citations of its own docs.
SELF_TEST_TREE = {
    "core/methods.h": (
        "// matrixGroupMethodNames() was here once; a comment is not code.\n"
        "namespace ddb {\n"
        "enum Family { kMatrixGroups };\n"
        "struct LiePoissonSystem { void fieldAt(); static void hat(); };\n"
        'inline const char* methodNames(Family) { return "ddb-cay"; }\n'
        'inline const char* threads() { return getenv("OPENBLAS_NUM_THREADS"); }\n'
        "}\n"),
    "core/relaxation.h": "namespace ddb { struct Relaxation { void advance(); }; }\n",
    "apps/CMakeLists.txt": (
        "add_executable(fluid-relax main.cc)  # not-a-target\n"
        "set(app_${component}_FOUND TRUE)\n"),
    "DOCS/guide/page.md": (
        "# A page\n\n## Heading one\n\n"
        "`ddb::methodNames(kMatrixGroups)`, `LiePoissonSystem::fieldAt`, `fluid-relax`, `--n 4`,\n"
        "`summary.json`, `OPENBLAS_NUM_THREADS=1`, `Eigen::MatrixXd`, `core/methods.h`, `G::hat`,\n"
        "`a + b`, `<method>.csv`, `_np4`, `app_mpi_FOUND`, `ValueError`, `apps/`,\n"
        "DOCS/guide/page.md, \"Heading one\".\n\n"
        "```cpp\nnotCheckedInCodeBlocks();\n```\n"),
    "DOCS/guide/wrong.md": (
        "# Wrong\n\n"
        "`matrixGroupMethodNames()`, `LiePoissonSystem::velocityInto`, `not-a-target`,\n"
        "`core/missing.h`, `missing.cc`, DOCS/guide/page.md, \"Heading two\".\n"
        "`Relaxation::advance()` but `ddb::Relaxation::fieldAt`.\n"),
    "DOCS/results/record.md": "# A record\n\n`removedLongAgo()` at its commit.\n",
}
SELF_TEST_ERRORS = [
    'DOCS/guide/wrong.md: DOCS/guide/page.md, "Heading two": no such heading',
    "DOCS/guide/wrong.md:3: `matrixGroupMethodNames()`: no matrixGroupMethodNames in the code",
    "DOCS/guide/wrong.md:3: `LiePoissonSystem::velocityInto`: no velocityInto in the code",
    "DOCS/guide/wrong.md:3: `not-a-target`: not in the code",
    "DOCS/guide/wrong.md:4: `core/missing.h`: no such file or folder",
    "DOCS/guide/wrong.md:4: `missing.cc`: no such file in the tree",
    "DOCS/guide/wrong.md:5: `ddb::Relaxation::fieldAt`: no file of the code has both Relaxation "
    "and fieldAt",
]


def self_test():
    """Runs the check on a tree of a few files, one page of which names what is not there and
    cites a heading that is not there; the check must find those and nothing else."""
    import tempfile
    docs = "docs/"
    with tempfile.TemporaryDirectory() as tmp:
        root = pathlib.Path(tmp)
        for rel, text in SELF_TEST_TREE.items():
            path = root / rel.replace("DOCS/", docs)
            path.parent.mkdir(parents=True, exist_ok=True)
            path.write_text(text.replace("DOCS/", docs), encoding="utf-8")
        errors, summary = check(root, min_citations=0)
    expected = [e.replace("DOCS/", docs) for e in SELF_TEST_ERRORS]
    if errors != expected:
        print("check_citations --self-test: expected\n  " + "\n  ".join(expected) +
              "\nfound\n  " + "\n  ".join(errors))
        return 1
    print(f"check_citations --self-test: the {len(errors)} wrong names and citations found, "
          "nothing else")
    return 0


def main(argv):
    if argv[1:] == ["--self-test"]:
        return self_test()
    if len(argv) != 2:
        print(__doc__)
        return 2
    root = pathlib.Path(argv[1]).resolve()
    if not (root / "docs").is_dir():
        print(f"check_citations: {root} has no docs/ folder")
        return 2
    errors, summary = check(root)
    for e in errors:
        print(e)
    print(summary)
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
