"""Pictures of SurfaceMaps results: offscreen VTK rendering to PNG.

``render_distortion(mesh, path)`` colours a mesh by its per-triangle
"MaxStretch" cell array (from vtkSurfaceMapEvaluation: max(s1, 1/s2)): 1 (no distortion) is
white, ``max_value`` and above dark red. ``render_checkerboard(mesh, path)``
draws a checkerboard of the mesh's "SpherePosition" (or given) coordinates:
the triangles are cut along the checker's planes in those coordinates
(interpolated linearly across each triangle, as a map on a common
triangulation is), so squares have straight edges on any surface that
carries the same coordinates. ``render_point_scalars(mesh, path, array, lo, hi)``
is a heat map of a point array (e.g. a population's "StandardDeviation").
``render_texture(mesh, path, image=None)`` draws the mesh textured by its
texture coordinates (per corner, "CornerTCoords", split at the seams with
vtkSurfaceTextureSeamSplitter; or the active point texture coordinates) with
an image file, or with ``checkerboard_texture()``: the package's generated
checkerboard, whose squares vary in hue with u and in brightness with v so that
stretch, flips and seams show. ``render_panels`` draws several surfaces side
by side, with captions, through one camera.

Every picture faces its surfaces' broadest side (along their smallest principal
axis), y up (z when looking along y), seen slightly from above, and fits every
surface into its panel at one scale.

Rendering needs an X display (Debian's VTK renders through X only). Without
one, ``ensure_display()`` (which every function here calls) starts a virtual
framebuffer, Xvfb (Debian package xvfb), for the process and stops it at exit.

From the command line::

    /usr/bin/python3 -m surfacemaps.render evaluated.vtp -o distortion.png

For a map evaluated with ``surfacemap evaluate MAPDIR``: a checkerboard of the
source's positions on the target, and the same pattern on the source::

    ... -m surfacemaps.render MAPDIR/approximating_1.vtp --checkerboard SourcePosition -o on_b.png
    ... -m surfacemaps.render MAPDIR/approximating_1.vtp --checkerboard SourcePosition \\
            --points-from MAPDIR/common_0.vtp -o on_a.png
"""

import argparse
import atexit
import collections
import math
import os
import select
import shutil
import signal
import subprocess
import sys
import time

import numpy as np

import vtkmodules.vtkRenderingFreeType  # noqa: F401  (text: captions and legends)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (the OpenGL back end)
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkLookupTable
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingAnnotation import vtkScalarBarActor
from vtkmodules.vtkRenderingCore import (vtkActor, vtkCamera, vtkPolyDataMapper, vtkRenderer, vtkRenderWindow,
                                         vtkTextActor, vtkWindowToImageFilter)

# How far the shared view turns away from facing the surfaces' broadest side (degrees), so that the shape reads as 3-D; the room left around the fitted surfaces.
VIEW_AZIMUTH, VIEW_ELEVATION = 0.0, 20.0
FIT_MARGIN = 1.12
# The width of a picture's colour legend and the height of the strip holding the captions (pixels).
LEGEND_WIDTH, CAPTION_HEIGHT = 150, 40
# How long Xvfb may take to accept connections (usually well under a second).
XVFB_TIMEOUT_S = 20.0

_display = {}


def _xlib():
    import ctypes
    import ctypes.util
    x11 = ctypes.CDLL(ctypes.util.find_library("X11") or "libX11.so.6")
    x11.XOpenDisplay.restype = ctypes.c_void_p
    x11.XOpenDisplay.argtypes = [ctypes.c_char_p]
    return x11


def _die_with_parent():
    """In Xvfb's process before exec: terminated when this process dies, even when it is killed."""
    import ctypes
    ctypes.CDLL(None).prctl(1, signal.SIGTERM)  # PR_SET_PDEATHSIG


def _stop(server):
    server.terminate()
    server.wait()  # its lock file and socket are gone when it returns


