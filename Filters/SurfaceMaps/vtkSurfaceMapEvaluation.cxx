#include "vtkSurfaceMapEvaluation.h"

#include "vtkSurfaceMapsConversion.h"
#include "vtkSurfaceMapsErrorGuard.h"
#include "vtkSurfaceMapsExecutive.h"

#include "base/Error.h"
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
#include <array>
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

// Points of a triangle mesh at which its distance to another surface is
// measured, each once: the vertices that no triangle uses, the triangles'
// vertices, the edges' midpoints and the triangles' centroids, in that order.
// The points [0, vertices) are all vertices (the Hausdorff distance), the
// points [sampledFrom, end) the samples inside the triangles (the two-sided
// distance).
struct DistanceSamples
{
  std::vector<Eigen::Vector3d> points;
  std::size_t vertices = 0;
  std::size_t sampledFrom = 0;
};

DistanceSamples distanceSamples(vtkPolyData* surface)
{
  const surfacemaps::PolygonMesh mesh = vtkSurfaceMapsConversion::ToPolygonMesh(surface);
  const int nv = static_cast<int>(mesh.points.size());
  std::vector<char> used(nv, 0);
  std::vector<std::array<int, 2>> edges;
  for (std::size_t f = 0; f < mesh.numberOfFaces(); ++f)
  {
    if (mesh.faceSize(f) != 3)
    {
      continue;
    }
    const int* t = mesh.face(f);
    for (int k = 0; k < 3; ++k)
    {
      used[t[k]] = 1;
      edges.push_back({ std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3]) });
    }
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  DistanceSamples samples;
  samples.points.reserve(nv + edges.size() + mesh.numberOfFaces());
  for (int pass = 0; pass < 2; ++pass)
  {
    for (int v = 0; v < nv; ++v)
    {
      if (used[v] == pass)
      {
        samples.points.push_back(mesh.points[v]);
      }
    }
    if (pass == 0)
    {
      samples.sampledFrom = samples.points.size();
    }
  }
  samples.vertices = samples.points.size();
  for (const auto& e : edges)
  {
    samples.points.push_back(0.5 * mesh.points[e[0]] + 0.5 * mesh.points[e[1]]);
  }
  for (std::size_t f = 0; f < mesh.numberOfFaces(); ++f)
  {
    if (mesh.faceSize(f) == 3)
    {
      const int* t = mesh.face(f);
      samples.points.push_back((1 / 3.0) * mesh.points[t[0]] + (1 / 3.0) * mesh.points[t[1]] +
        (1 / 3.0) * mesh.points[t[2]]);
    }
  }
  return samples;
}

// The largest closest-point distances from samples to a surface (over the
// vertices and over the samples inside the triangles), on all threads. Each
// thread queries a locator of its own, built on a shallow copy of the
// surface: VTK 9.1 does not document vtkStaticCellLocator's queries as
// thread-safe, and a locator costs about as much as a few thousand of the
// queries. The maxima do not depend on how the points are split.
class LargestDistance
{
public:
  LargestDistance(const DistanceSamples& samples, vtkPolyData* surface)
    : Samples(samples)
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
        this->Samples.points[i].data(), closest, query.Cell, cellId, subId, distance2);
      const std::size_t k = static_cast<std::size_t>(i);
      if (k < this->Samples.vertices)
      {
        query.LargestVertex = std::max(query.LargestVertex, distance2);
      }
      if (k >= this->Samples.sampledFrom)
      {
        query.LargestSampled = std::max(query.LargestSampled, distance2);
      }
    }
  }

  void Reduce()
  {
    for (const Query& query : this->Queries)
    {
      this->Vertex = std::max(this->Vertex, std::sqrt(query.LargestVertex));
      this->Sampled = std::max(this->Sampled, std::sqrt(query.LargestSampled));
    }
  }

  /// Over the vertices; over the samples inside the triangles.
  double Vertex = 0.0;
  double Sampled = 0.0;

private:
  struct Query
  {
    vtkSmartPointer<vtkPolyData> Surface;
    vtkSmartPointer<vtkStaticCellLocator> Locator;
    vtkSmartPointer<vtkGenericCell> Cell;
    double LargestVertex = 0.0;
    double LargestSampled = 0.0;
  };
  const DistanceSamples& Samples;
  vtkPolyData* Surface;
  vtkSMPThreadLocal<Query> Queries;
};

// The largest distances from `from`'s vertices and from its samples inside
// triangles to the surface `to`: {over the vertices, over the samples}.
std::array<double, 2> largestDistances(vtkPolyData* from, vtkPolyData* to)
{
  const DistanceSamples samples = distanceSamples(from);
  // The shallow copies share the surface's cells: build them once, before
  // the threads read them.
  to->BuildCells();
  LargestDistance largest(samples, to);
  vtkSMPTools::For(0, static_cast<vtkIdType>(samples.points.size()), 1024, largest);
  return { largest.Vertex, largest.Sampled };
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
    const std::array<double, 2> there = largestDistances(originals[k], approximations[k]);
    addField(output, sides[k][0], percentOfDiagonal(there[0], originals[k]));
    const double twoSided =
      std::max(there[1], largestDistances(approximations[k], originals[k])[1]);
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
    vtkSurfaceMapsErrorGuard::Policy(),
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

const char* vtkSurfaceMapEvaluation::GetLastErrorMessage() const
{
  return vtkSurfaceMapsErrorGuard::LastErrorMessage(this);
}

vtkExecutive* vtkSurfaceMapEvaluation::CreateDefaultExecutive()
{
  return vtkSurfaceMapsExecutive::New();
}

void vtkSurfaceMapEvaluation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
