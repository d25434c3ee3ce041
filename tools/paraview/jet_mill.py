"""Spiral jet mill at its last time step, seen from the top (ParaView 5.11, pvpython).

    xvfb-run -a pvpython tools/paraview/jet_mill.py RUN_DIR OUT.png

Opens RUN_DIR/particles.xdmf and RUN_DIR/fluid.xdmf with ParaView's default reader.
The gas: Threshold solid < 0.5 (the gas cells only, the chamber), a slice through the
chamber's mid-plane z = (z_lo + z_hi) / 2 coloured by gas speed, drawn at the floor
z = z_lo so that every particle lies above it. The particles: spheres (diameter
2 radius_m) coloured by speed. Looks down -z, x to the right; writes a 1200 x 800 PNG.
"""

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402


def main():
    s = common.load_scene(__doc__)
    view, particles, fluid, t, lo, hi, centre = (s.view, s.particles, s.fluid, s.t, s.lo, s.hi,
                                                 s.centre)

    common.show_particles(view, particles, t, bar_position=(0.84, 0.25),
                          preset="Inferno (matplotlib)")
    if fluid is not None:
        _, disp = common.show_gas_slice(view, fluid, t, normal=[0, 0, 1], origin=centre,
                                        gas_only=True, bar_position=(0.05, 0.25),
                                        preset="Blues")
        disp.Position = [0.0, 0.0, lo[2] - centre[2]]
    common.show_box_outline(view, lo, hi)
    common.add_title(view, "jet mill (top view)", t)

    half = max((hi[0] - lo[0]) * HEIGHT_OVER_WIDTH, hi[1] - lo[1]) / 2
    common.set_camera(view, centre, direction=[0, 0, 1], up=[0, 1, 0],
                      distance=10 * (hi[0] - lo[0]), parallel_scale=1.12 * half)
    common.save(view, s.out_png)


HEIGHT_OVER_WIDTH = common.HEIGHT / common.WIDTH

if __name__ == "__main__":
    main()
