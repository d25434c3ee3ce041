#!/usr/bin/env python3
"""Draws slices.png: vertical slices of the coupling's gas fraction through fluidized-bed runs at
given times, each through the row of the bed's largest gas fraction (its most open void), the bed
being the rows lateral_structure.py takes. Takes
LABEL=RUN_DIR@TIME arguments (the snapshot nearest TIME, from RUN_DIR/snapshots/fluid_*.h5) and
writes slices.png beside this script:
    /usr/bin/python3 results/fluidized_bed/slices.py "original=runs/studies/fluidized_bed/cg1@0.7" ...
"""
import os
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from lateral_structure import cell_size, rows_of_bed  # noqa: E402  (the same bed rows)
TOP = 8e-3  # [m] drawn height


def nearest_snapshot(folder, time):
    snaps = os.path.join(folder, "snapshots")
    best = None
    for name in sorted(os.listdir(snaps)):
        if not (name.startswith("fluid_") and name.endswith(".h5")):
            continue
        with h5py.File(os.path.join(snaps, name), "r") as f:
            t = float(f.attrs["time_s"])
        if best is None or abs(t - time) < abs(best[0] - time):
            best = (t, os.path.join(snaps, name))
    if best is None:
        sys.exit(f"no fluid snapshots in {snaps}")
    return best


def main(args):
    if not args:
        sys.exit(__doc__)
    fig, ax = plt.subplots(1, len(args), figsize=(2.2 * len(args) + 1, 4.2), squeeze=False)
    image = None
    for k, arg in enumerate(args):
        label, rest = arg.split("=", 1)
        folder, time = rest.rsplit("@", 1)
        t, path = nearest_snapshot(folder, float(time))
        with h5py.File(path, "r") as f:
            eps = f["porosity"][:]  # (z, y, x)
        nz, ny, nx = eps.shape
        dx = cell_size(folder)
        rows = rows_of_bed(eps)
        y = ny // 2 if rows is None else np.unravel_index(np.argmax(eps[rows]), eps[rows].shape)[1]
        top = min(nz, int(round(TOP / dx)))
        image = ax[0, k].imshow(eps[:top, y, :], origin="lower", cmap="viridis", vmin=0.35,
                                vmax=1.0, extent=(0, nx * dx * 1e3, 0, top * dx * 1e3))
        ax[0, k].set_title(f"{label}\nt = {t:.2f} s", fontsize=9)
        ax[0, k].set_xlabel("x [mm]")
    ax[0, 0].set_ylabel("height [mm]")
    fig.colorbar(image, ax=ax[0, :].tolist(), label="gas fraction", shrink=0.8)
    out = os.path.join(HERE, "slices.png")
    fig.savefig(out, dpi=110)
    print("wrote", out)


if __name__ == "__main__":
    main(sys.argv[1:])
