#!/usr/bin/env python3
"""Ratios of per-step times within one ddb-bench run.

Usage: ddb-bench --benchmark_format=json > bench.json; bench_ratios.py bench.json
(with --benchmark_repetitions=K the medians are used).
Prints each benchmark's time relative to rigid_body/rk4 (and heavy_top/rk4), with its
allocations, Newton iterations and predictor sweeps per step, and the targets:
rigid_body ddb-cay / rk4 <= 2.5, rk4 / rk4-handwritten <= 1.3, heavy_top ddb-cay / rk4 <= 3.
"""
import json
import sys


def main():
    data = json.load(open(sys.argv[1]))
    # With --benchmark_repetitions, the medians (named <benchmark>_median; with
    # --benchmark_report_aggregates_only they are all there is); otherwise the single runs.
    runs = [b for b in data["benchmarks"] if b.get("aggregate_name") == "median"]
    for b in runs:
        b["name"] = b["run_name"]
    if not runs:
        runs = [b for b in data["benchmarks"] if b.get("run_type") != "aggregate"]
    times = {b["name"]: b["cpu_time"] for b in runs}
    allocs = {b["name"]: b.get("allocs_per_step", float("nan")) for b in runs}
    newton = {b["name"]: b.get("newton_per_step") for b in runs}
    sweeps = {b["name"]: b.get("sweeps_per_step") for b in runs}
    for prefix in ("rigid_body", "heavy_top"):
        base = times.get(prefix + "/rk4")
        if not base:
            continue
        print(f"{prefix}: time per step relative to {prefix}/rk4 ({base:.1f} ns)")
        for name, t in times.items():
            if name.startswith(prefix + "/"):
                iterations = "" if newton[name] is None else f"  newton/step {newton[name]:.2f}"
                if sweeps[name] is not None:  # older runs have no sweeps counter
                    iterations += f"  sweeps/step {sweeps[name]:.2f}"
                print(f"  {name:32s} {t:10.1f} ns  x{t / base:7.2f}  allocs/step {allocs[name]:.0f}"
                      f"{iterations}")
    targets = [("rigid_body/ddb-cay", "rigid_body/rk4", 2.5),
               ("rigid_body/rk4", "rigid_body/rk4-handwritten", 1.3),
               ("heavy_top/ddb-cay", "heavy_top/rk4", 3.0)]
    for numerator, denominator, target in targets:
        if numerator in times and denominator in times:
            ratio = times[numerator] / times[denominator]
            print(f"{numerator} / {denominator} = {ratio:.2f} (target <= {target})")

if __name__ == "__main__":
    main()
