#include "StatisticsPictures.h"

#include "CommandSupport.h"

#include "vtkActor.h"
#include "vtkAxis.h"
#include "vtkCamera.h"
#include "vtkChartXY.h"
#include "vtkContextScene.h"
#include "vtkContextView.h"
#include "vtkDoubleArray.h"
#include "vtkLookupTable.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkPlot.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkScalarBarActor.h"
#include "vtkTable.h"
#include "vtkTextProperty.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWindowToImageFilter.h"

#include <cstdlib>
#include <stdexcept>

namespace surfacemap
{

namespace
{

const int Width = 800, Height = 600;

// The window's picture as PNG, written atomically to `path`.
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

vtkSmartPointer<vtkDoubleArray> column(const char* name, const std::vector<double>& values)
{
  auto array = vtkSmartPointer<vtkDoubleArray>::New();
  array->SetName(name);
  for (double v : values)
  {
    array->InsertNextValue(v);
  }
  return array;
}

// A chart of one plot (x, y) with axis titles, rendered to `path`; with
// `integerX`, one tick per x value (the x are 1, 2, ...).
void writeChart(int type,
  bool integerX,
  const std::vector<double>& x,
  const std::vector<double>& y,
  const char* xTitle,
  const char* yTitle,
  const char* title,
  const std::string& path)
{
  vtkNew<vtkTable> table;
  table->AddColumn(column(xTitle, x));
  table->AddColumn(column(yTitle, y));
  vtkNew<vtkContextView> view;
  view->GetRenderer()->SetBackground(1.0, 1.0, 1.0);
  view->GetRenderWindow()->SetOffScreenRendering(1);
  view->GetRenderWindow()->SetSize(Width, Height);
  vtkNew<vtkChartXY> chart;
  view->GetScene()->AddItem(chart);
  chart->SetTitle(title);
  vtkPlot* plot = chart->AddPlot(type);
  plot->SetInputData(table, 0, 1);
  plot->SetColor(51, 102, 178, 255);
  chart->GetAxis(vtkAxis::BOTTOM)->SetTitle(xTitle);
  if (integerX && !x.empty())
  {
    vtkAxis* axis = chart->GetAxis(vtkAxis::BOTTOM);
    vtkNew<vtkDoubleArray> ticks;
    for (double value : x)
    {
      ticks->InsertNextValue(value);
    }
    axis->SetCustomTickPositions(ticks);
    axis->SetBehavior(vtkAxis::FIXED);
    axis->SetRange(x.front() - 0.6, x.back() + 0.6);
  }
  chart->GetAxis(vtkAxis::LEFT)->SetTitle(yTitle);
  writeWindow(view->GetRenderWindow(), path);
}

} // namespace

void writeExplainedVariancePicture(const std::vector<double>& fractions, const std::string& path)
{
  std::vector<double> modes, percent;
  for (std::size_t m = 0; m < fractions.size(); ++m)
  {
    modes.push_back(m + 1.0);
    percent.push_back(100.0 * fractions[m]);
  }
  writeChart(vtkChart::BAR, true, modes, percent, "mode", "explained variance (%)",
    "Explained variance per mode", path);
}

void writeScoresPicture(const std::vector<double>& scores, int modes, const std::string& path)
{
  std::vector<double> x, y;
  const std::size_t n = modes > 0 ? scores.size() / modes : 0;
  for (std::size_t i = 0; i < n; ++i)
  {
    x.push_back(modes >= 2 ? scores[i * modes] : static_cast<double>(i));
    y.push_back(scores[i * modes + (modes >= 2 ? 1 : 0)]);
  }
  if (modes >= 2)
  {
    writeChart(vtkChart::POINTS, false, x, y, "score on mode 1", "score on mode 2",
      "Specimens on the first two modes", path);
  }
  else
  {
    writeChart(vtkChart::POINTS, false, x, y, "specimen", "score on mode 1", "Specimens on mode 1", path);
  }
}

void writeSpreadPicture(vtkPolyData* mean, const std::string& path)
{
  double range[2] = { 0.0, 1.0 };
  mean->GetPointData()->GetArray("StandardDeviation")->GetRange(range, 0);
  if (!(range[1] > range[0]))
  {
    range[1] = range[0] + 1.0;
  }
  vtkNew<vtkLookupTable> colours;
  colours->SetHueRange(0.667, 0.0); // blue (little spread) to red (much)
  colours->SetTableRange(range);
  colours->Build();
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(mean);
  mapper->SetScalarModeToUsePointFieldData();
  mapper->SelectColorArray("StandardDeviation");
  mapper->SetLookupTable(colours);
  mapper->SetScalarRange(range);
  mapper->ScalarVisibilityOn();
  mapper->InterpolateScalarsBeforeMappingOn();
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  vtkNew<vtkScalarBarActor> bar;
  bar->SetLookupTable(colours);
  bar->SetTitle("standard deviation");
  bar->GetTitleTextProperty()->SetColor(0.0, 0.0, 0.0);
  bar->GetLabelTextProperty()->SetColor(0.0, 0.0, 0.0);
  bar->SetNumberOfLabels(5);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->AddActor2D(bar);
  renderer->SetBackground(1.0, 1.0, 1.0);
  renderer->ResetCamera();
  renderer->GetActiveCamera()->Azimuth(30.0);
  renderer->GetActiveCamera()->Elevation(20.0);
  renderer->GetActiveCamera()->Zoom(1.3); // the shape, not its bounding sphere, fills the picture
  renderer->ResetCameraClippingRange();
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->AddRenderer(renderer);
  window->SetSize(Width, Height);
  writeWindow(window, path);
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
  ::Display* display = XOpenDisplay(nullptr);
  if (!display)
  {
    return std::string("cannot open the display '") + name + "' to render on";
  }
  XCloseDisplay(display);
  return "";
}
