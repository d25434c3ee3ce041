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
    common.side_view(__doc__, "fluidized bed")


if __name__ == "__main__":
    main()
