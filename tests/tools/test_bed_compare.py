#!/usr/bin/env python3
"""Checks of tools/bed_compare.py against values known exactly (ctest runs it with the configured
python3; exit status 0 when every check holds)."""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
import bed_compare as bc  # noqa: E402

failures = []


def check(what, ok):
    if not ok:
        failures.append(what)


# A sphere wholly inside a slab counts its whole volume; one cut at its centre, half (exact
# geometry, round-off tolerance).
r = np.array([1e-3])
check("sphere inside slab", abs(bc.slab_volume(np.array([0.0]), r, -2e-3, 2e-3)[0]
                                - 4 / 3 * math.pi * 1e-9) < 1e-21)
check("sphere cut at centre", abs(bc.slab_volume(np.array([0.0]), r, 0.0, 2e-3)[0]
                                  - 2 / 3 * math.pi * 1e-9) < 1e-21)

# The trapezoid rule is exact for a linear signal, however unevenly sampled.
t = np.array([0.0, 0.1, 0.15, 0.9, 1.0])
check("time mean of a line", abs(bc.time_mean(t, 3 + 2 * t) - 4.0) < 1e-12)

# A 2.4 Hz sine with a weaker 7 Hz one, sampled every 2 ms over 4.5 s: the peak lies within one
# frequency bin (1/4.5 s = 0.22 Hz) of 2.4 Hz.
t = np.arange(0, 4.5, 0.002)
p = 50 * np.sin(2 * math.pi * 2.4 * t) + 20 * np.sin(2 * math.pi * 7 * t) + 200
f, res = bc.dominant_frequency(t, p)
check(f"dominant frequency {f} Hz", abs(f - 2.4) <= res and abs(res - 1 / 4.498) < 1e-3)

# A symmetric profile has no scatter; adding independent noise of standard deviation s to a
# symmetric profile gives about s (200 points: the estimate's relative spread is about
# 1/sqrt(2 x 100) = 7 %, so 25 % is over three standard deviations).
x = np.linspace(0.0, 0.044, 201)
v = np.cos(2 * math.pi * (x - 0.022) / 0.044)
check("symmetric profile", bc.mirror_scatter(x, v, 0.044) < 1e-12)
rng = np.random.default_rng(1)
s = bc.mirror_scatter(x, v + rng.normal(0, 0.01, x.size), 0.044)
check(f"noisy profile scatter {s}", abs(s - 0.01) < 0.0025)

# The top of a bed of 100 particles whose tops lie at 1, 2, ..., 100 mm: the highest at 100 mm,
# numpy's linear quantile at 0.99 between the 99th and 100th tops (99.01 mm).
z = np.arange(1, 101) * 1e-3 - 5e-4
r = np.full(100, 5e-4)
check("bed top", abs(bc.bed_top(z, r) - 0.1) < 1e-15)
check("bed top, 99 %", abs(bc.bed_top(z, r, 0.99) - 0.09901) < 1e-12)

if failures:
    print("failed: " + "; ".join(failures))
    sys.exit(1)
print("bed_compare: all checks hold")
