#include "vtkSurfaceMapsCombination.h"

#include "vtkSurfaceArrayTransferAlgorithm.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkStringArray.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>
#include <stdexcept>

namespace
{

// Per-input correspondence data that a blend of positions does not carry over.
const char* const DroppedArrays[] = { "SourceCellId", "SourceBarycentric", "SpherePosition" };
const char* const LandmarksName = "Landmarks";

bool isFloating(vtkDataArray* array)
{
  return array->GetDataType() == VTK_FLOAT || array->GetDataType() == VTK_DOUBLE;
}

std::string idList(vtkIdList* ids)
{
  std::ostringstream text;
  text << "(";
  for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
  {
    text << (k ? " " : "") << ids->GetId(k);
  }
  text << ")";
  return text.str();
}

// The array named `name` on every mesh with the type and shape of mesh 0's,
// one tuple per point; empty otherwise.
std::vector<vtkDataArray*> sameArrayOnEveryMesh(const std::vector<vtkPolyData*>& meshes,
  const char* name)
{
  std::vector<vtkDataArray*> arrays;
  vtkDataArray* first = meshes[0]->GetPointData()->GetArray(name);
  for (vtkPolyData* mesh : meshes)
  {
    vtkDataArray* array = mesh->GetPointData()->GetArray(name);
    if (!array || array->GetDataType() != first->GetDataType() ||
      array->GetNumberOfComponents() != first->GetNumberOfComponents() ||
      array->GetNumberOfTuples() != mesh->GetNumberOfPoints())
    {
      return {};
    }
    arrays.push_back(array);
  }
  return arrays;
}

// sum_i c_i A_i a_i per tuple, A_i = rotation_i for rotated vectors, else
// identity; rounded (and clamped to the type's range) for integer types.
vtkSmartPointer<vtkDataArray> combineArray(const std::vector<vtkDataArray*>& arrays,
  const std::vector<double>& coefficients,
  const std::vector<Eigen::Matrix3d>* rotations)
{
  auto result = vtk::TakeSmartPointer(arrays[0]->NewInstance());
  result->SetName(arrays[0]->GetName());
  const int nc = arrays[0]->GetNumberOfComponents();
  const vtkIdType nt = arrays[0]->GetNumberOfTuples();
  result->SetNumberOfComponents(nc);
  for (int c = 0; c < nc; ++c)
  {
    if (const char* component = arrays[0]->GetComponentName(c))
    {
      result->SetComponentName(c, component);
    }
  }
  result->SetNumberOfTuples(nt);
  const bool integer = !isFloating(result);
  const double lowest = result->GetDataTypeMin(), highest = result->GetDataTypeMax();
  std::vector<double> sum(nc), tuple(nc);
  for (vtkIdType t = 0; t < nt; ++t)
  {
    std::fill(sum.begin(), sum.end(), 0.0);
    for (std::size_t i = 0; i < arrays.size(); ++i)
    {
      if (coefficients[i] == 0.0)
      {
        continue;
      }
      arrays[i]->GetTuple(t, tuple.data());
      if (rotations)
      {
        const Eigen::Vector3d r = (*rotations)[i] * Eigen::Vector3d(tuple[0], tuple[1], tuple[2]);
        tuple.assign(r.data(), r.data() + 3);
      }
      for (int c = 0; c < nc; ++c)
      {
        sum[c] += coefficients[i] * tuple[c];
      }
    }
    if (integer)
    {
      for (double& x : sum)
      {
        x = std::min(highest, std::max(lowest, std::round(x)));
      }
    }
    result->SetTuple(t, sum.data());
  }
  return result;
}

} // namespace

std::string vtkSurfaceMapsCombination::Name(vtkPolyData* mesh, const std::string& kind, int index)
{
  std::string name = kind + " " + std::to_string(index);
  auto* files = mesh
    ? vtkStringArray::SafeDownCast(mesh->GetFieldData()->GetAbstractArray("FileName"))
    : nullptr;
  if (files && files->GetNumberOfValues() > 0 && !files->GetValue(0).empty())
  {
    name += " (" + files->GetValue(0) + ")";
  }
  return name;
}

