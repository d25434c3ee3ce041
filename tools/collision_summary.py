#!/usr/bin/env python3
"""Text summary and collisions.png from a run folder's collisions.h5.

usage: /usr/bin/python3 tools/collision_summary.py RUN_DIR

Reads the groups /histograms, /totals, /rows and /grid, each optional. /grid arrays are taken as
indexed (x, y, z) unless the group has an attribute axis_order = "zyx". The map of where energy was
dissipated sums the grid over its axis with the fewest cells (the solver puts
output.collisions.grid_cells cells along the box's longest edge and cells of about that size along
the others, so a tall box is seen from the side). Exit 0 on success or when
there is no collisions.h5, 1 when the file cannot be read, 2 when RUN_DIR is missing.
"""
import os
import sys

import matplotlib

matplotlib.use("Agg")  # runs on headless machines
import h5py  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.colors import LogNorm  # noqa: E402
from matplotlib.ticker import MaxNLocator  # noqa: E402

MECHANISMS = [("dissipated_normal_damping_J", "normal damping"),
              ("dissipated_tangential_damping_J", "tangential damping"),
              ("dissipated_sliding_J", "sliding"), ("dissipated_rolling_J", "rolling")]
KINDS = [("normal", "impact_normal_speed"), ("tangential", "impact_tangential_speed")]


def array(group, name):
    if group is None or name not in group or not isinstance(group[name], h5py.Dataset):
        return None
    return np.asarray(group[name][()], dtype=float)


def scalar(group, name):
    """A total from the group's attributes, or from a scalar dataset if the writer used one."""
    if group is None:
        return None
    v = group.attrs.get(name)
    if v is None:
        v = array(group, name)
    if v is None or np.size(v) != 1:
        return None
    return float(np.ravel(v)[0])


def vector3(group, name):
    v = group.attrs.get(name) if name in group.attrs else array(group, name)
    return None if v is None or np.size(v) != 3 else np.ravel(np.asarray(v, dtype=float))


def quantile(edges, counts, q):
    """Quantile of a binned distribution, linear within the bin."""
    c = np.cumsum(counts)
    if c.size == 0 or c[-1] <= 0:
        return float("nan")
    target = q * c[-1]
    i = int(np.searchsorted(c, target))
    below = c[i - 1] if i > 0 else 0.0
    frac = (target - below) / counts[i] if counts[i] > 0 else 0.0
    return float(edges[i] + frac * (edges[i + 1] - edges[i]))


def histograms(f):
    """{kind: (edges, {"pp": counts, "pw": counts})}, from /histograms or else binned from /rows."""
    out = {}
    h, rows = f.get("/histograms"), f.get("/rows")
    for kind, stem in KINDS:
        edges = array(h, f"{stem}_edges_m_per_s")
        counts = {p: array(h, f"{stem}_counts_{p}") for p in ("pp", "pw")}
        counts = {p: c for p, c in counts.items()
                  if c is not None and edges is not None and c.size == edges.size - 1}
        if counts:
            out[kind] = (edges, counts)
            continue
        speed, idj = array(rows, f"{stem}_m_per_s"), array(rows, "id_j")
        if speed is None or idj is None or speed.size != idj.size:
            continue
        pos = speed[speed > 0]
        if pos.size == 0:
            continue
        edges = np.geomspace(pos.min(), pos.max() * 1.0001, 41)
        out[kind] = (edges, {"pp": np.histogram(speed[idj >= 0], edges)[0].astype(float),
                             "pw": np.histogram(speed[idj < 0], edges)[0].astype(float)})
    return out


