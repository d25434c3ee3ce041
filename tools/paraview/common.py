"""Shared pieces of the ParaView scripts in tools/paraview/ (pvpython, ParaView 5.11).

Not run by itself: each scenario script (box.py, fluidized_bed.py, jet_mill.py,
rheometer.py) puts this folder on sys.path and imports it. The scripts open a run
folder's particles.xdmf (and fluid.xdmf) with ParaView's default reader, go to the
last time step, draw the particles as spheres scaled by `radius_m` coloured by speed,
the gas as a slice coloured by gas speed, and save one PNG.
"""

import os
import sys
from types import SimpleNamespace

try:
    import tomllib
except ImportError:  # Python < 3.11
    tomllib = None

from paraview.simple import (
    ColorBy,
    CreateRenderView,
    GetAnimationScene,
    GetColorTransferFunction,
    GetOpacityTransferFunction,
    GetScalarBar,
    Glyph,
    OpenDataFile,
    Outline,
    Render,
    SaveScreenshot,
    SetActiveView,
    Show,
    Slice,
    Text,
    Threshold,
)

WIDTH, HEIGHT = 1200, 800


def parse_args(doc):
    """RUN_DIR OUT.png from the command line; the script's docstring on misuse."""
    if len(sys.argv) != 3 or sys.argv[1] in ("-h", "--help"):
        sys.stderr.write(doc)
        sys.exit(2 if len(sys.argv) != 2 else 0)
    run_dir, out_png = sys.argv[1], sys.argv[2]
    if not os.path.isfile(os.path.join(run_dir, "particles.xdmf")):
        sys.stderr.write("error: no particles.xdmf in %s\n" % run_dir)
        sys.exit(2)
    return run_dir, out_png


def read_config(run_dir):
    """The run's config.toml as a dict ({} where it cannot be read)."""
    path = os.path.join(run_dir, "config.toml")
    if tomllib is None or not os.path.isfile(path):
        return {}
    with open(path, "rb") as f:
        return tomllib.load(f)


def make_view():
    view = CreateRenderView()
    SetActiveView(view)
    view.ViewSize = [WIDTH, HEIGHT]
    view.OrientationAxesVisibility = 1
    view.Background = [1.0, 1.0, 1.0]
    # ParaView 5.11 uses a palette unless told to use this view's own background
    if hasattr(view, "UseColorPaletteForBackground"):
        view.UseColorPaletteForBackground = 0
    view.OrientationAxesLabelColor = [0.0, 0.0, 0.0]
    return view


def open_run(run_dir, name):
    """OpenDataFile on RUN_DIR/name, or None where the file is absent."""
    path = os.path.join(run_dir, name)
    if not os.path.isfile(path):
        return None
    return OpenDataFile(path)


def go_to_last_time(view, *readers):
    """Moves the animation (and the view) to the last time step; returns that time."""
    scene = GetAnimationScene()
    scene.UpdateAnimationUsingDataTimeSteps()
    times = []
    for r in readers:
        if r is not None and hasattr(r, "TimestepValues"):
            tv = r.TimestepValues
            times.extend(tv if hasattr(tv, "__len__") else [tv])
    t = max(times) if times else 0.0
    scene.AnimationTime = t
    view.ViewTime = t
    for r in readers:
        if r is not None:
            r.UpdatePipeline(t)
    return t


def style_bar(lut, view, title, position):
    bar = GetScalarBar(lut, view)
    bar.Title = title
    bar.ComponentTitle = ""
    bar.TitleColor = [0.0, 0.0, 0.0]
    bar.LabelColor = [0.0, 0.0, 0.0]
    bar.TitleFontSize = 18
    bar.LabelFontSize = 16
    bar.TitleBold = 1
    bar.RangeLabelFormat = "%-#6.3g"
    bar.AutomaticLabelFormat = 1
    bar.WindowLocation = "Any Location"
    bar.Orientation = "Vertical"
    bar.Position = position
    bar.ScalarBarLength = 0.4
    bar.Visibility = 1
    return bar


