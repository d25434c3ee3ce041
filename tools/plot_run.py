#!/usr/bin/env python3
"""Plots of a run folder's timeseries.csv, config.toml and log.txt.

usage: /usr/bin/python3 tools/plot_run.py RUN_DIR

Writes into RUN_DIR:
  energy_budget.png   every energy term by name, and the balance error relative to the energy moved
  kinetic_energy.png  the particles' kinetic energy (total, translational, rotational; log axis)
                      (these two only for a run with particles)
  gas.png             a run without particles: the gas's mean speed, kinetic energy and mass
                      balance error
  wall_loads.png      the particles' forces and torques on each wall, and the gas's force on the
                      walls (when the series has such columns)
and, by the config's scenario:
  bed.png             fluidized bed: bed height and pressure drop, with the bed weight per area
  torque.png          rheometer: impeller torque, impeller speed and the mean after the spin-up
  jet_mill.png        jet mill: kinetic energy, and the mass fed and the mass that left
Exit 0 on success or when there are fewer than two rows to plot, 2 when RUN_DIR or its
timeseries.csv is missing.
"""
import math
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")  # runs on headless machines and from cron-like drivers
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.ticker import FixedLocator  # noqa: E402

try:
    import tomllib  # Python 3.11
except ImportError:  # pragma: no cover - older pythons draw everything but what needs the config
    tomllib = None

DISSIPATED = [
    ("dissipated_normal_damping_J", "normal damping"),
    ("dissipated_tangential_damping_J", "tangential damping"),
    ("dissipated_sliding_J", "sliding friction"),
    ("dissipated_rolling_J", "rolling friction"),
]
# Names that read better than the solver's face names.
WALL_NAMES = {"z_lo": "floor (z_lo)", "z_hi": "roof (z_hi)", "top_plate": "top plate"}


# ---------------------------------------------------------------------------------------------
# Reading


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


def read_config(run):
    """The run's config.toml as a dict ({} when it is missing or unreadable)."""
    path = os.path.join(run, "config.toml")
    if tomllib is None or not os.path.isfile(path):
        return {}
    try:
        with open(path, "rb") as f:
            return tomllib.load(f)
    except (OSError, ValueError):
        return {}


def log_number(run, phrase):
    """The number after `phrase` on the first line of log.txt that holds it (the banner's derived
    numbers: "  bed weight per area, less buoyancy        44.1283 Pa  (...)"), or None."""
    path = os.path.join(run, "log.txt")
    if not os.path.isfile(path):
        return None
    num = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")
    with open(path, "r", encoding="utf-8", errors="replace") as f:
        for line in f:
            i = line.find(phrase)
            if i < 0:
                continue
            m = num.search(line, i + len(phrase))
            return float(m.group(0)) if m else None
    return None


def section(cfg, *keys):
    for k in keys:
        cfg = cfg.get(k, {}) if isinstance(cfg, dict) else {}
    return cfg if isinstance(cfg, dict) else {}


def scenario_of(cfg, cols):
    """The config's scenario, else guessed from the scenario's own columns."""
    s = cfg.get("scenario")
    if isinstance(s, str):
        return s
    for col, name in [("bed_height_m", "fluidized_bed"), ("torque_Nm", "rheometer"),
                      ("jet_mass_flow_kg_s", "jet_mill")]:
        if col in cols:
            return name
    return ""


# ---------------------------------------------------------------------------------------------
# Numbers (tested in tests/tools/test_plot_run.py)


def energy_sources(cols):
    """[(label, series)] of the energy put in since t = 0, by source. The CSV's energy_injected_J is
    their sum: wall work + gas work + stiffness change + inserted - removed; the last, which has no
    column of its own, is what the sum leaves after the others."""
    inj = cols.get("energy_injected_J")
    out = []
    rest = None if inj is None else inj.copy()
    for key, label in [("wall_work_J", "wall work (moving walls)"),
                       ("gas_work_on_particles_J", "gas work on the particles (drag, buoyancy)"),
                       ("stiffness_change_J", "stiffness change")]:
        if key in cols:
            out.append((label, cols[key]))
            if rest is not None:
                rest = rest - cols[key]
    if rest is not None:
        out.append(("particles inserted - removed", rest))
    return out


