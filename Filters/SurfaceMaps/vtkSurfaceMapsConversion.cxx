#include "vtkSurfaceMapsConversion.h"

#include "base/InputError.h"
#include "map/MapTransfer.h"
#include "mesh/LandmarkValidation.h"

#include "vtkAbstractArray.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkLogger.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStringArray.h"

#include <charconv>
#include <cmath>
#include <limits>
#include <sstream>

namespace
{
const char* const CornerTCoordsName = "CornerTCoords";
}

surfacemaps::PolygonMesh vtkSurfaceMapsConversion::ToPolygonMesh(vtkPolyData* input)
{
  surfacemaps::PolygonMesh mesh;
  vtkPoints* points = input->GetPoints();
  const vtkIdType np = points ? points->GetNumberOfPoints() : 0;
  vtkCellArray* polys = input->GetPolys();
  const vtkIdType corners = polys ? polys->GetNumberOfConnectivityIds() : 0;
  // The engine indexes with int: larger meshes are refused, never wrapped.
  if (np > std::numeric_limits<int>::max() || corners > std::numeric_limits<int>::max())
  {
    const std::string name = InputName(input, 0);
    throw surfacemaps::InputError((name == "input 0" ? std::string("a mesh") : name) +
      " is too large: " + std::to_string(np) + " points and " + std::to_string(corners) +
      " polygon corners (at most " + std::to_string(std::numeric_limits<int>::max()) +
      " of each are supported)");
  }
  mesh.points.resize(np);
  for (vtkIdType i = 0; i < np; ++i)
  {
    points->GetPoint(i, mesh.points[i].data());
  }
  mesh.nonPolygonCells = static_cast<std::size_t>(
    input->GetNumberOfVerts() + input->GetNumberOfLines() + input->GetNumberOfStrips());

  if (polys)
  {
    mesh.faceVertices.reserve(corners);
    auto it = vtk::TakeSmartPointer(polys->NewIterator());
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
    {
      vtkIdType n;
      const vtkIdType* ids;
      it->GetCurrentCell(n, ids);
      for (vtkIdType k = 0; k < n; ++k)
      {
        // Out of int range: -1 (never a valid index), the value kept for messages.
        if (ids[k] < std::numeric_limits<int>::min() || ids[k] > std::numeric_limits<int>::max())
        {
          if (mesh.wideIndices++ == 0)
          {
            mesh.firstWideIndexFace = static_cast<long long>(mesh.numberOfFaces());
            mesh.firstWideIndex = static_cast<long long>(ids[k]);
          }
          mesh.faceVertices.push_back(-1);
          continue;
        }
        mesh.faceVertices.push_back(static_cast<int>(ids[k]));
      }
      mesh.faceOffsets.push_back(static_cast<int>(mesh.faceVertices.size()));
    }
  }

  // Per-corner texture coordinates belong to polygons; with other cells in
  // front of them the cell ids would not line up, so only pure polygon data.
  vtkDataArray* tc = input->GetCellData()->GetArray(CornerTCoordsName);
  if (tc && tc->GetNumberOfComponents() == 6 && mesh.nonPolygonCells == 0 &&
    tc->GetNumberOfTuples() == static_cast<vtkIdType>(mesh.numberOfFaces()) &&
    mesh.faceVertices.size() == 3 * mesh.numberOfFaces())
  {
    mesh.cornerTexCoords.resize(mesh.faceVertices.size());
    double t[6];
    for (std::size_t f = 0; f < mesh.numberOfFaces(); ++f)
    {
      tc->GetTuple(static_cast<vtkIdType>(f), t);
      for (int k = 0; k < 3; ++k)
      {
        mesh.cornerTexCoords[3 * f + k] = Eigen::Vector2d(t[2 * k], t[2 * k + 1]);
      }
    }
  }
  return mesh;
}