def speed_range(source, array, association, t):
    """The magnitude range of a vector array at time t, as [lo, hi] with hi > lo."""
    source.UpdatePipeline(t)
    info = source.GetPointDataInformation() if association == "POINTS" \
        else source.GetCellDataInformation()
    a = info.GetArray(array)
    if a is None:
        return [0.0, 1.0]
    lo, hi = a.GetRange(-1)
    if not hi > lo:
        hi = lo + 1e-12 if lo > 0 else 1e-12
    return [lo, hi]


def show_particles(view, source, t, preset="Viridis (matplotlib)",
                   bar_position=(0.89, 0.05), resolution=12):
    """Spheres of diameter 2 radius_m at every particle, coloured by speed; returns the glyph."""
    glyph = Glyph(registrationName="particles_spheres", Input=source, GlyphType="Sphere")
    glyph.ScaleArray = ["POINTS", "radius_m"]
    glyph.ScaleFactor = 2.0  # the sphere glyph's diameter is 1
    glyph.GlyphMode = "All Points"
    glyph.OrientationArray = ["POINTS", "No orientation array"]
    glyph.GlyphType.ThetaResolution = resolution
    glyph.GlyphType.PhiResolution = resolution
    disp = Show(glyph, view)
    ColorBy(disp, ("POINTS", "velocity_m_per_s", "Magnitude"))
    lut = GetColorTransferFunction("velocity_m_per_s")
    lut.ApplyPreset(preset, True)
    lut.VectorMode = "Magnitude"
    lo, hi = speed_range(source, "velocity_m_per_s", "POINTS", t)
    lut.RescaleTransferFunction(0.0, hi)
    lut.AutomaticRescaleRangeMode = "Never"
    GetOpacityTransferFunction("velocity_m_per_s").RescaleTransferFunction(0.0, hi)
    disp.SetScalarBarVisibility(view, True)
    style_bar(lut, view, "particle speed [m/s]", list(bar_position))
    disp.Specular = 0.3
    return glyph, disp


def show_gas_slice(view, fluid, t, normal, origin, gas_only=False,
                   preset="Cool to Warm", bar_position=(0.02, 0.05), opacity=1.0):
    """A slice of the gas (cell data) coloured by gas speed; gas_only drops solid cells."""
    src = fluid
    if gas_only:
        thr = Threshold(registrationName="gas_cells", Input=fluid)
        thr.Scalars = ["CELLS", "solid"]
        thr.LowerThreshold = 0.0
        thr.UpperThreshold = 0.5
        src = thr
    sl = Slice(registrationName="gas_midplane", Input=src)
    sl.SliceType = "Plane"
    sl.SliceType.Origin = list(origin)
    sl.SliceType.Normal = list(normal)
    if hasattr(sl, "Triangulatetheslice"):
        sl.Triangulatetheslice = 0
    disp = Show(sl, view)
    # gas and particles share the array name: the gas gets a colour map of its own
    ColorBy(disp, ("CELLS", "velocity_m_per_s", "Magnitude"), separate=True)
    lut = GetColorTransferFunction("velocity_m_per_s", disp, separate=True)
    lut.ApplyPreset(preset, True)
    lut.VectorMode = "Magnitude"
    lo, hi = speed_range(sl, "velocity_m_per_s", "CELLS", t)
    lut.RescaleTransferFunction(0.0, hi)
    lut.AutomaticRescaleRangeMode = "Never"
    disp.Opacity = opacity
    disp.SetScalarBarVisibility(view, True)
    style_bar(lut, view, "gas speed [m/s]", list(bar_position))
    return sl, disp


def show_outline(view, source, color=(0.3, 0.3, 0.3)):
    o = Outline(Input=source)
    d = Show(o, view)
    d.AmbientColor = list(color)
    d.DiffuseColor = list(color)
    d.LineWidth = 1.5
    return o


