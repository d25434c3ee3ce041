#!/usr/bin/env python3
"""Each scenario's output as ParaView reads it: a tiny run of box, fluidized_bed, jet_mill and
rheometer, then ParaView's Python (pvpython, Debian's python3-paraview; paraview_probe.py) opens
particles.xdmf and fluid.xdmf with its default reader, and this script checks what it made against
the HDF5 files: point and cell counts, array names and values, the gas grid's extent, and the
time values of both files and of ParaView's time keeper.

ctest runs it as `python3 test_paraview_outputs.py LBDEM_CLI` with the configured python3 (numpy,
h5py); without pvpython on PATH it prints why and exits 77, which ctest reports as skipped."""
import json
import os
import shutil
import subprocess
import sys
import tempfile

import h5py
import numpy as np

SKIP = 77
# Tiny runs: a few ms of simulated time each, at least three snapshots (the start, one between,
# the end).
RUNS = {
    "box": "run box --set fill[0].count=150 --set 'fill[0].lo=[0.0,0.0,0.0]'"
           " --set 'fill[0].hi=[0.06,0.06,0.03]' --set run.end_time=0.004"
           " --set output.snapshot_interval=0.002",
    "fluidized_bed": "run fluidized_bed --set run.end_time=0.002"
                     " --set output.snapshot_interval=0.001",
    "jet_mill": "run jet_mill --set run.end_time=2e-4 --set output.snapshot_interval=1e-4",
    "rheometer": "run rheometer --set coarse_grain.size_factor=4 --set run.end_time=0.004"
                 " --set output.snapshot_interval=0.002",
}
PARTICLE_ARRAYS = {"radius_m": 1, "velocity_m_per_s": 3, "angular_velocity_rad_per_s": 3,
                   "force_N": 3, "id": 1, "material": 1, "coordination_number": 1}
GAS_ARRAYS = {"velocity_m_per_s": 3, "pressure_Pa": 1, "porosity": 1, "solid": 1}
VTK_VERTEX, VTK_POLY_VERTEX = 1, 2

failures = []


def check(what, ok):
    if not ok:
        failures.append(what)
    return ok


def close(a, b, rel):
    return abs(a - b) <= rel * max(abs(a), abs(b))


def check_particles(name, run, out, seen, times):
    check(f"{name}: particles.xdmf opens with Xdmf3ReaderS, not {seen['reader']}",
          seen["reader"] == "Xdmf3ReaderS")
    check(f"{name}: particle times {seen['times']} != particles.h5 {times}",
          seen["times"] == times)
    check(f"{name}: {len(seen['steps'])} particle steps", len(seen["steps"]) == len(times))
    for k, (t, step) in enumerate(zip(times, seen["steps"])):
        with h5py.File(os.path.join(run, f"snapshots/particles_{k:06d}.h5"), "r") as f:
            n = f["position_m"].shape[0]
        where = f"{name}: particles at t = {t!r}"
        check(f"{where}: data time {step['data_time']!r}", step["data_time"] == t)
        # One vertex cell per particle: what the Surface and Points representations draw.
        check(f"{where}: {step['points']} points, {step['cells']} cells for {n} particles",
              step["points"] == n and step["cells"] == n)
        if n:
            check(f"{where}: cell types {step['cell_types']}",
                  set(step["cell_types"]) <= {VTK_VERTEX, VTK_POLY_VERTEX})
            check(f"{where}: point arrays {step['point_arrays']}",
                  step["point_arrays"] == PARTICLE_ARRAYS)
    # The last snapshot's values as ParaView holds them: the datasets, bit for bit.
    k = len(times) - 1
    got = np.load(os.path.join(out, f"{name}_particles.npz"))
    with h5py.File(os.path.join(run, f"snapshots/particles_{k:06d}.h5"), "r") as f:
        check(f"{name}: no particles at the end", f["position_m"].shape[0] > 0)
        check(f"{name}: particle points differ from position_m",
              "points" in got and np.array_equal(got["points"], f["position_m"][...]))
        for a in PARTICLE_ARRAYS:
            check(f"{name}: particle array {a} differs from the snapshot's",
                  "point:" + a in got and np.array_equal(got["point:" + a], f[a][...]))
        n = f["position_m"].shape[0]
        coordination = f["coordination_number"][...]
        force = f["force_N"][...]
    # The run's last row and last snapshot are both at its end: each touching pair counted once in
    # the row's contacts_pp, and once at each of its two particles in the snapshot.
    with open(os.path.join(run, "timeseries.csv")) as f:
        header, *rows = [line.strip().split(",") for line in f if line.strip()]
    last = dict(zip(header, rows[-1]))
    # (timeseries.csv prints 9 significant digits: within 5e-9 relative of the time.)
    check(f"{name}: last row at t = {last['time_s']}, last snapshot at {times[-1]!r}",
          abs(float(last["time_s"]) - times[-1]) <= 1e-8 * times[-1])
    check(f"{name}: coordination numbers sum to {coordination.sum()}, twice contacts_pp is "
          f"{2 * int(last['contacts_pp'])}", coordination.sum() == 2 * int(last["contacts_pp"]))
    check(f"{name}: no force on any particle at the end", n == 0 or np.any(force != 0))