def _start_xvfb(why):
    """Starts Xvfb on a display number it picks itself (-displayfd: written once it accepts
    connections, no race with other servers); its name ":N". RuntimeError naming `why` and the
    reason when it cannot."""
    xvfb = shutil.which("Xvfb")
    if xvfb is None:
        raise RuntimeError(f"{why} and Xvfb, which would provide a virtual one, is not installed "
                           "(Debian package xvfb)")
    read_end, write_end = os.pipe()
    server = subprocess.Popen([xvfb, "-displayfd", str(write_end), "-screen", "0", "1920x1200x24",
                               "-nolisten", "tcp", "-noreset"], pass_fds=(write_end,), stdin=subprocess.DEVNULL,
                              stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                              preexec_fn=_die_with_parent if sys.platform.startswith("linux") else None)
    os.close(write_end)
    number, deadline = b"", time.monotonic() + XVFB_TIMEOUT_S
    while select.select([read_end], [], [], max(0.0, deadline - time.monotonic()))[0]:
        c = os.read(read_end, 1)
        if not c or c == b"\n":
            break
        number += c
    os.close(read_end)
    if not number:
        _stop(server)
        raise RuntimeError(f"{why} and Xvfb, started to provide a virtual one, did not accept connections")
    atexit.register(_stop, server)
    return ":" + number.decode()


def ensure_display():
    """Makes sure pictures can be rendered, or raises RuntimeError saying why not.

    Uses the display DISPLAY names when it opens; otherwise starts Xvfb for this process (stopped
    at exit, and when the process is killed), points DISPLAY at it and returns its name (None
    when a display was there). One X connection stays open until the process ends: an X server
    resets when its last client leaves, and a window opened during that reset makes VTK abort
    ("bad X server connection"); every picture's window closes its own connection."""
    if _display:
        return _display.get("virtual")
    x11 = _xlib()
    given = os.environ.get("DISPLAY")
    if given:
        connection = x11.XOpenDisplay(None)
        if connection:
            _display["held"] = connection
            return None
    why = (f"cannot open the display {given!r} to render on" if given else
           "no display to render on (DISPLAY is not set)")
    name = _start_xvfb(why)
    os.environ["DISPLAY"] = name
    connection = x11.XOpenDisplay(None)
    if not connection:
        raise RuntimeError(f"{why} and Xvfb started as display {name} does not accept connections")
    _display.update(held=connection, virtual=name)
    return name


def principal_axes(points):
    """Rows: the principal axes of `points` (n x 3), the largest spread first, each signed so that
    its largest component is positive (a mesh modelled y-up or z-up keeps that direction up)."""
    centred = np.asarray(points, dtype=float) - np.mean(points, axis=0)
    _, vectors = np.linalg.eigh(centred.T @ centred)
    axes = vectors[:, ::-1].T.copy()
    for axis in axes:
        axis *= -1.0 if axis[np.argmax(np.abs(axis))] < 0 else 1.0
    return axes


def _points(mesh):
    return vtk_to_numpy(mesh.GetPoints().GetData()).astype(float)


def shared_view(meshes, aspect, azimuth=VIEW_AZIMUTH, elevation=VIEW_ELEVATION):
    """(offset, view up) of the camera all `meshes` share, each seen from its centre + offset:
    facing their broadest side (along the smallest principal axis of all their points, each mesh
    centred), world y up as in VTK's default view (z when y is nearly the viewing direction),
    turned by `azimuth` and `elevation` degrees, at the distance at which every mesh fits a
    viewport of `aspect` (width / height): one scale for all, none cropped."""
    axes = principal_axes(np.vstack([_points(m) - _points(m).mean(axis=0) for m in meshes]))
    camera = vtkCamera()
    camera.SetFocalPoint(0.0, 0.0, 0.0)
    camera.SetPosition(*axes[2])
    camera.SetViewUp(0.0, 0.0, 1.0) if abs(axes[2][1]) > 0.9 else camera.SetViewUp(0.0, 1.0, 0.0)
    camera.OrthogonalizeViewUp()
    camera.Azimuth(azimuth)
    camera.Elevation(elevation)
    camera.OrthogonalizeViewUp()
    up, forward = np.array(camera.GetViewUp()), np.array(camera.GetDirectionOfProjection())
    right = np.cross(forward, up)
    slope = math.tan(math.radians(0.5 * camera.GetViewAngle())) / FIT_MARGIN
    distance = 0.0
    for mesh in meshes:
        d = _points(mesh) - np.array(mesh.GetCenter())
        depth = -(d @ forward)  # towards the viewer
        distance = max(distance, float(np.max(depth + np.abs(d @ up) / slope)),
                       float(np.max(depth + np.abs(d @ right) / (slope * aspect))))
    return -forward * distance, up


