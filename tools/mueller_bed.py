#!/usr/bin/env python3
"""Compare a run of the Mueller et al. pseudo-2-D bubbling bed (fluidized_bed preset mueller_u09)
with the magnetic-resonance measurements kept in results/validation/data/.

What it computes from the run folder, over the snapshots from --from (s) on:
  - the time-averaged vertical particle velocity across the width at 15, 25 and 35 mm above the
    distributor (particles whose centres lie within +-1.5 mm of the height, in 2 mm bins of x,
    averaged over particles and snapshots: a mass-weighted mean, as the MR signal of the seeds is);
  - the time-averaged voidage across the width at 16.4 and 31.2 mm: the particles' volume in a
    3 mm slab (exact sphere-slab intersection along z) per 2 mm bin of x (by centre), over the
    slab's volume;
  - the mean bed height, pressure drop and dominant frequency of the pressure drop
    (timeseries.csv), reported (the data set has no measurement of them).
Goals: each profile's RMS difference within twice the profiles' scatter, the measurement's
(from its left-right asymmetry: the bed is symmetric about its middle plane, so the mean profile
is too) and the run's sampling error (the standard error over 5 consecutive blocks of
snapshots) together; the bed's
expansion within 10 %, judged on the mean solid fraction at each voidage height (the expanded
height of a bed of given mass is inversely proportional to its mean solid fraction).
Writes the goals table (--csv, see bed_compare.py) and a figure (--png).

usage: mueller_bed.py RUN_DIR [--from 0.5] [--to END] [--png out.png] [--csv goals.csv]
"""
import argparse
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bed_compare as bc  # noqa: E402

WIDTH, DEPTH = 0.044, 0.010  # [m]
BIN = 0.002  # [m] lateral bins
BAND = 0.0015  # [m] half-thickness of the height slabs
VZ_HEIGHTS = (0.015, 0.025, 0.035)  # [m]
EPS_HEIGHTS = (0.0164, 0.0312)  # [m]
BLOCKS = 5  # consecutive blocks of snapshots for the run's sampling error


def profile_data(name):
    """x from one side wall and the value of a measured profile."""
    d = bc.read_csv_data(name)
    x = d["x_wall_m"] if "x_wall_m" in d else d["x_m"]
    return x, list(d.values())[-1]


def profile_of(snaps):
    """Time-averaged v_z and voidage profiles over a list of snapshots (x, v, r)."""
    nb = int(round(WIDTH / BIN))
    vz = {h: [np.zeros(nb), np.zeros(nb)] for h in VZ_HEIGHTS}
    eps = {h: np.zeros(nb) for h in EPS_HEIGHTS}
    for x, v, r in snaps:
        b = np.clip((x[:, 0] / BIN).astype(int), 0, nb - 1)
        for h, (sv, sn) in vz.items():
            m = np.abs(x[:, 2] - h) < BAND
            np.add.at(sv, b[m], v[m, 2] * r[m] ** 3)
            np.add.at(sn, b[m], r[m] ** 3)
        for h, acc in eps.items():
            np.add.at(acc, b, bc.slab_volume(x[:, 2], r, h - BAND, h + BAND))
    out_v = {h: np.where(sn > 0, sv / np.maximum(sn, 1e-300), np.nan) for h, (sv, sn) in vz.items()}
    out_e = {h: 1.0 - acc / (len(snaps) * BIN * DEPTH * 2 * BAND) for h, acc in eps.items()}
    return {**out_v, **out_e}


