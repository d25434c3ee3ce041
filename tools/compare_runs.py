#!/usr/bin/env python3
"""Plot of lbdem-compare-runs' output: one column of several runs overlaid, and their spectra.

usage: /usr/bin/python3 tools/compare_runs.py PREFIX [--png FILE]

Reads PREFIX_stats.csv and PREFIX_spectra.csv (written by lbdem-compare-runs --out PREFIX) and each
run's timeseries.csv (the run_dir column of the stats), and writes PREFIX.png: the time series with
the analysis window shaded and each run's window mean +- standard error drawn over it, and the
one-sided power spectral densities on log axes. Runs that share a label (two runs with the same size
factor are both "l = <size_factor>") are named by their folders. Exit 0 on success, 2 on missing or
unreadable input.
"""
import argparse
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")  # headless machines and study drivers
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.ticker import LogLocator, NullFormatter, ScalarFormatter  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plot_run import read_csv  # noqa: E402  (same partial-line handling as the run plots)
from run_labels import split_runs, unique_labels  # noqa: E402

UNITS = {"_Pa": "Pa", "_Nm": "N m", "_N": "N", "_J": "J", "_W": "W", "_kg": "kg", "_s": "s", "_m": "m",
         "_per_s": "1/s", "_Nms": "N m s", "_rad": "rad", "_m_per_s": "m/s"}


def unit_of(column):
    """The SI unit a column name ends in (torque_Nm -> N m), or '' for none."""
    best = ""
    for suffix, unit in UNITS.items():
        if column.endswith(suffix) and len(suffix) > len(best):
            best = suffix
    return UNITS.get(best, "")


def fail(msg):
    print(f"compare_runs: {msg}", file=sys.stderr)
    sys.exit(2)


def read_rows(path):
    if not os.path.isfile(path):
        fail(f"no {path} (run lbdem-compare-runs --out PREFIX first)")
    with open(path, newline="", encoding="utf-8") as f:
        return list(csv.DictReader(f))


def save(fig, path):
    tmp = path[: -len(".png")] + ".tmp.png" if path.endswith(".png") else path + ".tmp.png"
    fig.savefig(tmp, dpi=120, format="png")
    plt.close(fig)
    os.replace(tmp, path)  # a viewer never sees a half-written PNG
    print(path)


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter,
                                 epilog="\n\n".join(__doc__.split("\n\n")[1:]))
    ap.add_argument("prefix", metavar="PREFIX", help="prefix given to lbdem-compare-runs --out")
    ap.add_argument("--png", help="output picture (default: PREFIX.png)")
    ap.add_argument("--linear", action="store_true", help="linear frequency axis for the spectra")
    args = ap.parse_args(argv[1:])
    stats = read_rows(args.prefix + "_stats.csv")
    spectra = read_rows(args.prefix + "_spectra.csv")
    if not stats:
        fail(f"{args.prefix}_stats.csv has no runs")
    # Each run's spectrum by its place in the table (labels can repeat), then labels made unique:
    # two runs with the same size factor are named by their folders.
    run_spectra = split_runs(spectra, [s["label"] for s in stats],
                             key=lambda r: r["frequency_Hz"])
    labels = unique_labels([s["label"] for s in stats], [s["run_dir"] for s in stats])
    column = stats[0]["column"]
    unit = unit_of(column)
    ulabel = f" [{unit}]" if unit else ""

    fig, (top, bot) = plt.subplots(2, 1, figsize=(10, 8.5), gridspec_kw={"height_ratios": [1, 1]})
    t0 = min(float(s["t_from_s"]) for s in stats)
    t1 = max(float(s["t_to_s"]) for s in stats)
    top.axvspan(t0, t1, color="0.92", zorder=0, label="analysis window")
    for i, s in enumerate(stats):
        color = f"C{i}"
        series = os.path.join(s["run_dir"], "timeseries.csv")
        if not os.path.isfile(series):
            fail(f"no {series}")
        names, data = read_csv(series)
        if column not in names or "time_s" not in names:
            fail(f"{series} has no column {column}; known: {', '.join(names)}")
        t, y = data[:, names.index("time_s")], data[:, names.index(column)]
        mean, err, std = float(s["mean"]), float(s["stderr_mean"]), float(s["std"])
        note = "" if s["plateau"] == "1" else ", no plateau"
        top.plot(t, y, color=color, lw=0.9, alpha=0.85,
                 label=f"{labels[i]}: {mean:.4g} ± {err:.2g} (sd {std:.3g}{note})")
        a, b = float(s["t_from_s"]), float(s["t_to_s"])
        top.hlines(mean, a, b, color=color, lw=2, ls="--")
        top.fill_between([a, b], mean - err, mean + err, color=color, alpha=0.25, lw=0)
    top.set_xlabel("time [s]")
    top.set_ylabel(column + ulabel)
    top.set_title(f"{column}: window mean ± standard error (block averages), sd = fluctuation",
                  fontsize=10)
    top.grid(alpha=0.3)
    top.legend(fontsize=8, loc="best")

    plotted = 0
    for i, s in enumerate(stats):
        rows = run_spectra[i]
        f = np.array([float(r["frequency_Hz"]) for r in rows])
        p = np.array([float(r["psd_per_Hz"]) for r in rows])
        keep = (f > 0) & (p > 0)  # k = 0 holds only what the detrend left; log axes need > 0
        if keep.any():
            bot.plot(f[keep], p[keep], color=f"C{i}", lw=1.2,
                     label=f"{labels[i]} (peak {float(s['peak_frequency_Hz']):.3g} Hz)")
            plotted += 1
    if plotted:
        if not args.linear:
            bot.set_xscale("log")
            # Labels at 1, 2, 5 per decade: a short window spans only a decade or two of bins.
            bot.xaxis.set_major_locator(LogLocator(subs=(1.0, 2.0, 5.0)))
            bot.xaxis.set_major_formatter(ScalarFormatter())
            bot.xaxis.set_minor_formatter(NullFormatter())
        bot.set_yscale("log")
        bot.legend(fontsize=8)
    else:
        bot.text(0.5, 0.5, "no positive spectral values", ha="center", va="center",
                 transform=bot.transAxes)
    bot.set_xlabel("frequency [Hz]")
    squared = f"({unit})²" if " " in unit or "/" in unit else f"{unit}²"
    bot.set_ylabel(f"PSD [{squared}/Hz]" if unit else "PSD [1/Hz]")
    fs = sorted({float(r["frequency_Hz"]) for r in run_spectra[0]})
    res = f" (resolution {fs[1] - fs[0]:.3g} Hz)" if len(fs) > 1 else ""
    bot.set_title(f"one-sided PSD of the detrended, Hann-windowed signal{res}", fontsize=10)
    bot.grid(alpha=0.3, which="both")
    fig.tight_layout()
    save(fig, args.png or args.prefix + ".png")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