namespace
{
// Every cell of `mesh` uses existing points, and every point is finite.
void checkIndices(vtkPolyData* mesh, const std::string& name)
{
  const vtkIdType np = mesh->GetNumberOfPoints();
  vtkCellArray* arrays[4] = {
    mesh->GetVerts(), mesh->GetLines(), mesh->GetPolys(), mesh->GetStrips()
  };
  vtkIdType offset = 0;
  vtkNew<vtkIdList> ids;
  for (vtkCellArray* cells : arrays)
  {
    const vtkIdType n = cells ? cells->GetNumberOfCells() : 0;
    for (vtkIdType c = 0; c < n; ++c)
    {
      cells->GetCellAtId(c, ids);
      for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
      {
        if (ids->GetId(k) < 0 || ids->GetId(k) >= np)
        {
          throw std::invalid_argument(name + ": cell " + std::to_string(offset + c) +
            " uses vertex index " + std::to_string(ids->GetId(k)) + " (valid are 0 to " +
            std::to_string(np - 1) + ")");
        }
      }
    }
    offset += n;
  }
  for (vtkIdType v = 0; v < np; ++v)
  {
    double p[3];
    mesh->GetPoint(v, p);
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
    {
      throw std::invalid_argument(
        name + " has a vertex with non-finite coordinates (vertex " + std::to_string(v) + ")");
    }
  }
}
} // namespace

void vtkSurfaceMapsCombination::CheckSameConnectivity(const std::vector<vtkPolyData*>& meshes,
  const std::string& kind)
{
  for (std::size_t i = 0; i < meshes.size(); ++i)
  {
    checkIndices(meshes[i], Name(meshes[i], kind, static_cast<int>(i)));
  }
  vtkPolyData* first = meshes[0];
  vtkNew<vtkIdList> a, b;
  for (std::size_t i = 1; i < meshes.size(); ++i)
  {
    vtkPolyData* mesh = meshes[i];
    const std::string prefix = Name(mesh, kind, static_cast<int>(i)) +
      " does not have the connectivity of " + Name(first, kind, 0) + ": ";
    if (mesh->GetNumberOfPoints() != first->GetNumberOfPoints())
    {
      throw std::invalid_argument(prefix + std::to_string(mesh->GetNumberOfPoints()) +
        " points instead of " + std::to_string(first->GetNumberOfPoints()));
    }
    // Cell ids run over verts, lines, polys, strips in this order.
    vtkIdType offset = 0;
    for (int kindIndex = 0; kindIndex < 4; ++kindIndex)
    {
      vtkCellArray* mine = nullptr;
      vtkCellArray* reference = nullptr;
      const char* cellKind = nullptr;
      switch (kindIndex)
      {
        case 0:
          mine = mesh->GetVerts(), reference = first->GetVerts(), cellKind = "vertex cells";
          break;
        case 1:
          mine = mesh->GetLines(), reference = first->GetLines(), cellKind = "lines";
          break;
        case 2:
          mine = mesh->GetPolys(), reference = first->GetPolys(), cellKind = "polygons";
          break;
        default:
          mine = mesh->GetStrips(), reference = first->GetStrips(), cellKind = "strips";
          break;
      }
      const vtkIdType n = mine ? mine->GetNumberOfCells() : 0;
      const vtkIdType m = reference ? reference->GetNumberOfCells() : 0;
      if (n != m)
      {
        throw std::invalid_argument(
          prefix + std::to_string(n) + " " + cellKind + " instead of " + std::to_string(m));
      }
      for (vtkIdType c = 0; c < n; ++c)
      {
        mine->GetCellAtId(c, a);
        reference->GetCellAtId(c, b);
        bool same = a->GetNumberOfIds() == b->GetNumberOfIds();
        for (vtkIdType k = 0; same && k < a->GetNumberOfIds(); ++k)
        {
          same = a->GetId(k) == b->GetId(k);
        }
        if (!same)
        {
          throw std::invalid_argument(prefix + "cell " + std::to_string(offset + c) +
            " has the points " + idList(a) + " instead of " + idList(b));
        }
      }
      offset += n;
    }
  }
}

