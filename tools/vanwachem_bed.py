#!/usr/bin/env python3
"""Compare a run of the van Wachem et al. (2001) pseudo-2-D bubbling bed (fluidized_bed preset
vanwachem2001) with the measurements kept in results/validation/data/.

From the run folder, over t >= --from:
  - the mean bed height against the time mean of the measured one. The measured height is the
    top of the bed seen in the experiment's video: it swings from about 93 to 150 mm within
    0.2 s as a bubble lifts the surface and erupts, which a height below which most of the
    particles' volume lies cannot do. The goal compares the top of the highest particle (particle
    snapshots), the reading the Lethe example that publishes these data compares with them; the
    top without the highest 1 % of the particles and the height below which 95 % of the particle
    volume lies (timeseries.csv bed_height_m) are reported beside it;
  - the pressure 45 mm above the distributor (the preset's taps are at 45 mm and at the outlet,
    where the pressure is held at 0): the dominant frequency of its fluctuation against the peak
    of the measured spectrum (2.4 Hz), and its standard deviation against the measured one;
  - the voidage 45 mm above the distributor, in a slab 3 mm thick over the middle 10 mm of the
    width and the whole depth (particle snapshots), mean and standard deviation.
Goals (from the validation issue): bed height within 10 %, frequency within 20 %; the rest is
reported. Writes the goals table (--csv, bed_compare.py) and a figure (--png).

usage: vanwachem_bed.py RUN_DIR [--from 1.5] [--to END] [--png out.png] [--csv goals.csv]
"""
import argparse
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bed_compare as bc  # noqa: E402

WIDTH, DEPTH = 0.09, 0.008  # [m]
PROBE_Z, BAND = 0.045, 0.0015  # [m] the probe height and the slab's half-thickness
PROBE_X = (0.04, 0.05)  # [m] the middle 10 mm of the width


