#!/usr/bin/env python3
"""Plot of lbdem-collision-stats' output for several runs side by side (a coarse-graining series).

usage: /usr/bin/python3 tools/collision_stats.py OUT.csv [--png FILE]

Reads OUT.csv and OUT_impact_speed.csv (written by lbdem-collision-stats --csv OUT.csv) and, for
the maps, each run's collisions.h5 /grid (the run_dir column). Writes OUT.png with, per run:
collision frequencies per parcel and per represented original particle (particle-particle and
particle-wall), dissipated energy per kg of powder by mechanism over the window (in J for all
runs when any run's powder mass is unknown: no particles.h5 and a run that did not start
empty, so that its inflow ledger does not give the mass either), the normal
impact-speed distributions (from the per-contact rows where they cover the window, else from the
whole-run histograms: the legend says which), and a map of where the energy was dissipated over
the whole run, summed over the collision grid's axis with the fewest cells (a side view of a tall
box, a top view of the flat jet mill). Runs that share a label are named by their folders. Exit 0 on success, 2 on missing or unreadable input.
"""
import argparse
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")  # headless machines and study drivers
import h5py  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.colors import LogNorm  # noqa: E402
from matplotlib.ticker import MaxNLocator  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from collision_summary import grid_xyz, project  # noqa: E402  (the run plot's map, same view)
from run_labels import split_runs, unique_labels  # noqa: E402

MECHANISMS = [("normal_damping", "normal damping"), ("tangential_damping", "tangential damping"),
              ("sliding", "sliding"), ("rolling", "rolling")]
FREQS = [("freq_pp_per_parcel_per_s", "p-p per parcel"), ("freq_pw_per_parcel_per_s", "p-w per parcel"),
         ("freq_pp_per_original_per_s", "p-p per original"),
         ("freq_pw_per_original_per_s", "p-w per original")]


def fail(msg):
    print(f"collision_stats: {msg}", file=sys.stderr)
    sys.exit(2)


def read_rows(path):
    if not os.path.isfile(path):
        fail(f"no {path} (run lbdem-collision-stats --csv OUT.csv first)")
    with open(path, newline="", encoding="utf-8") as f:
        return list(csv.DictReader(f))


def num(row, key):
    try:
        return float(row[key])
    except (KeyError, ValueError):
        return float("nan")


def frequency_bars(ax, runs):
    width = 0.8 / len(runs)
    x = np.arange(len(FREQS))
    for i, r in enumerate(runs):
        vals = [num(r, k) for k, _ in FREQS]
        bars = ax.bar(x + (i - (len(runs) - 1) / 2) * width, vals, width, label=r["label"],
                      color=f"C{i}")
        ax.bar_label(bars, fmt="%.3g", fontsize=6, rotation=90, padding=2)
    ax.set_xticks(x, [lab for _, lab in FREQS], rotation=20, fontsize=8)
    ax.set_yscale("log")  # per-original values are l^3 below per-parcel ones
    ax.margins(y=0.25)
    ax.set_ylabel("collisions per particle per second [1/s]")
    ax.set_title("collision frequency", fontsize=10)
    ax.grid(alpha=0.3, axis="y", which="both")
    ax.legend(fontsize=8)


def energy_bars(ax, runs):
    x = np.arange(len(runs))
    bottom = np.zeros(len(runs))
    mass = np.array([num(r, "powder_mass_kg") for r in runs])
    # The powder mass comes from particles.h5, else from the inflow ledger of a run that started
    # empty; where neither gives it, every run is shown in joules (a per-kg bar beside a missing
    # one would not compare).
    per_kg = bool(np.all(np.isfinite(mass)))
    scale = mass if per_kg else np.ones(len(runs))
    for j, (k, lab) in enumerate(MECHANISMS):
        v = np.array([num(r, f"dissipated_{k}_J") for r in runs]) / scale
        ax.bar(x, v, 0.6, bottom=bottom, label=lab, color=f"C{j + 4}")
        bottom += np.nan_to_num(v)
    # Upright inside a tall bar (white), above a short one, so that five runs' labels do not run
    # into each other or the legend.
    top = np.nanmax(bottom) if np.any(bottom > 0) else 1.0
    for i, r in enumerate(runs):
        rate = (f"{num(r, 'dissipation_rate_per_kg_W_per_kg'):.3g} W/kg" if per_kg
                else f"{num(r, 'dissipation_rate_W'):.3g} W")
        inside = bottom[i] > 0.6 * top
        ax.text(i, 0.03 * top if inside else bottom[i],
                f" {rate}, {num(r, 'dissipated_per_collision_J'):.2g} J/coll.", ha="center",
                va="bottom", rotation=90, fontsize=7, color="white" if inside else "black")
    ax.set_xticks(x, [r["label"] for r in runs], rotation=20, ha="right", fontsize=8)
    ax.margins(y=0.1)
    ax.set_ylabel("dissipated in the window per kg of powder [J/kg]" if per_kg
                  else "dissipated in the window [J] (a powder mass is unknown)")
    ax.set_title("dissipated energy by mechanism", fontsize=10)
    ax.grid(alpha=0.3, axis="y")
    ax.legend(fontsize=7)


