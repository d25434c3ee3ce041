#!/usr/bin/env python3
"""Checks of the per-run plots (tools/plot_run.py, tools/collision_summary.py) and of the run
labels of the comparison tools (tools/run_labels.py): their helpers against values worked out by
hand, and the PNGs each scenario's run folder gets, on small generated run folders (ctest runs it
with the configured python3; exit status 0 when every check holds)."""
import math
import os
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
import collision_summary as cs  # noqa: E402
import plot_run as pr  # noqa: E402
import run_labels as rl  # noqa: E402

failures = []


def check(what, ok):
    if not ok:
        failures.append(what)


def close(a, b, tol=1e-12):
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    return a.shape == b.shape and bool(np.all((np.isnan(a) & np.isnan(b))
                                              | (np.abs(a - b) <= tol * np.maximum(1, np.abs(b)))))


# --- The energy budget's relative error -------------------------------------------------------
# Wall work that goes +2 J then back through zero to -1 J: the injected energy (the sum of the
# sources) crosses zero at the third row, where a ratio against it would blow up. The energy moved,
# kinetic + elastic + dissipated + |each source|, by hand:
#   row 0: 0;  row 1: 1 + 0 + 0.5 + 2 = 3.5;  row 2: 2 + 0.5 + 1 + 0 = 3.5;  row 3: 1 + 0 + 2 + 1 = 4.
# The gas work (0, -0.5, -1, -1) and stiffness change (0, 0.5, 1, 1) cancel in the sum but each adds
# its magnitude: + (0, 1, 2, 2).  So the moved energy is (0, 4.5, 5.5, 6).
cols = {
    "kinetic_energy_J": np.array([0.0, 1.0, 2.0, 1.0]),
    "elastic_energy_J": np.array([0.0, 0.0, 0.5, 0.0]),
    "dissipated_normal_damping_J": np.array([0.0, 0.3, 0.6, 1.5]),
    "dissipated_sliding_J": np.array([0.0, 0.2, 0.4, 0.5]),
    "wall_work_J": np.array([0.0, 2.0, 0.0, -1.0]),
    "gas_work_on_particles_J": np.array([0.0, -0.5, -1.0, -1.0]),
    "stiffness_change_J": np.array([0.0, 0.5, 1.0, 1.0]),
    "energy_injected_J": np.array([0.0, 2.0, 0.0, -1.0]),
    "energy_balance_error_J": np.array([0.0, 0.045, 0.11, -0.06]),
}
check("energy moved by hand", close(pr.energy_moved(cols), [0.0, 4.5, 5.5, 6.0]))
check("relative error against the energy moved",
      close(pr.relative_balance_error(cols), [0.0, 0.01, 0.02, -0.01]))
# Injected energy crosses zero at row 2; the ratio there stays finite and small.
check("finite where the injected energy is zero", np.isfinite(pr.relative_balance_error(cols)[2]))
# The sources: inserted - removed is what the injected sum leaves after the other three (0 here).
src = dict(pr.energy_sources(cols))
check("inserted - removed is the rest of the sum",
      close(src["particles inserted - removed"], [0.0, 0.0, 0.0, 0.0]))
cols2 = dict(cols, energy_injected_J=cols["energy_injected_J"] + np.array([0.0, 0.1, 0.2, 0.3]))
check("inserted - removed counts in the moved energy",
      close(pr.energy_moved(cols2), [0.0, 4.6, 5.7, 6.3]))
# Nothing moved and no error: 0; nothing moved but an error: no relative size (NaN).
z = {"kinetic_energy_J": np.zeros(2), "energy_injected_J": np.zeros(2),
     "energy_balance_error_J": np.array([0.0, 1e-20])}
check("0/0 is 0 and x/0 is NaN", close(pr.relative_balance_error(z), [0.0, math.nan]))

