"""Box scenario (particles settling in a closed box) at its last time step, seen from the side.

    xvfb-run -a pvpython tools/paraview/box.py RUN_DIR OUT.png

Opens RUN_DIR/particles.xdmf with ParaView's default reader (and RUN_DIR/fluid.xdmf,
where the run has gas: a slice through the box's mid-plane y = (y_lo + y_hi) / 2
coloured by gas speed), draws the particles as spheres (diameter 2 radius_m)
coloured by speed and the box's edges ([box] of config.toml), looking along +y;
writes a 1200 x 800 PNG. ParaView 5.11 (pvpython).
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
    common.add_title(view, "box", t)
    common.side_camera(view, lo, hi)
    common.save(view, out_png)


if __name__ == "__main__":
    main()
