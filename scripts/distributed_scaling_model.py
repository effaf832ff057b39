#!/usr/bin/env python3
"""The distributed DDB step's time per step against the number of ranks: measured on this
machine (P = 1, 2) and modelled for large P (docs/results/distributed.md, "A model for large P").

usage: distributed_scaling_model.py MEASURED.jsonl [OUT.png]

MEASURED.jsonl holds distributed-step-bench's lines (docs/data/distributed-step-bench.jsonl).
Prints the calibration, the model's table for N = 2048 and 4096 and the fewest ranks that
reach GLIFS's published time; with OUT.png also draws the figure.

The model, per step on P ranks in the library's default pr x pc grid (pc the largest divisor
of P not above sqrt(P), pr = P / pc), block b = 64, in the form of the ScaLAPACK Users'
Guide's performance model (flops / P + words / sqrt(P) + messages):
  T = K_f 8 N^3 / (P F) + K_v V / B
      + L (K_v (N / b) (ceil(log2 pr) + ceil(log2 pc)) + 2 K_s (P - 1) + M_inv)
  V = 16 N^2 (1/pr + 1/pc - 2/P)  bytes a rank receives in one pzgemm (SUMMA: the row strip
      of A and the column strip of B it does not hold; equal to distributed-step-bench's
      counted totals / P on 1 x 2, 2 x 1 and 2 x 2 grids)
  2 K_s (P - 1): the Poisson solves' all-to-all exchanges, two per solve, one solve per
      fixed-point sweep (K_s sweeps per step)
  M_inv = 2 N ceil(log2 pr) for alpha != 0: the LU factorisation's and the inversion's
      per-column reductions over a process column, 0 for alpha = 0
Calibrated here: F, one core's complex product rate (P = 1 product times); K_f, the step's
flops in products (P = 1 products per step, N = 1024); K_v, the step's bytes in products
(P = 2 bytes per step / bytes per product, N = 1024); K_s (P = 1, N = 1024); B, one rank's effective bandwidth
fitted by least squares to the alpha = 0 steps at P = 2 (their time over half the P = 1
step). Assumed, not measured: L, and a cluster's bandwidth per rank (below).
"""
import json
import math
import sys

# Assumptions (docs/results/distributed.md, "A model for large P"): MPI latency between nodes, and a
# cluster node's injection bandwidth (200 Gb/s InfiniBand HDR) shared by 64 ranks.
LATENCY_S = 2e-6
CLUSTER_RANK_BANDWIDTH = 25e9 / 64
BLOCK = 64
# GLIFS (Cifani, Viviani and Modin, J. Comput. Phys. 2023), as quoted by issue 25.
GLIFS_N, GLIFS_CORES, GLIFS_STEP_S = 4096, 2500, 0.55


def grid(p):
    cols = max(d for d in range(1, int(math.isqrt(p)) + 1) if p % d == 0)
    return p // cols, cols


def product_bytes_per_rank(n, p):
    rows, cols = grid(p)
    return 16.0 * n * n * (1.0 / rows + 1.0 / cols - 2.0 / p)


def calibrate(lines):
    at = {(r["n"], r["alpha"], r["ranks"]): r for r in lines}
    rates = [8.0 * r["n"] ** 3 / r["product_s"] for r in lines if r["ranks"] == 1]
    c = {"F": sum(rates) / len(rates)}
    for alpha in (0, 0.5):
        c[("K_f", alpha)] = at[(1024, alpha, 1)]["products_per_step"]
        c[("K_s", alpha)] = at[(1024, alpha, 1)]["sweeps_per_step"]
        two = at[(1024, alpha, 2)]
        c[("K_v", alpha)] = two["bytes_per_step"] / two["bytes_per_product"]
    # B: least squares of overhead = bytes per rank / B over the alpha = 0 points.
    xs, ys = [], []
    for n in (512, 1024):
        one, two = at[(n, 0, 1)], at[(n, 0, 2)]
        xs.append(two["bytes_per_step"] / 2)
        ys.append(two["step_s"] - one["step_s"] / 2)
    c["B_here"] = sum(x * x for x in xs) / sum(x * y for x, y in zip(xs, ys))
    return c


def step_time(c, n, p, alpha, bandwidth):
    rows, cols = grid(p)
    key = 0.5 if alpha else 0
    flops = c[("K_f", key)] * 8.0 * n**3 / (p * c["F"])
    volume = c[("K_v", key)] * product_bytes_per_rank(n, p) / bandwidth
    hops = math.ceil(math.log2(rows)) + math.ceil(math.log2(cols))
    messages = c[("K_v", key)] * (n / BLOCK) * hops + 2 * c[("K_s", key)] * (p - 1)
    if alpha:
        messages += 2 * n * math.ceil(math.log2(rows))
    return flops + volume + LATENCY_S * messages


def fewest_ranks(c, n, alpha, bandwidth, target):
    for p in range(1, 100001):
        if step_time(c, n, p, alpha, bandwidth) <= target:
            return p
    return None


