// The --pictures of every command: PNGs rendered with VTK (OpenGL through X,
// offscreen), charts and surfaces, each file written atomically.
//
// Debian's VTK 9.1 is built without EGL and OSMesa: its only render window
// is X's, which aborts the process when no display can be opened. Commands
// therefore prepare a display, a virtual one when there is none, before
// computing (checkDisplayForPictures, VirtualDisplay.h).
#pragma once

#include "vtkSmartPointer.h"

#include <string>
#include <vector>

class vtkDataArray;
class vtkLookupTable;
class vtkPolyData;
class vtkPoints;
class vtkPolyDataMapper;
class vtkTexture;
class vtkRenderWindow;
class vtkScalarsToColors;

namespace surfacemap
{

/// True if --pictures can be drawn (on the display, or on a virtual one
/// started for this process: prepareDisplay); otherwise prints why (no
/// display and no Xvfb) and returns false (the caller exits with
/// ExitBadInput before computing anything).
bool checkDisplayForPictures();

/// Prints the pictures written ("  pictures: a.png, b.png"), or that there
/// was nothing to draw.
void printPictures(const std::vector<std::string>& paths);

/// Renders `window` and writes its picture as PNG, atomically, to `path`.
/// Throws std::runtime_error naming `path` on failure.
void writeWindow(vtkRenderWindow* window, const std::string& path);

/// One line (or set of bars, or points) of a chart.
struct ChartSeries
{
  std::string label; // in the legend, shown when a chart has two or more series
  std::vector<double> x, y;
};

/// A chart: series of one kind (vtkChart::LINE, BAR or POINTS) with titles.
struct ChartPicture
{
  int type = 0;
  std::vector<ChartSeries> series;
  std::string xTitle, yTitle, title;
  bool integerX = false;  // ticks on the x values of the first series (1, 2, ...; at most 12)
  bool fractionY = false; // y axis fixed to [0, 1]
  bool legendLowerRight = false; // the legend where rising curves leave room, not top right
};

/// The chart rendered (800 x 600) and written atomically to `path`.
void writeChart(const ChartPicture& chart, const std::string& path);

/// Blue (low) to red (high) over `range` (a range of zero width is widened).
vtkSmartPointer<vtkLookupTable> rainbowTable(const double range[2]);

/// A mapper of `mesh` coloured by its point (or, with `cells`, cell) array `name`.
vtkSmartPointer<vtkPolyDataMapper> arrayMapper(vtkPolyData* mesh,
  const std::string& name,
  bool cells);

/// One surface of a picture: its coloured mapper (whose input, set with
/// SetInputData, is the surface the camera fits) and a caption (may be empty).
struct SurfacePanel
{
  vtkSmartPointer<vtkPolyDataMapper> mapper;
  std::string caption;
  /// Drawn on the surface through its active point texture coordinates, if set.
  vtkSmartPointer<vtkTexture> texture;
  /// The rotation taking this surface onto the first panel's (alignRotation);
  /// the panel is seen as the first is, turned back by it, so that the parts
  /// a map makes correspond face the viewer alike. Identity by default.
  double rotation[3][3] = { { 1.0, 0.0, 0.0 }, { 0.0, 1.0, 0.0 }, { 0.0, 0.0, 1.0 } };
};

/// Per-point normals of `mesh` (not split at sharp edges: smooth shading of
/// the closed surfaces drawn here, the triangles not shown).
vtkSmartPointer<vtkDataArray> smoothNormals(vtkPolyData* mesh);

/// The rotation that best aligns the points `moving` onto the corresponding
/// points `fixed` (as many, index by index; least squares after centring
/// both, a proper rotation: vtkLandmarkTransform's rigid body fit).
void alignRotation(vtkPoints* fixed, vtkPoints* moving, double rotation[3][3]);

/// A `size` x `size` RGB checkerboard of `squares` x `squares` checks whose
/// colour runs through the hues along u and from dark to light along v,
/// alternating with white, so that stretch, flips and seams show
/// (vtkSurfaceCheckerboardSource's image, as in surfacemaps.render).
vtkSmartPointer<vtkTexture> checkerboardTexture(int squares = 16, int size = 512);

/// The panels side by side (800 x 600 for one, 1200 x 600 for two), with a
/// colour legend of `legend` titled `legendTitle` at the right when `legend`
/// is given; written atomically. The first surface is seen facing its
/// broadest side (along its smallest principal axis), world y up (z when y
/// is nearly the viewing direction), slightly from above; every other one
/// from the same side after its `rotation`; each is centred and fitted whole
/// into its panel (not cropped); captions in a strip above the surfaces.
void writeSurfacePicture(const std::vector<SurfacePanel>& panels,
  vtkScalarsToColors* legend,
  const std::string& legendTitle,
  const std::string& path);

} // namespace surfacemap
