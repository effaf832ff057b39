#!/usr/bin/env python3
"""Fails if the README's feature table (systems × methods) says other than the method table.

The rows of kMethods (integrators/methods/method_table.h) give each method's group families,
whether it needs a Lagrangian or the metric α·I, its orders, whether it keeps the Casimirs and
whether it needs the matrices' spectral calculus (an exponential retraction, or a composition of
such a row: method_table.h's needsEigenbasis) and whether it needs the orbit preconditioner (the
linearly implicit factor: needsOrbitPreconditioner); the systems below give their family, whether they have a Lagrangian,
whether their metric is α·I and whether their matrices have the spectral calculus and the
preconditioner. From these this script makes the table the README must hold between its two markers.
A method that runs on a system is marked ✓, or, on the GPU, "built, not yet run on a GPU": the
CUDA backend is compiled and its host-side parts tested, but none of its device tests has run on
a GPU yet (docs/results/gpu.md); a method that does not run there is marked —.

    python3 tests/checks/check_feature_table.py <source tree>           check README.md
    python3 tests/checks/check_feature_table.py --print <source tree>   print the table
"""
import pathlib
import re
import sys

BEGIN = "<!-- feature table: tests/checks/check_feature_table.py -->"
END = "<!-- end of the feature table -->"

FAMILY = {"kFixedSizeGroups": 1, "kMatrixGroups": 2, "kBackendMatrixGroups": 4}

# What a cell says when the method runs there: ✓, or BUILT_NOT_RUN where it is compiled for
# that hardware but has never run on it.
RUNS = "✓"
BUILT_NOT_RUN = "built, not yet run on a GPU"

# (column, group family, has a Lagrangian, metric α·I, spectral calculus, orbit preconditioner,
# the mark of a method that runs there): systems/*.h and systems/zeitlin_fluid_on_backend.h; the
# heavy top has no regular Lagrangian, the heavy top and the Kirchhoff bodies have
# k♯ = α diag(k); the magnetic fluid's dual-number matrices have the spectral calculus
# (core/dual_eigenbasis.h) and the shift's preconditioner, and its metric, which swaps their
# parts, is α times its pairing's identity (DissipationMetric::scalarMultiple,
# systems/zeitlin_mhd.h). The GPU's column stays
# BUILT_NOT_RUN until the device tests have run on a GPU (docs/results/gpu.md).
SYSTEMS = [
    ("rigid body", 1, True, True, True, True, RUNS),
    ("heavy top", 1, False, False, True, True, RUNS),
    ("Kirchhoff", 1, True, False, True, True, RUNS),
    ("planar Kirchhoff, SE(2)", 1, True, False, True, True, RUNS),
    ("Manakov, SO(N)", 2, False, True, True, True, RUNS),
    ("fluid, SU(N)", 2, False, True, True, True, RUNS),
    ("fluid on MPI ranks", 4, False, True, True, True, RUNS),
    ("fluid on one GPU", 4, False, True, True, True, BUILT_NOT_RUN),
    ("MHD, SU(N) ⋉ su(N)*", 4, False, True, True, True, RUNS),
]

ROW = re.compile(
    r'\{"([a-z0-9-]+)",\s*"(?:[^"\\]|\\.)*",\s*([A-Za-z| \n]+?),\s*(true|false),\s*'
    r"(true|false),\s*(true|false),\s*(\d+),\s*(\d+),\s*MethodKind::(\w+),\s*"
    r'RetractionKind::(\w+),\s*SchemeKind::\w+,\s*"([a-z0-9-]*)"'
)


def methods(root):
    text = (root / "integrators/methods/method_table.h").read_text(encoding="utf-8")
    body = text[text.index("kMethods{{"):]
    rows = {}
    for m in ROW.finditer(body):
        name, flags, casimirs, lagrangian, scalar, order, order0, kind, retraction, base = m.groups()
        families = sum(FAMILY[f.strip()] for f in flags.split("|"))
        rows[name] = (name, families, casimirs == "true", lagrangian == "true", scalar == "true",
                      int(order), int(order0), kind, retraction, base)

    def recipe(name):
        """(kind, retraction) of the row a composition composes, else of the row itself."""
        _, _, _, _, _, _, _, kind, retraction, base = rows[name]
        return recipe(base) if kind == "kComposition" else (kind, retraction)

    def spectral(name):
        kind, retraction = recipe(name)
        return retraction in ("kExponential", "kTruncatedExponential2")

    def preconditioned(name):
        return recipe(name)[0] == "kLinearlyImplicitDdb"

    return [row[:7] + (spectral(name), preconditioned(name)) for name, row in rows.items()]


def table(root):
    head = ["method"] + [s[0] for s in SYSTEMS] + ["order", "keeps Casimirs"]
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for (name, families, casimirs, lagrangian, scalar, order, order0, spectral,
         preconditioned) in methods(root):
        cells = [f"`{name}`"]
        for _, family, has_lagrangian, has_scalar, has_spectral, has_weights, mark in SYSTEMS:
            runs = (families & family) and (has_lagrangian or not lagrangian) and (
                has_scalar or not scalar) and (has_spectral or not spectral) and (
                has_weights or not preconditioned)
            cells.append(mark if runs else "—")
        if order == 0:
            cells.append("adaptive")
        elif order == order0:
            cells.append(str(order))
        else:
            cells.append(f"{order} ({order0} at α = 0)")
        cells.append("✓" if casimirs else "—")
        lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines)


def main(argv):
    args = [a for a in argv[1:] if a != "--print"]
    if len(args) != 1:
        print(__doc__)
        return 2
    root = pathlib.Path(args[0]).resolve()
    expected = table(root)
    if "--print" in argv:
        print(expected)
        return 0
    readme = (root / "README.md").read_text(encoding="utf-8")
    if BEGIN not in readme or END not in readme:
        print(f"check_feature_table: README.md has no '{BEGIN}' ... '{END}'")
        return 1
    found = readme[readme.index(BEGIN) + len(BEGIN):readme.index(END)].strip()
    if found != expected:
        print("check_feature_table: README.md's feature table differs from the method table; "
              "it should read:\n" + expected)
        return 1
    print(f"check_feature_table: {len(methods(root))} methods × {len(SYSTEMS)} systems agree")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
