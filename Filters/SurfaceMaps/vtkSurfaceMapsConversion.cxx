#include "vtkSurfaceMapsConversion.h"

#include "base/Error.h"
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
const char* const CornerNormalsName = "CornerNormals";

// The cell array `name` of D values per corner (3 D components) as one vector
// per corner; empty unless it fits: pure triangle data (with other cells in
// front of the polygons the cell ids would not line up), one tuple per face.
template<int D>
std::vector<Eigen::Matrix<double, D, 1>> ReadCornerArray(vtkPolyData* input,
  const char* name,
  const surfacemaps::PolygonMesh& mesh)
{
  std::vector<Eigen::Matrix<double, D, 1>> corners;
  vtkDataArray* array = input->GetCellData()->GetArray(name);
  const std::size_t nf = mesh.numberOfFaces();
  if (!array || array->GetNumberOfComponents() != 3 * D || mesh.nonPolygonCells != 0 ||
    array->GetNumberOfTuples() != static_cast<vtkIdType>(nf) || mesh.faceVertices.size() != 3 * nf)
  {
    return corners;
  }
  corners.resize(3 * nf);
  for (std::size_t c = 0; c < corners.size(); ++c)
  {
    for (int d = 0; d < D; ++d)
    {
      corners[c][d] = array->GetComponent(static_cast<vtkIdType>(c / 3), D * (c % 3) + d);
    }
  }
  return corners;
}

// Per-corner vectors, three per triangle of `output` in the order of its
// polygons, added to it as the double cell array `name` with 3 D components
// per triangle.
template<int D>
void AddCornerArray(vtkPolyData* output,
  const char* name,
  const std::vector<Eigen::Matrix<double, D, 1>>& corners)
{
  const std::size_t nf = corners.size() / 3;
  auto array = vtkSmartPointer<vtkDoubleArray>::New();
  array->SetName(name);
  array->SetNumberOfComponents(3 * D);
  array->SetNumberOfTuples(static_cast<vtkIdType>(nf));
  for (std::size_t c = 0; c < corners.size(); ++c)
  {
    for (int d = 0; d < D; ++d)
    {
      array->SetComponent(static_cast<vtkIdType>(c / 3), D * (c % 3) + d, corners[c][d]);
    }
  }
  output->GetCellData()->AddArray(array);
}
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

  mesh.cornerTexCoords = ReadCornerArray<2>(input, CornerTCoordsName, mesh);
  mesh.cornerNormals = ReadCornerArray<3>(input, CornerNormalsName, mesh);
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

  // Per-corner data of a triangle mesh only (one tuple per face).
  const std::size_t nf = mesh.numberOfFaces();
  if (mesh.faceVertices.size() == 3 * nf)
  {
    if (!mesh.cornerTexCoords.empty() && mesh.cornerTexCoords.size() == 3 * nf)
    {
      AddCornerArray<2>(output, CornerTCoordsName, mesh.cornerTexCoords);
    }
    if (!mesh.cornerNormals.empty() && mesh.cornerNormals.size() == 3 * nf)
    {
      AddCornerArray<3>(output, CornerNormalsName, mesh.cornerNormals);
    }
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
    // VTK 9.1's vtkOBJReader makes a point per distinct (v, vt, vn) corner,
    // so a textured mesh read with it is open along its seams, with repeated
    // points there: say what the two defects together usually mean.
    const surfacemaps::MeshStatistics& stats = result.validation.statistics;
    if (stats.boundaryEdges > 0 && stats.duplicateVertices > 0)
    {
      defects.push_back("has both boundary edges and repeated points: if it was read with "
                        "vtkOBJReader (which splits vertices at texture seams), read it with "
                        "vtkSurfaceMeshReader, or merge the points with vtkCleanPolyData");
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

  AddCornerArray<2>(output, CornerTCoordsName,
    surfacemaps::transferCornerValues(
      source.points, source.triangles(), corners, triangles, points));
}

surfacemaps::Logger vtkSurfaceMapsConversion::EngineLog()
{
  surfacemaps::Logger log;
  log.sink = [](surfacemaps::Logger::Level level, const std::string& message)
  {
    // Info (a phase or refinement round done) is the progress `surfacemap -v`
    // shows, at level 1: not on stderr at vtkLogger's default cutoff (INFO),
    // so Python and C++ programs stay quiet; Detail (every iteration) needs -vv.
    if (level == surfacemaps::Logger::Warning)
    {
      vtkLog(WARNING, << message);
    }
    else if (level == surfacemaps::Logger::Info)
    {
      vtkVLog(vtkLogger::VERBOSITY_1, << message);
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