vtkSmartPointer<vtkPolyData> vtkSurfaceMapsConversion::ToPolyData(
  const surfacemaps::PolygonMesh& mesh)
{
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(mesh.points.size()));
  for (std::size_t i = 0; i < mesh.points.size(); ++i)
  {
    points->SetPoint(static_cast<vtkIdType>(i), mesh.points[i].data());
  }

  auto offsets = vtkSmartPointer<vtkIdTypeArray>::New();
  offsets->SetNumberOfValues(static_cast<vtkIdType>(mesh.faceOffsets.size()));
  for (std::size_t i = 0; i < mesh.faceOffsets.size(); ++i)
  {
    offsets->SetValue(static_cast<vtkIdType>(i), mesh.faceOffsets[i]);
  }
  auto connectivity = vtkSmartPointer<vtkIdTypeArray>::New();
  connectivity->SetNumberOfValues(static_cast<vtkIdType>(mesh.faceVertices.size()));
  for (std::size_t i = 0; i < mesh.faceVertices.size(); ++i)
  {
    connectivity->SetValue(static_cast<vtkIdType>(i), mesh.faceVertices[i]);
  }
  auto polys = vtkSmartPointer<vtkCellArray>::New();
  polys->SetData(offsets, connectivity);

  auto output = vtkSmartPointer<vtkPolyData>::New();
  output->SetPoints(points);
  output->SetPolys(polys);

  const std::size_t nf = mesh.numberOfFaces();
  if (!mesh.cornerTexCoords.empty() && mesh.faceVertices.size() == 3 * nf &&
    mesh.cornerTexCoords.size() == mesh.faceVertices.size())
  {
    auto tc = vtkSmartPointer<vtkDoubleArray>::New();
    tc->SetName(CornerTCoordsName);
    tc->SetNumberOfComponents(6);
    tc->SetNumberOfTuples(static_cast<vtkIdType>(nf));
    for (std::size_t f = 0; f < nf; ++f)
    {
      for (int k = 0; k < 3; ++k)
      {
        tc->SetComponent(static_cast<vtkIdType>(f), 2 * k, mesh.cornerTexCoords[3 * f + k].x());
        tc->SetComponent(static_cast<vtkIdType>(f), 2 * k + 1, mesh.cornerTexCoords[3 * f + k].y());
      }
    }
    output->GetCellData()->AddArray(tc);
  }
  AddPointArrays(output, mesh);
  return output;
}

void vtkSurfaceMapsConversion::AddPointArrays(vtkPolyData* output, const surfacemaps::PolygonMesh& mesh)
{
  using Type = surfacemaps::PolygonMeshPointArray::Type;
  vtkPointData* pd = output->GetPointData();
  for (const surfacemaps::PolygonMeshPointArray& a : mesh.pointArrays)
  {
    const vtkIdType tuples = static_cast<vtkIdType>(mesh.points.size());
    if (a.values.size() != static_cast<std::size_t>(tuples) * a.components)
    {
      continue; // not one tuple per point: nothing a reader hands over
    }
    vtkSmartPointer<vtkDataArray> array;
    switch (a.type)
    {
      case Type::UInt8:
        array = vtkSmartPointer<vtkUnsignedCharArray>::New();
        break;
      case Type::Int32:
        array = vtkSmartPointer<vtkIntArray>::New();
        break;
      case Type::Int64:
        array = vtkSmartPointer<vtkTypeInt64Array>::New();
        break;
      case Type::Float32:
        array = vtkSmartPointer<vtkFloatArray>::New();
        break;
      case Type::Float64:
        array = vtkSmartPointer<vtkDoubleArray>::New();
        break;
    }
    array->SetName(a.name.c_str());
    array->SetNumberOfComponents(a.components);
    array->SetNumberOfTuples(tuples);
    for (vtkIdType i = 0; i < tuples; ++i)
    {
      for (int c = 0; c < a.components; ++c)
      {
        array->SetComponent(i, c, a.values[static_cast<std::size_t>(i) * a.components + c]);
      }
    }
    // The attribute roles VTK's PLY reader gives them.
    if (a.name == "Normals" && a.components == 3)
    {
      pd->SetNormals(array);
    }
    else if (a.name == "TCoords" && a.components == 2)
    {
      pd->SetTCoords(array);
    }
    else if ((a.name == "RGB" && a.components == 3) || (a.name == "RGBA" && a.components == 4))
    {
      pd->SetScalars(array);
    }
    else
    {
      pd->AddArray(array);
    }
  }
}

