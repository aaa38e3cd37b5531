#include "vtkSurfaceMapOutputs.h"

#include "vtkSurfaceArrayTransferAlgorithm.h"
#include "vtkSurfaceMapsConversion.h"
#include "vtkSurfaceMapsPointDataTransfer.h"

#include "geometry/MapMetrics.h"
#include "map/MapTransfer.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkIntArray.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkStringArray.h"

#include <cmath>
#include <limits>
#include <set>
#include <string>

namespace
{
const char* const LandmarksName = "Landmarks";
const char* const SizingName = "Sizing";
const char* const SpherePositionName = "SpherePosition";
const char* const SourceCellIdName = "SourceCellId";
const char* const SourceBarycentricName = "SourceBarycentric";

template<typename ArrayT, typename T>
void addField(vtkFieldData* fields, const char* name, const std::vector<T>& values)
{
  auto array = vtkSmartPointer<ArrayT>::New();
  array->SetName(name);
  array->SetNumberOfValues(static_cast<vtkIdType>(values.size()));
  for (std::size_t k = 0; k < values.size(); ++k)
  {
    array->SetValue(static_cast<vtkIdType>(k), values[k]);
  }
  fields->AddArray(array);
}

template<typename ArrayT, typename T>
void addField(vtkFieldData* fields, const char* name, T value)
{
  addField<ArrayT>(fields, name, std::vector<T>{ value });
}

vtkSmartPointer<vtkDoubleArray> vectorArray(const char* name,
  const std::vector<Eigen::Vector3d>& values)
{
  auto array = vtkSmartPointer<vtkDoubleArray>::New();
  array->SetName(name);
  array->SetNumberOfComponents(3);
  array->SetNumberOfTuples(static_cast<vtkIdType>(values.size()));
  for (std::size_t v = 0; v < values.size(); ++v)
  {
    array->SetTypedTuple(static_cast<vtkIdType>(v), values[v].data());
  }
  return array;
}

// Per-triangle symmetric Dirichlet density of the map P -> Q (see the class
// documentation): 1 for an isometric triangle.
std::vector<double> distortionPerTriangle(const std::vector<Eigen::Vector3d>& P,
  const std::vector<Eigen::Vector3d>& Q,
  const std::vector<std::array<int, 3>>& triangles)
{
  const surfacemaps::MapMetrics metrics = surfacemaps::measureMap(P, Q, triangles);
  std::vector<double> result(triangles.size(), std::numeric_limits<double>::infinity());
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    const double s1 = metrics.s1[t], s2 = metrics.s2[t];
    const double a0 = metrics.areaP[t], a1 = metrics.areaQ[t];
    if (std::isfinite(metrics.distortion[t]) && s2 > 0.0 && a0 + a1 > 0.0)
    {
      result[t] =
        (a1 * (s1 * s1 + s2 * s2) + a0 * (1.0 / (s1 * s1) + 1.0 / (s2 * s2))) / (2.0 * (a0 + a1));
    }
  }
  return result;
}

// Points and triangles of an output.
void setGeometry(vtkPolyData* output,
  const std::vector<Eigen::Vector3d>& points,
  const std::vector<std::array<int, 3>>& triangles)
{
  surfacemaps::PolygonMesh mesh;
  mesh.points = points;
  for (const auto& t : triangles)
  {
    mesh.addFace({ t[0], t[1], t[2] });
  }
  vtkSmartPointer<vtkPolyData> poly = vtkSurfaceMapsConversion::ToPolyData(mesh);
  output->SetPoints(poly->GetPoints());
  output->SetPolys(poly->GetPolys());
}

// Where the output's points lie on `input` (SourceCellId, SourceBarycentric),
// and the input's own point arrays read there, each continuous or categorical
// as `modes` says. The map's own arrays are not carried over, nor global ids
// (they would no longer be unique) and ghost markers.
void setSourcePointData(vtkPolyData* output,
  vtkPolyData* input,
  const surfacemaps::PolygonMesh& inputMesh,
  const std::vector<surfacemaps::SurfacePoint>& points,
  vtkSurfaceArrayTransferAlgorithm* modes)
{
  vtkPointData* from = input->GetPointData();
  const std::set<std::string> skipped = { LandmarksName,
    SizingName,
    SpherePositionName,
    SourceCellIdName,
    SourceBarycentricName,
    vtkDataSetAttributes::GhostArrayName() };
  vtkAbstractArray* globalIds = from->GetGlobalIds();
  std::vector<vtkAbstractArray*> arrays;
  for (int a = 0; a < from->GetNumberOfArrays(); ++a)
  {
    vtkAbstractArray* array = from->GetAbstractArray(a);
    if (array && array->GetName() && !skipped.count(array->GetName()) && array != globalIds)
    {
      arrays.push_back(array);
    }
  }
  vtkPointData* to = output->GetPointData();
  vtkSurfaceMapsPointDataTransfer::SampleArrays(
    from, arrays, to, inputMesh.triangles(), points, modes);
  vtkSurfaceMapsConversion::AddSourcePoints(to, points);
}

