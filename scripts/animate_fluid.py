#!/usr/bin/env python3
"""Animation of a fluid-relax run from its fluid.hdf5
(docs/reference/command-lines-and-files.md, "fluid.hdf5").

Usage: animate_fluid.py FILE.hdf5 OUT.mp4

Renders the vorticity omega(theta, phi) of the saved frames (the `state` dataset, quflow's
real spherical-harmonic coefficients) on the sphere in Mollweide projection, as
plot_fluid.py does for the initial and final state (its function `vorticity`), with one
colour scale for every frame, the time of each frame, and N, alpha and the method in the
title. At most MAX_FRAMES frames are rendered, evenly spaced, the first and last always.
The video is written with ffmpeg (Debian: apt-get install ffmpeg) under a temporary name
and renamed when complete; without ffmpeg nothing is written and the exit status is 1.
"""
import math
import os
import shutil
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.animation import FFMpegWriter  # noqa: E402

from plot_fluid import L_MAX_PLOTTED, vorticity  # noqa: E402

MAX_FRAMES = 300
FRAMES_PER_SECOND = 15


def frame_indices(count):
    """At most MAX_FRAMES indices of 0..count-1, evenly spaced, first and last included."""
    if count <= MAX_FRAMES:
        return list(range(count))
    return sorted(set(np.linspace(0, count - 1, MAX_FRAMES).round().astype(int).tolist()))


def coefficients(state):
    """The state row (index l^2 + l + m) as plot_fluid's {(l, m): omega_lm}."""
    omega = {}
    for index, w in enumerate(state):
        l = math.isqrt(index)
        omega[(l, index - l * l - l)] = float(w)
    return omega


def attribute(f, name):
    value = f.attrs[name]
    return value.decode() if isinstance(value, bytes) else value


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    source, target = sys.argv[1], sys.argv[2]
    if shutil.which("ffmpeg") is None:
        print("animate_fluid.py: ffmpeg is not on PATH (Debian: apt-get install ffmpeg); "
              "no video written", file=sys.stderr)
        sys.exit(1)
    import h5py

    with h5py.File(source, "r") as f:
        n = int(attribute(f, "N"))
        title = "vorticity $\\omega(\\theta, \\varphi)$, N = %d, alpha = %g, %s" % (
            n, attribute(f, "alpha"), attribute(f, "method"))
        frames = frame_indices(f["state"].shape[0])
        if not frames:
            sys.exit("animate_fluid.py: %s has no frames" % source)
        states = [f["state"][k] for k in frames]
        times = f["time"][frames]
        steps = f["step"][frames]
    l_max = min(n - 1, L_MAX_PLOTTED)
    points = max(121, 2 * l_max + 1)
    latitude = np.linspace(-math.pi / 2, math.pi / 2, points)
    longitude = np.linspace(-math.pi, math.pi, 2 * points - 1)
    fields = [vorticity(coefficients(s), math.pi / 2 - latitude, longitude, l_max).astype(np.float32)
              for s in states]
    limit = max(float(np.abs(field).max()) for field in fields) or 1.0

    fig = plt.figure(figsize=(8, 5.2), layout="constrained")
    ax = fig.add_subplot(1, 1, 1, projection="mollweide")
    mesh = ax.pcolormesh(longitude, latitude, fields[0], cmap="RdBu_r", vmin=-limit, vmax=limit,
                         shading="auto", rasterized=True)
    ax.set_xticklabels([])
    ax.grid(alpha=0.3)
    truncated = " (l <= %d shown)" % l_max if l_max < n - 1 else ""
    heading = title + truncated + "\nt = %.4g (step %d)"
    stamp = fig.suptitle(heading % (times[0], steps[0]))
    fig.colorbar(mesh, ax=ax, orientation="horizontal", fraction=0.06, shrink=0.6,
                 label="$\\omega$ (one scale for every frame)")
    # The layout is fixed after the first frame, so that the sphere does not move as the
    # time stamp's width changes.
    fig.canvas.draw()
    fig.set_layout_engine("none")

    root, extension = os.path.splitext(target)
    partial = root + ".partial" + (extension or ".mp4")
    writer = FFMpegWriter(fps=FRAMES_PER_SECOND, metadata={"title": title})
    try:
        with writer.saving(fig, partial, dpi=100):
            for field, t, step in zip(fields, times, steps):
                mesh.set_array(field.ravel())
                stamp.set_text(heading % (t, step))
                writer.grab_frame()
        os.replace(partial, target)
    finally:
        if os.path.exists(partial):
            os.remove(partial)
    plt.close(fig)
    print("wrote", target, "(%d frames)" % len(frames))


if __name__ == "__main__":
    main()