def speed_distributions(ax, runs, hist):
    vmin, vmax = np.inf, 0.0  # range of occupied bins: the solver's bins span 1e-5..1e3 m/s
    # Each run's rows by their place in the table: two runs can share a label.
    per_run = split_runs(hist, [r["tool_label"] for r in runs],
                         key=lambda h: (h["pair"], h["kind"], h["bin_lo_m_per_s"]))
    for i, r in enumerate(runs):
        for pair, ls in [("pp", "-"), ("pw", "--")]:
            rows = [h for h in per_run[i] if h["pair"] == pair and h["kind"] == "normal"]
            if not rows:
                continue
            lo = np.array([float(h["bin_lo_m_per_s"]) for h in rows])
            hi = np.array([float(h["bin_hi_m_per_s"]) for h in rows])
            c = np.array([float(h["count"]) for h in rows])
            if c.sum() <= 0:
                continue
            # Density per unit log10(v): the bins are log-spaced, so this does not depend on them.
            dens = c / c.sum() / np.log10(hi / lo)
            vmin, vmax = min(vmin, lo[c > 0].min()), max(vmax, hi[c > 0].max())
            src = "rows" if rows[0]["source"] == "rows" else "whole run"
            ax.stairs(dens, np.append(lo, hi[-1]), color=f"C{i}", ls=ls, lw=1.4,
                      label=f"{r['label']} {'p-p' if pair == 'pp' else 'p-w'} ({src})")
    ax.set_xscale("log")
    if vmax > 0:
        ax.set_xlim(max(vmin, 1e-6 * vmax), vmax)
    ax.set_xlabel("impact normal speed [m/s]")
    ax.set_ylabel("impacts per decade / all impacts [-]")
    ax.set_title("impact-speed distribution", fontsize=10)
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=7, loc="upper left")  # the distributions peak right of the middle


def energy_map(run_dir):
    """(map of dissipated energy summed over the grid's axis with the fewest cells, the kept axes'
    names, the summed axis' name, extent in m, time) or None. The solver's grid has
    output.collisions.grid_cells cells along the box's longest edge and cells of about that size
    along the others, so a tall box is seen from the side and a flat one (the jet mill) from
    above."""
    path = os.path.join(run_dir, "collisions.h5")
    if not os.path.isfile(path):
        return None
    with h5py.File(path, "r") as f:
        g = f.get("/grid")
        if g is None or "dissipated_J" not in g or g["dissipated_J"].ndim != 3:
            return None
        d = grid_xyz(g)
        lo, hi = np.asarray(g["lo_m"][()]), np.asarray(g["hi_m"][()])
        t = float(f["/totals"].attrs.get("time_s", float("nan"))) if "/totals" in f else math.nan
    m, axes, summed, extent = project(d, lo, hi)
    return m, axes, summed, extent, t


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter,
                                 epilog="\n\n".join(__doc__.split("\n\n")[1:]))
    ap.add_argument("csv", metavar="OUT.csv", help="table written by lbdem-collision-stats --csv")
    ap.add_argument("--png", help="output picture (default: OUT.png)")
    args = ap.parse_args(argv[1:])
    stem = args.csv[:-4] if args.csv.endswith(".csv") else args.csv
    runs = read_rows(args.csv)
    hist = read_rows(stem + "_impact_speed.csv")
    if not runs:
        fail(f"{args.csv} has no runs")
    # Two runs with the same size factor share "l = <size_factor>": they are named by their
    # folders. tool_label keeps the label of the tables' rows.
    for r, lab in zip(runs, unique_labels([r["label"] for r in runs], [r["run_dir"] for r in runs])):
        r["tool_label"], r["label"] = r["label"], lab
    maps = [energy_map(r["run_dir"]) for r in runs]
    n_maps = sum(m is not None for m in maps)
    ncol = max(3, n_maps)
    fig = plt.figure(figsize=(4.6 * ncol, 9.5 if n_maps else 4.8))
    gs = fig.add_gridspec(2 if n_maps else 1, ncol)
    frequency_bars(fig.add_subplot(gs[0, 0]), runs)
    energy_bars(fig.add_subplot(gs[0, 1]), runs)
    speed_distributions(fig.add_subplot(gs[0, 2:]), runs, hist)
    pos = [m[0][m[0] > 0] for m in maps if m is not None]
    pos = np.concatenate(pos) if pos else np.array([])
    # One colour scale for every map, so that runs compare; floored at 1e-4 of the peak.
    norm = LogNorm(max(pos.min(), 1e-4 * pos.max()), pos.max()) if pos.size else None
    k = 0
    for r, m in zip(runs, maps):
        if m is None:
            continue
        ax = fig.add_subplot(gs[1, k])
        k += 1
        xz, (na, nb), summed, extent, t = m
        im = ax.imshow(np.where(xz > 0, xz, np.nan).T, origin="lower",
                       extent=[1e3 * e for e in extent], norm=norm, cmap="viridis",
                       aspect="equal", interpolation="nearest")
        ax.xaxis.set_major_locator(MaxNLocator(nbins=4))
        ax.set_xlabel(f"{na} [mm]")
        ax.set_ylabel(f"{nb} [mm]")
        ax.set_title(f"{r['label']}: dissipation 0..{t:.3g} s,\nsummed over {summed}"
                     f" ({' x '.join(map(str, xz.shape))} cells)", fontsize=9)
        fig.colorbar(im, ax=ax, label="dissipated per cell column [J]", shrink=0.9)
    window = f"{num(runs[0], 't_from_s'):.4g}..{num(runs[0], 't_to_s'):.4g} s"
    fig.suptitle(f"collision statistics, window {window}")
    fig.tight_layout()
    out = args.png or stem + ".png"
    tmp = out + ".tmp.png"
    fig.savefig(tmp, dpi=110, format="png")
    plt.close(fig)
    os.replace(tmp, out)  # a viewer never sees a half-written PNG
    print(out)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