surfacemaps::HalfedgeMesh vtkSurfaceMapsConversion::ToHalfedgeMesh(vtkPolyData* input)
{
  return surfacemaps::toHalfedgeMesh(ToPolygonMesh(input));
}

vtkSmartPointer<vtkPolyData> vtkSurfaceMapsConversion::ToPolyData(
  const surfacemaps::HalfedgeMesh& mesh)
{
  return ToPolyData(surfacemaps::toPolygonMesh(mesh));
}

std::vector<Eigen::Vector3d> vtkSurfaceMapsConversion::SpherePositions(vtkPolyData* input)
{
  std::vector<Eigen::Vector3d> positions;
  vtkDataArray* array = input ? input->GetPointData()->GetArray("SpherePosition") : nullptr;
  if (!array || array->GetNumberOfComponents() != 3 ||
    array->GetNumberOfTuples() != input->GetNumberOfPoints())
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

std::vector<int> vtkSurfaceMapsConversion::LandmarkIds(vtkPolyData* input,
  std::vector<std::string>& defects)
{
  std::vector<int> ids;
  vtkAbstractArray* abstract = input->GetPointData()->GetAbstractArray("Landmarks");
  if (!abstract)
  {
    return ids;
  }
  auto* array = vtkDataArray::SafeDownCast(abstract);
  if (!array)
  {
    defects.push_back("has a Landmarks array that is not numeric (one integer id per point, "
                      "-1 for none, is required)");
    return ids;
  }
  if (array->GetNumberOfComponents() != 1)
  {
    defects.push_back("has a Landmarks array with " +
      std::to_string(array->GetNumberOfComponents()) +
      " components (one integer id per point, -1 for none, is required)");
    return ids;
  }
  if (array->GetNumberOfTuples() != input->GetNumberOfPoints())
  {
    defects.push_back("has a Landmarks array of the wrong length (" +
      std::to_string(array->GetNumberOfTuples()) + " values for " +
      std::to_string(input->GetNumberOfPoints()) + " points)");
    return ids;
  }
  ids.resize(static_cast<std::size_t>(array->GetNumberOfTuples()));
  for (vtkIdType i = 0; i < array->GetNumberOfTuples(); ++i)
  {
    const double value = array->GetComponent(i, 0);
    if (!(value >= std::numeric_limits<int>::min() && value <= std::numeric_limits<int>::max()) ||
      value != std::floor(value))
    {
      char text[32];
      const auto end = std::to_chars(text, text + sizeof text, value).ptr; // shortest exact form
      defects.push_back("has a landmark id that is not an integer (" + std::string(text, end) +
        " at vertex " + std::to_string(i) + ")");
      ids.clear();
      return ids;
    }
    ids[i] = static_cast<int>(value);
  }
  return ids;
}

vtkSurfaceMapsConversion::ValidatedInput vtkSurfaceMapsConversion::Validate(vtkPolyData* input,
  const surfacemaps::MeshValidationOptions& options)
{
  ValidatedInput result;
  result.mesh = ToPolygonMesh(input);
  result.validation = surfacemaps::validateMesh(result.mesh, options);
  if (options.requireSurface)
  {
    std::vector<std::string>& defects = result.validation.defects;
    result.landmarkIds = LandmarkIds(input, defects);
    const std::vector<std::string> idDefects = surfacemaps::checkLandmarkIds(result.landmarkIds);
    defects.insert(defects.end(), idDefects.begin(), idDefects.end());
    if (!idDefects.empty())
    {
      result.landmarkIds.clear();
    }
  }
  return result;
}

std::string vtkSurfaceMapsConversion::InputName(vtkPolyData* input, int index)
{
  if (input)
  {
    auto* names = vtkStringArray::SafeDownCast(input->GetFieldData()->GetAbstractArray("FileName"));
    if (names && names->GetNumberOfValues() > 0 && !names->GetValue(0).empty())
    {
      return names->GetValue(0);
    }
  }
  return "input " + std::to_string(index);
}

void vtkSurfaceMapsConversion::AddSourcePoints(vtkPointData* pointData,
  const std::vector<surfacemaps::SurfacePoint>& points)
{
  const vtkIdType n = static_cast<vtkIdType>(points.size());
  auto cellIds = vtkSmartPointer<vtkIdTypeArray>::New();
  cellIds->SetName("SourceCellId");
  cellIds->SetNumberOfValues(n);
  auto barycentric = vtkSmartPointer<vtkDoubleArray>::New();
  barycentric->SetName("SourceBarycentric");
  barycentric->SetNumberOfComponents(3);
  barycentric->SetNumberOfTuples(n);
  for (vtkIdType v = 0; v < n; ++v)
  {
    cellIds->SetValue(v, points[v].triangle);
    barycentric->SetTypedTuple(v, points[v].barycentric.data());
  }
  pointData->AddArray(cellIds);
  pointData->AddArray(barycentric);
}

void vtkSurfaceMapsConversion::SetCornerTCoords(vtkPolyData* output,
  const surfacemaps::PolygonMesh& source,
  const std::vector<std::array<int, 3>>& triangles,
  const std::vector<surfacemaps::SurfacePoint>& points)
{
  const std::vector<Eigen::Vector2d>& corners = source.cornerTexCoords;
  if (corners.empty())
  {
    return;
  }
  auto array = vtkSmartPointer<vtkDoubleArray>::New();
  array->SetName("TCoords");
  array->SetNumberOfComponents(2);
  array->SetNumberOfTuples(static_cast<vtkIdType>(points.size()));
  for (std::size_t v = 0; v < points.size(); ++v)
  {
    const Eigen::Vector2d t = surfacemaps::evaluateCornerValues(corners, points[v]);
    array->SetTypedTuple(static_cast<vtkIdType>(v), t.data());
  }
  output->GetPointData()->SetTCoords(array);

  const std::vector<Eigen::Vector2d> values = surfacemaps::transferCornerValues(
    source.points, source.triangles(), corners, triangles, points);
  auto cornerArray = vtkSmartPointer<vtkDoubleArray>::New();
  cornerArray->SetName(CornerTCoordsName);
  cornerArray->SetNumberOfComponents(6);
  cornerArray->SetNumberOfTuples(static_cast<vtkIdType>(triangles.size()));
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    cornerArray->SetTypedTuple(static_cast<vtkIdType>(t), values[3 * t].data());
  }
  output->GetCellData()->AddArray(cornerArray);
}

surfacemaps::Logger vtkSurfaceMapsConversion::EngineLog()
{
  surfacemaps::Logger log;
  log.sink = [](surfacemaps::Logger::Level level, const std::string& message)
  {
    if (level == surfacemaps::Logger::Warning)
    {
      vtkLog(WARNING, << message);
    }
    else
    {
      vtkLog(TRACE, << message);
    }
  };
  return log;
}

std::vector<vtkPolyData*> vtkSurfaceMapsConversion::PolyDataOf(vtkInformationVector* vector)
{
  std::vector<vtkPolyData*> data(vector->GetNumberOfInformationObjects());
  for (std::size_t i = 0; i < data.size(); ++i)
  {
    data[i] = vtkPolyData::GetData(vector, static_cast<int>(i));
  }
  return data;
}