def main():
    if len(sys.argv) not in (2, 3):
        sys.exit(__doc__)
    with open(sys.argv[1]) as f:
        lines = [json.loads(line) for line in f if line.strip()]
    c = calibrate(lines)
    print("F = %.1f Gflop/s per core, B here = %.2f GB/s per rank" % (c["F"] / 1e9,
                                                                   c["B_here"] / 1e9))
    for alpha in (0, 0.5):
        print("alpha = %g: K_f = %.2f products, K_v = %.2f products' bytes, K_s = %g sweeps" %
              (alpha, c[("K_f", alpha)], c[("K_v", alpha)], c[("K_s", alpha)]))
    print("\nmeasured against the model (B here):")
    for r in lines:
        model = step_time(c, r["n"], r["ranks"], r["alpha"], c["B_here"])
        print("  N %4d alpha %-3g P %d: measured %.3f s, model %.3f s (%+.0f%%)" %
              (r["n"], r["alpha"], r["ranks"], r["step_s"], model,
               100 * (model / r["step_s"] - 1)))
    scenarios = {"B here": c["B_here"], "cluster B": CLUSTER_RANK_BANDWIDTH}
    ranks = [1, 4, 16, 64, 256, 500, 1024, 2500, 4096]
    print("\nmodelled time per step (s):")
    print("  N     alpha  bandwidth  " + "".join("%9d" % p for p in ranks))
    for n in (2048, 4096):
        for alpha in (0, 0.5):
            for name, bandwidth in scenarios.items():
                print("  %-5d %-6g %-10s " % (n, alpha, name) +
                      "".join("%9.3g" % step_time(c, n, p, alpha, bandwidth) for p in ranks))
    print("\nfewest ranks for %.2f s per step at N = %d:" % (GLIFS_STEP_S, GLIFS_N))
    for alpha in (0, 0.5):
        for name, bandwidth in scenarios.items():
            print("  alpha %g, %s: %s" % (alpha, name,
                                         fewest_ranks(c, GLIFS_N, alpha, bandwidth,
                                                      GLIFS_STEP_S)))
    if len(sys.argv) == 3:
        plot(c, lines, scenarios, sys.argv[2])


def plot(c, lines, scenarios, out):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    # Square grids and the measured P = 2: a prime P would give a P x 1 grid.
    ranks = [1, 2] + [k * k for k in range(2, 65)]
    colours = {512: "tab:gray", 1024: "tab:blue", 2048: "tab:green", 4096: "tab:red"}
    fig, axes = plt.subplots(1, 2, figsize=(12, 5.2), sharey=True)
    for ax, alpha in zip(axes, (0, 0.5)):
        for n, colour in colours.items():
            here = [step_time(c, n, p, alpha, scenarios["B here"]) for p in ranks]
            cluster = [step_time(c, n, p, alpha, scenarios["cluster B"]) for p in ranks]
            ax.plot(ranks, here, color=colour, lw=1.6, label="N = %d, model" % n)
            ax.plot(ranks, cluster, color=colour, lw=1.2, ls="--")
            ax.fill_between(ranks, here, cluster, color=colour, alpha=0.12, lw=0)
            measured = [r for r in lines if r["n"] == n and r["alpha"] == alpha]
            if measured:
                ax.plot([r["ranks"] for r in measured], [r["step_s"] for r in measured], "o",
                        color=colour, ms=7, mec="black", label="N = %d, measured" % n)
        if alpha == 0:
            ax.plot([GLIFS_CORES], [GLIFS_STEP_S], "*", color="black", ms=14,
                    label="GLIFS, N = 4096 (published)")
        ax.axvline(500, color="black", lw=0.8, ls=":")
        ax.text(540, 1.4e-3, "500 cores", fontsize=9)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_ylim(1e-3, 300)
        ax.set_xlabel("ranks P (one core each)")
        ax.set_title("α = %g" % alpha)
        ax.grid(True, which="major", alpha=0.3)
    axes[0].set_ylabel("time per DDB Cayley step (s)")
    # One legend for both panels, where the α = 0.5 panel has room (the GLIFS star is α = 0's).
    handles, labels = axes[0].get_legend_handles_labels()
    axes[1].legend(handles, labels, fontsize=8, loc="upper right")
    fig.suptitle("Distributed DDB Cayley step: measured on 1 and 2 ranks of this machine (dots), "
                 "modelled for large P (lines)\nsolid: this machine's bandwidth per rank "
                 "(%.2g GB/s, fitted); dashed: a cluster node's link shared by its ranks "
                 "(%.2g GB/s); latency %g µs" %
                 (c["B_here"] / 1e9, CLUSTER_RANK_BANDWIDTH / 1e9, LATENCY_S * 1e6), fontsize=10)
    fig.tight_layout()
    fig.savefig(out, dpi=120)


if __name__ == "__main__":
    main()