// Input i itself with its sphere embedding f_i as "SpherePosition".
void setEmbeddingOutput(vtkPolyData* output,
  vtkPolyData* input,
  const std::vector<Eigen::Vector3d>& embedding)
{
  output->CopyStructure(input);
  output->GetPointData()->PassData(input->GetPointData());
  output->GetCellData()->PassData(input->GetCellData());
  output->GetPointData()->AddArray(vectorArray(SpherePositionName, embedding));
  output->GetFieldData()->PassData(input->GetFieldData());
}

void setLandmarks(vtkPolyData* output, const std::vector<int>& ids)
{
  const vtkIdType n = output->GetNumberOfPoints();
  auto array = vtkSmartPointer<vtkIntArray>::New();
  array->SetName(LandmarksName);
  array->SetNumberOfValues(n);
  for (vtkIdType v = 0; v < n; ++v)
  {
    array->SetValue(v, static_cast<std::size_t>(n) == ids.size() ? ids[v] : -1);
  }
  output->GetPointData()->AddArray(array);
}

// Field data common to every output: certificate, sizes, energies, phases.
void setMapFieldData(vtkFieldData* fields,
  const surfacemaps::SurfaceMapResult& map,
  const std::vector<double>& embeddingSeconds,
  int index)
{
  bool bijective = !map.certificates.empty();
  for (const auto& c : map.certificates)
  {
    bijective = bijective && c.bijective;
  }
  addField<vtkIntArray>(fields, "InputIndex", index);
  addField<vtkIntArray>(fields, "Bijective", bijective ? 1 : 0);
  addField<vtkDoubleArray>(fields,
    "SphericalDegree",
    index < static_cast<int>(map.certificates.size()) ? map.certificates[index].degree : 0.0);
  addField<vtkIdTypeArray>(fields,
    "CommonVertices",
    static_cast<vtkIdType>(map.spherePositions.empty() ? 0 : map.spherePositions[0].size()));
  addField<vtkIdTypeArray>(fields, "CommonTriangles", static_cast<vtkIdType>(map.triangles.size()));
  addField<vtkDoubleArray>(fields, "Energy", map.energy.total);
  addField<vtkDoubleArray>(fields, "BarrierEnergy", map.energy.barrier);
  addField<vtkDoubleArray>(fields, "MeshEnergy", map.energy.meshQuality);
  addField<vtkDoubleArray>(fields, "ApproximationEnergy", map.energy.approximation);
  addField<vtkDoubleArray>(fields, "MapEnergy", map.energy.distortion);
  addField<vtkDoubleArray>(fields, "LandmarkError", map.landmarkError);
  addField<vtkIntArray>(fields, "SetAsideLandmarks", map.setAsideLandmarks);
  addField<vtkDoubleArray>(fields, "BaseDistance", map.baseDistance[index]);
  addField<vtkDoubleArray>(fields, "ErrorBound", map.errorBound[index]);
  addField<vtkDoubleArray>(fields, "MapSeconds", map.seconds);
  addField<vtkDoubleArray>(fields, "EmbeddingSeconds", embeddingSeconds);

  auto names = vtkSmartPointer<vtkStringArray>::New();
  names->SetName("PhaseName");
  std::vector<int> iterations, converged, stalled, vertices, splits, collapses, flips;
  std::vector<double> energy, landmarkError, seconds, remesh, derivatives, solve, lineSearch;
  for (const surfacemaps::MapPhaseReport& p : map.phases)
  {
    names->InsertNextValue(surfacemaps::phaseName(p.kind));
    iterations.push_back(p.iterations);
    converged.push_back(p.converged ? 1 : 0);
    stalled.push_back(p.stalledIterations);
    energy.push_back(p.energy);
    vertices.push_back(p.vertices);
    splits.push_back(p.splits);
    collapses.push_back(p.collapses);
    flips.push_back(p.flips);
    landmarkError.push_back(p.landmarkError);
    seconds.push_back(p.seconds);
    remesh.push_back(p.remeshSeconds);
    derivatives.push_back(p.derivativeSeconds);
    solve.push_back(p.solveSeconds);
    lineSearch.push_back(p.lineSearchSeconds);
  }
  fields->AddArray(names);
  addField<vtkIntArray>(fields, "PhaseIterations", iterations);
  addField<vtkIntArray>(fields, "PhaseConverged", converged);
  addField<vtkIntArray>(fields, "PhaseStalledIterations", stalled);
  addField<vtkDoubleArray>(fields, "PhaseEnergy", energy);
  addField<vtkIntArray>(fields, "PhaseVertices", vertices);
  addField<vtkIntArray>(fields, "PhaseSplits", splits);
  addField<vtkIntArray>(fields, "PhaseCollapses", collapses);
  addField<vtkIntArray>(fields, "PhaseFlips", flips);
  addField<vtkDoubleArray>(fields, "PhaseLandmarkError", landmarkError);
  addField<vtkDoubleArray>(fields, "PhaseSeconds", seconds);
  addField<vtkDoubleArray>(fields, "PhaseRemeshSeconds", remesh);
  addField<vtkDoubleArray>(fields, "PhaseDerivativeSeconds", derivatives);
  addField<vtkDoubleArray>(fields, "PhaseSolveSeconds", solve);
  addField<vtkDoubleArray>(fields, "PhaseLineSearchSeconds", lineSearch);
}