Panel = collections.namedtuple("Panel", "mesh configure caption texture", defaults=(None, None))
Panel.__doc__ = """One surface of a picture: `mesh`, `configure(mapper)` setting its colours, an optional
caption (top left) and an optional vtkTexture."""


def _caption(text, viewport):
    """A renderer in `viewport` holding only `text`, at its left."""
    actor = vtkTextActor()
    actor.SetInput(text)
    prop = actor.GetTextProperty()
    prop.SetColor(0.1, 0.1, 0.1)
    prop.SetFontSize(18)
    prop.SetVerticalJustificationToCentered()
    actor.GetPositionCoordinate().SetCoordinateSystemToNormalizedViewport()
    actor.SetPosition(0.03, 0.5)
    renderer = vtkRenderer()
    renderer.SetViewport(*viewport)
    renderer.SetBackground(1.0, 1.0, 1.0)
    renderer.AddActor2D(actor)
    return renderer


def smooth_normals(mesh):
    """Per-point normals of `mesh` (not split at sharp edges): smooth shading, triangles not shown."""
    from vtkmodules.vtkFiltersCore import vtkPolyDataNormals
    geometry = type(mesh)()
    geometry.CopyStructure(mesh)
    normals = vtkPolyDataNormals()
    normals.SetInputData(geometry)
    normals.SplittingOff()
    normals.ComputeCellNormalsOff()
    normals.Update()
    return normals.GetOutput().GetPointData().GetNormals()


def _legend(lookup_table, title, viewport, width_pixels):
    """A renderer holding only the colour legend: fixed font sizes, the title's small enough to
    fit `width_pixels` (a character is about 0.6 of the font size wide), the top label clear of
    the title."""
    bar = vtkScalarBarActor()
    bar.SetLookupTable(lookup_table)
    bar.SetTitle(title)
    bar.SetNumberOfLabels(5)
    bar.SetPosition(0.05, 0.08)
    bar.SetWidth(0.9)
    bar.SetHeight(0.8)
    bar.SetVerticalTitleSeparation(12)
    bar.UnconstrainedFontSizeOn()
    bar.GetTitleTextProperty().SetFontSize(max(9, min(18, int(width_pixels / (0.6 * (len(title) + 1))))))
    bar.GetLabelTextProperty().SetFontSize(14)
    for text in (bar.GetTitleTextProperty(), bar.GetLabelTextProperty()):
        text.SetColor(0.1, 0.1, 0.1)
        text.ItalicOff()
        text.ShadowOff()
    renderer = vtkRenderer()
    renderer.SetViewport(*viewport)
    renderer.SetBackground(1.0, 1.0, 1.0)
    renderer.AddActor2D(bar)
    return renderer


def _surface(panel, offset, up, viewport):
    mesh = panel.mesh
    if panel.texture is None and mesh.GetPointData().GetNormals() is None:
        # Not for a texture: split at its seams, normals of one side only would show the seams.
        mesh = type(mesh)()
        mesh.ShallowCopy(panel.mesh)
        mesh.GetPointData().SetNormals(smooth_normals(panel.mesh))
    mapper = vtkPolyDataMapper()
    mapper.SetInputData(mesh)
    panel.configure(mapper)
    actor = vtkActor()
    actor.SetMapper(mapper)
    if panel.texture is not None:
        actor.SetTexture(panel.texture)
    renderer = vtkRenderer()
    renderer.SetViewport(*viewport)
    renderer.AddActor(actor)
    renderer.SetBackground(1.0, 1.0, 1.0)
    centre = np.array(panel.mesh.GetCenter())
    camera = renderer.GetActiveCamera()
    camera.SetFocalPoint(*centre)
    camera.SetPosition(*(centre + offset))
    camera.SetViewUp(*up)
    renderer.ResetCameraClippingRange()
    return renderer, mapper


