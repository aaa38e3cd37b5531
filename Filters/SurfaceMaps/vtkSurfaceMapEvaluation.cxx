#include "vtkSurfaceMapEvaluation.h"

#include "vtkSurfaceMapsConversion.h"
#include "vtkSurfaceMapsErrorGuard.h"

#include "base/InputError.h"
#include "geometry/MapMetrics.h"
#include "geometry/SphericalTriangulation.h"
#include "mesh/MeshValidation.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkGenericCell.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkStaticCellLocator.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkSurfaceMapEvaluation);

namespace
{

void addField(vtkPolyData* output, const char* name, double value)
{
  auto array = vtkSmartPointer<vtkDoubleArray>::New();
  array->SetName(name);
  array->InsertNextValue(value);
  output->GetFieldData()->AddArray(array);
}

void addCellArray(vtkPolyData* output, const char* name, const std::vector<double>& values)
{
  auto array = vtkSmartPointer<vtkDoubleArray>::New();
  array->SetName(name);
  array->SetNumberOfValues(static_cast<vtkIdType>(values.size()));
  for (std::size_t i = 0; i < values.size(); ++i)
  {
    array->SetValue(static_cast<vtkIdType>(i), values[i]);
  }
  output->GetCellData()->AddArray(array);
}

// The largest closest-point distance from a set of points to a surface, on
// all threads. Each thread queries a locator of its own, built on a shallow
// copy of the surface: VTK 9.1 does not document vtkStaticCellLocator's
// queries as thread-safe, and a locator costs about as much as a few thousand
// of the queries. The maximum does not depend on how the points are split.
class LargestDistance
{
public:
  LargestDistance(const std::vector<Eigen::Vector3d>& points, vtkPolyData* surface)
    : Points(points)
    , Surface(surface)
  {
  }

  void Initialize()
  {
    Query& query = this->Queries.Local();
    query.Surface = vtkSmartPointer<vtkPolyData>::New();
    query.Locator = vtkSmartPointer<vtkStaticCellLocator>::New();
    query.Cell = vtkSmartPointer<vtkGenericCell>::New();
    query.Surface->ShallowCopy(this->Surface);
    query.Locator->SetDataSet(query.Surface);
    query.Locator->BuildLocator();
    query.Largest = 0.0;
  }

  void operator()(vtkIdType begin, vtkIdType end)
  {
    Query& query = this->Queries.Local();
    for (vtkIdType i = begin; i < end; ++i)
    {
      double closest[3], distance2;
      vtkIdType cellId;
      int subId;
      query.Locator->FindClosestPoint(
        this->Points[i].data(), closest, query.Cell, cellId, subId, distance2);
      query.Largest = std::max(query.Largest, distance2);
    }
  }

  void Reduce()
  {
    for (const Query& query : this->Queries)
    {
      this->Result = std::max(this->Result, std::sqrt(query.Largest));
    }
  }

