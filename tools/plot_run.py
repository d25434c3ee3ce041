#!/usr/bin/env python3
"""Plots of a run folder's timeseries.csv.

usage: /usr/bin/python3 tools/plot_run.py RUN_DIR

Writes into RUN_DIR: energy_budget.png, kinetic_energy.png, and wall_loads.png when the series
has wall force (*_N) or torque (*_Nm) columns. Exit 0 on success or when there are fewer than
two rows to plot, 2 when RUN_DIR or its timeseries.csv is missing.
"""
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")  # runs on headless machines and from cron-like drivers
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.ticker import FixedLocator  # noqa: E402

STORED = [("kinetic_energy_J", "kinetic"), ("elastic_energy_J", "elastic (springs + cohesion)")]
DISSIPATED = [
    ("dissipated_normal_damping_J", "dissipated: normal damping"),
    ("dissipated_tangential_damping_J", "dissipated: tangential damping"),
    ("dissipated_sliding_J", "dissipated: sliding friction"),
    ("dissipated_rolling_J", "dissipated: rolling friction"),
]
OTHER = [("stiffness_change_J", "stiffness change"), ("wall_work_J", "wall work")]


def read_csv(path):
    """Returns (names, 2-D float array). Rows of the wrong width are dropped: the solver appends
    and flushes row by row, so a file read during a run can end in a partial line."""
    with open(path, "r", encoding="utf-8", errors="replace") as f:
        header = f.readline().strip()
        names = [c.strip() for c in header.split(",")] if header else []
        rows = []
        for line in f:
            parts = line.strip().split(",")
            if len(parts) != len(names) or not line.endswith("\n"):
                continue
            row = []
            for p in parts:
                try:
                    row.append(float(p))
                except ValueError:
                    row.append(math.nan)
            rows.append(row)
    data = np.array(rows, dtype=float).reshape(len(rows), len(names))
    return names, data


def save(fig, path):
    # Atomic replace so a viewer or a concurrent plotting pass never reads a half-written PNG.
    tmp = path[: -len(".png")] + ".tmp.png"
    fig.savefig(tmp, dpi=120)
    plt.close(fig)
    os.replace(tmp, path)
    print(path)


def energy_budget(cols, t, tlabel, run_name, out):
    fig, (top, bot) = plt.subplots(2, 1, figsize=(12, 8), sharex=True,
                                   gridspec_kw={"height_ratios": [3, 2]})
    scale_terms = []

    def curve(y, label, **kw):
        top.plot(t, y, label=label, **kw)
        scale_terms.append(np.nanmax(np.abs(y)) if np.isfinite(y).any() else 0.0)

    kin, klabel = cols.get("kinetic_energy_J"), "kinetic"
    if kin is None and "kinetic_translational_J" in cols:
        kin = cols["kinetic_translational_J"] + cols.get("kinetic_rotational_J", 0.0)
        klabel = "kinetic (translational + rotational)"
    if kin is not None:
        curve(kin, klabel, lw=2, color="C0")
    if "potential_energy_J" in cols:
        pe = cols["potential_energy_J"]
        curve(pe - pe[0], "gravitational potential change since t0", lw=2, color="C1")
    if "elastic_energy_J" in cols:
        curve(cols["elastic_energy_J"], "elastic (springs + cohesion)", lw=2, color="C2")
    diss = [k for k, _ in DISSIPATED if k in cols]
    for (k, label), ls in zip(DISSIPATED, ["--", "-.", ":", (0, (5, 1, 1, 1))]):
        if k in cols:
            curve(cols[k], label, ls=ls)
    if len(diss) > 1:
        curve(sum(cols[k] for k in diss), "dissipated: total", color="k", lw=1.2, ls="--")
    for k, label in OTHER:
        if k in cols:
            curve(cols[k], label, lw=1, alpha=0.8)
    inj = cols.get("energy_injected_J")
    if inj is not None:
        curve(inj, "energy injected", color="k", lw=2.5, alpha=0.5)
    top.set_ylabel("energy [J]")
    top.axhline(0.0, color="0.6", lw=0.6)
    top.grid(alpha=0.3)
    if top.lines:
        # Outside the axes: inside, the legend hides curves whatever corner it picks.
        top.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0)
    top.set_title(f"{run_name}: energy budget")

    err = cols.get("energy_balance_error_J")
    if err is None:
        bot.text(0.5, 0.5, "no energy_balance_error_J column", ha="center", va="center",
                 transform=bot.transAxes)
        bot.set_ylabel("relative balance error [-]")
    else:
        # Early on the injected energy can be ~0 while round-off error is not; flooring the
        # denominator at a fraction of the run's energy scale keeps the ratio meaningful there.
        scale = max(scale_terms + [0.0])
        tiny = max(1e-9 * scale, 1e-300)
        # A closed system (injected identically 0) is judged against its own energy scale.
        diss = sum(cols[c] for c in cols if c.startswith("dissipated_"))
        ref = (np.abs(inj) if inj is not None else 0.0) + (diss if not isinstance(diss, int) else 0.0)
        if np.ndim(ref) and (np.abs(ref[np.isfinite(ref)]) > 0.0).any():
            # The energy that has passed through the budget so far (dissipated + |injected|), as a
            # running max: it stays a sane reference when wall work oscillates through zero.
            denom = np.maximum(np.fmax.accumulate(ref), tiny)
            ylabel = "balance error /\n(dissipated + |injected|) [-]"
        elif scale > 0.0:
            denom = np.full_like(err, scale)
            ylabel = "balance error /\nmax |energy term| [-]"
        else:  # nothing to normalise by: show the error itself
            denom = np.ones_like(err)
            ylabel = "balance error [J]"
        rel = err / denom
        bot.plot(t, rel, color="C3", lw=1.2)
        bot.axhline(0.0, color="0.6", lw=0.6)
        finite = np.abs(rel[np.isfinite(rel)])
        nonzero = finite[finite > 0.0]
        if nonzero.size:
            # symlog shows the sign and the decades of a drift; a threshold below the typical
            # value keeps the bulk of the curve on the log part even after an early spike.
            lt = max(0.1 * np.median(nonzero), 1e-8 * nonzero.max(), 1e-15)
            bot.set_yscale("symlog", linthresh=lt)
            # About five labelled ticks per sign, or the decade labels run into each other.
            k0, k1 = math.ceil(math.log10(lt)), math.ceil(math.log10(nonzero.max()))
            step = max(1, math.ceil((k1 - k0) / 5))
            dec = [10.0 ** k for k in range(k1, k0 - 1, -step)]
            lo, hi = np.nanmin(rel[np.isfinite(rel)]), np.nanmax(rel[np.isfinite(rel)])
            ticks = ([-d for d in dec if -d >= lo * 10] + [0.0]
                     + [d for d in dec[::-1] if d <= hi * 10])
            bot.yaxis.set_major_locator(FixedLocator(ticks))
            # symlog autoscaling pads by decades; a factor 2 beyond the data is enough.
            bot.set_ylim(2 * lo if lo < -lt else -lt, 2 * hi if hi > lt else lt)
        bot.set_ylabel(ylabel)
    bot.set_xlabel(tlabel)
    bot.grid(alpha=0.3, which="both")
    fig.tight_layout()
    save(fig, os.path.join(out, "energy_budget.png"))


