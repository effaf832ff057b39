#!/usr/bin/env python3
"""The fluid's benchmark table: seconds and products per step against N, per thread count.

Usage:
  for t in 1 2; do OPENBLAS_NUM_THREADS=$t build/bin/ddb-bench --benchmark_filter=zeitlin \\
      --benchmark_format=json > fluid-$t.json; done
  python3 scripts/fluid_bench_table.py fluid-1.json fluid-2.json

Times are wall-clock (real_time): with 2 BLAS threads the CPU time of the timing thread
says nothing of the other. Products per step = a step's time / the time of one complex N x N product
(zeitlin/gemm/<N>) in the same run. The exponent is the least-squares slope of
log(time) against log(N) over the sizes present.
"""
import json
import math
import re
import sys


def load(path):
    runs = {}
    for b in json.load(open(path))["benchmarks"]:
        if b.get("run_type") == "aggregate":
            continue
        m = re.fullmatch(r"(zeitlin(?:-[a-z]+)?/[a-z0-9-]+)/(\d+)", b["name"])
        if m:
            runs.setdefault(m.group(1), {})[int(m.group(2))] = b
    return runs


def milliseconds(benchmark):
    """A benchmark's wall time per iteration in ms, whatever its time unit."""
    return benchmark["real_time"] * {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}[benchmark["time_unit"]]


def slope(sizes, times):
    xs = [math.log(n) for n in sizes]
    ys = [math.log(t) for t in times]
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)


def main():
    files = sys.argv[1:]
    runs = [load(f) for f in files]
    header = "| benchmark | N |"
    rule = "|---|---|"
    for f in files:
        header += f" {f}: ms/step | products/step | iterations/step |"
        rule += "---|---|---|"
    print(header)
    print(rule)
    names = [n for n in runs[0] if n != "zeitlin/gemm"]
    for name in ["zeitlin/gemm"] + sorted(names):
        sizes = sorted(runs[0].get(name, {}))
        for n in sizes:
            row = f"| {name} | {n} |"
            for r in runs:
                b = r.get(name, {}).get(n)
                gemm = r["zeitlin/gemm"].get(n)
                if b is None or gemm is None:
                    row += " | | |"
                    continue
                ms, gms = milliseconds(b), milliseconds(gemm)
                iterations = None if "rk4" in name else b.get("iterations_per_step")
                row += f" {ms:.3g} | {ms / gms:.1f} | {'' if iterations is None else f'{iterations:.2f}'} |"
            print(row)
    print()
    for f, r in zip(files, runs):
        for name in ["zeitlin/gemm"] + sorted(names):
            sizes = sorted(r.get(name, {}))
            if len(sizes) >= 2:
                times = [r[name][n]["real_time"] for n in sizes]
                print(f"{f}: {name}: time ~ N^{slope(sizes, times):.2f} over N = {sizes[0]}..{sizes[-1]}")


if __name__ == "__main__":
    main()
