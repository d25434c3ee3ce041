#!/usr/bin/env python3
"""OpenMP thread scaling of lbdem on fixed cases: speed-up, parallel efficiency,
bitwise equality across thread counts, and where the time goes.

usage: ./lbdem bench scaling [--threads 1,2,...] [--case NAME]... [--out DIR]
       (called as /usr/bin/python3 bench/scaling.py BUILD_DIR [options])

Cases (default: all):
  dem_bed        the settled Hertz-Mindlin bed of bench/peers, N = 20,000, 2,000 timed steps
                 (lbdem-bench-dem): particle-steps/s
  lbm_box        the periodic Taylor-Green box, 64^3, 100 steps (lbdem-bench-lbm): MLUPS
  fluidized_bed  the default preset to 0.2 s (pour, ramp, fluidized): wall time
  rheometer      the default preset to 0.2 s (settling, then the impeller from 0.15 s): wall time
  jet_mill       the default preset to 3 ms (gas, feed, coupling): wall time

Each case runs once per thread count (default: 1 up to the cores present). The benchmarks print a
hash of their final state; the scenario runs are compared data set by data set in checkpoint.h5
(h5py, bytes), so a result that changes with the thread count is reported, not hidden. The
scenario runs' phase tables (end of log.txt) are plotted as well. Writes into DIR (default
$TMPDIR/lbdem-bench/scaling-STAMP): scaling.csv, scaling.png, phases.csv, phases.png. Exit 0;
1 if a result differed between thread counts or a run failed (the message says which); 2 on bad
input.
"""
import argparse
import csv
import os
import re
import subprocess
import sys
import time

import matplotlib

matplotlib.use("Agg")  # headless
import h5py  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

CASES = ["dem_bed", "lbm_box", "fluidized_bed", "rheometer", "jet_mill"]
SCENARIO_END = {"fluidized_bed": "0.2", "rheometer": "0.2", "jet_mill": "0.003"}


def fail(msg, code=2):
    print(f"lbdem bench scaling: {msg}", file=sys.stderr)
    sys.exit(code)


def run(cmd, env=None):
    t0 = time.monotonic()
    p = subprocess.run(cmd, capture_output=True, text=True, env=env)
    if p.returncode != 0:
        fail(f"'{' '.join(cmd)}' failed (exit {p.returncode}): {p.stderr.strip()[-400:]}", 1)
    return p.stdout, time.monotonic() - t0


def bench_case(build, case, threads, work):
    """(throughput, unit, seconds, state) of a benchmark executable's run on `threads`."""
    if case == "dem_bed":
        out, _ = run([f"{build}/bin/lbdem-bench-dem", "--n", "20000", "--steps", "2000",
                      "--cache", work, "--threads", str(threads)])
        m = re.search(r"(\S+)\s+particle-steps/s\s+loop_s=(\S+).*state_hash=(\w+)", out)
        if not m:
            fail(f"unexpected output of lbdem-bench-dem: {out.strip()[-300:]}", 1)
        return float(m.group(1)), "particle-steps/s", float(m.group(2)), m.group(3)
    out, secs = run([f"{build}/bin/lbdem-bench-lbm", "--n", "64", "--steps", "100",
                     "--threads", str(threads)])
    m = re.search(r"([\d.]+) MLUPS.*state_hash=(\w+)", out)
    if not m:
        fail(f"unexpected output of lbdem-bench-lbm: {out.strip()[-300:]}", 1)
    return float(m.group(1)), "MLUPS", 64**3 * 100 / float(m.group(1)) / 1e6, m.group(2)


def checkpoint_bytes(path):
    """Every data set of a checkpoint, as bytes, by name."""
    sets = {}
    with h5py.File(path, "r") as f:
        f.visititems(lambda n, o: sets.__setitem__(n, o[()].tobytes())
                     if isinstance(o, h5py.Dataset) else None)
    return sets


def phases_of(log):
    """The phase table at the end of a run's log.txt: {phase: seconds}."""
    table, on = {}, False
    for line in open(log, encoding="utf-8"):
        if line.startswith("wall time by phase"):
            on, table = True, {}
            continue
        m = re.match(r"  (.+?)\s+(-?[\d.]+) s\s+(-?[\d.]+) %$", line.rstrip("\n")) if on else None
        if m:
            table[m.group(1)] = float(m.group(2))
        elif on:
            on = False
    return table


def scenario_case(build, case, threads, work):
    out = os.path.join(work, f"{case}_t{threads}")
    subprocess.run(["rm", "-rf", out], check=True)
    cmd = [f"{build}/bin/lbdem-cli", "run", case, "--threads", str(threads), "--out", out,
           "--no-plots", "--set", f"run.end_time={SCENARIO_END[case]}"]
    run(cmd)
    log = os.path.join(out, "log.txt")
    wall = float(re.search(r"^wall time ([\d.e+-]+) s", open(log).read(), re.M).group(1))
    sim = float(SCENARIO_END[case])
    return sim / wall, "simulated s per wall s", wall, checkpoint_bytes(
        os.path.join(out, "checkpoint.h5")), phases_of(log)


def save(fig, path):
    tmp = path + ".tmp"
    fig.savefig(tmp, dpi=110, format="png")
    plt.close(fig)
    os.replace(tmp, path)


