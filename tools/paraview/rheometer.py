"""Powder rheometer at its last time step, seen from the side (ParaView 5.11, pvpython).

    xvfb-run -a pvpython tools/paraview/rheometer.py RUN_DIR OUT.png

Opens RUN_DIR/particles.xdmf with ParaView's default reader and cuts the powder
through the cup's axis (x = y = 0): the half with y > 0 stays, drawn as spheres
(diameter 2 radius_m) coloured by speed, so the cut face shows the speed from the
impeller out to the cup wall. The cup ([rheometer] cup_radius, cup_height of
config.toml) is a semi-transparent cylinder, its section in the cut plane drawn as
lines. Looks along +y, z up; writes a 1200 x 800 PNG.
"""

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402
from paraview.simple import Clip, Cylinder, Line, Show  # noqa: E402


def main():
    run_dir, out_png = common.parse_args(__doc__)
    rh = common.read_config(run_dir).get("rheometer", {})
    radius = rh.get("cup_radius", 0.025)
    cup_h = rh.get("cup_height", 0.1)
    view = common.make_view()
    particles = common.open_run(run_dir, "particles.xdmf")
    t = common.go_to_last_time(view, particles)
    b = particles.GetDataInformation().GetBounds()
    top = max(b[5], rh.get("blade_bottom", 0.01) + rh.get("blade_height", 0.01)) \
        if b[5] > b[4] else cup_h

    half = Clip(registrationName="back_half", Input=particles)
    half.ClipType = "Plane"
    half.ClipType.Origin = [0.0, 0.0, 0.0]
    half.ClipType.Normal = [0.0, 1.0, 0.0]
    half.Invert = 0  # keep y > 0
    half.Crinkleclip = 1
    common.show_particles(view, half, t, bar_position=(0.80, 0.25))

    # the cup: a semi-transparent cylinder, and its section in the cut plane as lines
    cup = Cylinder(registrationName="cup")
    cup.Radius = radius
    cup.Height = cup_h
    cup.Resolution = 96
    d = Show(cup, view)
    d.Orientation = [90.0, 0.0, 0.0]  # the cylinder's axis from y to z
    d.Position = [0.0, 0.0, cup_h / 2]
    d.Opacity = 0.2
    d.DiffuseColor = [0.6, 0.65, 0.75]
    d.AmbientColor = [0.6, 0.65, 0.75]
    for p1, p2 in (([-radius, 0, 0], [-radius, 0, cup_h]), ([radius, 0, 0], [radius, 0, cup_h]),
                   ([-radius, 0, 0], [radius, 0, 0])):
        line = Line(Point1=p1, Point2=p2)
        ld = Show(line, view)
        ld.DiffuseColor = [0.25, 0.25, 0.3]
        ld.AmbientColor = [0.25, 0.25, 0.3]
        ld.LineWidth = 2.0

    common.add_title(view, "rheometer (cut through the axis)", t)
    # the powder and the cup's lower part; the empty upper cup cut at 1.3 x the fill
    z_hi = min(cup_h, 1.3 * top)
    centre = [0.0, 0.0, z_hi / 2 + 0.03 * z_hi]
    scale = 1.15 * max(z_hi / 2, radius * common.HEIGHT / common.WIDTH)
    common.set_camera(view, centre, direction=[0, -1, 0], up=[0, 0, 1],
                      distance=10 * cup_h, parallel_scale=scale)
    common.save(view, out_png)


if __name__ == "__main__":
    main()
