#!/usr/bin/env python3
"""Does a bed stay laterally uniform, or do voids grow in it? From the gas-fraction snapshots of
fluidized-bed run folders (snapshots/fluid_*.h5, the coupling's porosity on the gas grid), per
snapshot and over the lower 85 % of the bed (the horizontal rows whose mean gas fraction is below
0.7, the surface rows left out):
  row_sd       the standard deviation of the gas fraction within each row, averaged over the rows;
  block_row_sd the same on cubes of 0.8 mm (4 original diameters), where the grid divides them:
               it compares beds whose kernels differ in width (2 parcel diameters);
  eps_max      the largest gas fraction in those rows (a void reads above about 0.8);
  void_share   the share of their cells above 0.8;
  band_sd      the standard deviation of the rows' mean gas fraction: horizontal voidage bands
               (one-dimensional voidage waves) raise it while the rows stay uniform;
  band_spacing the mean distance between neighbouring void bands (local maxima of the rows' mean
               above its average) [mm], empty with fewer than two.
A uniformly expanded bed keeps row_sd and band_sd at their noise floor; one-dimensional voidage
waves raise band_sd alone; their lateral break-up into voids and bubbles raises row_sd. Writes CSV to stdout. Run from anywhere:
    /usr/bin/python3 results/fluidized_bed/lateral_structure.py RUN_DIR [RUN_DIR ...] > lateral_structure.csv
"""
import os
import sys
import tomllib

import h5py
import numpy as np

BLOCK = 0.8e-3  # [m]
VOID = 0.8


def rows_of_bed(eps):
    profile = eps.mean(axis=(1, 2))
    bed = np.where(profile < 0.7)[0]
    if len(bed) == 0:
        return None
    return np.arange(0, int(0.85 * bed.max()) + 1)


def block_means(eps, dx):
    b = BLOCK / dx
    n = int(round(b))
    if abs(b - n) > 1e-6 or eps.shape[1] % n or eps.shape[2] % n:
        return None
    nz = eps.shape[0] // n * n
    if nz == 0:
        return None
    z, y, x = nz // n, eps.shape[1] // n, eps.shape[2] // n
    return eps[:nz].reshape(z, n, y, n, x, n).mean(axis=(1, 3, 5))


def cell_size(folder):
    with open(os.path.join(folder, "config.toml"), "rb") as f:
        return float(tomllib.load(f)["fluid"]["dx"])


def main(folders):
    print("case,time_s,bed_rows,row_sd,block_row_sd,eps_max,void_share,band_sd,band_spacing_mm")
    for folder in folders:
        snaps = os.path.join(folder, "snapshots")
        names = sorted(n for n in os.listdir(snaps) if n.startswith("fluid_") and n.endswith(".h5"))
        dx = cell_size(folder)
        for name in names:
            with h5py.File(os.path.join(snaps, name), "r") as f:
                eps = f["porosity"][:]  # (z, y, x)
                t = float(f.attrs["time_s"])
            rows = rows_of_bed(eps)
            if rows is None:
                continue
            bed = eps[rows]
            blocks = block_means(bed, dx)
            block_sd = "" if blocks is None else f"{blocks.std(axis=(1, 2)).mean():.5f}"
            means = bed.mean(axis=(1, 2))
            peaks = [k for k in range(1, len(means) - 1)
                     if means[k] > means.mean() and means[k] >= means[k - 1]
                     and means[k] > means[k + 1]]
            spacing = f"{np.diff(peaks).mean() * dx * 1e3:.2f}" if len(peaks) > 1 else ""
            print(f"{os.path.basename(os.path.normpath(folder))},{t:.4f},{len(rows)},"
                  f"{bed.std(axis=(1, 2)).mean():.5f},{block_sd},{bed.max():.4f},"
                  f"{(bed > VOID).mean():.5f},{means.std():.4f},{spacing}")


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    main(sys.argv[1:])