def plot_phases(phase_rows, path):
    """The phase timers' shares per case and thread count as stacked bars (phases.csv's rows)."""
    keys = list(dict.fromkeys((p["case"], int(p["threads"])) for p in phase_rows))
    names = list(dict.fromkeys(p["phase"] for p in phase_rows))
    # One line per word of the case's name under each bar, so that neighbours do not touch.
    labels = [c.replace("_", "\n") + f"\n{t} thr" for c, t in keys]
    fig, ax = plt.subplots(figsize=(max(6, 1.1 * len(keys)) + 3, 5))
    bottom = np.zeros(len(keys))
    for j, name in enumerate(names):
        vals = []
        for c, t in keys:
            mine = [p for p in phase_rows if p["case"] == c and int(p["threads"]) == t]
            tot = sum(float(p["seconds"]) for p in mine)
            s = sum(float(p["seconds"]) for p in mine if p["phase"] == name)
            vals.append(100 * s / tot if tot > 0 else 0)
        ax.bar(range(len(keys)), vals, bottom=bottom, label=name, color=plt.cm.tab20(j % 20))
        bottom += np.array(vals)
    ax.set_xticks(range(len(keys)), labels, fontsize=9)
    ax.set_ylabel("share of wall time [%]")
    ax.legend(fontsize=7, bbox_to_anchor=(1.01, 1), loc="upper left")
    fig.suptitle("Where the time goes (phase timers, end of each run's log.txt)")
    fig.tight_layout()
    save(fig, path)


def main():
    ap = argparse.ArgumentParser(description="lbdem OpenMP thread scaling")
    ap.add_argument("build")
    ap.add_argument("--threads", default=",".join(str(t) for t in range(1, (os.cpu_count() or 1) + 1)))
    ap.add_argument("--case", action="append", choices=CASES)
    ap.add_argument("--out")
    ap.add_argument("--replot-phases", metavar="CSV",
                    help="draw phases.png next to an existing phases.csv and stop (build unused)")
    a = ap.parse_args()
    if a.replot_phases:
        with open(a.replot_phases) as f:
            plot_phases(list(csv.DictReader(f)),
                        os.path.join(os.path.dirname(a.replot_phases) or ".", "phases.png"))
        return 0
    try:
        threads = sorted({int(t) for t in a.threads.split(",")})
    except ValueError:
        fail(f"--threads '{a.threads}': give a comma-separated list of counts, e.g. 1,2")
    if not threads or threads[0] < 1:
        fail(f"--threads '{a.threads}': counts must be >= 1")
    cases = a.case or CASES
    out = a.out or os.path.join(os.environ.get("TMPDIR", "/tmp"), "lbdem-bench",
                                "scaling-" + time.strftime("%Y%m%d_%H%M%S"))
    os.makedirs(out, exist_ok=True)
    rows, phase_rows, differs = [], [], False
    for case in cases:
        base = None
        for t in threads:
            if case in ("dem_bed", "lbm_box"):
                speed, unit, secs, state = bench_case(a.build, case, t, out)
                phases = {}
            else:
                speed, unit, secs, state, phases = scenario_case(a.build, case, t, out)
            if base is None:
                base = (speed, state)
            same = state == base[1]
            if not same:
                differs = True
                bad = ([k for k in sorted(set(state) | set(base[1]))
                        if state.get(k) != base[1].get(k)]
                       if isinstance(state, dict) else ["state_hash"])
                print(f"{case}: {t} threads differ from {threads[0]} in {', '.join(bad[:5])}",
                      file=sys.stderr)
            speedup = speed / base[0]
            rows.append({"case": case, "threads": t, "throughput": f"{speed:.6g}", "unit": unit,
                         "seconds": f"{secs:.4g}", "speedup": f"{speedup:.4g}",
                         "efficiency": f"{speedup * threads[0] / t:.4g}",
                         "bitwise_same_as_first": "yes" if same else "NO"})
            print(f"{case:14s} {t:3d} threads  {speed:12.5g} {unit:24s} speed-up {speedup:6.3f}  "
                  f"efficiency {speedup * threads[0] / t:6.3f}  bitwise {'same' if same else 'DIFFERENT'}",
                  flush=True)
            for name, s in phases.items():
                phase_rows.append({"case": case, "threads": t, "phase": name, "seconds": s})
    with open(os.path.join(out, "scaling.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    if phase_rows:
        with open(os.path.join(out, "phases.csv"), "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=list(phase_rows[0].keys()))
            w.writeheader()
            w.writerows(phase_rows)

    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4.2))
    for i, case in enumerate(cases):
        r = [x for x in rows if x["case"] == case]
        t = [x["threads"] for x in r]
        ax1.plot(t, [float(x["speedup"]) for x in r], "o-", color=f"C{i}", label=case)
        ax2.plot(t, [float(x["efficiency"]) for x in r], "o-", color=f"C{i}", label=case)
    ax1.plot(threads, [t / threads[0] for t in threads], "k--", lw=0.8, label="ideal")
    ax1.set_ylabel(f"speed-up over {threads[0]} thread(s)")
    ax2.set_ylabel("parallel efficiency")
    ax2.set_ylim(0, 1.1)
    for ax in (ax1, ax2):
        ax.set_xlabel("OpenMP threads")
        ax.set_xticks(threads)
        ax.legend(fontsize=8)
    fig.suptitle(f"lbdem thread scaling ({os.cpu_count()} cores)")
    fig.tight_layout()
    save(fig, os.path.join(out, "scaling.png"))

    if phase_rows:
        plot_phases(phase_rows, os.path.join(out, "phases.png"))
    print(f"scaling table: {out}/scaling.csv, plot: {out}/scaling.png"
          + (f", phases: {out}/phases.png" if phase_rows else ""))
    return 1 if differs else 0


if __name__ == "__main__":
    sys.exit(main())