def profiles(run, t_from, t_to):
    """Bin centres, the profiles over the window, each profile's sampling error (the standard
    error of the mean over BLOCKS consecutive blocks of snapshots, RMS over the bins) and the
    number of snapshots."""
    snaps = [(x, v, r) for _, x, v, r in bc.snapshots(run, t_from, t_to)]
    if not snaps:
        sys.exit(f"mueller_bed.py: no snapshot at or after t = {t_from} s in {run}")
    centres = (np.arange(int(round(WIDTH / BIN))) + 0.5) * BIN
    whole = profile_of(snaps)
    nblocks = min(BLOCKS, len(snaps))
    blocks = [profile_of([snaps[i] for i in idx])
              for idx in np.array_split(np.arange(len(snaps)), nblocks)]
    error = {}
    for h in whole:
        if nblocks < 2:
            error[h] = 0.0
            continue
        b = np.array([blk[h] for blk in blocks])
        se = np.nanstd(b, axis=0, ddof=1) / np.sqrt(nblocks)
        error[h] = float(np.sqrt(np.nanmean(se ** 2)))
    return centres, whole, error, len(snaps)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("run")
    ap.add_argument("--from", dest="t_from", type=float, default=0.5)
    ap.add_argument("--to", dest="t_to", type=float, default=math.inf,
                    help="end of the window [s] (default: the run's end)")
    ap.add_argument("--png")
    ap.add_argument("--csv")
    a = ap.parse_args()
    x, prof, run_error, used = profiles(a.run, a.t_from, a.t_to)
    s = bc.read_series(a.run, ["pressure_drop_Pa", "bed_height_m"], a.t_from, a.t_to)
    f_dp, f_res = bc.dominant_frequency(s["time_s"], s["pressure_drop_Pa"])
    comparisons = [("v_z", h, f"mueller_U0.9_vz_h{1e3 * h:.0f}mm.csv", prof[h], "m/s")
                   for h in VZ_HEIGHTS]
    comparisons += [("voidage", h, f"mueller_U0.9_voidage_h{1e3 * h:.1f}mm.csv", prof[h], "-")
                    for h in EPS_HEIGHTS]
    rows = []
    for q, h, name, comp, unit in comparisons:
        xm, vm = profile_data(name)
        c = np.interp(xm, x, comp)
        ok = np.isfinite(c)
        rms_d = float(np.sqrt(np.mean((c[ok] - vm[ok]) ** 2)))
        # Both profiles' scatter: the measurement's, from its left-right asymmetry (no error bars
        # are published), and lbdem's sampling error over time (blocks of snapshots). The run's
        # asymmetry is not counted as scatter: a mean profile of this symmetric bed that leans
        # to one side is part of the difference.
        scatter = float(np.hypot(bc.mirror_scatter(xm, vm, WIDTH), run_error[h]))
        rows.append(bc.goal_row(
            f"{q} profile at {1e3 * h:.3g} mm: RMS of measured and lbdem; RMS difference", unit,
            float(np.sqrt(np.mean(vm[ok] ** 2))), float(np.sqrt(np.mean(c[ok] ** 2))), rms_d,
            f"<= 2 x the profiles' scatter ({scatter:.2g})", rms_d <= 2 * scatter))
        if q == "voidage":
            phi_m, phi_c = 1 - float(vm[ok].mean()), 1 - float(c[ok].mean())
            rows.append(bc.goal_row(f"mean solid fraction at {1e3 * h:.3g} mm (bed expansion)",
                                    "-", phi_m, phi_c, phi_c - phi_m, "within 10 %",
                                    abs(phi_c - phi_m) <= 0.10 * phi_m))
    dp, hb = s["pressure_drop_Pa"], s["bed_height_m"]
    rows.append(bc.goal_row("mean pressure drop", "Pa", float("nan"), dp.mean(), float("nan"),
                            "reported (weight per area 186.2 Pa)", None))
    rows.append(bc.goal_row("mean bed height", "m", float("nan"), hb.mean(), float("nan"),
                            "reported", None))
    rows.append(bc.goal_row("dominant frequency of the pressure drop", "Hz", float("nan"), f_dp,
                            float("nan"), f"reported (resolution {f_res:.2g} Hz)", None))
    print(f"# {a.run}: {used} snapshots from t = {a.t_from} s; window "
          f"{s['time_s'][-1] - s['time_s'][0]:.3g} s")
    bc.report(rows, a.csv)
    if a.png:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(1, 5, figsize=(17, 3.4))
        for k, (q, h, name, comp, unit) in enumerate(comparisons):
            xm, vm = profile_data(name)
            ax[k].plot(1e3 * xm, vm, "ko", ms=3, label="MR (Mueller et al.)")
            ax[k].plot(1e3 * x, comp, "r-", label="lbdem")
            ax[k].set_xlabel("x [mm]")
            ax[k].set_ylabel("v_z [m/s]" if q == "v_z" else "voidage [-]")
            ax[k].set_title(f"{q}, {1e3 * h:.1f} mm")
        ax[0].legend(fontsize=7)
        fig.tight_layout()
        bc.save_figure(fig, a.png)


if __name__ == "__main__":
    main()
