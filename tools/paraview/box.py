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
    common.side_view(__doc__, "box")


if __name__ == "__main__":
    main()