# --- The rheometer ----------------------------------------------------------------------------
# 600 rpm from 0.15 s over a 0.02 s ramp: 0 before, half at 0.16 s, full after 0.17 s.
check("impeller speed profile",
      close(pr.impeller_rpm([0.1, 0.15, 0.16, 0.17, 0.3], 600, 0.15, 0.02),
            [0, 0, 300, 600, 600]))
check("no ramp: a step", close(pr.impeller_rpm([0.1, 0.2], 60, 0.15, 0.0), [0, 60]))
# One revolution at 600 rpm is 0.1 s: the window starts at 0.25 s; a 0.3 s ramp is later.
check("window after one revolution", abs(pr.steady_window_start(600, 0.15, 0.02) - 0.25) < 1e-12)
check("window after a long ramp", abs(pr.steady_window_start(600, 0.15, 0.3) - 0.45) < 1e-12)
m, sd, n = pr.window_mean([0.1, 0.2, 0.3, 0.4], [9.0, 1.0, 2.0, 4.0], 0.15)
check(f"window mean {m} sd {sd} n {n}",
      abs(m - 7 / 3) < 1e-12 and abs(sd - math.sqrt(14 / 9)) < 1e-12 and n == 3)

# --- Collision grid: summed over the axis with the fewest cells -------------------------------
check("tall box: side view, summed over y (z first, then y, among equals)",
      cs.projection_axis((3, 3, 16)) == 1)
check("flat mill: top view", cs.projection_axis((16, 16, 1)) == 2)
check("cube: top view", cs.projection_axis((16, 16, 16)) == 2)
d = np.arange(3 * 3 * 16, dtype=float).reshape(3, 3, 16)
mp, axes, summed, extent = cs.project(d, [0, 0, 0], [0.06, 0.06, 0.32])
check("projection keeps x and z with grid_cells along z",
      mp.shape == (3, 16) and axes == ["x", "z"] and summed == "y"
      and close(extent, [0, 0.06, 0, 0.32]) and close(mp, d.sum(axis=1)))

# --- Labels of compared runs ------------------------------------------------------------------
check("unique labels from folders",
      rl.unique_labels(["l = 4", "l = 4", "l = 2"], ["/r/a", "/r/b", "/r/c"])
      == ["a", "b", "l = 2"])
check("folder names that collide take their parent",
      rl.unique_labels(["l = 1", "l = 1"], ["/x/run", "/y/run"]) == ["x/run", "y/run"])
check("distinct labels stay", rl.unique_labels(["p", "q"], ["/a", "/b"]) == ["p", "q"])
rows = ([{"label": "l = 4", "f": f, "run": 0} for f in (0, 1, 2)]
        + [{"label": "l = 4", "f": f, "run": 1} for f in (0, 1)]
        + [{"label": "l = 2", "f": f, "run": 2} for f in (0, 1)])
split = rl.split_runs(rows, ["l = 4", "l = 4", "l = 2"], key=lambda r: r["f"])
check("each run's own rows",
      [[r["run"] for r in b] for b in split] == [[0, 0, 0], [1, 1], [2, 2]])
split = rl.split_runs(rows[3:], ["l = 3", "l = 4", "l = 2"], key=lambda r: r["f"])
check("a run without rows gets none", [len(b) for b in split] == [0, 2, 2])

# --- Log and config readers -------------------------------------------------------------------
with tempfile.TemporaryDirectory() as tmp:
    with open(os.path.join(tmp, "log.txt"), "w") as f:
        f.write("fluidized bed derived numbers:\n"
                "  bed weight per area, less buoyancy        44.1283 Pa       (the fluidized)\n")
    check("W/A from the log", pr.log_number(tmp, "bed weight per area") == 44.1283)
    check("absent phrase", pr.log_number(tmp, "no such line") is None)


