#include "vtkSurfaceMapTransfer.h"

#include "vtkSurfaceMapsCombination.h"
#include "vtkSurfaceMapsConversion.h"
#include "vtkSurfaceMapsErrorGuard.h"
#include "vtkSurfaceMapsPointDataTransfer.h"

#include "base/Error.h"
#include "geometry/SphericalTriangulation.h"
#include "map/MapTransfer.h"
#include "mesh/MeshValidation.h"

#include "vtkAbstractArray.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkSurfaceMapTransfer);

static_assert(
  vtkSurfaceMapTransfer::InvalidInputError == vtkSurfaceMapsErrorGuard::InvalidInputError,
  "the module's error codes");

struct vtkSurfaceMapTransfer::vtkInternals
{
  std::vector<std::string> ArrayNames;
};

namespace
{
const char* const SpherePositionName = "SpherePosition";
const char* const SourceCellIdName = "SourceCellId";
const char* const SourceBarycentricName = "SourceBarycentric";

// Largest deviation of a SpherePosition's length from 1 (the map writes
// normalised doubles; anything further off is not a sphere embedding). The
// values are used as given, not normalised again: point location only
// depends on directions, and the exact values keep a transfer from saved
// files bit for bit equal to the map filter's own mapped output.
const double UnitTolerance = 1e-6;

// "port 2 (T on the target, common_1.vtp)".
std::string portName(vtkPolyData* data, int port)
{
  static const char* const roles[4] = { "target mesh",
    "source mesh",
    "common triangulation on the target",
    "common triangulation on the source" };
  std::string name = "port " + std::to_string(port) + " (" + roles[port];
  const std::string file = vtkSurfaceMapsConversion::InputName(data, port);
  if (file != "input " + std::to_string(port))
  {
    name += ", " + file;
  }
  return name + ")";
}

// One input: its triangles and its certified sphere embedding.
struct PortMesh
{
  std::string name;
  surfacemaps::PolygonMesh mesh;
  std::vector<std::array<int, 3>> triangles;
  std::vector<Eigen::Vector3d> sphere;
};

PortMesh readPort(vtkPolyData* data, int port)
{
  PortMesh p;
  p.name = portName(data, port);
  if (!data || data->GetNumberOfPoints() == 0 || data->GetNumberOfCells() == 0)
  {
    throw surfacemaps::InputError(p.name + " is empty");
  }
  // The module's input validation, as far as a lookup needs (ids in range
  // for 64-bit, triangles only, finite coordinates).
  surfacemaps::MeshValidationOptions options;
  options.requireSurface = false;
  vtkSurfaceMapsConversion::ValidatedInput validated =
    vtkSurfaceMapsConversion::Validate(data, options);
  if (!validated.validation.valid())
  {
    std::string message;
    for (const std::string& d : validated.validation.defects)
    {
      message += (message.empty() ? "" : "; ") + p.name + " " + d;
    }
    throw surfacemaps::InputError(message);
  }
  p.mesh = std::move(validated.mesh);
  const std::size_t nv = p.mesh.points.size();
  p.triangles = p.mesh.triangles();

  vtkDataArray* array = data->GetPointData()->GetArray(SpherePositionName);
  if (!array)
  {
    throw surfacemaps::InputError(
      p.name + " has no SpherePosition point array (its sphere embedding in the map's frame)");
  }
  p.sphere = vtkSurfaceMapsConversion::SpherePositions(data);
  if (p.sphere.empty())
  {
    throw surfacemaps::InputError(p.name + " has a SpherePosition array of the wrong shape (" +
      std::to_string(array->GetNumberOfTuples()) + " x " +
      std::to_string(array->GetNumberOfComponents()) + " values for " + std::to_string(nv) +
      " points)");
  }
  for (std::size_t v = 0; v < nv; ++v)
  {
    const double length = p.sphere[v].norm();
    if (!(std::abs(length - 1.0) <= UnitTolerance))
    {
      throw surfacemaps::InputError(p.name +
        " has a SpherePosition that is not a unit vector at point " + std::to_string(v) +
        " (length " + std::to_string(length) + ")");
    }
  }
  const surfacemaps::BijectivityCertificate certificate =
    surfacemaps::certifyBijective(p.sphere, p.triangles);
  if (!certificate.bijective)
  {
    throw surfacemaps::InputError(p.name +
      " has a SpherePosition array that is not a bijective embedding: " + certificate.reason);
  }
  return p;
}

// Ports 2 and 3 are the same triangulation T (lifted onto two inputs).
void checkSameTriangulation(const PortMesh& onTarget, const PortMesh& onSource)
{
  std::string where;
  if (onTarget.mesh.points.size() != onSource.mesh.points.size())
  {
    where = std::to_string(onTarget.mesh.points.size()) + " vs " +
      std::to_string(onSource.mesh.points.size()) + " points";
  }
  else if (onTarget.triangles.size() != onSource.triangles.size())
  {
    where = std::to_string(onTarget.triangles.size()) + " vs " +
      std::to_string(onSource.triangles.size()) + " triangles";
  }
  else
  {
    for (std::size_t t = 0; t < onTarget.triangles.size() && where.empty(); ++t)
    {
      if (onTarget.triangles[t] != onSource.triangles[t])
      {
        where = "first difference at triangle " + std::to_string(t);
      }
    }
  }
  if (!where.empty())
  {
    throw surfacemaps::InputError(onTarget.name + " and " + onSource.name +
      " do not hold the same common triangulation (" + where + ")");
  }
}

// Where point location on the source starts for each T vertex: T's
// "SourceCellId" on the source when it names source triangles, else nothing.
std::vector<int> startTriangles(vtkPolyData* commonOnSource, std::size_t sourceTriangles)
{
  vtkDataArray* ids = commonOnSource->GetPointData()->GetArray(SourceCellIdName);
  if (!ids || ids->GetNumberOfComponents() != 1 ||
    ids->GetNumberOfTuples() != commonOnSource->GetNumberOfPoints())
  {
    return {};
  }
  std::vector<int> start(static_cast<std::size_t>(ids->GetNumberOfTuples()));
  for (vtkIdType v = 0; v < ids->GetNumberOfTuples(); ++v)
  {
    const double t = ids->GetComponent(v, 0);
    if (!(t >= 0.0 && t < static_cast<double>(sourceTriangles)))
    {
      return {};
    }
    start[v] = static_cast<int>(t);
  }
  return start;
}

// The source arrays to transfer: the named ones (each must exist), or all but
// the map's own bookkeeping arrays and ids.
std::vector<vtkAbstractArray*> selectArrays(vtkPointData* source,
  const std::vector<std::string>& names,
  const std::string& sourceName)
{
  std::vector<vtkAbstractArray*> arrays;
  if (names.empty())
  {
    for (int a = 0; a < source->GetNumberOfArrays(); ++a)
    {
      vtkAbstractArray* array = source->GetAbstractArray(a);
      const std::string name = array && array->GetName() ? array->GetName() : "";
      if (name.empty() || name == SpherePositionName || name == "Landmarks" ||
        name == SourceCellIdName || name == SourceBarycentricName ||
        array->GetDataType() == VTK_ID_TYPE)
      {
        continue;
      }
      arrays.push_back(array);
    }
    return arrays;
  }
  for (const std::string& name : names)
  {
    if (name == SourceCellIdName || name == SourceBarycentricName)
    {
      throw surfacemaps::InputError(
        "'" + name + "' cannot be transferred: the output has its own array of that name");
    }
    vtkAbstractArray* array = source->GetAbstractArray(name.c_str());
    if (!array)
    {
      std::string present;
      for (int a = 0; a < source->GetNumberOfArrays(); ++a)
      {
        const char* n = source->GetArrayName(a);
        present += (present.empty() ? "" : ", ") + std::string(n ? n : "(unnamed)");
      }
      throw surfacemaps::InputError(sourceName + " has no point array '" + name +
        "' (point arrays: " + (present.empty() ? "none" : present) + ")");
    }
    arrays.push_back(array);
  }
  return arrays;
}

// The four meshes with their certified embeddings f_to, f_from, g_to, g_from;
// ports 2 and 3 checked to hold the same triangulation.
struct Ports
{
  PortMesh Target, Source, CommonOnTarget, CommonOnSource;
};

Ports readPorts(vtkPolyData* const inputs[4])
{
  PortMesh ports[4];
  for (int port = 0; port < 4; ++port)
  {
    ports[port] = readPort(inputs[port], port);
  }
  checkSameTriangulation(ports[2], ports[3]);
  return { std::move(ports[0]), std::move(ports[1]), std::move(ports[2]), std::move(ports[3]) };
}

// Every target vertex through the map onto the source.
std::vector<surfacemaps::SurfacePoint> mapTargetVertices(const Ports& ports,
  vtkPolyData* commonOnSource)
{
  surfacemaps::MapTransferOptions options;
  options.startTriangles = startTriangles(commonOnSource, ports.Source.triangles.size());
  // The same input on both sides: the identity, exact at the vertices.
  options.identity = ports.Target.sphere == ports.Source.sphere &&
    ports.Target.triangles == ports.Source.triangles &&
    ports.CommonOnTarget.sphere == ports.CommonOnSource.sphere;
  return surfacemaps::transferPoints(ports.Target.sphere,
    ports.CommonOnTarget.triangles,
    ports.CommonOnTarget.sphere,
    ports.CommonOnSource.sphere,
    ports.Source.sphere,
    ports.Source.triangles,
    options);
}

// The target with the source's arrays (and point texture coordinates, unless
// the source has per-corner ones) sampled at the mapped points, each in the
// mode `modes` gives it.
void sampleOntoTarget(vtkPolyData* output,
  vtkPolyData* target,
  const std::vector<std::array<int, 3>>& targetTriangles,
  vtkPolyData* source,
  const PortMesh& sourcePort,
  const std::vector<vtkAbstractArray*>& arrays,
  const std::vector<surfacemaps::SurfacePoint>& points,
  vtkSurfaceArrayTransferAlgorithm* modes)
{
  output->CopyStructure(target);
  output->GetCellData()->PassData(target->GetCellData());
  output->GetFieldData()->PassData(target->GetFieldData());
  vtkPointData* from = source->GetPointData();
  vtkPointData* to = output->GetPointData();
  std::vector<vtkAbstractArray*> transferred = arrays;
  vtkDataArray* pointTCoords = from->GetTCoords();
  const bool cornerTCoords = !sourcePort.mesh.cornerTexCoords.empty();
  if (pointTCoords && !cornerTCoords &&
    std::find(transferred.begin(), transferred.end(), pointTCoords) == transferred.end())
  {
    transferred.push_back(pointTCoords);
  }
  vtkSurfaceMapsPointDataTransfer::SampleArrays(
    from, transferred, to, sourcePort.triangles, points, modes);
  vtkSurfaceMapsConversion::AddSourcePoints(to, points);
  vtkSurfaceMapsConversion::SetCornerTCoords(output, sourcePort.mesh, targetTriangles, points);
}

} // namespace