def energy_moved(cols):
    """The energy moved, as the DEM watchdog takes it (run/dem_driver.cpp): kinetic +
    elastic + dissipated + |each source|. It grows from the first motion on and does not cross zero
    the way the injected energy (a sum of signed sources) or the potential energy do. Inserted and
    removed energy enter as one source, their difference: the series holds no more."""
    n = len(next(iter(cols.values())))
    moved = np.zeros(n)
    for key in ["kinetic_energy_J", "elastic_energy_J"] + [k for k, _ in DISSIPATED]:
        if key in cols:
            moved = moved + cols[key]
    if "kinetic_energy_J" not in cols and "kinetic_translational_J" in cols:
        moved = moved + cols["kinetic_translational_J"] + cols.get("kinetic_rotational_J", 0.0)
    for _, s in energy_sources(cols):
        moved = moved + np.abs(s)
    return moved


def relative_balance_error(cols):
    """energy_balance_error_J / energy_moved(cols); 0 where both are 0 (before anything moves),
    NaN where only the denominator is (an error with no energy moved has no relative size)."""
    err = cols["energy_balance_error_J"]
    moved = energy_moved(cols)
    with np.errstate(divide="ignore", invalid="ignore"):
        rel = np.where(moved > 0, err / np.where(moved > 0, moved, 1.0),
                       np.where(err == 0, 0.0, np.nan))
    return rel


def impeller_rpm(t, rpm, start, ramp):
    """The impeller speed of the rheometer's prescribed motion (dem/walls/prescribed_motion.hpp):
    at rest until `start`, a linear ramp over `ramp`, then `rpm`."""
    t = np.asarray(t, dtype=float)
    if ramp > 0:
        frac = np.clip((t - start) / ramp, 0.0, 1.0)
    else:
        frac = (t > start).astype(float)
    return rpm * frac


def steady_window_start(rpm, start, ramp):
    """Start of the rheometer's steady window: one revolution after the impeller starts, as the
    rheometer study takes it (studies/rheometer_study.cpp), or the end of the ramp if
    that is later."""
    rev = 60.0 / max(abs(rpm), 1e-300)
    return start + max(rev, ramp)


def window_mean(t, y, t0):
    """(mean, standard deviation, samples) of y over the rows with t > t0; NaNs when there are
    none."""
    t, y = np.asarray(t), np.asarray(y)
    sel = (t > t0) & np.isfinite(y)
    if not sel.any():
        return math.nan, math.nan, 0
    return float(np.mean(y[sel])), float(np.std(y[sel])), int(sel.sum())


# ---------------------------------------------------------------------------------------------
# Drawing


def save(fig, path):
    # Atomic replace so a viewer or a concurrent plotting pass never reads a half-written PNG.
    tmp = path[: -len(".png")] + ".tmp.png"
    fig.savefig(tmp, dpi=120)
    plt.close(fig)
    os.replace(tmp, path)
    print(path)


def nonzero(y, scale):
    y = np.asarray(y, dtype=float)
    fin = y[np.isfinite(y)]
    return fin.size > 0 and np.max(np.abs(fin)) > 1e-9 * scale


def note_handle(ax, text):
    """A legend line with no symbol: for what the plot leaves out."""
    ax.plot([], [], " ", label=text)