# --- Each scenario's PNGs from a generated run folder ------------------------------------------
def make_run(root, name, scenario, extra_cols, config, log=""):
    run = os.path.join(root, name)
    os.makedirs(run)
    t = np.linspace(0.0, 0.3, 31)
    base = {
        "time_s": t, "particles": 100 + 0 * t, "kinetic_energy_J": 1e-3 * t,
        "kinetic_translational_J": 0.8e-3 * t, "kinetic_rotational_J": 0.2e-3 * t,
        "potential_energy_J": 1.0 - 1e-3 * t, "elastic_energy_J": 1e-5 * t,
        "dissipated_normal_damping_J": 1e-4 * t, "dissipated_tangential_damping_J": 1e-5 * t,
        "dissipated_sliding_J": 2e-4 * t, "dissipated_rolling_J": 0 * t,
        "stiffness_change_J": 0 * t, "wall_work_J": 1e-4 * np.sin(20 * t),
        "energy_injected_J": 1e-4 * np.sin(20 * t), "energy_balance_error_J": 1e-9 * t,
        "mass_removed_kg": 0 * t, "wall_z_lo_force_z_N": -0.1 + 0 * t,
        "wall_z_lo_torque_axis_Nm": 0 * t, "mass_inserted_kg": 0 * t,
    }
    base.update({k: f(t) for k, f in extra_cols.items()})
    names = list(base)
    with open(os.path.join(run, "timeseries.csv"), "w") as f:
        f.write(",".join(names) + "\n")
        for i in range(t.size):
            f.write(",".join(f"{base[n][i]:.10g}" for n in names) + "\n")
    with open(os.path.join(run, "config.toml"), "w") as f:
        f.write(f"scenario = '{scenario}'\n\n[dem]\nmax_energy_error = 0.1\n\n{config}\n")
    with open(os.path.join(run, "log.txt"), "w") as f:
        f.write(log)
    return run


common = {"energy_budget.png", "kinetic_energy.png", "wall_loads.png"}
with tempfile.TemporaryDirectory() as root:
    runs = [
        (make_run(root, "fb", "fluidized_bed",
                  {"bed_height_m": lambda t: 0.016 + 0.002 * t,
                   "pressure_drop_Pa": lambda t: 44 * np.minimum(t / 0.15, 1),
                   "gas_work_on_particles_J": lambda t: -1e-5 * t,
                   "gas_force_on_walls_z_N": lambda t: 0.01 + 0 * t},
                  "[bed]\nheight_fraction = 0.95\npressure_taps = [0.0, 0.024]\n",
                  "  bed weight per area, less buoyancy        44.1283 Pa\n"), {"bed.png"}),
        (make_run(root, "rh", "rheometer",
                  {"torque_Nm": lambda t: 0.05 * (t > 0.15), "cup_torque_Nm": lambda t: -0.04 * t,
                   "floor_torque_Nm": lambda t: -0.01 * t},
                  "[rheometer]\nrpm = 600\nstart = 0.1\nramp = 0.02\n"), {"torque.png"}),
        (make_run(root, "jm", "jet_mill",
                  {"mass_inserted_kg": lambda t: 1e-3 * t, "mass_removed_kg": lambda t: 1e-4 * t,
                   "wall_chamber_force_z_N": lambda t: 0.2 * t}, ""), {"jet_mill.png"}),
        (make_run(root, "box", "box", {}, ""), set()),
    ]
    # Running the plots is also the check that none raises; stdout names the files.
    devnull = open(os.devnull, "w")
    for run, own in runs:
        stdout, sys.stdout = sys.stdout, devnull
        try:
            rc = pr.main(["plot_run.py", run])
        finally:
            sys.stdout = stdout
        pngs = {f for f in os.listdir(run) if f.endswith(".png")}
        want = common | own
        check(f"{os.path.basename(run)}: exit {rc}, PNGs {sorted(pngs)}, expected {sorted(want)}",
              rc == 0 and pngs == want)
    devnull.close()

if failures:
    print("FAILED:\n  " + "\n  ".join(failures))
    sys.exit(1)
print("all plot_run checks hold")
