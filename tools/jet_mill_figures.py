#!/usr/bin/env python3
"""The jet mill study's figures (Scott, Borissova, Di Renzo & Ghadiri, Figs. 2-6) across cases.

usage: /usr/bin/python3 tools/jet_mill_figures.py STUDY_DIR --from T0 --to T1 --offset T_SPIN
       [--radius R] [--no-maps CASE]... CASE...

Reads, for each CASE, STUDY_DIR/CASE/timeseries.csv and the CSVs of lbdem-jet-mill-maps
(STUDY_DIR/CASE/mill_*.csv). Writes into STUDY_DIR: positions.png (particles seen from above at
the window's end, Fig. 2), speed_map.png (mean particle speed on x-y bins over the window, colour
0-30 m/s, Fig. 3), gas_midplane.png (gas speed on the mid-plane at the window's end, capped at
120 m/s, Fig. 4), gas_profiles.png (gas tangential and radial velocity against radius; the
radial one as cell means and as the link-counted flux per cylinder area, mill_gas_radial_flow.csv),
kinetic_energy.png (total particle kinetic energy against study time, Fig. 5), wall_profile.png
(mean particle speed against distance from the outer wall over the window, Fig. 6). Study time is
run time less T_SPIN (the gas spin-up). A case named by --no-maps CASE (repeatable) has maps of
another window (a folder of kept outputs whose snapshots are gone): its panels of Figs. 2-4 stay
empty and say so, it is left out of the gas profiles and Fig. 6 (their titles name it), and only
its kinetic energy is drawn. Exit 0 on success, 2 on missing input.
"""
import argparse
import csv
import gzip
import os
import sys

import matplotlib

matplotlib.use("Agg")  # headless machines and study drivers
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def fail(msg):
    print(f"jet_mill_figures: {msg}", file=sys.stderr)
    sys.exit(2)


def columns(path):
    """The CSV's columns as arrays; {} with a warning if the file is missing (that case's panel
    stays empty: one case without output must not cost the others their figures)."""
    if not os.path.isfile(path) and os.path.isfile(path + ".gz"):
        path += ".gz"  # results/ keeps the large maps gzipped
    if not os.path.isfile(path):
        print(f"jet_mill_figures: warning: no {path} (run lbdem-jet-mill-maps, or ./lbdem study "
              "jet_mill)", file=sys.stderr)
        return {}
    opener = gzip.open if path.endswith(".gz") else open
    with opener(path, "rt", newline="", encoding="utf-8") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        return {}
    return {k: np.array([float(r[k]) if r[k] not in ("", None) else np.nan for r in rows])
            for k in rows[0].keys()}


def save(fig, path):
    tmp = path + ".tmp"
    fig.savefig(tmp, dpi=110, format="png", bbox_inches="tight")
    plt.close(fig)
    os.replace(tmp, path)  # a viewer never sees a half-written PNG


def grid(x, y, v):
    """Scattered bin centres on a regular grid -> (extent, 2-D array with NaN where empty)."""
    xs, ys = np.unique(x), np.unique(y)
    h = np.min(np.diff(xs)) if len(xs) > 1 else 1e-3
    x0, y0 = xs.min(), ys.min()
    nx, ny = int(round((xs.max() - x0) / h)) + 1, int(round((ys.max() - y0) / h)) + 1
    a = np.full((ny, nx), np.nan)
    a[np.rint((y - y0) / h).astype(int), np.rint((x - x0) / h).astype(int)] = v
    return [1e3 * (x0 - h / 2), 1e3 * (x0 + (nx - 0.5) * h), 1e3 * (y0 - h / 2),
            1e3 * (y0 + (ny - 0.5) * h)], a


def panels(n):
    cols = min(n, 5)
    rows = (n + cols - 1) // cols
    fig, axes = plt.subplots(rows, cols, figsize=(3.2 * cols + 1.2, 3.2 * rows), squeeze=False)
    for ax in axes.ravel()[n:]:
        ax.set_visible(False)
    return fig, axes.ravel()