def render_panels(panels, path, panel_size=(400, 320), columns=None, legend=None, azimuth=VIEW_AZIMUTH,
                  elevation=VIEW_ELEVATION):
    """PNG of the `panels` (Panel) in a grid of `columns` (default: all in one row up to 5, else
    rows of at most 5), each `panel_size` pixels (a caption strip on top when a panel has a
    caption), through one camera (shared_view), with a colour legend at the right when `legend`
    is (title, None): the lookup table of the first panel's mapper. Written atomically."""
    ensure_display()
    n = len(panels)
    columns = columns or (n if n <= 5 else math.ceil(n / math.ceil(n / 5)))
    rows = math.ceil(n / columns)
    surfaces_width = panel_size[0] * columns
    width = surfaces_width + LEGEND_WIDTH if legend else surfaces_width
    share = surfaces_width / width
    strip = CAPTION_HEIGHT / panel_size[1] if any(p.caption for p in panels) else 0.0
    offset, up = shared_view([p.mesh for p in panels], panel_size[0] / (panel_size[1] * (1.0 - strip)), azimuth,
                             elevation)
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(width, panel_size[1] * rows)
    first_mapper = None
    for k, panel in enumerate(panels):
        row, column = divmod(k, columns)
        left, right = share * column / columns, share * (column + 1) / columns
        bottom, top = 1.0 - (row + 1) / rows, 1.0 - row / rows
        below_caption = top - strip / rows
        renderer, mapper = _surface(panel, offset, up, (left, bottom, right, below_caption))
        first_mapper = first_mapper or mapper
        window.AddRenderer(renderer)
        if strip:
            window.AddRenderer(_caption(panel.caption or "", (left, below_caption, right, top)))
    if legend:
        window.AddRenderer(_legend(first_mapper.GetLookupTable(), legend[0], (share, 0.0, 1.0, 1.0),
                                   width - surfaces_width))
    window.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    grab.Update()
    writer = vtkPNGWriter()
    temporary = path + ".tmp.png"
    writer.SetFileName(temporary)
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()
    window.Finalize()
    os.replace(temporary, path)


def _render(mesh, path, configure, size=(800, 600), title=None, texture=None, **view):
    """One panel of `size` (the legend, when `title` is given, included)."""
    panel_size = (size[0] - LEGEND_WIDTH if title is not None else size[0], size[1])
    render_panels([Panel(mesh, configure, None, texture)], path, panel_size=panel_size,
                  legend=(title, None) if title is not None else None, **view)


def distortion_table(max_value=3.0):
    """White at 1 (no distortion) to red at `max_value`, dark red above."""
    table = vtkLookupTable()
    table.SetNumberOfTableValues(256)
    for i in range(256):
        t = i / 255.0
        table.SetTableValue(i, 1.0, 1.0 - 0.8 * t, 1.0 - 0.9 * t, 1.0)
    table.SetRange(1.0, max_value)
    table.SetAboveRangeColor(0.5, 0.0, 0.0, 1.0)
    table.UseAboveRangeColorOn()
    table.Build()
    return table


def render_distortion(mesh, path, max_value=3.0, **view):
    """PNG of `mesh` coloured by its "MaxStretch" cell array (1 white -> max_value red)."""
    if mesh.GetCellData().GetArray("MaxStretch") is None:
        raise ValueError("the mesh has no MaxStretch cell array (run vtkSurfaceMapEvaluation first)")
    table = distortion_table(max_value)

    def configure(mapper):
        mapper.SetScalarModeToUseCellFieldData()
        mapper.SelectColorArray("MaxStretch")
        mapper.SetLookupTable(table)
        mapper.UseLookupTableScalarRangeOn()
        mapper.ScalarVisibilityOn()

    _render(mesh, path, configure, **view)


def render_point_scalars(mesh, path, array, minimum, maximum, **view):
    """PNG of `mesh` coloured by the 1-component point array `array`: white at `minimum` to dark
    red at `maximum` (a heat map, e.g. the per-vertex "StandardDeviation" of a population), with
    a colour legend titled ``view["title"]`` when given."""
    values = mesh.GetPointData().GetArray(array)
    if values is None or values.GetNumberOfComponents() != 1:
        raise ValueError(f"the mesh has no 1-component point array {array!r}")
    table = vtkLookupTable()
    table.SetNumberOfTableValues(256)
    for i in range(256):
        t = i / 255.0
        table.SetTableValue(i, 1.0 - 0.45 * t, 1.0 - 0.95 * t, 1.0 - 0.95 * t, 1.0)
    table.SetRange(minimum, maximum if maximum > minimum else minimum + 1.0)
    table.Build()

    def configure(mapper):
        mapper.SetScalarModeToUsePointFieldData()
        mapper.SelectColorArray(array)
        mapper.SetLookupTable(table)
        mapper.UseLookupTableScalarRangeOn()
        mapper.ScalarVisibilityOn()
        mapper.InterpolateScalarsBeforeMappingOn()

    _render(mesh, path, configure, **view)