vtkSurfaceMapTransfer::vtkSurfaceMapTransfer()
  : Internals(new vtkInternals)
{
  this->SetNumberOfInputPorts(4);
  this->SetNumberOfOutputPorts(1);
}

vtkSurfaceMapTransfer::~vtkSurfaceMapTransfer() = default;

void vtkSurfaceMapTransfer::AddArrayName(const char* name)
{
  if (!name)
  {
    return;
  }
  this->Internals->ArrayNames.emplace_back(name);
  this->Modified();
}

void vtkSurfaceMapTransfer::RemoveAllArrayNames()
{
  if (!this->Internals->ArrayNames.empty())
  {
    this->Internals->ArrayNames.clear();
    this->Modified();
  }
}

int vtkSurfaceMapTransfer::GetNumberOfArrayNames()
{
  return static_cast<int>(this->Internals->ArrayNames.size());
}

const char* vtkSurfaceMapTransfer::GetArrayName(int index)
{
  return index >= 0 && index < this->GetNumberOfArrayNames()
    ? this->Internals->ArrayNames[index].c_str()
    : nullptr;
}

int vtkSurfaceMapTransfer::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

int vtkSurfaceMapTransfer::RequestData(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  vtkPolyData* inputs[4];
  for (int port = 0; port < 4; ++port)
  {
    inputs[port] = vtkPolyData::GetData(inputVector[port], 0);
  }
  vtkPolyData* target = inputs[0];
  vtkPolyData* source = inputs[1];
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  output->Initialize();

  // Point location fails only on embeddings that are not bijective, which
  // readPorts certified: anything but an InputError is an internal error.
  const vtkSurfaceMapsErrorGuard::Report internal{ "internal error: ", vtkErrorCode::UnknownError };
  vtkSurfaceMapsErrorGuard::Policy policy;
  policy.NoResultError = internal;
  policy.OtherError = internal;
  return vtkSurfaceMapsErrorGuard::Run(
    this,
    policy,
    [&]
    {
      this->SetProgressText("Checking the map's embeddings");
      this->UpdateProgress(0.0);
      const Ports ports = readPorts(inputs);
      const std::vector<vtkAbstractArray*> arrays =
        selectArrays(source->GetPointData(), this->Internals->ArrayNames, ports.Source.name);
      if (this->GetAbortExecute())
      {
        return 1;
      }

      this->SetProgressText("Mapping the target's vertices onto the source");
      this->UpdateProgress(0.4);
      const std::vector<surfacemaps::SurfacePoint> points = mapTargetVertices(ports, inputs[3]);

      this->SetProgressText("Sampling the source's point data");
      this->UpdateProgress(0.8);
      sampleOntoTarget(
        output, target, ports.Target.triangles, source, ports.Source, arrays, points, this);
      this->UpdateProgress(1.0);
      return 1;
    },
    [output] { output->Initialize(); });
}

