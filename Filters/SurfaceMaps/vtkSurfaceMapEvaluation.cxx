#include "vtkSurfaceMapEvaluation.h"

#include "vtkSurfaceMapsConversion.h"

#include "MapMetrics.h"
#include "MeshValidation.h"
#include "SphericalTriangulation.h"

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
#include "vtkSmartPointer.h"
#include "vtkStaticCellLocator.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

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

std::vector<Eigen::Vector3d> spherePositions(vtkPolyData* mesh)
{
  std::vector<Eigen::Vector3d> positions;
  vtkDataArray* array = mesh->GetPointData()->GetArray("SpherePosition");
  if (!array || array->GetNumberOfComponents() != 3 ||
    array->GetNumberOfTuples() != mesh->GetNumberOfPoints())
  {
    return positions;
  }
  positions.resize(static_cast<std::size_t>(array->GetNumberOfTuples()));
  for (vtkIdType i = 0; i < array->GetNumberOfTuples(); ++i)
  {
    array->GetTuple(i, positions[i].data());
  }
  return positions;
}

// Largest distance from a vertex of `original` to the surface `approximation`,
// in percent of the original's bounding-box diagonal.
double hausdorffPercent(vtkPolyData* original, vtkPolyData* approximation)
{
  vtkNew<vtkStaticCellLocator> locator;
  locator->SetDataSet(approximation);
  locator->BuildLocator();
  vtkNew<vtkGenericCell> cell;
  double largest = 0.0;
  for (vtkIdType i = 0; i < original->GetNumberOfPoints(); ++i)
  {
    double p[3], closest[3], distance2;
    vtkIdType cellId;
    int subId;
    original->GetPoint(i, p);
    locator->FindClosestPoint(p, closest, cell, cellId, subId, distance2);
    largest = std::max(largest, std::sqrt(distance2));
  }
  const double diagonal = original->GetLength();
  return diagonal > 0.0 ? 100.0 * largest / diagonal : 0.0;
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
  try
  {
    const surfacemaps::PolygonMesh P = vtkSurfaceMapsConversion::ToPolygonMesh(source);
    const surfacemaps::PolygonMesh Q = vtkSurfaceMapsConversion::ToPolygonMesh(target);
    const std::string sourceName = vtkSurfaceMapsConversion::InputName(source, 0);
    const std::string targetName = vtkSurfaceMapsConversion::InputName(target, 1);
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
    const auto triangles = P.triangles();
    const surfacemaps::MapMetrics metrics = surfacemaps::measureMap(P.points, Q.points, triangles);

    output->ShallowCopy(source);
    addCellArray(output, "SingularValueMax", metrics.s1);
    addCellArray(output, "SingularValueMin", metrics.s2);
    addCellArray(output, "Distortion", metrics.distortion);
    addCellArray(output, "AreaSource", metrics.areaP);
    addCellArray(output, "AreaTarget", metrics.areaQ);
    addField(output, "SymmetricDirichlet", metrics.symmetricDirichlet);
    addField(output, "AreaBelow1.5", metrics.fractionBelow[0]);
    addField(output, "AreaBelow2", metrics.fractionBelow[1]);
    addField(output, "MaxDistortion", metrics.maxDistortion);
    addField(output, "DegenerateTriangles", static_cast<double>(metrics.degenerateTriangles));
    // The cumulative distortion curve: area fraction of the source below
    // each distortion from 1 to 3 in steps of 0.01.
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
    const auto sourceStats = surfacemaps::validateMesh(P).statistics;
    const auto targetStats = surfacemaps::validateMesh(Q).statistics;
    addField(output, "MinAngleSource", sourceStats.minAngle);
    addField(output, "MeanMinAngleSource", sourceStats.meanMinAngle);
    addField(output, "MinAngleTarget", targetStats.minAngle);
    addField(output, "MeanMinAngleTarget", targetStats.meanMinAngle);
    if (sourceOriginal)
    {
      addField(output, "HausdorffSource", hausdorffPercent(sourceOriginal, source));
    }
    if (targetOriginal)
    {
      addField(output, "HausdorffTarget", hausdorffPercent(targetOriginal, target));
    }
    const auto sphereP = spherePositions(source);
    const auto sphereQ = spherePositions(target);
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
  catch (const std::exception& e)
  {
    output->Initialize();
    vtkErrorMacro(<< e.what());
    return 0;
  }
  return 1;
}

void vtkSurfaceMapEvaluation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