def _cut_along(mesh, coordinates, axis, squares):
    """`mesh` with its triangles cut along the planes on which component `axis` of `coordinates`,
    times squares / 2, is an integer: split at each plane in turn, the part below kept, the part
    above cut further (vtkClipPolyData interpolates the point data along the cut edges)."""
    from vtkmodules.vtkFiltersCore import vtkAppendPolyData, vtkClipPolyData
    low, high = (v * squares / 2.0 for v in mesh.GetPointData().GetArray(coordinates).GetRange(axis))
    pieces, rest = vtkAppendPolyData(), mesh
    for k in range(math.floor(low) + 1, math.ceil(high)):
        values = vtk_to_numpy(rest.GetPointData().GetArray(coordinates))[:, axis] * squares / 2.0
        scalars = numpy_to_vtk(np.ascontiguousarray(values), deep=1)
        scalars.SetName("Cut")
        rest.GetPointData().SetScalars(scalars)
        clip = vtkClipPolyData()
        clip.SetInputData(rest)
        clip.SetValue(float(k))
        clip.GenerateClippedOutputOn()
        clip.Update()
        pieces.AddInputData(clip.GetClippedOutput())
        rest = clip.GetOutput()
    pieces.AddInputData(rest)
    pieces.Update()
    result = pieces.GetOutput()
    result.GetPointData().RemoveArray("Cut")
    return result


def checkered(mesh, coordinates="SpherePosition", squares=8):
    """`mesh` with its triangles cut along the planes c = 2 k / `squares` of each component c of
    its 3-component point array `coordinates` (interpolated linearly across each triangle), and
    the cell array "Checkerboard": per piece the parity (0 or 1) of the cube its coordinates lie
    in. Drawn cell by cell, squares have straight edges in those coordinates."""
    array = mesh.GetPointData().GetArray(coordinates)
    if array is None or array.GetNumberOfComponents() != 3:
        raise ValueError(f"the mesh has no 3-component point array {coordinates!r}")
    current = type(mesh)()
    current.CopyStructure(mesh)
    current.GetPointData().AddArray(array)
    current.GetPointData().SetNormals(smooth_normals(mesh))  # interpolated along the cuts: no seams
    for axis in range(3):
        current = _cut_along(current, coordinates, axis, squares)
    positions = vtk_to_numpy(current.GetPointData().GetArray(coordinates))
    polys = current.GetPolys()
    offsets = vtk_to_numpy(polys.GetOffsetsArray())
    centroids = np.add.reduceat(positions[vtk_to_numpy(polys.GetConnectivityArray())], offsets[:-1], axis=0)
    centroids /= np.diff(offsets)[:, None]
    parity = np.floor((centroids + 2.0) * squares / 2.0).astype(int).sum(axis=1) % 2
    checks = numpy_to_vtk(parity.astype(float), deep=1)
    checks.SetName("Checkerboard")
    current.GetCellData().AddArray(checks)
    return current


def configure_checkerboard(mapper):
    """Colours a checkered() mesh: blue and cream squares."""
    table = vtkLookupTable()
    table.SetNumberOfTableValues(2)
    table.SetTableValue(0, 0.15, 0.3, 0.6, 1.0)
    table.SetTableValue(1, 0.95, 0.95, 0.9, 1.0)
    table.SetRange(0.0, 1.0)
    table.Build()
    mapper.SetScalarModeToUseCellFieldData()
    mapper.SelectColorArray("Checkerboard")
    mapper.SetLookupTable(table)
    mapper.UseLookupTableScalarRangeOn()
    mapper.ScalarVisibilityOn()


def render_checkerboard(mesh, path, coordinates="SpherePosition", squares=8, **view):
    """PNG of `mesh` with a checkerboard of a 3-component point array (default SpherePosition):
    `squares` across [-1, 1], straight-edged (checkered())."""
    _render(checkered(mesh, coordinates, squares), path, configure_checkerboard, **view)


def checkerboard_texture(squares=16, size=512):
    """A ``size`` x ``size`` RGB vtkImageData: ``squares`` x ``squares`` checks whose colour runs
    through the hues along u and from dark to light along v, alternating with white (the image of
    vtkSurfaceCheckerboardSource, as the command line's pictures draw it)."""
    from . import vtkSurfaceCheckerboardSource
    source = vtkSurfaceCheckerboardSource()
    source.SetSquares(squares)
    source.SetSize(size)
    source.Update()
    return source.GetOutput()


