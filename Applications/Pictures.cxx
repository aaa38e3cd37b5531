#include "Pictures.h"

#include "AtomicFiles.h"
#include "Commands.h"

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
#include "vtkLookupTable.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkPlot.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
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
// The share of a surface picture's width its colour legend takes.
const double LegendShare = 0.12;

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

// One tick per value of `x` on `axis`, which then stays fixed around them.
void integerTicks(vtkAxis* axis, const std::vector<double>& x)
{
  vtkNew<vtkDoubleArray> ticks;
  for (double value : x)
  {
    ticks->InsertNextValue(value);
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

// A caption in the top left corner of `renderer`.
void addCaption(vtkRenderer* renderer, const std::string& caption)
{
  vtkNew<vtkTextActor> text;
  text->SetInput(caption.c_str());
  text->GetTextProperty()->SetColor(0.1, 0.1, 0.1);
  text->GetTextProperty()->SetFontSize(18);
  text->GetTextProperty()->SetVerticalJustificationToTop();
  text->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  text->SetPosition(0.03, 0.96);
  renderer->AddActor2D(text);
}

// A renderer showing `mapper`'s surface in the default view of every
// picture, in `viewport` (xmin, ymin, xmax, ymax).
vtkSmartPointer<vtkRenderer> surfaceRenderer(const SurfacePanel& panel, const double viewport[4])
{
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
  renderer->ResetCamera();
  renderer->GetActiveCamera()->Azimuth(30.0);
  renderer->GetActiveCamera()->Elevation(20.0);
  renderer->GetActiveCamera()->Zoom(1.3); // the shape, not its bounding sphere, fills the panel
  renderer->ResetCameraClippingRange();
  if (!panel.caption.empty())
  {
    addCaption(renderer, panel.caption);
  }
  return renderer;
}

// A renderer in `viewport` holding only the colour legend of `colours`.
vtkSmartPointer<vtkRenderer> legendRenderer(vtkScalarsToColors* colours,
  const std::string& title,
  const double viewport[4])
{
  vtkNew<vtkScalarBarActor> bar;
  bar->SetLookupTable(colours);
  bar->SetTitle(title.c_str());
  bar->SetNumberOfLabels(5);
  bar->SetPosition(0.05, 0.1);
  bar->SetWidth(0.9);
  bar->SetHeight(0.8);
  if (colours->GetIndexedLookup())
  {
    // Categorical colours are labelled by annotations, which the bar draws
    // on its left: leave them room inside the legend's viewport.
    bar->SetPosition(0.45, 0.1);
    bar->SetWidth(0.5);
  }
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
  const std::string missing = missingDisplay();
  if (missing.empty())
  {
    return true;
  }
  printError("--pictures: " + missing + "; run under 'xvfb-run -a' or leave --pictures out");
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
  const double surfaces = legend ? 1.0 - LegendShare : 1.0;
  for (int k = 0; k < n; ++k)
  {
    const double viewport[4] = { surfaces * k / n, 0.0, surfaces * (k + 1) / n, 1.0 };
    window->AddRenderer(surfaceRenderer(panels[k], viewport));
  }
  if (legend)
  {
    const double viewport[4] = { surfaces, 0.0, 1.0, 1.0 };
    window->AddRenderer(legendRenderer(legend, legendTitle, viewport));
  }
  writeWindow(window, path);
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

// Xlib last: its macros (None, Status, Bool) clash with the VTK headers.
#include <X11/Xlib.h>

std::string surfacemap::missingDisplay()
{
  // VTK's X render window aborts the process when it cannot open the display,
  // so the display is tried here first.
  const char* name = std::getenv("DISPLAY");
  if (!name || !*name)
  {
    return "no display to render on (DISPLAY is not set)";
  }
  // The connection stays open until the process ends: an X server (Xvfb
  // under xvfb-run) resets when its last client leaves, and a picture's
  // window opened during that reset fails (VTK aborts or crashes). Every
  // picture window closes its own connection, so this one keeps the server up.
  static ::Display* held = nullptr;
  if (!held)
  {
    held = XOpenDisplay(nullptr);
  }
  if (!held)
  {
    return std::string("cannot open the display '") + name + "' to render on";
  }
  return "";
}
