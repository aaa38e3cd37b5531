#include "EvaluationPictures.h"

#include "EvaluationOutputs.h"
#include "Pictures.h"

#include "vtkCellData.h"
#include "vtkChart.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkLookupTable.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace surfacemap
{

namespace
{

// The distortion shown darkest (as surfaces.render draws it).
const double DistortionShownDarkest = 3.0;
// Squares of the checkerboard along the longest side of the source's box: at
// most 8, fewer on coarse meshes so that every square spans several vertices.
int checkerSquares(vtkIdType vertices)
{
  return std::max(3, std::min(8, static_cast<int>(std::lround(std::sqrt(vertices) / 6.0))));
}

// White at 1 (no distortion) to red at DistortionShownDarkest, dark red above.
vtkSmartPointer<vtkLookupTable> distortionTable()
{
  auto table = vtkSmartPointer<vtkLookupTable>::New();
  table->SetNumberOfTableValues(256);
  for (int i = 0; i < 256; ++i)
  {
    const double t = i / 255.0;
    table->SetTableValue(i, 1.0, 1.0 - 0.8 * t, 1.0 - 0.9 * t, 1.0);
  }
  table->SetTableRange(1.0, DistortionShownDarkest);
  table->SetAboveRangeColor(0.5, 0.0, 0.0, 1.0);
  table->UseAboveRangeColorOn();
  table->Build();
  return table;
}

// Blue and cream squares.
vtkSmartPointer<vtkLookupTable> checkerTable()
{
  auto table = vtkSmartPointer<vtkLookupTable>::New();
  table->SetNumberOfTableValues(2);
  table->SetTableValue(0, 0.15, 0.3, 0.6, 1.0);
  table->SetTableValue(1, 0.95, 0.95, 0.9, 1.0);
  table->SetTableRange(0.0, 1.0);
  table->Build();
  return table;
}

// Per vertex, the parity (0 or 1) of the 3-D checkerboard cell its
// normalised source position lies in; interpolated before mapping, the two
// colours meet half way between vertices of different parity.
vtkSmartPointer<vtkDoubleArray> checkerboard(vtkPolyData* source)
{
  vtkSmartPointer<vtkDoubleArray> positions = sourcePositions(source);
  const int squares = checkerSquares(source->GetNumberOfPoints());
  auto checks = vtkSmartPointer<vtkDoubleArray>::New();
  checks->SetName("Checkerboard");
  checks->SetNumberOfTuples(positions->GetNumberOfTuples());
  for (vtkIdType v = 0; v < positions->GetNumberOfTuples(); ++v)
  {
    long cells = 0;
    for (int k = 0; k < 3; ++k)
    {
      cells += static_cast<long>(std::floor((positions->GetComponent(v, k) + 2.0) * squares / 2.0));
    }
    checks->SetValue(v, static_cast<double>(cells % 2));
  }
  return checks;
}

// `mesh` (geometry only) with the arrays given.
vtkSmartPointer<vtkPolyData> withArrays(vtkPolyData* mesh,
  vtkDataArray* cellArray,
  vtkDataArray* pointArray)
{
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->CopyStructure(mesh);
  copy->GetCellData()->AddArray(cellArray);
  copy->GetPointData()->AddArray(pointArray);
  return copy;
}

// A mapper colouring `mesh` by its array `name` through `table`.
vtkSmartPointer<vtkPolyDataMapper> colouredBy(vtkPolyData* mesh,
  const char* name,
  bool cells,
  vtkLookupTable* table)
{
  vtkSmartPointer<vtkPolyDataMapper> mapper = arrayMapper(mesh, name, cells);
  if (!cells)
  {
    mapper->InterpolateScalarsBeforeMappingOn();
  }
  mapper->SetColorModeToMapScalars();
  mapper->SetLookupTable(table);
  mapper->UseLookupTableScalarRangeOn();
  return mapper;
}

} // namespace

void writeMapPictures(const MapSides& sides, vtkPolyData* result, const std::string& prefix)
{
  vtkDataArray* distortion = result->GetCellData()->GetArray("MaxStretch");
  if (!distortion || distortion->GetNumberOfTuples() != sides.target->GetNumberOfCells())
  {
    throw std::runtime_error("no per-triangle distortion to draw in " + prefix + "distortion.png");
  }
  vtkSmartPointer<vtkDoubleArray> checks = checkerboard(sides.source);
  const vtkSmartPointer<vtkPolyData> meshes[2] = { withArrays(sides.source, distortion, checks),
    withArrays(sides.target, distortion, checks) };
  const std::string captions[2] = { sides.sourceCaption, sides.targetCaption };

  vtkSmartPointer<vtkLookupTable> heat = distortionTable();
  vtkSmartPointer<vtkLookupTable> squares = checkerTable();
  std::vector<SurfacePanel> heatPanels, checkerPanels;
  for (int k = 0; k < 2; ++k)
  {
    heatPanels.push_back({ colouredBy(meshes[k], "MaxStretch", true, heat), captions[k] });
    checkerPanels.push_back({ colouredBy(meshes[k], "Checkerboard", false, squares), captions[k] });
  }
  writeSurfacePicture(heatPanels, heat, "distortion", prefix + "distortion.png");
  writeSurfacePicture(checkerPanels, nullptr, "", prefix + "checkerboard.png");
}

void writeDistortionCurvePicture(const std::vector<std::pair<std::string, vtkPolyData*>>& curves,
  const std::string& path)
{
  ChartPicture chart;
  chart.type = vtkChart::LINE;
  chart.xTitle = "distortion max(s1, 1/s2)";
  chart.yTitle = "area fraction below";
  chart.title = "Cumulative distortion";
  chart.fractionY = true;
  for (const auto& [label, result] : curves)
  {
    vtkDataArray* samples = result->GetFieldData()->GetArray("DistortionCurve");
    if (!samples || samples->GetNumberOfComponents() != 2)
    {
      throw std::runtime_error("no distortion curve to draw in " + path);
    }
    ChartSeries series;
    series.label = label;
    for (vtkIdType k = 0; k < samples->GetNumberOfTuples(); ++k)
    {
      series.x.push_back(samples->GetComponent(k, 0));
      series.y.push_back(samples->GetComponent(k, 1));
    }
    chart.series.push_back(series);
  }
  writeChart(chart, path);
}

} // namespace surfacemap