def _read_image(path):
    from vtkmodules.vtkIOImage import vtkImageReader2Factory
    reader = vtkImageReader2Factory.CreateImageReader2(str(path))
    if reader is None or not os.path.isfile(str(path)):
        raise ValueError(f"{path}: not an image file VTK can read (PNG, JPEG, BMP, TIFF, PNM)")
    reader.SetFileName(str(path))
    reader.Update()
    return reader.GetOutput()


def render_texture(mesh, path, image=None, squares=16, **view):
    """PNG of `mesh` textured with `image` (a file name; None: checkerboard_texture(squares)).

    Per-corner texture coordinates ("CornerTCoords", e.g. of an OBJ or of a transfer's output)
    are split at their seams first, so no triangle is stretched across the texture; otherwise
    the mesh's active point texture coordinates are used. ValueError when it has neither."""
    from vtkmodules.vtkRenderingCore import vtkTexture
    from . import vtkSurfaceTextureSeamSplitter
    if mesh.GetCellData().GetArray("CornerTCoords") is not None:
        splitter = vtkSurfaceTextureSeamSplitter()
        splitter.SetInputData(mesh)
        splitter.Update()
        mesh = splitter.GetOutput()
    if mesh.GetPointData().GetTCoords() is None:
        raise ValueError("the mesh has no texture coordinates (neither CornerTCoords nor point TCoords)")
    texture = vtkTexture()
    texture.SetInputData(checkerboard_texture(squares) if image is None else _read_image(image))
    texture.InterpolateOn()
    texture.RepeatOff()
    texture.EdgeClampOn()

    def configure(mapper):
        mapper.ScalarVisibilityOff()

    _render(mesh, path, configure, texture=texture, **view)


def _darkest(text):
    """argparse's `type` for --max: a distortion above 1 (the lightest colour) up to 1e6."""
    try:
        value = float(text)
    except ValueError:
        value = None
    if value is None or not 1.0 < value <= 1e6:
        raise argparse.ArgumentTypeError(f"needs a number above 1 up to 1e6, not '{text}'")
    return value


def main(argv=None):
    from . import read_mesh

    parser = argparse.ArgumentParser(prog="python3 -m surfacemaps.render",
                                     description="Render a mesh to PNG: distortion heat map, checkerboard or texture.")
    parser.add_argument("mesh", help="mesh file (e.g. the output of vtkSurfaceMapEvaluation saved as .vtp)")
    parser.add_argument("-o", "--output", required=True, help="PNG file")
    parser.add_argument("--checkerboard", metavar="ARRAY", nargs="?", const="SpherePosition",
                        help="draw a checkerboard of this point array instead of the distortion")
    parser.add_argument("--texture", metavar="IMAGE", nargs="?", const="",
                        help="draw the mesh textured by its texture coordinates with IMAGE (PNG, JPEG, ...; "
                             "without IMAGE: the package's checkerboard)")
    parser.add_argument("--max", type=_darkest, default=3.0,
                        help="distortion shown darkest (default 3, above 1 up to 1e6)")
    parser.add_argument("--points-from", metavar="MESH",
                        help="draw at the points of MESH instead (same points in the same order), e.g. "
                             "common_0.vtp for the source side of a map's checkerboard")
    args = parser.parse_args(argv)
    try:
        mesh = read_mesh(args.mesh)
        if args.points_from:
            other = read_mesh(args.points_from)
            if other.GetNumberOfPoints() != mesh.GetNumberOfPoints():
                raise ValueError(f"{args.points_from} has {other.GetNumberOfPoints()} points, "
                                 f"{args.mesh} has {mesh.GetNumberOfPoints()}")
            moved = type(mesh)()
            moved.ShallowCopy(mesh)
            moved.SetPoints(other.GetPoints())
            mesh = moved
        if args.texture is not None:
            render_texture(mesh, args.output, args.texture or None)
        elif args.checkerboard:
            render_checkerboard(mesh, args.output, args.checkerboard)
        else:
            render_distortion(mesh, args.output, args.max)
    except (OSError, ValueError, RuntimeError) as e:
        print(f"surfacemaps.render: error: {e}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