def energy_budget(cols, t, tlabel, run_name, out, cfg):
    fig, (top, bot) = plt.subplots(2, 1, figsize=(12, 8), sharex=True,
                                   gridspec_kw={"height_ratios": [3, 2]})
    terms = []  # (label, series, style)
    kin = cols.get("kinetic_energy_J")
    if kin is None and "kinetic_translational_J" in cols:
        kin = cols["kinetic_translational_J"] + cols.get("kinetic_rotational_J", 0.0)
    if kin is not None:
        terms.append(("stored: kinetic", kin, dict(lw=2, color="C0")))
    if "potential_energy_J" in cols:
        pe = cols["potential_energy_J"]
        terms.append(("stored: gravitational potential, change since t = 0", pe - pe[0],
                      dict(lw=2, color="C1")))
    if "elastic_energy_J" in cols:
        terms.append(("stored: elastic (contact springs + cohesion)", cols["elastic_energy_J"],
                      dict(lw=2, color="C2")))
    diss = [k for k, _ in DISSIPATED if k in cols]
    for (k, label), color in zip(DISSIPATED, ["C3", "C4", "C5", "C6"]):
        if k in cols:
            terms.append((f"dissipated: {label}", cols[k], dict(ls="--", lw=1.4, color=color)))
    if len(diss) > 1:
        terms.append(("dissipated: total", sum(cols[k] for k in diss),
                      dict(ls="--", lw=1.4, color="k")))
    for (label, s), color in zip(energy_sources(cols), ["tab:cyan", "tab:olive", "navy", "darkgoldenrod"]):
        terms.append((f"source: {label}", s, dict(ls=":", lw=2, color=color)))
    inj = cols.get("energy_injected_J")
    if inj is not None:
        # Beneath the others: it often equals one source, which stays visible on top of it.
        terms.append(("energy injected = sum of the sources", inj,
                      dict(color="k", lw=4, alpha=0.3, zorder=1.5)))
    scale = max([np.nanmax(np.abs(s)) if np.isfinite(s).any() else 0.0 for _, s, _ in terms]
                + [0.0])
    zero = []
    for label, s, kw in terms:
        if nonzero(s, scale):
            top.plot(t, s, label=label, **kw)
        else:
            zero.append(label.split(": ", 1)[-1])
    if zero:
        note_handle(top, "zero throughout:\n  " + ",\n  ".join(zero))
    top.set_ylabel("energy [J]")
    top.axhline(0.0, color="0.6", lw=0.6)
    top.grid(alpha=0.3)
    if top.lines:
        # Outside the axes: inside, the legend hides curves whatever corner it picks.
        top.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0,
                   title="balance: change of stored + dissipated\n= injected (the work of the"
                         " sources)", title_fontsize=8)
    top.set_title(f"{run_name}: energy budget of the particles since t = 0")

    if "energy_balance_error_J" not in cols:
        bot.text(0.5, 0.5, "no energy_balance_error_J column", ha="center", va="center",
                 transform=bot.transAxes)
        bot.set_ylabel("relative balance error [-]")
    else:
        rel = relative_balance_error(cols)
        bot.plot(t, rel, color="C3", lw=1.2)
        bot.axhline(0.0, color="0.6", lw=0.6)
        symlog_axis(bot, rel)
        bot.set_ylabel("balance error /\nenergy moved [-]")
        limit = section(cfg, "dem").get("max_energy_error")
        watch = (f"; the DEM watchdog stops a run above {limit:g}"
                 if isinstance(limit, (int, float)) else "")
        bot.set_title("energy moved = kinetic + elastic + dissipated + |each source|" + watch,
                      fontsize=9)
    bot.set_xlabel(tlabel)
    bot.grid(alpha=0.3, which="both")
    fig.tight_layout()
    save(fig, os.path.join(out, "energy_budget.png"))


def symlog_axis(ax, y):
    fin = y[np.isfinite(y)]
    mags = np.abs(fin)
    pos = mags[mags > 0.0]
    if not pos.size:
        return
    # symlog shows the sign and the decades of a drift; a threshold below the typical value keeps
    # the bulk of the curve on the log part even after an early spike.
    lt = max(0.1 * np.median(pos), 1e-8 * pos.max(), 1e-15)
    ax.set_yscale("symlog", linthresh=lt)
    # About five labelled ticks per sign, or the decade labels run into each other.
    k0, k1 = math.ceil(math.log10(lt)), math.ceil(math.log10(pos.max()))
    step = max(1, math.ceil((k1 - k0) / 5))
    dec = [10.0 ** k for k in range(k1, k0 - 1, -step)]
    lo, hi = float(np.min(fin)), float(np.max(fin))
    ticks = [-d for d in dec if -d >= lo * 10] + [0.0] + [d for d in dec[::-1] if d <= hi * 10]
    ax.yaxis.set_major_locator(FixedLocator(ticks))
    # symlog autoscaling pads by decades; a factor 2 beyond the data is enough.
    ax.set_ylim(2 * lo if lo < -lt else -lt, 2 * hi if hi > lt else lt)


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
    ax.set_ylabel("kinetic energy of the particles [J]")
    ax.set_title(f"{run_name}: kinetic energy")
    ax.grid(alpha=0.3, which="both")
    fig.tight_layout()
    save(fig, os.path.join(out, "kinetic_energy.png"))


