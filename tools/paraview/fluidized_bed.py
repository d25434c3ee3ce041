"""Fluidized bed at its last time step, seen from the side (ParaView 5.11, pvpython).

    xvfb-run -a pvpython tools/paraview/fluidized_bed.py RUN_DIR OUT.png

Opens RUN_DIR/particles.xdmf and RUN_DIR/fluid.xdmf with ParaView's default reader
and draws the particles as spheres (diameter 2 radius_m) coloured by speed, the gas
on the box's mid-plane y = (y_lo + y_hi) / 2 coloured by gas speed (behind the front
half of the particles), and the box's edges ([box] of config.toml), looking along +y;
writes a 1200 x 800 PNG.
"""

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402


def main():
    run_dir, out_png = common.parse_args(__doc__)
    view = common.make_view()
    particles = common.open_run(run_dir, "particles.xdmf")
    fluid = common.open_run(run_dir, "fluid.xdmf")
    t = common.go_to_last_time(view, particles, fluid)
    lo, hi = common.box_of(run_dir, particles, fluid)
    centre = [(a + b) / 2 for a, b in zip(lo, hi)]

    common.show_particles(view, particles, t, bar_position=(0.64, 0.25))
    if fluid is not None:
        common.show_gas_slice(view, fluid, t, normal=[0, 1, 0], origin=centre,
                              bar_position=(0.27, 0.25))
    common.show_box_outline(view, lo, hi)
    common.add_title(view, "fluidized bed", t)
    common.side_camera(view, lo, hi)
    common.save(view, out_png)


if __name__ == "__main__":
    main()
