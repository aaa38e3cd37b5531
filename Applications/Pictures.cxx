#include "Pictures.h"

#include "AtomicFiles.h"
#include "Commands.h"
#include "VirtualDisplay.h"

#include "vtkSurfaceCheckerboardSource.h"

#include "vtkActor.h"
#include "vtkAxis.h"
#include "vtkCamera.h"
#include "vtkChartLegend.h"
#include "vtkChartXY.h"
#include "vtkContextScene.h"
#include "vtkContextView.h"
#include "vtkCoordinate.h"
#include "vtkDoubleArray.h"
#include "vtkImageData.h"
#include "vtkLandmarkTransform.h"
#include "vtkLookupTable.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkPlot.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkPolyDataNormals.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkScalarBarActor.h"
#include "vtkTable.h"
#include "vtkTextActor.h"
#include "vtkTextProperty.h"
#include "vtkTexture.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWindowToImageFilter.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

namespace surfacemap
{

namespace
{

const int Height = 600;
// Width of a picture of one panel or chart, and of each of several panels.
const int SingleWidth = 800, PanelWidth = 600;
// The share of a surface picture's width its colour legend takes, and its
// least width in pixels (room for a title of about 16 characters).
const double LegendShare = 0.12;
const int MinLegendWidth = 144;
// Height of the strip above the surfaces that holds their captions (pixels).
const int CaptionHeight = 40;

vtkSmartPointer<vtkDoubleArray> column(const std::string& name, const std::vector<double>& values)
{
  auto array = vtkSmartPointer<vtkDoubleArray>::New();
  array->SetName(name.c_str());
  for (double v : values)
  {
    array->InsertNextValue(v);
  }
  return array;
}

// Ticks of an axis of integers: more would overlap at 800 pixels.
const std::size_t MaxIntegerTicks = 12;

// A tick on every value of `x` (every second, third... when there are more
// than MaxIntegerTicks) on `axis`, which then stays fixed around them.
void integerTicks(vtkAxis* axis, const std::vector<double>& x)
{
  vtkNew<vtkDoubleArray> ticks;
  const std::size_t step = (x.size() + MaxIntegerTicks - 1) / MaxIntegerTicks;
  for (std::size_t k = 0; k < x.size(); k += step)
  {
    ticks->InsertNextValue(x[k]);
  }
  axis->SetCustomTickPositions(ticks);
  axis->SetBehavior(vtkAxis::FIXED);
  axis->SetRange(x.front() - 0.6, x.back() + 0.6);
}

void addSeries(vtkChartXY* chart, int type, const ChartSeries& series, int index)
{
  static const unsigned char colours[][3] = {
    { 51, 102, 178 }, { 214, 96, 38 }, { 60, 150, 70 }, { 150, 60, 160 }
  };
  const unsigned char* colour = colours[index % 4];
  vtkNew<vtkTable> table;
  table->AddColumn(column("x", series.x));
  table->AddColumn(column(series.label.empty() ? "y" : series.label, series.y));
  vtkPlot* plot = chart->AddPlot(type);
  plot->SetInputData(table, 0, 1);
  plot->SetColor(colour[0], colour[1], colour[2], 255);
  plot->SetWidth(2.0);
}

// A renderer in `viewport` holding only `caption`, at its left.
vtkSmartPointer<vtkRenderer> captionRenderer(const std::string& caption, const double viewport[4])
{
  vtkNew<vtkTextActor> text;
  text->SetInput(caption.c_str());
  text->GetTextProperty()->SetColor(0.1, 0.1, 0.1);
  text->GetTextProperty()->SetFontSize(18);
  text->GetTextProperty()->SetVerticalJustificationToCentered();
  text->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  text->SetPosition(0.03, 0.5);
  auto renderer = vtkSmartPointer<vtkRenderer>::New();
  renderer->SetViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
  renderer->SetBackground(1.0, 1.0, 1.0);
  renderer->AddActor2D(text);
  return renderer;
}

// How far the view turns away from facing the first surface's broadest side
// (degrees), so that the shape reads as 3-D.
const double ViewAzimuth = 0.0, ViewElevation = 20.0;
// Room left around a fitted surface (1: it touches the viewport's edges).
const double FitMargin = 1.12;

// The surface a panel draws: its mapper's input.
vtkPolyData* panelMesh(const SurfacePanel& panel)
{
  return vtkPolyData::SafeDownCast(panel.mapper->GetInput());
}

// The principal axes of `mesh`'s points (rows, the largest spread first),
// each signed so that its largest component is positive: a mesh modelled
// y-up or z-up keeps that direction up.
void principalAxes(vtkPolyData* mesh, double axes[3][3])
{
  const vtkIdType n = mesh->GetNumberOfPoints();
  double mean[3] = { 0.0, 0.0, 0.0 }, covariance[3][3] = {};
  for (vtkIdType v = 0; v < n; ++v)
  {
    vtkMath::Add(mean, mesh->GetPoint(v), mean);
  }
  vtkMath::MultiplyScalar(mean, n > 0 ? 1.0 / n : 0.0);
  for (vtkIdType v = 0; v < n; ++v)
  {
    double d[3];
    vtkMath::Subtract(mesh->GetPoint(v), mean, d);
    for (int i = 0; i < 3; ++i)
    {
      for (int j = 0; j < 3; ++j)
      {
        covariance[i][j] += d[i] * d[j];
      }
    }
  }
  double vectors[3][3], values[3];
  double* a[3] = { covariance[0], covariance[1], covariance[2] };
  double* v[3] = { vectors[0], vectors[1], vectors[2] };
  vtkMath::Jacobi(a, values, v); // eigenvectors in columns, largest eigenvalue first
  for (int k = 0; k < 3; ++k)
  {
    int largest = 0;
    for (int i = 0; i < 3; ++i)
    {
      axes[k][i] = vectors[i][k];
      largest = std::abs(axes[k][i]) > std::abs(axes[k][largest]) ? i : largest;
    }
    vtkMath::MultiplyScalar(axes[k], axes[k][largest] < 0.0 ? -1.0 : 1.0);
  }
}

// The view of the first panel: facing its broadest side (looking along its
// smallest principal axis), world y up as in VTK's default view (z when y
// is nearly the viewing direction), raised by ViewElevation; `forward` is
// the direction of projection.
void firstView(const SurfacePanel& panel, double forward[3], double up[3])
{
  double axes[3][3];
  principalAxes(panelMesh(panel), axes);
  const double* toViewer = axes[2];
  double worldUp[3] = { 0.0, 1.0, 0.0 };
  if (std::abs(toViewer[1]) > 0.9)
  {
    worldUp[1] = 0.0;
    worldUp[2] = 1.0;
  }
  vtkNew<vtkCamera> camera;
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetPosition(toViewer[0], toViewer[1], toViewer[2]);
  camera->SetViewUp(worldUp);
  camera->OrthogonalizeViewUp();
  camera->Azimuth(ViewAzimuth);
  camera->Elevation(ViewElevation);
  camera->OrthogonalizeViewUp();
  camera->GetDirectionOfProjection(forward);
  camera->GetViewUp(up);
}

// Points `camera` (direction of projection `forward`, `up`) at the centre of
// `mesh` from the distance at which all of it fits a viewport of `aspect`
// (width / height).
void fitCamera(vtkCamera* camera,
  vtkPolyData* mesh,
  const double forward[3],
  const double up[3],
  double aspect)
{
  double right[3];
  vtkMath::Cross(forward, up, right);
  const double slope =
    std::tan(vtkMath::RadiansFromDegrees(0.5 * camera->GetViewAngle())) / FitMargin;
  const double* centre = mesh->GetCenter();
  double distance = 0.0;
  for (vtkIdType v = 0; v < mesh->GetNumberOfPoints(); ++v)
  {
    double d[3];
    vtkMath::Subtract(mesh->GetPoint(v), centre, d);
    const double depth = -vtkMath::Dot(d, forward); // towards the viewer
    distance = std::max({ distance,
      depth + std::abs(vtkMath::Dot(d, up)) / slope,
      depth + std::abs(vtkMath::Dot(d, right)) / (slope * aspect) });
  }
  camera->SetFocalPoint(centre[0], centre[1], centre[2]);
  camera->SetPosition(centre[0] - forward[0] * distance,
    centre[1] - forward[1] * distance,
    centre[2] - forward[2] * distance);
  camera->SetViewUp(up[0], up[1], up[2]);
}

} // namespace

vtkSmartPointer<vtkDataArray> smoothNormals(vtkPolyData* mesh)
{
  vtkNew<vtkPolyData> geometry;
  geometry->CopyStructure(mesh);
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputData(geometry);
  normals->SplittingOff();
  normals->ComputeCellNormalsOff();
  normals->Update();
  return normals->GetOutput()->GetPointData()->GetNormals();
}

namespace
{

// `panel`'s mapper drawing its surface with smooth normals, unless it has
// normals or a texture (split at its seams, where normals of one side only
// would show the seams).
void smoothShading(const SurfacePanel& panel)
{
  vtkPolyData* mesh = panelMesh(panel);
  if (panel.texture || mesh->GetPointData()->GetNormals())
  {
    return;
  }
  vtkNew<vtkPolyData> shaded;
  shaded->ShallowCopy(mesh);
  shaded->GetPointData()->SetNormals(smoothNormals(mesh));
  panel.mapper->SetInputData(shaded);
}

// A renderer showing `panel`'s surface in `viewport` (xmin, ymin, xmax,
// ymax) of `aspect`, seen as the first panel is (`forward`, `up`) turned
// back by the panel's rotation onto the first: corresponding sides face the
// viewer alike.
vtkSmartPointer<vtkRenderer> surfaceRenderer(const SurfacePanel& panel,
  const double forward[3],
  const double up[3],
  const double viewport[4],
  double aspect)
{
  smoothShading(panel);
  vtkNew<vtkActor> actor;
  actor->SetMapper(panel.mapper);
  if (panel.texture)
  {
    actor->SetTexture(panel.texture);
  }
  auto renderer = vtkSmartPointer<vtkRenderer>::New();
  renderer->SetViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
  renderer->AddActor(actor);
  renderer->SetBackground(1.0, 1.0, 1.0);
  double back[3][3], panelForward[3], panelUp[3];
  vtkMath::Transpose3x3(panel.rotation, back);
  vtkMath::Multiply3x3(back, forward, panelForward);
  vtkMath::Multiply3x3(back, up, panelUp);
  fitCamera(renderer->GetActiveCamera(), panelMesh(panel), panelForward, panelUp, aspect);
  renderer->ResetCameraClippingRange();
  return renderer;
}

// A renderer in `viewport` holding only the colour legend of `colours`.
vtkSmartPointer<vtkRenderer> legendRenderer(vtkScalarsToColors* colours,
  const std::string& title,
  const double viewport[4],
  int widthPixels)
{
  vtkNew<vtkScalarBarActor> bar;
  bar->SetLookupTable(colours);
  bar->SetTitle(title.c_str());
  bar->SetNumberOfLabels(5);
  bar->SetPosition(0.05, 0.08);
  bar->SetWidth(0.9);
  bar->SetHeight(0.8);
  bar->SetVerticalTitleSeparation(12); // keeps the top label clear of the title
  if (colours->GetIndexedLookup())
  {
    // Categorical colours are labelled by annotations, which the bar draws
    // on its left: leave them room inside the legend's viewport.
    bar->SetPosition(0.45, 0.08);
    bar->SetWidth(0.5);
  }
  // Fixed sizes, the title's made small enough to fit the legend's width
  // (a character is about 0.6 of the font size wide).
  bar->UnconstrainedFontSizeOn();
  const int titleSize =
    std::max(9, std::min(18, static_cast<int>(widthPixels / (0.6 * (title.size() + 1)))));
  bar->GetTitleTextProperty()->SetFontSize(titleSize);
  bar->GetLabelTextProperty()->SetFontSize(14);
  bar->GetAnnotationTextProperty()->SetFontSize(14);
  for (vtkTextProperty* text : { bar->GetTitleTextProperty(),
         bar->GetLabelTextProperty(),
         bar->GetAnnotationTextProperty() }) // annotations: the labels of categorical colours
  {
    text->SetColor(0.1, 0.1, 0.1);
    text->ItalicOff();
    text->ShadowOff();
  }
  auto renderer = vtkSmartPointer<vtkRenderer>::New();
  renderer->SetViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
  renderer->SetBackground(1.0, 1.0, 1.0);
  renderer->AddActor2D(bar);
  return renderer;
}

} // namespace

bool checkDisplayForPictures()
{
  const std::string missing = prepareDisplay();
  if (missing.empty())
  {
    return true;
  }
  printError("--pictures: " + missing + "; install xvfb or leave --pictures out");
  return false;
}

void printPictures(const std::vector<std::string>& paths)
{
  std::string list;
  for (const std::string& path : paths)
  {
    list += (list.empty() ? "" : ", ") + path;
  }
  std::printf("  pictures: %s\n", list.empty() ? "none (no numeric array to draw)" : list.c_str());
}

void writeWindow(vtkRenderWindow* window, const std::string& path)
{
  window->Render();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  grab->Update();
  vtkNew<vtkPNGWriter> png;
  png->WriteToMemoryOn();
  png->SetInputConnection(grab->GetOutputPort());
  png->Write();
  vtkUnsignedCharArray* bytes = png->GetResult();
  if (png->GetErrorCode() != 0 || !bytes || bytes->GetNumberOfValues() == 0)
  {
    throw std::runtime_error("cannot encode " + path + " as PNG");
  }
  writeFileAtomically(path,
    std::string(reinterpret_cast<const char*>(bytes->GetPointer(0)),
      static_cast<std::size_t>(bytes->GetNumberOfValues())));
  window->Finalize();
}

void writeChart(const ChartPicture& picture, const std::string& path)
{
  vtkNew<vtkContextView> view;
  view->GetRenderer()->SetBackground(1.0, 1.0, 1.0);
  view->GetRenderWindow()->SetOffScreenRendering(1);
  view->GetRenderWindow()->SetSize(SingleWidth, Height);
  vtkNew<vtkChartXY> chart;
  view->GetScene()->AddItem(chart);
  chart->SetTitle(picture.title);
  for (std::size_t s = 0; s < picture.series.size(); ++s)
  {
    addSeries(chart, picture.type, picture.series[s], static_cast<int>(s));
  }
  chart->SetShowLegend(picture.series.size() > 1);
  if (picture.legendLowerRight)
  {
    chart->GetLegend()->SetVerticalAlignment(vtkChartLegend::BOTTOM);
    chart->GetLegend()->SetHorizontalAlignment(vtkChartLegend::RIGHT);
  }
  chart->GetAxis(vtkAxis::BOTTOM)->SetTitle(picture.xTitle);
  chart->GetAxis(vtkAxis::LEFT)->SetTitle(picture.yTitle);
  if (picture.integerX && !picture.series.empty() && !picture.series[0].x.empty())
  {
    integerTicks(chart->GetAxis(vtkAxis::BOTTOM), picture.series[0].x);
  }
  if (picture.fractionY)
  {
    chart->GetAxis(vtkAxis::LEFT)->SetBehavior(vtkAxis::FIXED);
    chart->GetAxis(vtkAxis::LEFT)->SetRange(0.0, 1.0);
  }
  writeWindow(view->GetRenderWindow(), path);
}

vtkSmartPointer<vtkLookupTable> rainbowTable(const double range[2])
{
  const double high = range[1] > range[0] ? range[1] : range[0] + 1.0;
  auto colours = vtkSmartPointer<vtkLookupTable>::New();
  colours->SetHueRange(0.667, 0.0);
  colours->SetTableRange(range[0], high);
  colours->Build();
  return colours;
}

void writeSurfacePicture(const std::vector<SurfacePanel>& panels,
  vtkScalarsToColors* legend,
  const std::string& legendTitle,
  const std::string& path)
{
  const int n = static_cast<int>(panels.size());
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(n == 1 ? SingleWidth : PanelWidth * n, Height);
  const int width = window->GetSize()[0];
  const int legendPixels =
    legend ? std::max(MinLegendWidth, static_cast<int>(width * LegendShare)) : 0;
  const double surfaces = 1.0 - static_cast<double>(legendPixels) / width;
  // Captions in a strip above the surfaces, which never reach into it.
  const bool captions = std::any_of(
    panels.begin(), panels.end(), [](const SurfacePanel& p) { return !p.caption.empty(); });
  const double top = captions ? 1.0 - static_cast<double>(CaptionHeight) / Height : 1.0;
  const double aspect = width * surfaces / n / (Height * top);
  double forward[3], up[3];
  firstView(panels.front(), forward, up);
  for (int k = 0; k < n; ++k)
  {
    const double viewport[4] = { surfaces * k / n, 0.0, surfaces * (k + 1) / n, top };
    window->AddRenderer(surfaceRenderer(panels[k], forward, up, viewport, aspect));
    if (captions)
    {
      const double strip[4] = { viewport[0], top, viewport[2], 1.0 };
      window->AddRenderer(captionRenderer(panels[k].caption, strip));
    }
  }
  if (legend)
  {
    const double viewport[4] = { surfaces, 0.0, 1.0, 1.0 };
    window->AddRenderer(legendRenderer(legend, legendTitle, viewport, legendPixels));
  }
  writeWindow(window, path);
}

void alignRotation(vtkPoints* fixed, vtkPoints* moving, double rotation[3][3])
{
  vtkNew<vtkLandmarkTransform> fit;
  fit->SetModeToRigidBody();
  fit->SetSourceLandmarks(moving);
  fit->SetTargetLandmarks(fixed);
  fit->Update();
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      rotation[i][j] = fit->GetMatrix()->GetElement(i, j);
    }
  }
}

vtkSmartPointer<vtkPolyDataMapper> arrayMapper(vtkPolyData* mesh,
  const std::string& name,
  bool cells)
{
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputData(mesh);
  if (cells)
  {
    mapper->SetScalarModeToUseCellFieldData();
  }
  else
  {
    mapper->SetScalarModeToUsePointFieldData();
  }
  mapper->SelectColorArray(name.c_str());
  mapper->ScalarVisibilityOn();
  return mapper;
}

vtkSmartPointer<vtkTexture> checkerboardTexture(int squares, int size)
{
  vtkNew<vtkSurfaceCheckerboardSource> checkerboard;
  checkerboard->SetSquares(squares);
  checkerboard->SetSize(size);
  checkerboard->Update();
  vtkSmartPointer<vtkImageData> image = checkerboard->GetOutput();
  auto texture = vtkSmartPointer<vtkTexture>::New();
  texture->SetInputData(image);
  texture->InterpolateOn();
  texture->RepeatOff();
  texture->EdgeClampOn();
  return texture;
}

} // namespace surfacemap