def summarise(f, hists, name):
    lines = [f"collisions.h5 of {name}"]
    tot = f.get("/totals")
    if tot is not None:
        t = scalar(tot, "time_s")
        npp, npw = scalar(tot, "collisions_pp"), scalar(tot, "collisions_pw")
        if t is not None:
            lines.append(f"  at t = {t:.6g} s")
        n = [f"{v:.0f} {lab}" for v, lab in [(npp, "particle-particle"), (npw, "particle-wall")]
             if v is not None]
        if n:
            lines.append("  collisions: " + ", ".join(n))
        d = [(lab, scalar(tot, k)) for k, lab in MECHANISMS]
        d = [(lab, v) for lab, v in d if v is not None]
        if d:
            lines.append("  dissipated [J]: " + ", ".join(f"{lab} {v:.4g}" for lab, v in d)
                         + f"; total {sum(v for _, v in d):.4g}")
    for kind, (edges, counts) in hists.items():
        for p, c in counts.items():
            lines.append(f"  {kind} impact speed {p} [m/s]: {c.sum():.0f} impacts, median "
                         f"{quantile(edges, c, 0.5):.3g}, 95th pct {quantile(edges, c, 0.95):.3g}")
    rows = f.get("/rows")
    idj = array(rows, "id_j")
    if idj is not None and idj.size:
        n = idj.size
        lines.append(f"  rows: {n} contacts ({int((idj >= 0).sum())} pp, {int((idj < 0).sum())} pw)")
        t0, t1 = array(rows, "t_start_s"), array(rows, "t_end_s")
        if t0 is not None and t1 is not None and t0.size == n == t1.size:
            lines.append(f"    contact duration [s]: median {np.median(t1 - t0):.3g}, "
                         f"max {np.max(t1 - t0):.3g}")
        for k, lab in [("max_overlap_m", "max overlap [m]"),
                       ("max_normal_force_N", "max normal force [N]")]:
            v = array(rows, k)
            if v is not None and v.size == n:
                lines.append(f"    {lab}: median {np.median(v):.3g}, max {np.max(v):.3g}")
        v = array(rows, "dissipated_J")
        if v is not None and v.size == n:
            lines.append(f"    dissipated [J]: sum {v.sum():.4g}")
        walls, nw = np.unique((-1 - idj[idj < 0]).astype(int), return_counts=True)
        if walls.size:
            lines.append("    impacts per wall: " + ", ".join(
                f"wall {w}: {c}" for w, c in zip(walls, nw)))
    g = f.get("/grid")
    dg = array(g, "dissipated_J")
    if dg is not None:
        cg = array(g, "counts")
        lines.append(f"  grid: {'x'.join(map(str, grid_xyz(g).shape))} cells (x, y, z), dissipated "
                     f"{dg.sum():.4g} J"
                     + (f", {cg.sum():.0f} contacts" if cg is not None else ""))
    print("\n".join(lines))


def draw_hist(ax, edges, counts, kind):
    edges = edges.copy()
    # A log axis cannot show a 0 m/s edge; drawing that bin from a decade below the next edge
    # keeps its counts visible.
    if edges[0] <= 0 < edges[1]:
        edges[0] = edges[1] / 10
    for p, label in [("pp", "particle-particle"), ("pw", "particle-wall")]:
        if p in counts:
            ax.stairs(counts[p], edges, label=f"{label} ({counts[p].sum():.0f})", lw=1.5)
    if (edges > 0).all():
        ax.set_xscale("log")
    peak = max(c.max() for c in counts.values()) if counts else 0
    lo = min((c[c > 0].min() for c in counts.values() if (c > 0).any()), default=0)
    if lo > 0 and peak / lo > 1e3:  # heavy tails vanish on a linear count axis
        ax.set_yscale("log")
    ax.set_xlabel(f"impact {kind} speed [m/s]")
    ax.set_ylabel("impacts per bin [-]")
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=8, loc="best")


def grid_xyz(g):
    """The /grid's dissipated_J indexed (x, y, z), whatever order it was written in."""
    d = array(g, "dissipated_J")
    order = g.attrs.get("axis_order", "xyz")
    order = order.decode() if isinstance(order, bytes) else str(order)
    return d.transpose(2, 1, 0) if order == "zyx" and d.ndim == 3 else d


def projection_axis(shape):
    """The axis the map sums over: the one with the fewest cells, z first among equals (a top view).
    The solver sizes the cells as (longest box edge) / output.collisions.grid_cells on every axis,
    so the longest edge holds grid_cells of them and a tall box only a few across: a map summed over
    the long axis would show those few."""
    return min((2, 1, 0), key=lambda a: shape[a])


def project(d, lo=None, hi=None):
    """(2-D map indexed (first kept axis, second kept axis), the kept axes' names, the summed
    axis' name, extent [a_lo, a_hi, b_lo, b_hi] in m or None)."""
    a = projection_axis(d.shape)
    keep = [k for k in range(3) if k != a]
    extent = ([lo[keep[0]], hi[keep[0]], lo[keep[1]], hi[keep[1]]]
              if lo is not None and hi is not None else None)
    return d.sum(axis=a), ["xyz"[k] for k in keep], "xyz"[a], extent