  double Result = 0.0;

private:
  struct Query
  {
    vtkSmartPointer<vtkPolyData> Surface;
    vtkSmartPointer<vtkStaticCellLocator> Locator;
    vtkSmartPointer<vtkGenericCell> Cell;
    double Largest = 0.0;
  };
  const std::vector<Eigen::Vector3d>& Points;
  vtkPolyData* Surface;
  vtkSMPThreadLocal<Query> Queries;
};

double largestDistance(const std::vector<Eigen::Vector3d>& points, vtkPolyData* surface)
{
  // The shallow copies share the surface's cells: build them once, before
  // the threads read them.
  surface->BuildCells();
  LargestDistance largest(points, surface);
  vtkSMPTools::For(0, static_cast<vtkIdType>(points.size()), 1024, largest);
  return largest.Result;
}

// Largest distance from a vertex of `original` to the surface `approximation`.
double largestVertexDistance(vtkPolyData* original, vtkPolyData* approximation)
{
  std::vector<Eigen::Vector3d> points(original->GetNumberOfPoints());
  for (vtkIdType i = 0; i < original->GetNumberOfPoints(); ++i)
  {
    original->GetPoint(i, points[i].data());
  }
  return largestDistance(points, approximation);
}

// Largest distance from points sampled inside the triangles of `from` (their
// vertices, edge midpoints and centroids) to the surface `to`.
double largestSampledDistance(vtkPolyData* from, vtkPolyData* to)
{
  const surfacemaps::PolygonMesh mesh = vtkSurfaceMapsConversion::ToPolygonMesh(from);
  const double weights[7][3] = { { 1, 0, 0 },
    { 0, 1, 0 },
    { 0, 0, 1 },
    { 0.5, 0.5, 0 },
    { 0, 0.5, 0.5 },
    { 0.5, 0, 0.5 },
    { 1 / 3.0, 1 / 3.0, 1 / 3.0 } };
  std::vector<Eigen::Vector3d> points;
  points.reserve(7 * mesh.numberOfFaces());
  for (std::size_t f = 0; f < mesh.numberOfFaces(); ++f)
  {
    if (mesh.faceSize(f) != 3)
    {
      continue;
    }
    const int* t = mesh.face(f);
    for (const auto& w : weights)
    {
      points.push_back(
        w[0] * mesh.points[t[0]] + w[1] * mesh.points[t[1]] + w[2] * mesh.points[t[2]]);
    }
  }
  return largestDistance(points, to);
}

double percentOfDiagonal(double distance, vtkPolyData* reference)
{
  const double diagonal = reference->GetLength();
  return diagonal > 0.0 ? 100.0 * distance / diagonal : 0.0;
}

// P and Q share their points and triangles (throws std::invalid_argument
// naming the first difference otherwise) and are triangle meshes.
void checkSameTriangulation(const surfacemaps::PolygonMesh& P,
  const surfacemaps::PolygonMesh& Q,
  const std::string& sourceName,
  const std::string& targetName)
{
  if (P.points.size() != Q.points.size() || P.faceVertices != Q.faceVertices ||
    P.faceOffsets != Q.faceOffsets)
  {
    std::string where = P.points.size() != Q.points.size()
      ? std::to_string(P.points.size()) + " vs " + std::to_string(Q.points.size()) + " points"
      : "different triangles";
    for (std::size_t f = 0;
         f < std::min(P.numberOfFaces(), Q.numberOfFaces()) && P.points.size() == Q.points.size();
         ++f)
    {
      if (P.faceSize(f) != Q.faceSize(f) ||
        !std::equal(P.face(f), P.face(f) + P.faceSize(f), Q.face(f)))
      {
        where = "first difference at triangle " + std::to_string(f);
        break;
      }
    }
    throw std::invalid_argument(
      sourceName + " and " + targetName + " do not have the same connectivity (" + where + ")");
  }
  for (std::size_t f = 0; f < P.numberOfFaces(); ++f)
  {
    if (P.faceSize(f) != 3)
    {
      throw std::invalid_argument(sourceName + " is not a triangle mesh (face " +
        std::to_string(f) + " has " + std::to_string(P.faceSize(f)) + " vertices)");
    }
  }
}

// Every given input passes the module's input validation, to the extent a
// measurement needs (results may hold degenerate triangles); throws
// surfacemaps::InputError naming the input and the first defects otherwise.
void checkMeasurable(vtkPolyData* const inputs[4])
{
  static const char* const roles[4] = { "source", "target", "source original", "target original" };
  surfacemaps::MeshValidationOptions options;
  options.requireSurface = false;
  std::string message;
  for (int k = 0; k < 4; ++k)
  {
    if (!inputs[k] && k >= 2)
    {
      continue;
    }
    std::string name = roles[k];
    const std::string fileName = vtkSurfaceMapsConversion::InputName(inputs[k], k);
    if (inputs[k] && fileName != "input " + std::to_string(k))
    {
      name = fileName;
    }
    if (!inputs[k])
    {
      message += (message.empty() ? "" : "; ") + name + " is missing";
      continue;
    }
    for (const std::string& d :
      vtkSurfaceMapsConversion::Validate(inputs[k], options).validation.defects)
    {
      message += (message.empty() ? "" : "; ") + name + " " + d;
    }
  }
  if (!message.empty())
  {
    throw surfacemaps::InputError(message);
  }
}

// Per-triangle singular values, distortion and areas, and their summary.
void addDistortion(vtkPolyData* output, const surfacemaps::MapMetrics& metrics)
{
  addCellArray(output, "SingularValueMax", metrics.s1);
  addCellArray(output, "SingularValueMin", metrics.s2);
  addCellArray(output, "MaxStretch", metrics.distortion);
  addCellArray(output, "AreaSource", metrics.areaP);
  addCellArray(output, "AreaTarget", metrics.areaQ);
  addField(output, "SymmetricDirichlet", metrics.symmetricDirichlet);
  addField(output, "AreaBelow1.5", metrics.fractionBelow[0]);
  addField(output, "AreaBelow2", metrics.fractionBelow[1]);
  addField(output, "MaxDistortion", metrics.maxDistortion);
  addField(output, "DegenerateTriangles", static_cast<double>(metrics.degenerateTriangles));
}

// The cumulative distortion curve: area fraction of the source below each
// distortion from 1 to 3 in steps of 0.01.
void addDistortionCurve(vtkPolyData* output, const surfacemaps::MapMetrics& metrics)
{
  std::vector<double> samples;
  for (int k = 0; k <= 200; ++k)
  {
    samples.push_back(1.0 + 0.01 * k);
  }
  const std::vector<double> curve = metrics.cumulativeCurve(samples);
  auto curveArray = vtkSmartPointer<vtkDoubleArray>::New();
  curveArray->SetName("DistortionCurve");
  curveArray->SetNumberOfComponents(2);
  curveArray->SetComponentName(0, "Distortion");
  curveArray->SetComponentName(1, "AreaFractionBelow");
  for (std::size_t k = 0; k < samples.size(); ++k)
  {
    const double pair[2] = { samples[k], curve[k] };
    curveArray->InsertNextTuple(pair);
  }
  output->GetFieldData()->AddArray(curveArray);
}

void addAngles(vtkPolyData* output,
  const surfacemaps::PolygonMesh& P,
  const surfacemaps::PolygonMesh& Q)
{
  const auto sourceStats = surfacemaps::validateMesh(P).statistics;
  const auto targetStats = surfacemaps::validateMesh(Q).statistics;
  addField(output, "MinAngleSource", sourceStats.minAngle);
  addField(output, "MeanMinAngleSource", sourceStats.meanMinAngle);
  addField(output, "MinAngleTarget", targetStats.minAngle);
  addField(output, "MeanMinAngleTarget", targetStats.meanMinAngle);
}

// Hausdorff and two-sided distances of each side to its original, where given.
void addApproximationErrors(vtkPolyData* output,
  vtkPolyData* source,
  vtkPolyData* target,
  vtkPolyData* sourceOriginal,
  vtkPolyData* targetOriginal)
{
  const char* sides[2][3] = { { "HausdorffSource", "TwoSidedDistanceSource", nullptr },
    { "HausdorffTarget", "TwoSidedDistanceTarget", nullptr } };
  vtkPolyData* approximations[2] = { source, target };
  vtkPolyData* originals[2] = { sourceOriginal, targetOriginal };
  for (int k = 0; k < 2; ++k)
  {
    if (!originals[k])
    {
      continue;
    }
    addField(output,
      sides[k][0],
      percentOfDiagonal(largestVertexDistance(originals[k], approximations[k]), originals[k]));
    const double twoSided = std::max(largestSampledDistance(originals[k], approximations[k]),
      largestSampledDistance(approximations[k], originals[k]));
    addField(output, sides[k][1], percentOfDiagonal(twoSided, originals[k]));
  }
}

// Bijectivity of both sides' sphere embeddings, where both are given.
void addBijectivity(vtkPolyData* output,
  vtkPolyData* source,
  vtkPolyData* target,
  const std::vector<std::array<int, 3>>& triangles)
{
  const auto sphereP = vtkSurfaceMapsConversion::SpherePositions(source);
  const auto sphereQ = vtkSurfaceMapsConversion::SpherePositions(target);
  if (!sphereP.empty() && !sphereQ.empty())
  {
    const auto cp = surfacemaps::certifyBijective(sphereP, triangles);
    const auto cq = surfacemaps::certifyBijective(sphereQ, triangles);
    addField(output, "Bijective", cp.bijective && cq.bijective ? 1.0 : 0.0);
    addField(output,
      "NonPositiveTriangles",
      static_cast<double>(cp.nonPositiveTriangles + cq.nonPositiveTriangles));
  }
}

} // namespace