def show_box_outline(view, lo, hi, color=(0.3, 0.3, 0.3)):
    """The wire frame of the box lo..hi (the [box] of config.toml)."""
    from paraview.simple import Box
    b = Box(registrationName="box_walls")
    b.XLength, b.YLength, b.ZLength = [h - l for l, h in zip(lo, hi)]
    b.Center = [(l + h) / 2 for l, h in zip(lo, hi)]
    return show_outline(view, b, color)


def add_title(view, text, time_s):
    label = Text(registrationName="title")
    label.Text = "%s   t = %.4g s" % (text, time_s)
    d = Show(label, view)
    d.Color = [0.0, 0.0, 0.0]
    d.FontSize = 20
    d.WindowLocation = "Upper Left Corner"
    return label


def box_of(run_dir, *sources):
    """The run's box: [box] lo and hi of config.toml, else the bounds of the first source."""
    box = read_config(run_dir).get("box", {})
    if "lo" in box and "hi" in box:
        return list(box["lo"]), list(box["hi"])
    for s in sources:
        if s is not None:
            b = s.GetDataInformation().GetBounds()
            return [b[0], b[2], b[4]], [b[1], b[3], b[5]]
    return [0.0, 0.0, 0.0], [1.0, 1.0, 1.0]


def side_camera(view, lo, hi, margin=1.2):
    """Looks along +y at the box lo..hi, z up, the whole box in the picture."""
    centre = [(a + b) / 2 for a, b in zip(lo, hi)]
    width, height = hi[0] - lo[0], hi[2] - lo[2]
    scale = margin * max(height / 2, width / 2 * HEIGHT / WIDTH)
    centre[2] += 0.06 * height  # room for the title above the box
    set_camera(view, centre, direction=[0, -1, 0], up=[0, 0, 1],
               distance=4 * max(hi[1] - lo[1], height), parallel_scale=scale)


def set_camera(view, focal, direction, up, distance=None, parallel_scale=None):
    """Looks at focal from focal + direction * distance (parallel projection)."""
    Render(view)  # the first render resets the camera: render before placing it
    view.CameraParallelProjection = 1
    view.CameraFocalPoint = list(focal)
    d = distance if distance is not None else 1.0
    view.CameraPosition = [f + c * d for f, c in zip(focal, direction)]
    view.CameraViewUp = list(up)
    if parallel_scale is not None:
        view.CameraParallelScale = parallel_scale
    else:
        view.ResetCamera(False)


def save(view, out_png):
    Render(view)
    SaveScreenshot(out_png, view, ImageResolution=[WIDTH, HEIGHT],
                   TransparentBackground=0, CompressionLevel="9")
    print("wrote %s" % out_png)


def load_scene(doc):
    """The command line, a view, both files at their last common time and the box: what every
    scenario's script starts from (fluid is None for a run without gas)."""
    run_dir, out_png = parse_args(doc)
    view = make_view()
    particles = open_run(run_dir, "particles.xdmf")
    fluid = open_run(run_dir, "fluid.xdmf")
    t = go_to_last_time(view, particles, fluid)
    lo, hi = box_of(run_dir, particles, fluid)
    return SimpleNamespace(run_dir=run_dir, out_png=out_png, view=view, particles=particles,
                           fluid=fluid, t=t, lo=lo, hi=hi,
                           centre=[(a + b) / 2 for a, b in zip(lo, hi)])


def side_view(doc, title):
    """A box-shaped run seen along +y: particles by speed, the gas on the mid-plane y where the
    run has gas, the box's edges (box.py, fluidized_bed.py)."""
    s = load_scene(doc)
    show_particles(s.view, s.particles, s.t, bar_position=(0.64, 0.25))
    if s.fluid is not None:
        show_gas_slice(s.view, s.fluid, s.t, normal=[0, 1, 0], origin=s.centre,
                       bar_position=(0.27, 0.25))
    show_box_outline(s.view, s.lo, s.hi)
    add_title(s.view, title, s.t)
    side_camera(s.view, s.lo, s.hi)
    save(s.view, s.out_png)
