"""What the validation comparisons of bubbling beds share: a run's time series, the dominant
frequency of a signal, the scatter of a measured profile, and the goals table that
`./lbdem study validation` gathers from each case (mueller_bed.py, vanwachem_bed.py).

Goals table (goals.csv in the run folder): one row per compared quantity,
    quantity,unit,measured,lbdem,difference,goal,within_goal
where difference is lbdem - measured (or the RMS difference of two profiles), goal says what is
asked of it in words, and within_goal is yes, no or - (reported, no goal).
"""
import csv
import math
import os

import numpy as np

DATA = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "results", "validation",
                    "data")
GOAL_HEADER = "quantity,unit,measured,lbdem,difference,goal,within_goal"


def read_csv_data(name):
    """The columns of a data file of results/validation/data as a dict of arrays ('#' lines are
    the file's provenance and are skipped)."""
    with open(os.path.join(DATA, name)) as f:
        rows = list(csv.reader(line for line in f if not line.startswith("#")))
    head = rows[0]
    cols = np.array([[float(v) for v in r] for r in rows[1:] if r], dtype=float)
    return {h: cols[:, k] for k, h in enumerate(head)}


def read_series(run, columns, t_from, t_to=math.inf):
    """time_s and the named columns of RUN/timeseries.csv from t_from to t_to."""
    with open(os.path.join(run, "timeseries.csv")) as f:
        rows = list(csv.DictReader(f))
    t = np.array([float(r["time_s"]) for r in rows])
    keep = (t >= t_from) & (t <= t_to)
    out = {"time_s": t[keep]}
    for c in columns:
        out[c] = np.array([float(r[c]) for r in rows])[keep]
    return out


def time_mean(t, v):
    """Mean over time of samples that need not be evenly spaced (trapezoid rule): digitised
    curves crowd their points where the curve bends."""
    trapezoid = getattr(np, "trapezoid", None) or np.trapz  # numpy 2 renamed it
    return float(trapezoid(v, t) / (t[-1] - t[0]))


def dominant_frequency(t, v, f_lo=0.5, f_hi=20.0):
    """The frequency of the largest peak of the Hann-windowed periodogram of v (evenly sampled at
    times t), smoothed over three bins, between f_lo and f_hi; its resolution is 1/(t[-1]-t[0])."""
    dt = float(np.median(np.diff(t)))
    x = (v - v.mean()) * np.hanning(len(v))
    spec = np.abs(np.fft.rfft(x)) ** 2
    spec = np.convolve(spec, np.ones(3) / 3, mode="same")
    freq = np.fft.rfftfreq(len(v), dt)
    band = (freq >= f_lo) & (freq <= f_hi)
    return float(freq[band][np.argmax(spec[band])]), float(1.0 / (t[-1] - t[0]))


def mirror_scatter(x, v, width):
    """The scatter of a measured profile across a bed that is symmetric about its middle: the
    RMS of half the difference between the profile and its mirror image, v(x) against
    v(width - x), over the points whose mirror lies within the data. Two readings of one value
    with standard deviation s differ by sqrt(2) s on average, hence the division by sqrt(2)."""
    order = np.argsort(x)
    xs, vs = x[order], v[order]
    mirrored = width - xs
    inside = (mirrored >= xs[0]) & (mirrored <= xs[-1])
    if inside.sum() < 3:
        return float("nan")
    d = vs[inside] - np.interp(mirrored[inside], xs, vs)
    return float(np.sqrt(np.mean(d * d)) / np.sqrt(2.0))


def cap_volume(r, h):
    """Volume of a sphere of radius r below a plane at height h above its lowest point (0..2r)."""
    h = np.clip(h, 0.0, 2 * r)
    return math.pi * h * h * (3 * r - h) / 3.0


def slab_volume(z, r, lo, hi):
    """Volume of spheres (centres z, radius r) between the planes lo < hi (exact along z)."""
    return cap_volume(r, hi - (z - r)) - cap_volume(r, lo - (z - r))


def bed_top(z, r, quantile=1.0):
    """The top of a bed from its particles (centres z, radii r): the given quantile of the
    particles' tops z + r (1.0: the highest particle, which one splashed particle sets; 0.99
    leaves out the highest 1 %)."""
    return float(np.quantile(z + r, quantile))


def snapshots(run, t_from, t_to=math.inf):
    """(time, position, velocity, radius) of each particle snapshot of RUN/particles.h5 from
    t_from to t_to, in SI units."""
    import h5py
    with h5py.File(os.path.join(run, "particles.h5"), "r") as f:
        snaps = f["snapshots"]
        for key in sorted(snaps.keys()):
            t = float(f["time_s"][int(key)])
            if t < t_from or t > t_to:
                continue
            s = snaps[key]
            yield t, s["position_m"][()], s["velocity_m_per_s"][()], s["radius_m"][()]


def goal_row(quantity, unit, measured, lbdem, difference, goal, within):
    """One row of the goals table; within: True, False or None (reported, no goal)."""
    flag = "-" if within is None else ("yes" if within else "no")
    return [quantity, unit, f"{measured:.4g}", f"{lbdem:.4g}", f"{difference:.4g}", goal, flag]


def report(rows, csv_path=None):
    """Prints the goals table and, with csv_path, writes it (write_goals)."""
    print(GOAL_HEADER)
    for r in rows:
        print(",".join(r))
    if csv_path:
        write_goals(csv_path, rows)


def save_figure(fig, path):
    """Saves a matplotlib figure atomically (temp + rename)."""
    fig.savefig(path + ".tmp.png", dpi=110)
    os.replace(path + ".tmp.png", path)


def write_goals(path, rows):
    """Writes the goals table atomically (temp + rename)."""
    with open(path + ".tmp", "w") as f:
        f.write(GOAL_HEADER + "\n")
        w = csv.writer(f, lineterminator="\n")
        for r in rows:
            w.writerow(r)
    os.replace(path + ".tmp", path)
