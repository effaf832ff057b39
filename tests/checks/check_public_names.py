#!/usr/bin/env python3
"""Fails if the README or docs/guide show a C++ name of the library that tests/api/ does not
compile (CONTRIBUTING.md, "Public names"): a name a user can copy from the docs is one whose
removal or renaming must fail CI before a user sees it, so every such name is used in
tests/api/public_names.cc (or, while it is deprecated, tests/api/deprecated_names.cc), which
the build compiles.

A name the docs show is, in README.md and docs/guide/*.md:
  * a header `<ddb/...>` or `ddb/....h` (code blocks and inline code);
  * an identifier in C++ code blocks (their comments included) or inline code that is the
    library's: it appears in the code (comments and strings stripped) of a header under core/,
    groups/, systems/, integrators/, distributed/ or cuda/, and not in the code of Eigen's, the
    C++ library's or MPI's headers (so a name both use, `Matrix`, `value`, is not demanded:
    tests/api/ uses those anyway);
    with an upper-case letter or a digit (SO3, makeMethod, kSteady), or written as a call or
    qualified (`relax(...)`, `ddb::relax`), so that words of the prose are not names.
The name must appear as a word (or the header as an #include) in tests/api/.

    python3 tests/checks/check_public_names.py <source tree>
"""
import glob
import pathlib
import re
import sys

LIBRARY_DIRS = ["core", "groups", "systems", "integrators", "distributed", "cuda"]
FOREIGN_HEADERS = ["/usr/include/eigen3/Eigen/src/Core/**/*.h", "/usr/include/c++/*/bits/*.h",
                   "/usr/lib/x86_64-linux-gnu/openmpi/include/mpi.h"]
# Words the docs' examples use that are not the library's names: Eigen's typedefs (made by a
# macro, so not in its headers' text), Ceres's Jet, the namespace, and example variables.
NOT_NAMES = {"ddb", "Jet", "mu0", "omega", "inertia_"}
EIGEN_TYPEDEF = re.compile(r"^(Matrix|Vector|RowVector|Array)[0-9X]*c?[dfi]$")
WORD = re.compile(r"\b[A-Za-z_][A-Za-z0-9_]*\b")
HEADER = re.compile(r"\bddb/[A-Za-z0-9_/]+\.h\b")
# An identifier with what follows it: a call "(" or a template "<", and what precedes it.
TOKEN = re.compile(r"(ddb::)?(?<![-\w./])([A-Za-z_][A-Za-z0-9_]*)(\s*[(<])?")


def code_words(text):
    text = re.sub(r"//[^\n]*", "", text)
    text = re.sub(r"/\*.*?\*/", "", text, flags=re.S)
    text = re.sub(r'"(?:\\.|[^"\\\n])*"', '""', text)
    return set(WORD.findall(text))


def shown(tree):
    """{name: first doc showing it}, {header: first doc showing it}."""
    names, headers = {}, {}
    for doc in [tree / "README.md"] + sorted((tree / "docs/guide").glob("*.md")):
        text = doc.read_text()
        where = str(doc.relative_to(tree))
        pieces = []
        for m in re.finditer(r"```(\w*)\n(.*?)```", text, re.S):
            if m.group(1) in ("cpp", "c++", "cc", "cmake", ""):
                for h in HEADER.findall(m.group(2)):
                    headers.setdefault(h, where)
            if m.group(1) in ("cpp", "c++", "cc"):
                pieces.append(m.group(2))  # its comments too: they name types and functions
        prose = re.sub(r"```.*?```", "", text, flags=re.S)
        for m in re.finditer(r"`([^`\n]+)`", prose):
            for h in HEADER.findall(m.group(1)):
                headers.setdefault(h, where)
            pieces.append(m.group(1))
        for piece in pieces:
            for qualified, name, follow in TOKEN.findall(piece):
                if re.search(r"[A-Z0-9]", name) or qualified or follow:
                    names.setdefault(name, where)
    return names, headers


def main():
    tree = pathlib.Path(sys.argv[1])
    library = set()
    for d in LIBRARY_DIRS:
        for header in (tree / d).rglob("*.h"):
            library |= code_words(header.read_text())
    foreign = set()
    for pattern in FOREIGN_HEADERS:
        for path in glob.glob(pattern, recursive=True):
            foreign |= code_words(open(path, errors="ignore").read())
    api = "".join(p.read_text() for p in sorted((tree / "tests/api").glob("*.cc")))
    api_words = set(WORD.findall(api))
    api_headers = set(re.findall(r"#include <(ddb/[^>]+)>", api))
    names, headers = shown(tree)
    names = {n: w for n, w in names.items()
             if n in library and n not in foreign and len(n) > 2 and n not in NOT_NAMES and
             not EIGEN_TYPEDEF.match(n)}
    missing = [(n, w) for n, w in sorted(names.items()) if n not in api_words]
    missing += [(h, w) for h, w in sorted(headers.items()) if h not in api_headers]
    for name, where in missing:
        print(f"{where}: shows `{name}`, which tests/api/ does not compile")
    print(f"check_public_names: {len(names)} names and {len(headers)} headers the docs show, "
          f"{len(missing)} not compiled by tests/api/")
    return 1 if missing else 0


if __name__ == "__main__":
    sys.exit(main())