def check_gas(name, run, out, seen, times, expect_solid):
    check(f"{name}: fluid.xdmf opens with Xdmf3ReaderS, not {seen['reader']}",
          seen["reader"] == "Xdmf3ReaderS")
    # The same time values as the particles, to the last bit: one time step in ParaView.
    check(f"{name}: gas times {seen['times']} != particle times {times}", seen["times"] == times)
    with h5py.File(os.path.join(run, "fluid.h5"), "r") as f:
        cells = [int(c) for c in f["grid/cells"][...]]
        lo = f["grid/lower_corner_m"][...]
        dx = float(f["grid/spacing_m"][0])
        centre = f["grid/origin_m"][...]
    # Bounds: VTK's origin + n spacing and fluid.h5's corner + dx/2, a product and a sum each in
    # double precision, against the same in numpy: a few ulp apart.
    rel = 1e-13
    for a in range(3):
        check(f"{name}: first cell centre {centre[a]} is not the corner + dx/2",
              close(centre[a], lo[a] + dx / 2, rel) or abs(centre[a]) < rel * dx)
    n_cells = cells[0] * cells[1] * cells[2]
    n_nodes = (cells[0] + 1) * (cells[1] + 1) * (cells[2] + 1)
    check(f"{name}: {len(seen['steps'])} gas steps", len(seen["steps"]) == len(times))
    for t, step in zip(times, seen["steps"]):
        where = f"{name}: gas at t = {t!r}"
        check(f"{where}: data time {step['data_time']!r}", step["data_time"] == t)
        check(f"{where}: {step['cells']} cells, {step['points']} points for cells {cells}",
              step["cells"] == n_cells and step["points"] == n_nodes)
        check(f"{where}: cell arrays {step['cell_arrays']}", step["cell_arrays"] == GAS_ARRAYS)
        check(f"{where}: point arrays {step['point_arrays']}", step["point_arrays"] == {})
        b = step["bounds"]
        for a in range(3):
            hi = lo[a] + cells[a] * dx
            check(f"{where}: bounds {b[2 * a:2 * a + 2]} on axis {a}, the lattice [{lo[a]}, {hi}]",
                  (close(b[2 * a], lo[a], rel) or abs(lo[a]) < rel * dx)
                  and (close(b[2 * a + 1], hi, rel) or abs(hi) < rel * dx))
    k = len(times) - 1
    got = np.load(os.path.join(out, f"{name}_fluid.npz"))
    with h5py.File(os.path.join(run, f"snapshots/fluid_{k:06d}.h5"), "r") as f:
        for a, comps in GAS_ARRAYS.items():
            want = f[a][...].reshape((n_cells, comps) if comps > 1 else (n_cells,))
            check(f"{name}: gas array {a} differs from the snapshot's (order z, y, x)",
                  np.array_equal(got["cell:" + a], want))
        solid, eps = f["solid"][...], f["porosity"][...]
    check(f"{name}: {int(solid.sum())} solid cells", (solid.sum() > 0) == expect_solid)
    check(f"{name}: a solid cell with porosity", np.all(eps[solid == 1] == 0))


def main():
    cli = sys.argv[1]
    pvpython = shutil.which("pvpython")
    if not pvpython:
        print("skipped: pvpython not found (Debian package python3-paraview)")
        return SKIP
    with tempfile.TemporaryDirectory(prefix="lbdem_paraview_") as tmp:
        runs = {}
        for name, args in RUNS.items():
            runs[name] = os.path.join(tmp, name)
            r = subprocess.run(f"{cli} {args} --threads 1 --no-plots --out {runs[name]}",
                               shell=True, capture_output=True, text=True)
            if r.returncode != 0:
                print(f"{name}: lbdem-cli exited {r.returncode}:\n{r.stderr}")
                return 1
        probe = os.path.join(os.path.dirname(os.path.abspath(__file__)), "paraview_probe.py")
        r = subprocess.run([pvpython, probe, tmp, *runs.values()], capture_output=True, text=True)
        if r.returncode != 0:
            print(f"pvpython exited {r.returncode}:\n{r.stdout}\n{r.stderr}")
            return 1
        for name, run in runs.items():
            with open(os.path.join(tmp, name + ".json")) as f:
                seen = json.load(f)
            with h5py.File(os.path.join(run, "particles.h5"), "r") as f:
                times = [float(t) for t in f["time_s"][...]]
            check(f"{name}: {len(times)} snapshots", len(times) >= 3)
            check_particles(name, run, tmp, seen["particles"], times)
            gas = os.path.exists(os.path.join(run, "fluid.h5"))
            check(f"{name}: gas output {'' if gas else 'not '}written",
                  gas == (name in ("fluidized_bed", "jet_mill")))
            if gas:
                check_gas(name, run, tmp, seen["fluid"], times, expect_solid=name == "jet_mill")
            # With both files open, ParaView's time keeper (the animation's one slider) holds each
            # instant once.
            check(f"{name}: time keeper {seen['time_keeper']} != {times}",
                  seen["time_keeper"] == times)
            print(f"{name}: {len(times)} snapshots at {times} s, particles "
                  f"{[s['cells'] for s in seen['particles']['steps']]}"
                  + (f", gas cells {seen['fluid']['steps'][0]['cells']}" if gas else ""))
    for f in failures:
        print("FAILED:", f)
    return 1 if failures else 0


sys.exit(main())