def configured_grid_cells(run):
    """output.collisions.grid_cells from the run's config.toml, or None."""
    try:
        import tomllib
        with open(os.path.join(run, "config.toml"), "rb") as f:
            v = tomllib.load(f).get("output", {}).get("collisions", {}).get("grid_cells")
        return int(v) if isinstance(v, int) else None
    except (ImportError, OSError, ValueError):
        return None


def draw_grid(fig, ax, g, grid_cells=None):
    d = grid_xyz(g)
    m, (na, nb), summed, extent = project(d, vector3(g, "lo_m"), vector3(g, "hi_m"))
    pos = m[m > 0]
    # Log colours for a wide range, floored at 1e-6 of the peak so that near-empty cells do not
    # squeeze the hot spots into one colour.
    norm = (LogNorm(max(pos.min(), 1e-6 * pos.max()), pos.max())
            if pos.size and pos.max() > 100 * pos.min() else None)
    im = ax.imshow(np.where(m > 0, m, np.nan).T if norm else m.T, origin="lower",
                   extent=None if extent is None else [1e3 * e for e in extent], norm=norm,
                   aspect="equal", cmap="viridis", interpolation="nearest")
    fig.colorbar(im, ax=ax, label=f"dissipated energy, summed over {summed} [J]")
    unit = "[mm]" if extent else "[cell]"
    ax.xaxis.set_major_locator(MaxNLocator(nbins=4))
    cells = " x ".join(str(n) for n in d.shape)
    cfg = f"\n(output.collisions.grid_cells = {grid_cells})" if grid_cells else ""
    ax.set_xlabel(f"{na} {unit}\ngrid of {cells} cells (x, y, z){cfg}", fontsize=9)
    ax.set_ylabel(f"{nb} {unit}")
    ax.set_title(f"dissipated energy,\nsummed over {summed}", fontsize=10)


def main(argv):
    if len(argv) != 2:
        print("usage: collision_summary.py RUN_DIR", file=sys.stderr)
        return 2
    run = argv[1]
    if not os.path.isdir(run):
        print(f"collision_summary: no run folder {run}", file=sys.stderr)
        return 2
    path = os.path.join(run, "collisions.h5")
    if not os.path.isfile(path):
        print(f"collision_summary: no collisions.h5 in {run}, nothing to do")
        return 0
    name = os.path.basename(os.path.normpath(os.path.abspath(run)))
    try:
        f = h5py.File(path, "r")
    except OSError as e:
        print(f"collision_summary: cannot read {path}: {e}", file=sys.stderr)
        return 1
    with f:
        hists = histograms(f)
        summarise(f, hists, name)
        g = f.get("/grid")
        has_grid = (isinstance(g, h5py.Group) and array(g, "dissipated_J") is not None
                    and array(g, "dissipated_J").ndim == 3)
        if g is not None and not has_grid:
            print("  grid: no 3-D dissipated_J dataset, map skipped")
        panels = [k for k, _ in KINDS if k in hists] + (["grid"] if has_grid else [])
        if not panels:
            print("collision_summary: nothing to plot, collisions.png not written")
            return 0
        # The map's panel is as wide as its picture (a tall box's side view is narrow) and its
        # colour bar need.
        widths = [1.0] * len(panels)
        if has_grid:
            shape = project(grid_xyz(g))[0].shape
            widths[-1] = 0.55 + 0.45 * min(1.0, shape[0] / max(shape[1], 1))
        fig, axes = plt.subplots(1, len(panels), figsize=(5.2 * sum(widths), 4.5), squeeze=False,
                                 gridspec_kw={"width_ratios": widths})
        for ax, p in zip(axes[0], panels):
            if p == "grid":
                draw_grid(fig, ax, g, configured_grid_cells(run))
            else:
                draw_hist(ax, hists[p][0], hists[p][1], p)
        fig.suptitle(f"{name}: collisions")
        fig.tight_layout()
    out = os.path.join(run, "collisions.png")
    tmp = os.path.join(run, "collisions.tmp.png")
    fig.savefig(tmp, dpi=120, bbox_inches="tight")  # then rename: no half-written PNG is seen
    plt.close(fig)
    os.replace(tmp, out)
    print(out)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