def snapshot_series(run, t_from, t_to):
    """Per particle snapshot: its time, the voidage at the probe, the bed's top (highest particle)
    and its top without the highest 1 %."""
    times, eps, top, top99 = [], [], [], []
    for t, x, _, r in bc.snapshots(run, t_from, t_to):
        m = (x[:, 0] >= PROBE_X[0]) & (x[:, 0] < PROBE_X[1])
        vol = bc.slab_volume(x[m, 2], r[m], PROBE_Z - BAND, PROBE_Z + BAND).sum()
        times.append(t)
        eps.append(1.0 - vol / ((PROBE_X[1] - PROBE_X[0]) * DEPTH * 2 * BAND))
        top.append(bc.bed_top(x[:, 2], r))
        top99.append(bc.bed_top(x[:, 2], r, 0.99))
    return np.array(times), np.array(eps), np.array(top), np.array(top99)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("run")
    ap.add_argument("--from", dest="t_from", type=float, default=1.5)
    ap.add_argument("--to", dest="t_to", type=float, default=math.inf,
                    help="end of the window [s] (default: the run's end)")
    ap.add_argument("--png")
    ap.add_argument("--csv")
    a = ap.parse_args()

    s = bc.read_series(a.run, ["pressure_drop_Pa", "bed_height_m"], a.t_from, a.t_to)
    if len(s["time_s"]) < 64:
        sys.exit(f"vanwachem_bed.py: {len(s['time_s'])} rows of {a.run}/timeseries.csv from "
                 f"t = {a.t_from} s; at least 64 needed (let the run go on, or lower --from)")
    t, p, h = s["time_s"], s["pressure_drop_Pa"], s["bed_height_m"]
    f_lbdem, f_res = bc.dominant_frequency(t, p)
    te, eps, top, top99 = snapshot_series(a.run, a.t_from, a.t_to)

    mh = bc.read_csv_data("vanwachem2001_bed_height.csv")
    mp = bc.read_csv_data("vanwachem2001_relative_pressure.csv")
    mv = bc.read_csv_data("vanwachem2001_voidage.csv")
    psd = bc.read_csv_data("vanwachem2001_pressure_psd.csv")
    h_meas = bc.time_mean(mh["t_s"], mh["h_m"])
    p_rel = mp["p_rel_Pa"] - bc.time_mean(mp["t_s"], mp["p_rel_Pa"])
    sd_meas = float(np.sqrt(bc.time_mean(mp["t_s"], p_rel ** 2)))
    f_meas = float(psd["f_Hz"][np.argmax(psd["PSD"])])
    e_meas = bc.time_mean(mv["t_s"], mv["voidage"])
    esd_meas = float(np.sqrt(bc.time_mean(mv["t_s"], (mv["voidage"] - e_meas) ** 2)))

    rows = [
        bc.goal_row("mean bed height (top of the highest particle)", "m", h_meas, top.mean(),
                    top.mean() - h_meas, "within 10 %", abs(top.mean() - h_meas) <= 0.10 * h_meas),
        bc.goal_row("mean bed height (top without the highest 1 % of the particles)", "m", h_meas,
                    top99.mean(), top99.mean() - h_meas, "reported", None),
        bc.goal_row("mean bed height (95 % of the particle volume below)", "m", h_meas, h.mean(),
                    h.mean() - h_meas, "reported", None),
        bc.goal_row("dominant frequency of the pressure at 45 mm", "Hz", f_meas, f_lbdem,
                    f_lbdem - f_meas, f"within 20 % (resolution {f_res:.2g} Hz)",
                    abs(f_lbdem - f_meas) <= 0.20 * f_meas),
        bc.goal_row("standard deviation of the pressure at 45 mm", "Pa", sd_meas, p.std(),
                    p.std() - sd_meas, "reported", None),
        bc.goal_row("mean voidage at 45 mm (middle 10 mm)", "-", e_meas, eps.mean(),
                    eps.mean() - e_meas, "reported", None),
        bc.goal_row("standard deviation of the voidage at 45 mm", "-", esd_meas, eps.std(),
                    eps.std() - esd_meas, "reported", None),
    ]
    print(f"# {a.run}: {t[-1] - t[0]:.3g} s from t = {a.t_from} s, {len(te)} snapshots; "
          f"mean pressure at 45 mm {p.mean():.4g} Pa")
    bc.report(rows, a.csv)
    if a.png:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(1, 4, figsize=(17, 3.4))
        w = min(2.0, t[-1] - t[0])  # the measured series span about 2 s
        m = t >= t[-1] - w
        ax[0].plot(mp["t_s"] - mp["t_s"][0], p_rel, "k-", lw=0.8, label="van Wachem et al.")
        ax[0].plot(t[m] - t[m][0], p[m] - p.mean(), "r-", lw=0.8, label="lbdem")
        ax[0].set_xlabel("t - t0 [s]")
        ax[0].set_ylabel("p - mean, 45 mm [Pa]")
        ax[0].legend(fontsize=7)
        dt = float(np.median(np.diff(t)))
        x = (p - p.mean()) * np.hanning(len(p))
        spec = np.abs(np.fft.rfft(x)) ** 2
        freq = np.fft.rfftfreq(len(p), dt)
        band = (freq > 0.3) & (freq < 10)
        ax[1].plot(psd["f_Hz"], psd["PSD"] / psd["PSD"].max(), "k-", label="measured")
        ax[1].plot(freq[band], spec[band] / spec[band].max(), "r-", lw=0.8, label="lbdem")
        ax[1].set_xlim(0, 10)
        ax[1].set_xlabel("f [Hz]")
        ax[1].set_ylabel("spectrum / its peak")
        ax[2].plot(mh["t_s"] - mh["t_s"][0], mh["h_m"], "k.-", label="measured")
        ax[2].plot(t[m] - t[m][0], h[m], "r-", lw=0.8, label="lbdem, 95 % of the volume")
        mt = te >= te[-1] - w
        ax[2].plot(te[mt] - te[mt][0], top[mt], "b.-", lw=0.8, label="lbdem, highest particle")
        ax[2].legend(fontsize=7)
        ax[2].set_xlabel("t - t0 [s]")
        ax[2].set_ylabel("bed height [m]")
        ax[3].plot(mv["t_s"] - mv["t_s"][0], mv["voidage"], "k-", lw=0.8, label="measured")
        me = te >= te[-1] - w
        ax[3].plot(te[me] - te[me][0], eps[me], "r.-", label="lbdem")
        ax[3].set_xlabel("t - t0 [s]")
        ax[3].set_ylabel("voidage at 45 mm")
        fig.tight_layout()
        bc.save_figure(fig, a.png)


if __name__ == "__main__":
    main()
