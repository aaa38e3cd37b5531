#include "EvaluationPictures.h"

#include "EvaluationOutputs.h"
#include "Pictures.h"

#include "vtkAppendPolyData.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkChart.h"
#include "vtkClipPolyData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkLookupTable.h"
#include "vtkNew.h"
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
// Squares of the checkerboard along the longest side of the source's box.
const int CheckerSquares = 8;

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

// `mesh` with its triangles cut along the planes on which component `axis`
// of its point array `name`, times CheckerSquares / 2, is an integer (the
// array interpolated linearly across each triangle, as the map is): split
// at each plane in turn, the part below kept, the part above cut further.
vtkSmartPointer<vtkPolyData> cutAlong(vtkPolyData* mesh, const char* name, int axis)
{
  auto rest = vtkSmartPointer<vtkPolyData>::New();
  rest->ShallowCopy(mesh);
  double range[2];
  mesh->GetPointData()->GetArray(name)->GetRange(range, axis);
  vtkNew<vtkAppendPolyData> pieces;
  for (double k = std::floor(range[0] * CheckerSquares / 2.0) + 1.0;
       k < range[1] * CheckerSquares / 2.0;
       k += 1.0)
  {
    vtkDataArray* positions = rest->GetPointData()->GetArray(name);
    vtkNew<vtkDoubleArray> scaled;
    scaled->SetName("Cut");
    scaled->SetNumberOfTuples(positions->GetNumberOfTuples());
    for (vtkIdType v = 0; v < positions->GetNumberOfTuples(); ++v)
    {
      scaled->SetValue(v, positions->GetComponent(v, axis) * CheckerSquares / 2.0);
    }
    rest->GetPointData()->SetScalars(scaled);
    vtkNew<vtkClipPolyData> clip;
    clip->SetInputData(rest);
    clip->SetValue(k);
    clip->GenerateClippedOutputOn();
    clip->Update();
    pieces->AddInputData(clip->GetClippedOutput());
    rest = vtkSmartPointer<vtkPolyData>::New();
    rest->ShallowCopy(clip->GetOutput());
  }
  pieces->AddInputData(rest);
  pieces->Update();
  auto result = vtkSmartPointer<vtkPolyData>::New();
  result->ShallowCopy(pieces->GetOutput());
  result->GetPointData()->RemoveArray("Cut");
  return result;
}

// `mesh` (geometry only) with `positions` cut along the checker's planes in
// every axis (cutAlong) and the cell array "Checkerboard": per piece the
// parity (0 or 1) of the cube of side 2 / CheckerSquares its positions'
// centroid lies in. The squares' edges are straight in `positions`: on the
// source they are planar cuts, on the target exactly the map's image of them.
vtkSmartPointer<vtkPolyData> checkered(vtkPolyData* mesh, vtkDataArray* positions)
{
  auto current = vtkSmartPointer<vtkPolyData>::New();
  current->CopyStructure(mesh);
  current->GetPointData()->AddArray(positions);
  current->GetPointData()->SetNormals(smoothNormals(mesh)); // interpolated along the cuts: no seams
  for (int axis = 0; axis < 3; ++axis)
  {
    current = cutAlong(current, positions->GetName(), axis);
  }
  vtkDataArray* cut = current->GetPointData()->GetArray(positions->GetName());
  vtkNew<vtkDoubleArray> checks;
  checks->SetName("Checkerboard");
  vtkCellArray* polygons = current->GetPolys();
  vtkIdType n = 0;
  const vtkIdType* ids = nullptr;
  for (polygons->InitTraversal(); polygons->GetNextCell(n, ids);)
  {
    long cube = 0;
    for (int k = 0; k < 3; ++k)
    {
      double centroid = 0.0;
      for (vtkIdType i = 0; i < n; ++i)
      {
        centroid += cut->GetComponent(ids[i], k) / n;
      }
      cube += static_cast<long>(std::floor((centroid + 2.0) * CheckerSquares / 2.0));
    }
    checks->InsertNextValue(static_cast<double>(cube % 2));
  }
  current->GetCellData()->AddArray(checks);
  return current;
}

// `mesh` (geometry only) with the cell array given.
vtkSmartPointer<vtkPolyData> withArray(vtkPolyData* mesh, vtkDataArray* cellArray)
{
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->CopyStructure(mesh);
  copy->GetCellData()->AddArray(cellArray);
  return copy;
}

// A mapper colouring `mesh` by its cell array `name` through `table`.
vtkSmartPointer<vtkPolyDataMapper> colouredBy(vtkPolyData* mesh,
  const char* name,
  vtkLookupTable* table)
{
  vtkSmartPointer<vtkPolyDataMapper> mapper = arrayMapper(mesh, name, true);
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
  vtkSmartPointer<vtkDoubleArray> positions = sourcePositions(sides.source);
  const vtkSmartPointer<vtkPolyData> meshes[2] = { withArray(sides.source, distortion),
    withArray(sides.target, distortion) };
  const vtkSmartPointer<vtkPolyData> checks[2] = { checkered(sides.source, positions),
    checkered(sides.target, positions) };
  const std::string captions[2] = { sides.sourceCaption, sides.targetCaption };

  vtkSmartPointer<vtkLookupTable> heat = distortionTable();
  vtkSmartPointer<vtkLookupTable> squares = checkerTable();
  std::vector<SurfacePanel> heatPanels, checkerPanels;
  for (int k = 0; k < 2; ++k)
  {
    heatPanels.push_back({ colouredBy(meshes[k], "MaxStretch", heat), captions[k] });
    checkerPanels.push_back({ colouredBy(checks[k], "Checkerboard", squares), captions[k] });
  }
  // The target seen from the source's side: rotated onto it through the map
  // (its points correspond to the source's one by one).
  alignRotation(sides.source->GetPoints(), sides.target->GetPoints(), heatPanels[1].rotation);
  std::copy(&heatPanels[1].rotation[0][0],
    &heatPanels[1].rotation[0][0] + 9,
    &checkerPanels[1].rotation[0][0]);
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
  chart.legendLowerRight = true;
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