def chamber(ax, radius):
    t = np.linspace(0, 2 * np.pi, 200)
    ax.plot(1e3 * radius * np.cos(t), 1e3 * radius * np.sin(t), color="0.3", lw=0.8)
    ax.set_aspect("equal")
    ax.set_xlabel("x [mm]")
    if ax.get_subplotspec().is_first_col():
        ax.set_ylabel("y [mm]")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("root")
    ap.add_argument("cases", nargs="+")
    ap.add_argument("--from", dest="t0", type=float, required=True)
    ap.add_argument("--to", dest="t1", type=float, required=True)
    ap.add_argument("--offset", type=float, default=0.0)
    ap.add_argument("--radius", type=float, default=0.025, help="chamber radius [m]")
    ap.add_argument("--no-maps", action="append", default=[], metavar="CASE",
                    help="a case whose mill_*.csv maps are not of this window: not drawn")
    a = ap.parse_args()
    root, cases = a.root, a.cases
    if not os.path.isdir(root):
        fail(f"no folder {root}")
    for c in a.no_maps:
        if c not in cases:
            fail(f"--no-maps {c}: not one of the cases ({', '.join(cases)})")
    stale = set(a.no_maps)

    def maps(c, name):
        # Another window's maps would pass for this one's beside the other cases: left out.
        return {} if c in stale else columns(os.path.join(root, c, name))

    def title(c, text=None):
        return f"{c}: maps of another window, not drawn" if c in stale else (text or c)
    win = f"study time {a.t0 - a.offset:.3g}-{a.t1 - a.offset:.3g} s"

    fig, axes = panels(len(cases))
    dots = None
    for ax, c in zip(axes, cases):
        p = maps(c, "mill_positions.csv")
        if p:
            dots = ax.scatter(1e3 * p["x_m"], 1e3 * p["y_m"], s=0.2, c=p["speed_m_per_s"],
                              cmap="viridis", vmin=0, vmax=30, rasterized=True)
        chamber(ax, a.radius)
        ax.set_title(title(c, f"{c}: {len(p.get('x_m', []))} parcels"), fontsize=9)
    if dots is not None:
        fig.colorbar(dots, ax=list(axes[:len(cases)]), label="particle speed [m/s]", shrink=0.8)
    fig.suptitle(f"Particles seen from above at study time {a.t1 - a.offset:.3g} s")
    save(fig, os.path.join(root, "positions.png"))

    fig, axes = panels(len(cases))
    im = None
    for ax, c in zip(axes, cases):
        m = maps(c, "mill_speed_map.csv")
        if m:
            ext, arr = grid(m["x_m"], m["y_m"], m["mean_speed_m_per_s"])
            im = ax.imshow(arr, origin="lower", extent=ext, vmin=0, vmax=30, cmap="jet")
        chamber(ax, a.radius)
        ax.set_title(title(c), fontsize=9)
    if im is not None:
        fig.colorbar(im, ax=list(axes[:len(cases)]), label="mean particle speed [m/s]", shrink=0.8)
    fig.suptitle(f"Mean particle speed, {win}")
    save(fig, os.path.join(root, "speed_map.png"))

    fig, axes = panels(len(cases))
    im = None
    for ax, c in zip(axes, cases):
        path = os.path.join(root, c, "mill_gas_midplane.csv")
        if c not in stale and (os.path.isfile(path) or os.path.isfile(path + ".gz")):
            g = columns(path)
            ext, arr = grid(g["x_m"], g["y_m"], np.minimum(g["speed_m_per_s"], 120))
            im = ax.imshow(arr, origin="lower", extent=ext, vmin=0, vmax=120, cmap="jet")
        chamber(ax, a.radius)
        ax.set_title(title(c), fontsize=9)
    if im is not None:
        fig.colorbar(im, ax=list(axes[:len(cases)]), label="gas speed [m/s] (capped at 120)",
                     shrink=0.8)
    fig.suptitle(f"Gas speed on the mid-plane at study time {a.t1 - a.offset:.3g} s")
    save(fig, os.path.join(root, "gas_midplane.png"))

    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10, 4))
    for i, c in enumerate(cases):
        if c in stale:
            continue
        path = os.path.join(root, c, "mill_gas_profile.csv")
        if os.path.isfile(path) or os.path.isfile(path + ".gz"):
            g = columns(path)
            ax1.plot(1e3 * g["radius_m"], g["u_theta_m_per_s"], color=f"C{i}", label=c)
            ax2.plot(1e3 * g["radius_m"], g["u_r_m_per_s"], color=f"C{i}", ls=":",
                     label=f"{c}, cell mean")
        path = os.path.join(root, c, "mill_gas_radial_flow.csv")
        if os.path.isfile(path):
            q = columns(path)
            ax2.plot(1e3 * q["radius_m"], q["u_r_m_per_s"], color=f"C{i}",
                     label=f"{c}, link flux / (2 pi r H rho)")
    if stale:
        ax1.set_title(f"maps of another window, not drawn: {', '.join(sorted(stale))}", fontsize=8)
    ax1.set_ylabel("gas tangential velocity [m/s]")
    ax2.set_ylabel("gas radial velocity [m/s] (outwards +)")
    for ax in (ax1, ax2):
        ax.set_xlabel("radius [mm]")
        ax.set_xlim(0, 1e3 * a.radius)  # the grid's corners lie outside the chamber
        ax.axhline(0, color="0.6", lw=0.5)
        ax.legend(fontsize=8)
    fig.suptitle(f"Gas velocity against radius (chamber height average) at study time {a.t1 - a.offset:.3g} s")
    fig.tight_layout()
    save(fig, os.path.join(root, "gas_profiles.png"))

    fig, ax = plt.subplots(figsize=(7, 4.5))
    for i, c in enumerate(cases):
        t = columns(os.path.join(root, c, "timeseries.csv"))
        if not t:
            continue
        ax.plot(t["time_s"] - a.offset, 1e3 * t["kinetic_energy_J"], color=f"C{i}", label=c)
    ax.axvspan(a.t0 - a.offset, a.t1 - a.offset, color="0.9", zorder=0, label="window")
    ax.set_xlabel("study time [s] (run time less the gas spin-up)")
    ax.set_ylabel("total particle kinetic energy [mJ]")
    ax.set_xlim(left=0)
    ax.legend(fontsize=8)
    fig.tight_layout()
    save(fig, os.path.join(root, "kinetic_energy.png"))

    fig, ax = plt.subplots(figsize=(7, 4.5))
    for i, c in enumerate(cases):
        w = maps(c, "mill_wall_profile.csv")
        if w:
            ax.plot(1e3 * w["wall_distance_m"], w["mean_speed_m_per_s"], "o-", ms=3,
                    color=f"C{i}", label=c)
    ax.set_xlabel("distance from the outer wall [mm]")
    ax.set_ylabel("mean particle speed [m/s]")
    note = f"\n(maps of another window, not drawn: {', '.join(sorted(stale))})" if stale else ""
    ax.set_title(f"Mean particle speed against distance from the wall, {win}{note}")
    ax.legend(fontsize=8)
    fig.tight_layout()
    save(fig, os.path.join(root, "wall_profile.png"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