namespace
{
using surfacemaps::Similarity;

// sum_i c_i T_i(x_i) per point (T_i the identity without `transforms`), in
// the point type of mesh 0.
vtkSmartPointer<vtkPoints> combinedPoints(const std::vector<vtkPolyData*>& meshes,
  const std::vector<double>& coefficients,
  const std::vector<Similarity>& transforms)
{
  vtkPolyData* first = meshes[0];
  const vtkIdType np = first->GetNumberOfPoints();
  vtkNew<vtkPoints> points;
  points->SetDataType(first->GetPoints() ? first->GetPoints()->GetDataType() : VTK_DOUBLE);
  points->SetNumberOfPoints(np);
  for (vtkIdType v = 0; v < np; ++v)
  {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (std::size_t i = 0; i < meshes.size(); ++i)
    {
      if (coefficients[i] == 0.0)
      {
        continue;
      }
      Eigen::Vector3d x;
      meshes[i]->GetPoint(v, x.data());
      if (!transforms.empty())
      {
        const Similarity& s = transforms[i];
        x = s.Scale * (s.Rotation * x) + s.Translation;
      }
      sum += coefficients[i] * x;
    }
    points->SetPoint(v, sum.data());
  }
  return points;
}

// The arrays a blend does not carry: correspondence data and the active
// normals (the surface orientation of one input).
std::set<std::string> droppedArrayNames(vtkPointData* from)
{
  std::set<std::string> dropped(std::begin(DroppedArrays), std::end(DroppedArrays));
  if (vtkDataArray* normals = from->GetNormals())
  {
    if (normals->GetName())
    {
      dropped.insert(normals->GetName());
    }
  }
  return dropped;
}

// Input 0's point arrays, each combined over the inputs that all have it:
// landmarks as input 0's, categorical arrays as the reference input's, the
// active vectors rotated with the transforms.
void combinePointArrays(const std::vector<vtkPolyData*>& meshes,
  const std::vector<double>& coefficients,
  const std::vector<Similarity>& transforms,
  int reference,
  vtkSurfaceArrayTransferAlgorithm* modes,
  vtkPointData* to)
{
  vtkPointData* from = meshes[0]->GetPointData();
  const std::set<std::string> dropped = droppedArrayNames(from);
  const char* vectorsName = from->GetVectors() ? from->GetVectors()->GetName() : nullptr;
  std::vector<Eigen::Matrix3d> rotations;
  for (std::size_t i = 0; i < meshes.size(); ++i)
  {
    rotations.push_back(transforms.empty() ? Eigen::Matrix3d::Identity() : transforms[i].Rotation);
  }
  for (int a = 0; a < from->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = from->GetArray(a);
    const char* name = array ? array->GetName() : nullptr;
    if (!name || dropped.count(name))
    {
      continue;
    }
    if (std::string(name) == LandmarksName)
    {
      to->AddArray(array);
      continue;
    }
    const std::vector<vtkDataArray*> arrays = sameArrayOnEveryMesh(meshes, name);
    if (arrays.empty())
    {
      continue;
    }
    if (modes->ResolveArrayTransferMode(array) ==
      vtkSurfaceArrayTransferAlgorithm::ARRAY_TRANSFER_CATEGORICAL)
    {
      to->AddArray(arrays[reference]);
      continue;
    }
    const bool rotate =
      vectorsName && std::string(name) == vectorsName && array->GetNumberOfComponents() == 3;
    to->AddArray(combineArray(arrays, coefficients, rotate ? &rotations : nullptr));
  }
}

// Input 0's active attributes, where their arrays made it.
void copyActiveAttributes(vtkPointData* from, vtkPointData* to)
{
  for (int attribute : { vtkDataSetAttributes::SCALARS,
         vtkDataSetAttributes::VECTORS,
         vtkDataSetAttributes::TCOORDS,
         vtkDataSetAttributes::TENSORS })
  {
    vtkDataArray* active = from->GetAttribute(attribute);
    if (active && active->GetName() && to->GetArray(active->GetName()))
    {
      to->SetActiveAttribute(active->GetName(), attribute);
    }
  }
}
} // namespace

void vtkSurfaceMapsCombination::Combine(const std::vector<vtkPolyData*>& meshes,
  const std::vector<double>& coefficients,
  const std::vector<Similarity>& transforms,
  int reference,
  vtkSurfaceArrayTransferAlgorithm* modes,
  vtkPolyData* output)
{
  vtkSmartPointer<vtkPoints> points = combinedPoints(meshes, coefficients, transforms);
  output->CopyStructure(meshes[0]);
  output->SetPoints(points);
  combinePointArrays(meshes, coefficients, transforms, reference, modes, output->GetPointData());
  copyActiveAttributes(meshes[0]->GetPointData(), output->GetPointData());
}