def wall_label(name):
    if name in WALL_NAMES:
        return WALL_NAMES[name]
    if re.fullmatch(r"[xy]_(lo|hi)", name):
        return f"side wall {name}"
    return name.replace("_", " ")


def wall_groups(names):
    """[(panel y label, [(curve label, column, name in the note of curves left out)])] of the wall
    loads in the series."""
    forces, torques, gas = [], [], []
    for n in names:
        m = re.fullmatch(r"wall_(.+)_force_z_N", n)
        if m:
            forces.append((wall_label(m.group(1)), n, f"force on {wall_label(m.group(1))}"))
        m = re.fullmatch(r"wall_(.+)_torque_axis_Nm", n)
        if m:
            torques.append((wall_label(m.group(1)), n, f"torque on {wall_label(m.group(1))}"))
    # The rheometer's walls: the impeller drive torque and the reactions of cup and floor.
    for n, label in [("torque_Nm", "impeller (blades + shaft), drive torque"),
                     ("cup_torque_Nm", "cup wall"), ("floor_torque_Nm", "cup floor")]:
        if n in names:
            torques.append((label, n, f"torque on {label.split(',')[0]}"))
    for a in "xyz":
        if f"gas_force_on_walls_{a}_N" in names:
            gas.append((f"{a} component", f"gas_force_on_walls_{a}_N", f"gas force {a}"))
    return [(u, g) for u, g in [
        ("particles' force on the wall,\nz component [N]", forces),
        ("particles' torque about\nthe wall's axis [N m]", torques),
        ("gas force on all walls [N]", gas)] if g]


def wall_loads(cols, names, t, tlabel, run_name, out):
    groups = wall_groups(names)
    if not groups:
        return
    shown, zero = [], []
    for unit, group in groups:
        scale = max([np.nanmax(np.abs(cols[c])) if np.isfinite(cols[c]).any() else 0.0
                     for _, c, _ in group] + [1e-300])
        keep = [g for g in group if nonzero(cols[g[1]], scale)]
        zero += [g[2] for g in group if g not in keep]
        if keep:
            shown.append((unit, keep))
    if not shown:
        shown = groups[:1]
    fig, axes = plt.subplots(len(shown), 1, figsize=(10, 2.8 * len(shown) + 1.4), sharex=True,
                             squeeze=False)
    for ax, (unit, group) in zip(axes[:, 0], shown):
        for i, (label, c, _) in enumerate(group):
            ax.plot(t, cols[c], label=label, lw=1.2, color=f"C{i}")
        ax.axhline(0.0, color="0.6", lw=0.6)
        ax.set_ylabel(unit)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0)
    axes[0, 0].set_title(f"{run_name}: wall loads")
    axes[-1, 0].set_xlabel(tlabel)
    if zero:
        fig.text(0.01, 0.005, "zero throughout (not drawn): " + ", ".join(zero), fontsize=8,
                 va="bottom", wrap=True)
    fig.tight_layout(rect=(0, 0.04 if zero else 0, 1, 1))
    save(fig, os.path.join(out, "wall_loads.png"))


def inlet_ramp(cfg):
    """(ramp_start, ramp_time, speed) of the first gas inlet face with a ramp, or None."""
    for face in section(cfg, "fluid", "faces").values():
        if isinstance(face, dict) and face.get("kind") == "inlet" and "ramp_start" in face:
            v = face.get("velocity", [0.0, 0.0, 0.0])
            return (float(face["ramp_start"]), float(face.get("ramp_time", 0.0)),
                    float(np.linalg.norm(np.asarray(v, dtype=float))))
    return None


