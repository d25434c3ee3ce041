#!/usr/bin/env python3
"""Draws the figures of this folder from its kept series: bed_series.png, bed height and
pressure drop over time for the Bond-number-10 original against its coarse-grained runs (left)
and for the cohesionless CG 2-4 runs (right); displaced_gas.png, the cohesionless CG 2, 3 and 4 beds
before and with the displaced gas; original_and_cg.png, the cohesionless original against CG 2, 3
and 4 with the current coupling (and CG 2 with the original's kernel width), with the lateral
structure of their gas fraction
(lateral_structure.csv, from lateral_structure.py). Run from the repository root:
    /usr/bin/python3 results/fluidized_bed/plot_series.py"""
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
WEIGHT = 44.11 + 0.35  # weight per area less buoyancy, plus the gas head over the column [Pa]


def series(name):
    d = np.genfromtxt(os.path.join(HERE, name + "_series.csv"), delimiter=",", names=True)
    return d["time_s"], d["bed_height_m"] * 1e3, d["pressure_drop_Pa"]


groups = [
    ("Bond number 10: original and CG", [("cg1_bo10", "original (CG 1)"),
                                          ("cg2_bo10_l3", "CG 2, Bond number kept (l^3)"),
                                          ("cg2_bo10_l2", "CG 2, tensile strength kept (l^2)"),
                                          ("cg4_bo10_l3", "CG 4, l^3"),
                                          ("cg4_bo10_l2", "CG 4, l^2")]),
    ("cohesionless: CG 2, 3, 4", [("cg2", "CG 2"), ("cg3", "CG 3"), ("cg4", "CG 4"),
                                  ("cg4_wide", "CG 4, 8 x 8 mm")]),
]
fig, ax = plt.subplots(2, 2, figsize=(11, 6.5), sharex=True)
for col, (title, cases) in enumerate(groups):
    for name, label in cases:
        t, h, dp = series(name)
        ax[0, col].plot(t, h, lw=1, label=label)
        ax[1, col].plot(t, dp, lw=0.8, label=label)
    ax[0, col].set_title(title)
    ax[0, col].set_ylabel("bed height [mm]")
    ax[1, col].set_ylabel("pressure drop [Pa]")
    ax[1, col].set_xlabel("time [s]")
    ax[1, col].axhline(WEIGHT, color="k", ls=":", lw=0.8, label="weight / area + gas head")
    ax[1, col].set_ylim(30, 60)
    ax[0, col].set_ylim(4, 9)
    ax[0, col].legend(fontsize=8)
ax[1, 1].legend(fontsize=8, loc="lower right")
fig.tight_layout()
out = os.path.join(HERE, "bed_series.png")
fig.savefig(out, dpi=110)
print("wrote", out)

# The cohesionless CG 3 and 4 beds before and with the displaced gas (d(eps)/dt in the gas
# continuity): the plug oscillation the term damps.
fig, ax = plt.subplots(2, 1, figsize=(8, 5.5), sharex=True)
for name, label in [("cg2", "CG 2, before the term"), ("cg2_displaced", "CG 2, displaced gas"),
                    ("cg3", "CG 3, before the term"), ("cg3_displaced", "CG 3, displaced gas"),
                    ("cg4", "CG 4, before the term"), ("cg4_displaced", "CG 4, displaced gas")]:
    t, h, dp = series(name)
    keep = t >= 0.15
    ax[0].plot(t[keep], h[keep], lw=1, label=label)
    ax[1].plot(t[keep], dp[keep], lw=0.8, label=label)
ax[0].set_ylabel("bed height [mm]")
ax[1].set_ylabel("pressure drop [Pa]")
ax[1].set_xlabel("time [s]")
ax[1].axhline(WEIGHT, color="k", ls=":", lw=0.8, label="weight / area + gas head")
ax[0].legend(fontsize=8)
fig.tight_layout()
out = os.path.join(HERE, "displaced_gas.png")
fig.savefig(out, dpi=110)
print("wrote", out)

# The cohesionless original against CG 2-4 with the current coupling: bed height, pressure drop,
# and the lateral structure of the gas fraction (the within-row sd of 0.8 mm cubes, the same scale
# for every kernel width; lateral_structure.py).
fig, ax = plt.subplots(3, 1, figsize=(8, 8), sharex=True)
cases = [("cg1_displaced", "cg1", "original (CG 1)"), ("cg2_displaced", "cg2", "CG 2"),
         ("cg3_displaced", "cg3", "CG 3"), ("cg4_displaced", "cg4", "CG 4"),
         ("cg2_kernel02", "cg2_kernel02", "CG 2, the original's 0.2 mm kernel")]
lateral = np.genfromtxt(os.path.join(HERE, "lateral_structure.csv"), delimiter=",", names=True,
                        dtype=None, encoding="utf-8")
for k, (series_name, case, label) in enumerate(cases):
    t, h, dp = series(series_name)
    keep = t >= 0.15
    colour = f"C{k}"
    ax[0].plot(t[keep], h[keep], color=colour, lw=1, label=label)
    ax[1].plot(t[keep], dp[keep], color=colour, lw=0.8, label=label)
    rows = lateral[lateral["case"] == case]
    if len(rows) and np.isfinite(rows["block_row_sd"]).any():
        ax[2].semilogy(rows["time_s"], rows["block_row_sd"], "o-", color=colour, ms=3, lw=1,
                       label=label)
ax[0].set_ylabel("bed height [mm]")
ax[1].set_ylabel("pressure drop [Pa]")
ax[1].axhline(WEIGHT, color="k", ls=":", lw=0.8, label="weight / area + gas head")
ax[2].set_ylabel("gas fraction sd within a row\n(0.8 mm cubes)")
ax[2].set_xlabel("time [s]")
ax[0].legend(fontsize=8)
ax[2].legend(fontsize=8)
fig.tight_layout()
out = os.path.join(HERE, "original_and_cg.png")
fig.savefig(out, dpi=110)
print("wrote", out)
