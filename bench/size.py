#!/usr/bin/env python3
"""How cost and memory grow with problem size: throughput and resident bytes per
particle and per cell, DEM from 10^4 to 10^6 particles, LBM from 32^3 to 256^3 cells.

usage: ./lbdem bench size [--dem-n 10000,...] [--lbm-n 32,...] [--threads T] [--settle S]
                          [--dem-steps K] [--lbm-steps K] [--precision double,single] [--out DIR]
       (called as /usr/bin/python3 bench/size.py BUILD_DIR [options]; --dem-n '' or --lbm-n ''
       leaves that part out)

DEM: the Hertz-Mindlin bed of bench/peers (lbdem-bench-dem), 8 layers deep like its N = 20,000
case, with the footprint grown to the size asked (side S = round(sqrt(N / 8)), N = 8 S^2: a bed of
the same depth, so every size has about the same contacts per particle; a 50 x 50 footprint made
N = 10^6 a column 400 layers high, still falling after the settling steps, Z = 0.7), settled for
S steps of 1e-5 s (default 3,000: the 8 layers close their 50 um gaps in 9 ms; the contact number
Z of each size is in the table), then K timed steps of 1e-6 s.
LBM: the coupled gas kernel (lbdem-bench-lbm --porous: TRT, Guo-Zhao porous form, per-cell force
and velocity sums) on the periodic Taylor-Green box, K timed steps, in each precision asked
(default both).

Each size runs in a process of its own (a DEM bed is settled and cached by a process before the
measured one). Memory is the resident set right after the timed loop less that of the program
before it built anything (/proc/self/status, core/memory.hpp), divided by the particles or
interior cells; the peak (set-up temporaries included, less the same base) is in the CSV too. For
the LBM the table sets it beside what the solver's fields need: 19 populations (AA pattern, one
lattice), 3 of force, the porosity (8 B: always double), its reciprocal and drag, 3 of velocity
sums, at 8 B each in double and 4 B in single, and a 1 B flag per stored cell, stored cells being
(N + 2)^3 with the ghost layer. At small sizes the fixed cost of the process (OpenMP thread stacks, about 10 MB)
dominates.
Writes DIR/size.csv (after every size) and DIR/size.png (default DIR:
$TMPDIR/lbdem-bench/size-STAMP). Exit 0; 1 if a run failed (the others stay in the table); 2 on
bad input.
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
import matplotlib.pyplot as plt  # noqa: E402

# Per stored cell, see the docstring: populations, force, porosity, 1/eps and alpha, sums, flag.
LBM_FIELD_BYTES = {p: 19 * b + 3 * b + 8 + 2 * b + 3 * b + 1
                   for p, b in (("double", 8), ("single", 4))}


def fail(msg, code=2):
    print(f"lbdem bench size: {msg}", file=sys.stderr)
    sys.exit(code)


def sizes(text, name, check):
    if text.strip() == "":
        return []
    try:
        vals = [int(v) for v in text.split(",")]
    except ValueError:
        fail(f"{name} '{text}': give a comma-separated list of integers")
    for v in vals:
        msg = check(v)
        if msg:
            fail(f"{name} {v}: {msg}")
    return vals


class RunFailed(Exception):
    pass


def run(cmd):
    t0 = time.monotonic()
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode != 0:
        raise RunFailed(f"'{' '.join(cmd)}' failed (exit {p.returncode}): "
                        f"{p.stderr.strip()[-400:]}")
    return p.stdout, time.monotonic() - t0


def measure(label, cmds, pattern, failed):
    """Runs cmds in turn; from the last one's output (text, wall s, resident and peak bytes, the
    match of pattern), or None with the reason on stderr and label added to failed."""
    try:
        for cmd in cmds:
            text, wall = run(cmd)
        used, peak = memory(text)
    except (RunFailed, ValueError) as e:
        print(f"{label}: {e}", file=sys.stderr)
        failed.append(label)
        return None
    m = re.search(pattern, text)
    if not m:
        print(f"{label}: unexpected output: {text.strip()[-300:]}", file=sys.stderr)
        failed.append(label)
        return None
    return text, wall, used, peak, m


FIELDS = ["part", "precision", "size", "unit", "threads", "throughput", "throughput_unit",
          "contacts_per_particle", "bytes_per_unit", "expected_bytes_per_unit",
          "measured_over_expected", "resident_bytes", "peak_bytes", "wall_s"]


def save_csv(out, rows):
    """size.csv as it stands (rewritten after every size: a later failure loses nothing)."""
    tmp = os.path.join(out, "size.csv.tmp")
    with open(tmp, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=FIELDS)
        w.writeheader()
        w.writerows(rows)
    os.replace(tmp, os.path.join(out, "size.csv"))


def memory(out):
    """(resident bytes less the program's own before it built anything, peak likewise)."""
    m = {}
    for k in ("rss_bytes", "base_rss_bytes", "peak_bytes"):
        hit = re.search(rf"\b{k}=(\d+)", out)
        if not hit:
            raise ValueError(f"no {k}= in: {out.strip()[-300:]}")
        m[k] = int(hit.group(1))
    return m["rss_bytes"] - m["base_rss_bytes"], m["peak_bytes"] - m["base_rss_bytes"]


def main():
    ap = argparse.ArgumentParser(description="lbdem cost and memory against problem size")
    ap.add_argument("build")
    ap.add_argument("--dem-n", default="10000,30000,100000,300000,1000000")
    ap.add_argument("--lbm-n", default="32,64,128,256")
    ap.add_argument("--threads", type=int, default=os.cpu_count() or 1)
    ap.add_argument("--settle", type=int, default=3000)
    ap.add_argument("--dem-steps", type=int, default=500)
    ap.add_argument("--lbm-steps", type=int, default=20)
    ap.add_argument("--precision", default="double,single")
    ap.add_argument("--out")
    a = ap.parse_args()
    dem_n = sizes(a.dem_n, "--dem-n", lambda v: None if 32 <= v <= 10**8 else
                  "give a particle count from 32 to 1e8 (it is rounded to 8 layers of S x S)")
    lbm_n = sizes(a.lbm_n, "--lbm-n", lambda v: None if 8 <= v <= 512 else
                  "give a cube edge from 8 to 512 cells")
    for name, v in (("--threads", a.threads), ("--settle", a.settle),
                    ("--dem-steps", a.dem_steps), ("--lbm-steps", a.lbm_steps)):
        if v < 1:
            fail(f"{name} {v}: must be >= 1")
    precisions = [p for p in a.precision.split(",") if p]
    if not precisions or any(p not in LBM_FIELD_BYTES for p in precisions):
        fail(f"--precision '{a.precision}': give double, single or double,single")
    if not dem_n and not lbm_n:
        fail("nothing to run: --dem-n and --lbm-n are both empty")
    out = a.out or os.path.join(os.environ.get("TMPDIR", "/tmp"), "lbdem-bench",
                                "size-" + time.strftime("%Y%m%d_%H%M%S"))
    os.makedirs(out, exist_ok=True)
    cache = os.path.join(out, "beds")
    rows = []
    failed = []
    for asked in dem_n:
        side = max(2, round((asked / 8) ** 0.5))
        n = 8 * side * side
        cmd = [f"{a.build}/bin/lbdem-bench-dem", "--n", str(n), "--side", str(side),
               "--threads", str(a.threads), "--settle", str(a.settle), "--cache", cache]
        # Settle (and cache) the bed in a process of its own, so that the measured one holds only
        # the timed solver: memory the allocator keeps after the settling run would otherwise
        # count as the particles'.
        got = measure(f"DEM N={n}", [cmd + ["--steps", "1"], cmd + ["--steps", str(a.dem_steps)]],
                      r"Z=(\S+?)\s+\d+\s+(\S+)\s+particle-steps/s", failed)
        if not got:
            continue
        text, wall, used, peak, m = got
        rows.append({"part": "dem", "precision": "", "size": n, "unit": "particle", "threads": a.threads,
                     "throughput": float(m.group(2)), "throughput_unit": "particle-steps/s",
                     "contacts_per_particle": float(m.group(1)), "bytes_per_unit": used / n,
                     "expected_bytes_per_unit": "", "measured_over_expected": "",
                     "resident_bytes": used, "peak_bytes": peak, "wall_s": round(wall, 1)})
        print(f"DEM N={n:>9,}: {float(m.group(2)):10.4g} particle-steps/s  Z={m.group(1)}  "
              f"{used / n:8.0f} B/particle  (peak {peak / 2**30:.2f} GiB)", flush=True)
        save_csv(out, rows)
    for prec, n in [(p, n) for p in precisions for n in lbm_n]:
        got = measure(f"LBM {n}^3 {prec}",
                      [[f"{a.build}/bin/lbdem-bench-lbm", "--porous", "--n", str(n),
                        "--threads", str(a.threads), "--steps", str(a.lbm_steps),
                        "--warmup", "2", "--precision", prec]], r"([\d.]+) MLUPS", failed)
        if not got:
            continue
        text, wall, used, peak, m = got
        cells = n**3
        expected = LBM_FIELD_BYTES[prec] * (n + 2) ** 3 / cells
        rows.append({"part": "lbm", "precision": prec, "size": cells, "unit": "cell",
                     "threads": a.threads,
                     "throughput": float(m.group(1)) * 1e6, "throughput_unit": "cell-updates/s",
                     "contacts_per_particle": "", "bytes_per_unit": used / cells,
                     "expected_bytes_per_unit": expected,
                     "measured_over_expected": used / cells / expected,
                     "resident_bytes": used, "peak_bytes": peak, "wall_s": round(wall, 1)})
        print(f"LBM {n:>3}^3 {prec:6}: {float(m.group(1)):8.1f} MLUPS  {used / cells:6.1f} B/cell "
              f"(fields {expected:.1f}: {used / cells / expected:.3f})  "
              f"(peak {peak / 2**30:.2f} GiB)", flush=True)
        save_csv(out, rows)
    if not rows:
        print(f"lbdem bench size: every run failed ({', '.join(failed)})", file=sys.stderr)
        return 1

    fig, axes = plt.subplots(2, 2, figsize=(10, 7))
    for col, (part, label, scale, unit) in enumerate(
            (("dem", "particles N", 1, "particle-steps/s"),
             ("lbm", "cells N^3", 1e-6, "MLUPS"))):
        r = [x for x in rows if x["part"] == part]
        ax_t, ax_m = axes[0][col], axes[1][col]
        if not r:
            ax_t.set_visible(False)
            ax_m.set_visible(False)
            continue
        for i, prec in enumerate(sorted({x["precision"] for x in r})):
            rp = [x for x in r if x["precision"] == prec]
            s = [x["size"] for x in rp]
            tag = f", {prec}" if prec else ""
            ax_t.semilogx(s, [x["throughput"] * scale for x in rp], "o-", color=f"C{i}",
                          label=prec or None)
            ax_m.semilogx(s, [x["bytes_per_unit"] for x in rp], "o-", color=f"C{i}",
                          label="resident, measured" + tag)
            if part == "lbm":
                ax_m.semilogx(s, [x["expected_bytes_per_unit"] for x in rp], "--",
                              color=f"C{i}", label="solver fields" + tag)
        if part == "lbm":
            ax_t.legend(fontsize=8)
        ax_t.set_ylabel(f"{unit} ({a.threads} thread(s))")
        ax_t.set_ylim(bottom=0)
        ax_m.set_ylabel(f"bytes per {r[0]['unit']}")
        ax_m.set_ylim(bottom=0)
        ax_m.legend(fontsize=8)
        for ax in (ax_t, ax_m):
            ax.set_xlabel(label)
            ax.grid(alpha=0.3)
    fig.suptitle("lbdem cost and memory against size (DEM bed; coupled LBM kernel)")
    fig.tight_layout()
    tmp = os.path.join(out, "size.png.tmp")
    fig.savefig(tmp, dpi=110, format="png")
    os.replace(tmp, os.path.join(out, "size.png"))
    print(f"size table: {out}/size.csv, plot: {out}/size.png")
    if failed:
        print(f"lbdem bench size: failed: {', '.join(failed)} (the others are in the table)",
              file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