bool vtkSurfaceMapsCombination::IndexedValues::Set(int i, double value)
{
  auto found = this->Values.find(i);
  if (found != this->Values.end() && found->second == value)
  {
    return false;
  }
  this->Values[i] = value;
  return true;
}

double vtkSurfaceMapsCombination::IndexedValues::Get(int i, double fallback) const
{
  auto found = this->Values.find(i);
  return found != this->Values.end() ? found->second : fallback;
}

bool vtkSurfaceMapsCombination::IndexedValues::Clear()
{
  const bool changed = !this->Values.empty();
  this->Values.clear();
  return changed;
}

void vtkSurfaceMapsCombination::IndexedValues::Print(ostream& os, const char* whenEmpty) const
{
  if (this->Values.empty())
  {
    os << " " << whenEmpty;
  }
  for (const auto& v : this->Values)
  {
    os << " " << v.first << ": " << v.second;
  }
}

void vtkSurfaceMapsCombination::CheckPresent(const std::vector<vtkPolyData*>& inputs,
  const char* what)
{
  if (inputs.empty())
  {
    throw std::invalid_argument(std::string("no ") + what);
  }
  for (std::size_t i = 0; i < inputs.size(); ++i)
  {
    if (!inputs[i])
    {
      throw std::invalid_argument(
        std::string(what) + " " + std::to_string(i) + " is not a vtkPolyData");
    }
  }
}

surfacemaps::ShapePoints vtkSurfaceMapsCombination::Points(vtkPolyData* mesh)
{
  surfacemaps::ShapePoints points(mesh->GetNumberOfPoints());
  for (vtkIdType v = 0; v < mesh->GetNumberOfPoints(); ++v)
  {
    mesh->GetPoint(v, points[v].data());
  }
  return points;
}

std::vector<std::array<int, 3>> vtkSurfaceMapsCombination::Triangles(vtkPolyData* mesh)
{
  std::vector<std::array<int, 3>> triangles;
  vtkCellArray* polys = mesh->GetPolys();
  if (!polys)
  {
    return triangles;
  }
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < polys->GetNumberOfCells(); ++c)
  {
    polys->GetCellAtId(c, ids);
    for (vtkIdType k = 1; k + 1 < ids->GetNumberOfIds(); ++k)
    {
      triangles.push_back({ static_cast<int>(ids->GetId(0)),
        static_cast<int>(ids->GetId(k)),
        static_cast<int>(ids->GetId(k + 1)) });
    }
  }
  return triangles;
}

void vtkSurfaceMapsCombination::AddField(vtkPolyData* output,
  const char* name,
  int components,
  const std::vector<double>& values)
{
  auto array = vtkSmartPointer<vtkDoubleArray>::New();
  array->SetName(name);
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(static_cast<vtkIdType>(values.size()) / components);
  for (std::size_t k = 0; k < values.size(); ++k)
  {
    array->SetValue(static_cast<vtkIdType>(k), values[k]);
  }
  output->GetFieldData()->AddArray(array);
}

void vtkSurfaceMapsCombination::AddAlignmentFields(vtkPolyData* output,
  const surfacemaps::ProcrustesResult& alignment,
  bool withScale)
{
  std::vector<double> matrices, scales;
  for (const Similarity& s : alignment.transforms)
  {
    for (int r = 0; r < 3; ++r)
    {
      for (int c = 0; c < 3; ++c)
      {
        matrices.push_back(s.Scale * s.Rotation(r, c));
      }
      matrices.push_back(s.Translation(r));
    }
    scales.push_back(s.Scale);
  }
  AddField(output, "AlignmentRMS", 1, alignment.rms);
  AddField(output, "AlignmentTransform", 12, matrices);
  if (withScale)
  {
    AddField(output, "AlignmentScale", 1, scales);
  }
}

surfacemaps::AlignmentKind vtkSurfaceMapsCombination::AlignmentOf(int alignMode)
{
  switch (alignMode)
  {
    case 0:
      return surfacemaps::AlignmentKind::None;
    case 2:
      return surfacemaps::AlignmentKind::Similarity;
    default:
      return surfacemaps::AlignmentKind::Rigid;
  }
}
