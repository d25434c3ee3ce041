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
  - the mean bed height and the dominant frequency of the pressure drop (timeseries.csv).
Writes a table (stdout and --csv) of measured against computed values with the RMS differences,
and a figure (--png).

usage: mueller_bed.py RUN_DIR [--from 0.5] [--png out.png] [--csv out.csv]
"""
import argparse
import csv
import math
import os
import sys

import h5py
import numpy as np

DATA = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "results", "validation", "data")
WIDTH, DEPTH = 0.044, 0.010  # [m]
BIN = 0.002  # [m] lateral bins
BAND = 0.0015  # [m] half-thickness of the height slabs


def read_data(name):
    """Columns x_m (from one side wall) and the value, skipping '#' comments and the header."""
    xs, vs = [], []
    with open(os.path.join(DATA, name)) as f:
        rows = [r for r in csv.reader(line for line in f if not line.startswith("#"))]
    head = rows[0]
    ix = head.index("x_wall_m") if "x_wall_m" in head else head.index("x_m")
    iv = len(head) - 1
    for r in rows[1:]:
        xs.append(float(r[ix]))
        vs.append(float(r[iv]))
    return np.array(xs), np.array(vs)


def cap_volume(r, h):
    """Volume of a sphere of radius r below a plane at height h above its lowest point (0..2r)."""
    h = np.clip(h, 0.0, 2 * r)
    return math.pi * h * h * (3 * r - h) / 3.0


def slab_volume(z, r, lo, hi):
    """Volume of spheres (centres z, radius r) between the planes lo < hi."""
    return cap_volume(r, hi - (z - r)) - cap_volume(r, lo - (z - r))


def profiles(run, t_from):
    edges = np.arange(0.0, WIDTH + 1e-12, BIN)
    centres = 0.5 * (edges[1:] + edges[:-1])
    nb = len(centres)
    vz = {h: [np.zeros(nb), np.zeros(nb)] for h in (0.015, 0.025, 0.035)}
    eps = {h: np.zeros(nb) for h in (0.0164, 0.0312)}
    used = 0
    with h5py.File(os.path.join(run, "particles.h5"), "r") as f:
        snaps = f["snapshots"]
        for key in sorted(snaps.keys()):
            s = snaps[key]
            t = float(f["time_s"][int(key)])
            if t < t_from:
                continue
            x = s["position_m"][()]
            v = s["velocity_m_per_s"][()]
            r = s["radius_m"][()]
            b = np.clip((x[:, 0] / BIN).astype(int), 0, nb - 1)
            for h, (sv, sn) in vz.items():
                m = np.abs(x[:, 2] - h) < BAND
                np.add.at(sv, b[m], v[m, 2] * r[m] ** 3)
                np.add.at(sn, b[m], r[m] ** 3)
            for h, acc in eps.items():
                vol = slab_volume(x[:, 2], r, h - BAND, h + BAND)
                np.add.at(acc, b, vol)
            used += 1
    if used == 0:
        sys.exit(f"mueller_bed.py: no snapshot at or after t = {t_from} s in {run}")
    out_v = {h: np.where(sn > 0, sv / np.maximum(sn, 1e-300), np.nan) for h, (sv, sn) in vz.items()}
    out_e = {h: 1.0 - acc / (used * BIN * DEPTH * 2 * BAND) for h, acc in eps.items()}
    return centres, out_v, out_e, used


def series(run, t_from):
    with open(os.path.join(run, "timeseries.csv")) as f:
        rows = list(csv.DictReader(f))
    t = np.array([float(r["time_s"]) for r in rows])
    m = t >= t_from
    dp = np.array([float(r["pressure_drop_Pa"]) for r in rows])[m]
    h = np.array([float(r["bed_height_m"]) for r in rows])[m]
    dt = np.median(np.diff(t[m]))
    spec = np.abs(np.fft.rfft(dp - dp.mean())) ** 2
    freq = np.fft.rfftfreq(len(dp), dt)
    k = 1 + int(np.argmax(spec[1:]))
    return {"mean_dp_Pa": dp.mean(), "sd_dp_Pa": dp.std(), "mean_bed_height_m": h.mean(),
            "dominant_frequency_Hz": freq[k], "window_s": t[m][-1] - t[m][0]}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("run")
    ap.add_argument("--from", dest="t_from", type=float, default=0.5)
    ap.add_argument("--png")
    ap.add_argument("--csv")
    a = ap.parse_args()
    x, v, e, used = profiles(a.run, a.t_from)
    s = series(a.run, a.t_from)
    rows = []
    comparisons = [("vz", 0.015, "mueller_U0.9_vz_h15mm.csv", v[0.015]),
                   ("vz", 0.025, "mueller_U0.9_vz_h25mm.csv", v[0.025]),
                   ("vz", 0.035, "mueller_U0.9_vz_h35mm.csv", v[0.035]),
                   ("voidage", 0.0164, "mueller_U0.9_voidage_h16.4mm.csv", e[0.0164]),
                   ("voidage", 0.0312, "mueller_U0.9_voidage_h31.2mm.csv", e[0.0312])]
    print(f"# {a.run}: {used} snapshots from t = {a.t_from} s; window {s['window_s']:.3g} s")
    print(f"# mean dp {s['mean_dp_Pa']:.4g} Pa (sd {s['sd_dp_Pa']:.3g}), mean bed height "
          f"{s['mean_bed_height_m']:.4g} m, dominant dp frequency {s['dominant_frequency_Hz']:.3g} Hz")
    print("quantity,height_m,rms_measured,rms_difference,mean_measured,mean_computed")
    for q, h, name, comp in comparisons:
        xm, vm = read_data(name)
        c = np.interp(xm, x, comp)
        ok = np.isfinite(c)
        rms_d = float(np.sqrt(np.mean((c[ok] - vm[ok]) ** 2)))
        rms_m = float(np.sqrt(np.mean(vm[ok] ** 2)))
        rows.append((q, h, rms_m, rms_d, float(vm[ok].mean()), float(c[ok].mean())))
        print(f"{q},{h},{rms_m:.4g},{rms_d:.4g},{vm[ok].mean():.4g},{c[ok].mean():.4g}")
    if a.csv:
        with open(a.csv + ".tmp", "w") as f:
            f.write("quantity,height_m,rms_measured,rms_difference,mean_measured,mean_computed\n")
            for r in rows:
                f.write(",".join(str(t) for t in r) + "\n")
        os.replace(a.csv + ".tmp", a.csv)
    if a.png:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(1, 5, figsize=(17, 3.4))
        for k, (q, h, name, comp) in enumerate(comparisons):
            xm, vm = read_data(name)
            ax[k].plot(1e3 * xm, vm, "ko", ms=3, label="MR (Mueller et al.)")
            ax[k].plot(1e3 * x, comp, "r-", label="lbdem")
            ax[k].set_xlabel("x [mm]")
            ax[k].set_ylabel("v_z [m/s]" if q == "vz" else "voidage [-]")
            ax[k].set_title(f"{q}, {1e3 * h:.1f} mm")
        ax[0].legend(fontsize=7)
        fig.tight_layout()
        fig.savefig(a.png + ".tmp.png", dpi=110)
        os.replace(a.png + ".tmp.png", a.png)


if __name__ == "__main__":
    main()
