"""Pictures of SurfaceMaps results: offscreen VTK rendering to PNG.

``render_distortion(mesh, path)`` colours a mesh by its per-triangle
"MaxStretch" cell array (from vtkSurfaceMapEvaluation: max(s1, 1/s2)): 1 (no distortion) is
white, ``max_value`` and above dark red. ``render_checkerboard(mesh, path)``
draws a checkerboard of the mesh's "SpherePosition" (or given) coordinates,
so a map's effect on a regular pattern can be seen on any surface that
carries the same coordinates. ``render_point_scalars(mesh, path, array, lo, hi)``
is a heat map of a point array (e.g. a population's "StandardDeviation").
``render_texture(mesh, path, image=None)`` draws the mesh textured by its
texture coordinates (per corner, "CornerTCoords", split at the seams with
vtkSurfaceTextureSeamSplitter; or the active point texture coordinates) with
an image file, or with ``checkerboard_texture()``: the package's generated
checkerboard, whose squares vary in hue with u and in brightness with v so that
stretch, flips and seams show.

Rendering needs a display; on a headless machine run the script under
``xvfb-run -a`` (Debian package xvfb, installed by .ci/install-deps.sh).

From the command line::

    xvfb-run -a /usr/bin/python3 -m surfacemaps.render evaluated.vtp -o distortion.png

For a map evaluated with ``surfacemap evaluate MAPDIR``: a checkerboard of the
source's positions on the target, and the same pattern on the source::

    ... -m surfacemaps.render MAPDIR/approximating_1.vtp --checkerboard SourcePosition -o on_b.png
    ... -m surfacemaps.render MAPDIR/approximating_1.vtp --checkerboard SourcePosition \\
            --points-from MAPDIR/common_0.vtp -o on_a.png
"""

import argparse
import os
import sys

import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (the OpenGL back end)
from vtkmodules.vtkCommonCore import vtkLookupTable, vtkDoubleArray
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingAnnotation import vtkScalarBarActor
from vtkmodules.vtkRenderingCore import (vtkActor, vtkPolyDataMapper, vtkRenderer, vtkRenderWindow,
                                         vtkWindowToImageFilter)


_held_display = []


def _hold_display():
    """Opens one X connection that stays open until the process ends: an X server (Xvfb under
    xvfb-run) resets when its last client leaves, and a window opened during that reset makes VTK
    abort ("bad X server connection"). Every picture's window closes its own connection."""
    if _held_display or not os.environ.get("DISPLAY"):
        return
    import ctypes
    import ctypes.util
    try:
        x11 = ctypes.CDLL(ctypes.util.find_library("X11") or "libX11.so.6")
    except OSError:
        return  # VTK's window reports the missing display itself
    x11.XOpenDisplay.restype = ctypes.c_void_p
    x11.XOpenDisplay.argtypes = [ctypes.c_char_p]
    connection = x11.XOpenDisplay(None)
    if connection:
        _held_display.append(connection)


def _render(mesh, path, configure_mapper, size=(800, 600), azimuth=30.0, elevation=20.0, title=None, zoom=1.0,
            texture=None):
    _hold_display()
    mapper = vtkPolyDataMapper()
    mapper.SetInputData(mesh)
    configure_mapper(mapper)
    actor = vtkActor()
    actor.SetMapper(mapper)
    if texture is not None:
        actor.SetTexture(texture)
    renderer = vtkRenderer()
    renderer.AddActor(actor)
    if title is not None:  # a colour legend of the mapper's lookup table
        bar = vtkScalarBarActor()
        bar.SetLookupTable(mapper.GetLookupTable())
        bar.SetTitle(title)
        bar.SetNumberOfLabels(5)
        bar.SetWidth(0.12)
        bar.SetHeight(0.6)
        bar.SetPosition(0.85, 0.2)
        for text in (bar.GetTitleTextProperty(), bar.GetLabelTextProperty()):
            text.SetColor(0.1, 0.1, 0.1)
            text.ItalicOff()
            text.ShadowOff()
        renderer.AddActor2D(bar)
    renderer.SetBackground(1.0, 1.0, 1.0)
    renderer.ResetCamera()
    camera = renderer.GetActiveCamera()
    camera.Azimuth(azimuth)
    camera.Elevation(elevation)
    camera.Zoom(zoom)
    renderer.ResetCameraClippingRange()
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.AddRenderer(renderer)
    window.SetSize(*size)
    window.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.Update()
    writer = vtkPNGWriter()
    temporary = path + ".tmp.png"
    writer.SetFileName(temporary)
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()
    window.Finalize()
    os.replace(temporary, path)


def render_distortion(mesh, path, max_value=3.0, **view):
    """PNG of `mesh` coloured by its "MaxStretch" cell array (1 white -> max_value red)."""
    if mesh.GetCellData().GetArray("MaxStretch") is None:
        raise ValueError("the mesh has no MaxStretch cell array (run vtkSurfaceMapEvaluation first)")
    table = vtkLookupTable()
    table.SetNumberOfTableValues(256)
    for i in range(256):
        t = i / 255.0
        table.SetTableValue(i, 1.0, 1.0 - 0.8 * t, 1.0 - 0.9 * t, 1.0)
    table.SetRange(1.0, max_value)
    table.SetAboveRangeColor(0.5, 0.0, 0.0, 1.0)
    table.UseAboveRangeColorOn()
    table.Build()

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


def render_checkerboard(mesh, path, coordinates="SpherePosition", squares=8, **view):
    """PNG of `mesh` with a checkerboard of a 3-component point array (default SpherePosition)."""
    array = mesh.GetPointData().GetArray(coordinates)
    if array is None or array.GetNumberOfComponents() != 3:
        raise ValueError(f"the mesh has no 3-component point array {coordinates!r}")
    checks = vtkDoubleArray()
    checks.SetName("Checkerboard")
    for i in range(array.GetNumberOfTuples()):
        x, y, z = array.GetTuple3(i)
        cells = sum(int((c + 2.0) * squares / 2.0) for c in (x, y, z))
        checks.InsertNextValue(float(cells % 2))
    copy = type(mesh)()
    copy.ShallowCopy(mesh)
    copy.GetPointData().AddArray(checks)
    table = vtkLookupTable()
    table.SetNumberOfTableValues(2)
    table.SetTableValue(0, 0.15, 0.3, 0.6, 1.0)
    table.SetTableValue(1, 0.95, 0.95, 0.9, 1.0)
    table.SetRange(0.0, 1.0)
    table.Build()

    def configure(mapper):
        mapper.SetScalarModeToUsePointFieldData()
        mapper.SelectColorArray("Checkerboard")
        mapper.SetLookupTable(table)
        mapper.UseLookupTableScalarRangeOn()
        mapper.ScalarVisibilityOn()
        mapper.InterpolateScalarsBeforeMappingOn()

    _render(copy, path, configure, **view)


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
    parser.add_argument("--max", type=float, default=3.0, help="distortion shown darkest (default 3)")
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
    except (OSError, ValueError) as e:
        print(f"surfacemaps.render: error: {e}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
