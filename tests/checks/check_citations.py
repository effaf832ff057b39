#!/usr/bin/env python3
"""Fails if a citation of the docs points nowhere (CONTRIBUTING: a move of a file or a
heading is then mechanical, and a reader who follows a comment finds the text it means).

A citation is a path under docs/ named in the code, the scripts, the build files or the
docs themselves, optionally followed by a section and a heading:

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

    python3 tests/checks/check_citations.py <source tree>
"""
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


def scanned_files(root):
    for path in sorted(root.rglob("*")):
        rel = path.relative_to(root).as_posix()
        if (not path.is_file() or rel.split("/")[0].startswith(SKIPPED_PREFIX)
                or any(rel == d or rel.startswith(d + "/") for d in SKIPPED_DIRS)):
            continue
        if path.suffix in SCANNED_SUFFIXES or path.name == "CMakeLists.txt":
            yield path, rel


def main(argv):
    if len(argv) != 2:
        print(__doc__)
        return 2
    root = pathlib.Path(argv[1]).resolve()
    if not (root / "docs").is_dir():
        print(f"check_citations: {root} has no docs/ folder")
        return 2
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
    if count < 200:
        errors.append(f"found only {count} citations: is {root} the source tree?")
    for e in errors:
        print(e)
    print(f"check_citations: {count} citations of docs/, {with_heading} by heading, "
          f"{len(errors)} pointing nowhere")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