void setDistortion(vtkPolyData* output, const std::vector<double>& distortion)
{
  auto array = vtkSmartPointer<vtkDoubleArray>::New();
  array->SetName("Distortion");
  array->SetNumberOfValues(static_cast<vtkIdType>(distortion.size()));
  for (std::size_t t = 0; t < distortion.size(); ++t)
  {
    array->SetValue(static_cast<vtkIdType>(t), distortion[t]);
  }
  output->GetCellData()->AddArray(array);
}

} // namespace

vtkSurfaceMapOutputs::vtkSurfaceMapOutputs(const surfacemaps::SurfaceMapResult& map,
  const std::vector<vtkPolyData*>& inputs,
  const std::vector<surfacemaps::MapInput>& mapInputs,
  const std::vector<double>& embeddingSeconds,
  vtkSurfaceArrayTransferAlgorithm* arrayModes)
  : Map(map)
  , Inputs(inputs)
  , MapInputs(mapInputs)
  , EmbeddingSeconds(embeddingSeconds)
  , ArrayModes(arrayModes)
{
}

void vtkSurfaceMapOutputs::InputEmbeddings(const std::vector<vtkPolyData*>& outputs) const
{
  for (std::size_t i = 0; i < outputs.size(); ++i)
  {
    setEmbeddingOutput(outputs[i], this->Inputs[i], this->Map.inputSpherePositions[i]);
    setMapFieldData(
      outputs[i]->GetFieldData(), this->Map, this->EmbeddingSeconds, static_cast<int>(i));
  }
}

void vtkSurfaceMapOutputs::CommonTriangulation(const std::vector<vtkPolyData*>& outputs) const
{
  const surfacemaps::SurfaceMapResult& map = this->Map;
  for (std::size_t i = 0; i < outputs.size(); ++i)
  {
    vtkPolyData* output = outputs[i];
    const surfacemaps::MapInput& input = this->MapInputs[i];
    setGeometry(output, map.lifted[i], map.triangles);
    setSourcePointData(output, this->Inputs[i], input.mesh, map.sourcePoints[i], this->ArrayModes);
    vtkSurfaceMapsConversion::SetCornerTCoords(
      output, input.mesh, map.triangles, map.sourcePoints[i]);
    output->GetPointData()->AddArray(vectorArray(SpherePositionName, map.spherePositions[i]));
    setLandmarks(output, map.landmarks);
    setDistortion(output,
      i == 0 ? std::vector<double>(map.triangles.size(), 1.0)
             : distortionPerTriangle(map.lifted[0], map.lifted[i], map.triangles));
    output->GetFieldData()->PassData(this->Inputs[i]->GetFieldData());
    setMapFieldData(output->GetFieldData(), map, this->EmbeddingSeconds, static_cast<int>(i));
  }
}

void vtkSurfaceMapOutputs::MappedInput(const std::vector<vtkPolyData*>& outputs, int k) const
{
  const int n = static_cast<int>(outputs.size());
  const std::vector<std::array<int, 3>> triangles = this->MapInputs[k].mesh.triangles();
  std::vector<std::vector<surfacemaps::SurfacePoint>> sources(n);
  std::vector<std::vector<Eigen::Vector3d>> points(n);
  for (int j = 0; j < n; ++j)
  {
    sources[j] = surfacemaps::transferVertices(this->Map, this->MapInputs, k, j);
    const std::vector<std::array<int, 3>> onJ = this->MapInputs[j].mesh.triangles();
    for (const surfacemaps::SurfacePoint& p : sources[j])
    {
      points[j].push_back(
        surfacemaps::evaluateSurfacePoint(this->MapInputs[j].mesh.points, onJ, p));
    }
  }
  for (int i = 0; i < n; ++i)
  {
    vtkPolyData* output = outputs[i];
    const surfacemaps::MapInput& input = this->MapInputs[i];
    setGeometry(output, points[i], triangles);
    setSourcePointData(output, this->Inputs[i], input.mesh, sources[i], this->ArrayModes);
    setLandmarks(output, this->MapInputs[k].landmarks);
    output->GetCellData()->PassData(this->Inputs[k]->GetCellData());
    // After the cells of input k: input i's texture replaces k's own.
    vtkSurfaceMapsConversion::SetCornerTCoords(output, input.mesh, triangles, sources[i]);
    setDistortion(output,
      i == k ? std::vector<double>(triangles.size(), 1.0)
             : distortionPerTriangle(points[k], points[i], triangles));
    output->GetFieldData()->PassData(this->Inputs[i]->GetFieldData());
    setMapFieldData(output->GetFieldData(), this->Map, this->EmbeddingSeconds, i);
  }
}
