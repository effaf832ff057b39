#!/usr/bin/env python3
"""Ratios of per-step times within one ddb-bench run.

Usage: ddb-bench --benchmark_format=json > bench.json; bench_ratios.py bench.json
Prints each benchmark's time relative to rigid_body/rk4 (and heavy_top/rk4), and the
issue's targets: ddb-cay / rk4 and rk4 / odeint-rk4.
"""
import json
import sys


def main():
    data = json.load(open(sys.argv[1]))
    times = {b["name"]: b["cpu_time"] for b in data["benchmarks"] if b.get("run_type") != "aggregate"}
    allocs = {b["name"]: b.get("allocs_per_step", float("nan")) for b in data["benchmarks"]}
    for prefix in ("rigid_body", "heavy_top"):
        base = times.get(prefix + "/rk4")
        if not base:
            continue
        print(f"{prefix}: time per step relative to {prefix}/rk4 ({base:.1f} ns)")
        for name, t in times.items():
            if name.startswith(prefix + "/"):
                print(f"  {name:32s} {t:10.1f} ns  x{t / base:7.2f}  allocs/step {allocs[name]:.0f}")
    rb = lambda n: times.get("rigid_body/" + n)  # noqa: E731
    if rb("ddb-cay") and rb("rk4") and rb("odeint-rk4"):
        print(f"ddb-cay / rk4 = {rb('ddb-cay') / rb('rk4'):.2f} (target <= 3)")
        print(f"rk4 / odeint-rk4 = {rb('rk4') / rb('odeint-rk4'):.2f} (target <= 1.1)")


if __name__ == "__main__":
    main()