namespace
{

// Whether every cell of `mesh` is a triangle (a polygon of three points).
bool onlyTriangles(vtkPolyData* mesh)
{
  vtkCellArray* polys = mesh->GetPolys();
  return mesh->GetNumberOfCells() == mesh->GetNumberOfPolys() &&
    (mesh->GetNumberOfPolys() == 0 || polys->IsHomogeneous() == 3);
}

std::string triangleText(const std::array<int, 3>& t)
{
  return "(" + std::to_string(t[0]) + ", " + std::to_string(t[1]) + ", " + std::to_string(t[2]) +
    ")";
}

} // namespace

std::string vtkSurfaceMapTransfer::DescribeConnectivityDifference(vtkPolyData* mesh,
  vtkPolyData* reference,
  const char* referenceName)
{
  const std::string name = referenceName ? referenceName : "the reference";
  if (!mesh || !reference)
  {
    return mesh ? "is compared with no mesh" : "is no mesh";
  }
  if (mesh->GetNumberOfPoints() != reference->GetNumberOfPoints())
  {
    return "has " + std::to_string(mesh->GetNumberOfPoints()) + " vertices, " + name + " has " +
      std::to_string(reference->GetNumberOfPoints());
  }
  const bool referenceTriangles = onlyTriangles(reference);
  const auto mine = vtkSurfaceMapsCombination::Triangles(mesh);
  const auto theirs = vtkSurfaceMapsCombination::Triangles(reference);
  const std::size_t count = referenceTriangles ? theirs.size() : 0;
  if (!referenceTriangles || !onlyTriangles(mesh) || mine.size() != count)
  {
    return "has " + std::to_string(mesh->GetNumberOfCells()) + " cells, " + name + " has " +
      std::to_string(count) + " triangles";
  }
  for (std::size_t t = 0; t < count; ++t)
  {
    const auto& a = mine[t];
    const auto& b = theirs[t];
    bool same = false;
    for (int shift = 0; shift < 3 && !same; ++shift)
    {
      same = a[0] == b[shift] && a[1] == b[(shift + 1) % 3] && a[2] == b[(shift + 2) % 3];
    }
    if (!same)
    {
      return "has triangle " + std::to_string(t) + " as " + triangleText(a) + ", " + name +
        " has " + triangleText(b);
    }
  }
  return "";
}

void vtkSurfaceMapTransfer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ArrayNames:";
  if (this->Internals->ArrayNames.empty())
  {
    os << " (all)";
  }
  for (const std::string& name : this->Internals->ArrayNames)
  {
    os << " " << name;
  }
  os << "\n";
}