vtkSurfaceMapEvaluation::vtkSurfaceMapEvaluation()
{
  this->SetNumberOfInputPorts(4);
}

int vtkSurfaceMapEvaluation::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  if (port >= 2)
  {
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  }
  return 1;
}

double vtkSurfaceMapEvaluation::GetSummaryValue(const char* name)
{
  vtkPolyData* output = this->GetOutput();
  vtkDataArray* array = output ? output->GetFieldData()->GetArray(name) : nullptr;
  return array && array->GetNumberOfTuples() > 0 ? array->GetTuple1(0)
                                                 : std::numeric_limits<double>::quiet_NaN();
}

int vtkSurfaceMapEvaluation::RequestData(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  vtkPolyData* source = vtkPolyData::GetData(inputVector[0], 0);
  vtkPolyData* target = vtkPolyData::GetData(inputVector[1], 0);
  vtkPolyData* sourceOriginal = vtkPolyData::GetData(inputVector[2], 0);
  vtkPolyData* targetOriginal = vtkPolyData::GetData(inputVector[3], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  output->Initialize();
  return vtkSurfaceMapsErrorGuard::Run(
    this,
    vtkSurfaceMapsErrorGuard::MessageOnly(),
    [&]
    {
      vtkPolyData* const inputs[4] = { source, target, sourceOriginal, targetOriginal };
      checkMeasurable(inputs);
      const surfacemaps::PolygonMesh P = vtkSurfaceMapsConversion::ToPolygonMesh(source);
      const surfacemaps::PolygonMesh Q = vtkSurfaceMapsConversion::ToPolygonMesh(target);
      checkSameTriangulation(P,
        Q,
        vtkSurfaceMapsConversion::InputName(source, 0),
        vtkSurfaceMapsConversion::InputName(target, 1));
      const auto triangles = P.triangles();
      const surfacemaps::MapMetrics metrics =
        surfacemaps::measureMap(P.points, Q.points, triangles);

      output->ShallowCopy(source);
      addDistortion(output, metrics);
      addDistortionCurve(output, metrics);
      addAngles(output, P, Q);
      addApproximationErrors(output, source, target, sourceOriginal, targetOriginal);
      addBijectivity(output, source, target, triangles);
      return 1;
    },
    [output] { output->Initialize(); });
}

void vtkSurfaceMapEvaluation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