def kinetic_energy(cols, t, tlabel, run_name, out):
    fig, ax = plt.subplots(figsize=(9, 5))
    plotted = 0
    for k, label, kw in [("kinetic_energy_J", "total", {"lw": 2}),
                         ("kinetic_translational_J", "translational", {"ls": "--"}),
                         ("kinetic_rotational_J", "rotational", {"ls": ":"})]:
        if k not in cols:
            continue
        y = np.where(cols[k] > 0.0, cols[k], np.nan)  # log axis: non-positive values are dropped
        if np.isfinite(y).any():
            ax.plot(t, y, label=label, **kw)
            plotted += 1
    if plotted:
        ax.set_yscale("log")
        ax.legend()
    else:
        ax.text(0.5, 0.5, "no positive kinetic energy values", ha="center", va="center",
                transform=ax.transAxes)
    ax.set_xlabel(tlabel)
    ax.set_ylabel("kinetic energy [J]")
    ax.set_title(f"{run_name}: kinetic energy")
    ax.grid(alpha=0.3, which="both")
    fig.tight_layout()
    save(fig, os.path.join(out, "kinetic_energy.png"))


def wall_loads(cols, names, t, tlabel, run_name, out):
    forces = [n for n in names if n.endswith("_N") and n != "time_s"]
    torques = [n for n in names if n.endswith("_Nm")]
    groups = [(g, u) for g, u in [(forces, "force [N]"), (torques, "torque [N m]")] if g]
    if not groups:
        return
    # Force and torque get separate panels: they have different units.
    fig, axes = plt.subplots(len(groups), 1, figsize=(9, 3.5 * len(groups) + 1), sharex=True,
                             squeeze=False)
    for ax, (group, unit) in zip(axes[:, 0], groups):
        for n in group:
            ax.plot(t, cols[n], label=n, lw=1)
        ax.set_ylabel(unit)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    axes[0, 0].set_title(f"{run_name}: wall loads")
    axes[-1, 0].set_xlabel(tlabel)
    fig.tight_layout()
    save(fig, os.path.join(out, "wall_loads.png"))


def main(argv):
    if len(argv) != 2:
        print("usage: plot_run.py RUN_DIR", file=sys.stderr)
        return 2
    run = argv[1]
    csv = os.path.join(run, "timeseries.csv")
    if not os.path.isdir(run):
        print(f"plot_run: no run folder {run}", file=sys.stderr)
        return 2
    if not os.path.isfile(csv):
        print(f"plot_run: no timeseries.csv in {run}", file=sys.stderr)
        return 2
    names, data = read_csv(csv)
    if data.shape[0] < 2:
        print(f"plot_run: {csv} has {data.shape[0]} row(s); need 2 to plot, nothing written")
        return 0
    cols = {n: data[:, i] for i, n in enumerate(names)}
    if "time_s" in cols:
        t, tlabel = cols["time_s"], "time [s]"
    else:
        t, tlabel = np.arange(data.shape[0], dtype=float), "output row [-]"
    run_name = os.path.basename(os.path.normpath(os.path.abspath(run)))
    energy_budget(cols, t, tlabel, run_name, run)
    kinetic_energy(cols, t, tlabel, run_name, run)
    wall_loads(cols, names, t, tlabel, run_name, run)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