def bed(cols, t, tlabel, run_name, run, cfg):
    weight = log_number(run, "bed weight per area")
    fig, (top, bot) = plt.subplots(2, 1, figsize=(10, 7), sharex=True)
    top.plot(t, 1e3 * cols["bed_height_m"], color="C0", lw=1.5, label="bed height")
    frac = section(cfg, "bed").get("height_fraction")
    top.set_ylabel("bed height [mm]")
    what = (f"the height below which {100 * frac:g} % of the particle volume lies"
            if isinstance(frac, (int, float)) else "bed height")
    top.set_title(f"{run_name}: fluidized bed\n{what}", fontsize=11)
    taps = section(cfg, "bed").get("pressure_taps")
    tap_text = (f" between the taps at z = {1e3 * taps[0]:g} and {1e3 * taps[1]:g} mm"
                if isinstance(taps, list) and len(taps) == 2 else "")
    bot.plot(t, cols["pressure_drop_Pa"], color="C1", lw=1.5, label="pressure drop" + tap_text)
    if weight is not None:
        bot.axhline(weight, color="k", ls="--", lw=1.2,
                    label=f"W/A = {weight:.4g} Pa: bed weight per area, less buoyancy (log.txt)")
    else:
        note_handle(bot, "W/A not drawn: log.txt has no 'bed weight per area' line")
    ramp = inlet_ramp(cfg)
    if ramp is not None and t.size and ramp[0] < t[-1]:
        a, d, u = ramp
        for ax in (top, bot):
            ax.axvspan(a, a + d, color="0.9", zorder=0,
                       label=f"gas inflow ramp to {u:.3g} m/s" if ax is bot else None)
    for ax in (top, bot):
        ax.grid(alpha=0.3)
    bot.set_ylabel("pressure drop [Pa]")
    bot.set_xlabel(tlabel)
    bot.legend(fontsize=8, loc="best")
    fig.tight_layout()
    save(fig, os.path.join(run, "bed.png"))


def torque(cols, t, tlabel, run_name, out, cfg):
    rh = section(cfg, "rheometer")
    rpm, start, ramp = rh.get("rpm"), rh.get("start"), rh.get("ramp", 0.0)
    fig, ax = plt.subplots(figsize=(10, 5.5))
    ax.plot(t, cols["torque_Nm"], color="C0", lw=1.0, label="impeller torque (blades + shaft)")
    ax.axhline(0.0, color="0.6", lw=0.6)
    ax.set_xlabel(tlabel)
    ax.set_ylabel("impeller torque [N m]")
    ax.grid(alpha=0.3)
    handles = []
    if all(isinstance(v, (int, float)) for v in (rpm, start, ramp)):
        t0 = steady_window_start(rpm, start, ramp)
        mean, sd, n = window_mean(t, cols["torque_Nm"], t0)
        if n > 0:
            ax.hlines(mean, t0, t[-1], color="C3", lw=2.5, zorder=3,
                      label=f"mean over t > {t0:.3g} s: {mean:.4g} N m (sd {sd:.2g}, {n} rows)")
            ax.axvspan(t0, t[-1], color="C3", alpha=0.07, lw=0)
        else:
            note_handle(ax, f"no mean: the run ends before t = {t0:.3g} s\n(one revolution"
                            " after the impeller starts)")
        right = ax.twinx()
        right.plot(t, impeller_rpm(t, rpm, start, ramp), color="0.35", ls="--", lw=1.4,
                   label=f"impeller speed (right axis): {rpm:g} rpm from t = {start:g} s,"
                         f" ramp {ramp:g} s")
        right.set_ylabel("impeller speed [rpm]")
        right.set_ylim(0, 1.15 * max(abs(rpm), 1e-12))
        handles = right.get_legend_handles_labels()
    else:
        note_handle(ax, "no [rheometer] rpm, start, ramp in config.toml: speed and mean not drawn")
    h, lab = ax.get_legend_handles_labels()
    if handles:
        h, lab = h + handles[0], lab + handles[1]
    ax.legend(h, lab, fontsize=8, loc="upper left")
    ax.set_title(f"{run_name}: rheometer torque; the mean starts one revolution after the"
                 " impeller does", fontsize=11)
    fig.tight_layout()
    save(fig, os.path.join(out, "torque.png"))


