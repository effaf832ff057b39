"""Writes the Python module's reference page from its own docstrings, for the API reference
(docs/CMakeLists.txt): every function, class, method and property of `ddb`, each docstring
shown verbatim as `help(ddb)` shows it (pybind11 puts the signatures on its first lines), so
that the page says what the built module says.

    python3 python/api_reference.py BUILD/python OUT.md
"""

import inspect
import sys


def entry(lines, heading, doc):
    lines += [heading, ""]
    if doc and doc.strip():
        # A fenced block: Doxygen shows it verbatim (no commands, HTML or Markdown in it).
        lines += ["```", inspect.cleandoc(doc).replace("```", "'''"), "```", ""]


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: api_reference.py MODULE_DIR OUT.md")
    sys.path.insert(0, sys.argv[1])
    import ddb  # noqa: E402 (the module just built, from the folder given)

    lines = [
        "# The Python module ddb: reference {#python_api}",
        "",
        "Generated from the built module's docstrings by `python/api_reference.py`; the guide is",
        "`docs/guide/python.md`.",
        "",
    ]
    entry(lines, "## The module", ddb.__doc__)
    members = [(n, m) for n, m in inspect.getmembers(ddb) if not n.startswith("_")]
    lines += ["## Functions", ""]
    for name, member in members:
        if callable(member) and not inspect.isclass(member):
            entry(lines, f"### {name}", member.__doc__)
    lines += ["## Classes", ""]
    for name, member in members:
        if not inspect.isclass(member):
            continue
        entry(lines, f"### {name}", member.__doc__)
        for attr, value in member.__dict__.items():
            if attr.startswith("_") and attr != "__init__":
                continue
            if isinstance(value, property):
                entry(lines, f"#### {name}.{attr} (property)", value.__doc__)
            elif callable(value) or isinstance(value, (staticmethod, classmethod)):
                entry(lines, f"#### {name}.{attr}", getattr(member, attr).__doc__)
    with open(sys.argv[2], "w", encoding="utf-8") as out:
        out.write("\n".join(lines).rstrip() + "\n")


if __name__ == "__main__":
    main()