def gas(cols, t, tlabel, run_name, out):
    """A run without particles: its gas's own columns."""
    rows = [(key, label) for key, label in
            [("gas_mean_speed_m_s", "mean gas speed [m/s]"),
             ("gas_kinetic_energy_J", "gas kinetic energy [J]"),
             ("gas_mass_balance_error_kg", "gas mass balance error [kg]")] if key in cols]
    if not rows:
        return
    fig, axes = plt.subplots(len(rows), 1, figsize=(10, 2.6 * len(rows) + 1), sharex=True,
                             squeeze=False)
    for ax, (key, label) in zip(axes[:, 0], rows):
        ax.plot(t, cols[key], color="C0", lw=1.5)
        ax.set_ylabel(label)
        ax.grid(alpha=0.3)
    axes[0, 0].set_title(f"{run_name}: gas")
    axes[-1, 0].set_xlabel(tlabel)
    fig.tight_layout()
    save(fig, os.path.join(out, "gas.png"))


def jet_mill(cols, t, tlabel, run_name, out):
    fig, (top, bot) = plt.subplots(2, 1, figsize=(10, 7), sharex=True)
    if "kinetic_energy_J" in cols:
        top.plot(t, cols["kinetic_energy_J"], color="C0", lw=1.5, label="kinetic energy")
    top.set_ylabel("kinetic energy of the\nparticles in the mill [J]")
    if "particles" in cols:
        right = top.twinx()
        right.plot(t, cols["particles"], color="0.4", ls=":", lw=1.5, label="parcels (right axis)")
        right.set_ylabel("parcels in the mill [-]")
        h1, l1 = top.get_legend_handles_labels()
        h2, l2 = right.get_legend_handles_labels()
        top.legend(h1 + h2, l1 + l2, fontsize=8, loc="upper left")
    top.grid(alpha=0.3)
    top.set_title(f"{run_name}: jet mill")
    fed = cols.get("mass_inserted_kg")
    gone = cols.get("mass_removed_kg")
    if fed is not None:
        bot.plot(t, 1e3 * fed, color="C2", lw=1.5, label="fed (inserted)")
    if gone is not None:
        bot.plot(t, 1e3 * gone, color="C3", lw=2,
                 label="left the mill (through the outlet; any lost through a face included)")
    if fed is not None and gone is not None:
        bot.plot(t, 1e3 * (fed - gone), color="C0", ls="--", lw=1.2, label="in the mill")
    bot.set_ylabel("particle mass, cumulative [g]")
    bot.set_xlabel(tlabel)
    bot.grid(alpha=0.3)
    bot.legend(fontsize=8, loc="upper left")
    fig.tight_layout()
    save(fig, os.path.join(out, "jet_mill.png"))


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
    cfg = read_config(run)
    run_name = os.path.basename(os.path.normpath(os.path.abspath(run)))
    if "particles" in cols:
        energy_budget(cols, t, tlabel, run_name, run, cfg)
        kinetic_energy(cols, t, tlabel, run_name, run)
    else:
        gas(cols, t, tlabel, run_name, run)
    wall_loads(cols, names, t, tlabel, run_name, run)
    scenario = scenario_of(cfg, cols)
    if scenario == "fluidized_bed" and {"bed_height_m", "pressure_drop_Pa"} <= cols.keys():
        bed(cols, t, tlabel, run_name, run, cfg)
    if scenario == "rheometer" and "torque_Nm" in cols:
        torque(cols, t, tlabel, run_name, run, cfg)
    if scenario == "jet_mill":
        jet_mill(cols, t, tlabel, run_name, run)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
