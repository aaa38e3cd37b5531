#include "vtkSphereEmbeddingFilter.h"

#include "vtkSurfaceMapsConversion.h"
#include "vtkSurfaceMapsErrorGuard.h"
#include "vtkSurfaceMapsExecutive.h"
#include "vtkSurfaceMapsSettingAccess.h"

#include "base/Error.h"
#include "embedding/SphereEmbedding.h"
#include "geometry/Rotation.h"
#include "map/MapSettings.h"
#include "mesh/MeshValidation.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <cmath>
#include <map>
#include <string>

vtkStandardNewMacro(vtkSphereEmbeddingFilter);

namespace
{
// The list's embedding entries between the filter's members and the
// engine's options (see vtkSurfaceMapsSettingAccess).
struct Access
{
  static const std::vector<surfacemaps::EmbeddingSetting>& Table()
  {
    return surfacemaps::embeddingSettings();
  }

  static surfacemaps::SphereEmbeddingOptions OptionsOf(vtkSphereEmbeddingFilter* filter)
  {
    surfacemaps::SphereEmbeddingOptions options;
#define SURFACEMAPS_EMBEDDING_SETTING(Name, field, Type, ...)                                      \
  options.field = surfacemaps::settingValue<Type>(filter->Get##Name());
#include "settings/SettingList.def"
    return options;
  }

  static void SetAll(vtkSphereEmbeddingFilter* filter,
    const surfacemaps::SphereEmbeddingOptions& options)
  {
#define SURFACEMAPS_EMBEDDING_SETTING(Name, field, ...)                                            \
  filter->Set##Name(                                                                               \
    static_cast<decltype(filter->Get##Name())>(surfacemaps::settingNumber(options.field)));
#include "settings/SettingList.def"
  }
};

template<typename ArrayT, typename T>
void addFieldValue(vtkPolyData* output, const char* name, T value)
{
  auto array = vtkSmartPointer<ArrayT>::New();
  array->SetName(name);
  array->InsertNextValue(value);
  output->GetFieldData()->AddArray(array);
}
} // namespace

vtkSphereEmbeddingFilter::vtkSphereEmbeddingFilter()
{
  this->SetNumberOfInputPorts(2);
}

int vtkSphereEmbeddingFilter::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  }
  return 1;
}

namespace
{
// Landmark id -> sphere position, for the vertices with an id >= 0.
// A defective Landmarks array is an input error naming `what`.
std::map<int, Eigen::Vector3d> landmarkPositions(vtkPolyData* mesh,
  const std::vector<Eigen::Vector3d>& sphere,
  const std::string& what)
{
  std::map<int, Eigen::Vector3d> result;
  std::vector<std::string> defects;
  const std::vector<int> ids = vtkSurfaceMapsConversion::LandmarkIds(mesh, defects);
  if (!defects.empty())
  {
    throw surfacemaps::InputError(what + " " + defects.front());
  }
  for (std::size_t v = 0; v < ids.size() && v < sphere.size(); ++v)
  {
    if (ids[v] >= 0)
    {
      result[ids[v]] = sphere[v];
    }
  }
  return result;
}

// Every defect of the mesh, each after the input's name; empty when valid.
std::string defectsOf(const surfacemaps::MeshValidationResult& validation, const std::string& name)
{
  std::string message;
  for (const std::string& defect : validation.defects)
  {
    message += (message.empty() ? "" : "; ") + name + " " + defect;
  }
  return message;
}

surfacemaps::SphereEmbeddingResult embed(vtkSphereEmbeddingFilter* self,
  const surfacemaps::PolygonMesh& mesh)
{
  self->SetProgressText("Sphere embedding");
  self->UpdateProgress(0.0);
  surfacemaps::SphereEmbeddingOptions options = Access::OptionsOf(self);
  vtkSurfaceMapsSettingAccess::CheckRanges<Access>(options);
  options.progress = [self](double fraction)
  {
    self->UpdateProgress(fraction);
    return !self->GetAbortExecute();
  };
  options.log = vtkSurfaceMapsConversion::EngineLog();
  return surfacemaps::embedOnSphere(mesh, options);
}

// Rigid rotation of the embedding onto the reference's landmarks; returns the
// RMS angle between the matched landmarks, or -1 when there are none to match.
double alignToReference(vtkSphereEmbeddingFilter* self,
  vtkPolyData* input,
  vtkPolyData* reference,
  const surfacemaps::PolygonMesh& mesh,
  const std::string& name,
  surfacemaps::SphereEmbeddingResult& result)
{
  const auto own = landmarkPositions(input, result.positions, name);
  const auto other = landmarkPositions(
    reference, vtkSurfaceMapsConversion::SpherePositions(reference), "the reference");
  std::vector<Eigen::Vector3d> from, to;
  for (const auto& [id, p] : own)
  {
    const auto it = other.find(id);
    if (it != other.end())
    {
      from.push_back(p);
      to.push_back(it->second.normalized());
    }
  }
  if (from.empty())
  {
    vtkWarningWithObjectMacro(self,
      << name
      << ": no landmark ids in common with the reference embedding; "
         "not rotated");
    return -1.0;
  }
  const Eigen::Matrix3d R = surfacemaps::bestRotation(from, to);
  for (Eigen::Vector3d& p : result.positions)
  {
    p = (R * p).normalized();
  }
  double sum = 0.0;
  for (std::size_t k = 0; k < from.size(); ++k)
  {
    const Eigen::Vector3d q = R * from[k];
    sum += std::pow(std::atan2(q.cross(to[k]).norm(), q.dot(to[k])), 2);
  }
  // A rotation keeps every orientation, but the certificate is cheap:
  // recheck after rounding.
  result.certificate = surfacemaps::certifyBijective(result.positions, mesh.triangles());
  if (!result.certificate.bijective)
  {
    throw surfacemaps::NoResultError(
      "the rotated embedding is not bijective: " + result.certificate.reason);
  }
  return std::sqrt(sum / static_cast<double>(from.size()));
}

// The input with "SpherePosition" (and, on request, its points on the sphere)
// and the embedding's figures as field data.
void writeOutput(vtkPolyData* output,
  vtkPolyData* input,
  const surfacemaps::SphereEmbeddingResult& result,
  bool pointsOnSphere,
  double alignmentError)
{
  output->ShallowCopy(input);
  auto sphere = vtkSmartPointer<vtkDoubleArray>::New();
  sphere->SetName("SpherePosition");
  sphere->SetNumberOfComponents(3);
  sphere->SetNumberOfTuples(static_cast<vtkIdType>(result.positions.size()));
  for (std::size_t i = 0; i < result.positions.size(); ++i)
  {
    sphere->SetTuple(static_cast<vtkIdType>(i), result.positions[i].data());
  }
  // ShallowCopy gave the output its own attribute and field data objects
  // (sharing the arrays), so adding arrays leaves the input untouched.
  output->GetPointData()->AddArray(sphere);

  if (pointsOnSphere)
  {
    auto original = vtkSmartPointer<vtkDoubleArray>::New();
    original->DeepCopy(input->GetPoints()->GetData());
    original->SetName("InputPosition");
    output->GetPointData()->AddArray(original);
    auto points = vtkSmartPointer<vtkPoints>::New();
    points->SetDataTypeToDouble();
    points->SetData(sphere);
    output->SetPoints(points);
  }

  addFieldValue<vtkDoubleArray>(output, "EmbeddingDistortion", result.distortion);
  addFieldValue<vtkDoubleArray>(output, "EmbeddingEnergy", result.energy);
  addFieldValue<vtkIntArray>(output, "EmbeddingNewtonIterations", result.newtonIterations);
  addFieldValue<vtkIntArray>(output, "EmbeddingLevels", result.levels);
  addFieldValue<vtkIntArray>(output, "EmbeddingAttempt", result.attempt);
  addFieldValue<vtkDoubleArray>(output, "EmbeddingSeconds", result.seconds);
  addFieldValue<vtkDoubleArray>(output, "EmbeddingSmallestAreaRatio", result.smallestAreaRatio);
  if (alignmentError >= 0.0)
  {
    addFieldValue<vtkDoubleArray>(output, "LandmarkAlignmentError", alignmentError);
  }
}

} // namespace

int vtkSphereEmbeddingFilter::RequestData(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkPolyData* reference = vtkPolyData::GetData(inputVector[1], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  output->Initialize();
  const std::string name = vtkSurfaceMapsConversion::InputName(input, 0);

  return vtkSurfaceMapsErrorGuard::Run(
    this,
    vtkSurfaceMapsErrorGuard::WithPrefix(name + ": "),
    [&]
    {
      this->SetProgressText("Validating the input");
      const vtkSurfaceMapsConversion::ValidatedInput validated =
        vtkSurfaceMapsConversion::Validate(input);
      const surfacemaps::PolygonMesh& mesh = validated.mesh;
      const std::string defects = defectsOf(validated.validation, name);
      if (!defects.empty())
      {
        return vtkSurfaceMapsErrorGuard::Fail(
          this, vtkSurfaceMapsErrorGuard::InvalidInputError, defects);
      }
      surfacemaps::SphereEmbeddingResult result = embed(this, mesh);
      const double alignmentError =
        reference ? alignToReference(this, input, reference, mesh, name, result) : -1.0;
      writeOutput(output, input, result, this->OutputPointsOnSphere, alignmentError);
      this->UpdateProgress(1.0);
      return 1;
    },
    [output] { output->Initialize(); });
}

const char* vtkSphereEmbeddingFilter::GetLastErrorMessage() const
{
  return vtkSurfaceMapsErrorGuard::LastErrorMessage(this);
}

vtkExecutive* vtkSphereEmbeddingFilter::CreateDefaultExecutive()
{
  return vtkSurfaceMapsExecutive::New();
}

void vtkSphereEmbeddingFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "OutputPointsOnSphere: " << this->OutputPointsOnSphere << "\n";
  vtkSurfaceMapsSettingAccess::Print<Access>(this, os, indent);
}

double vtkSphereEmbeddingFilter::GetSetting(int i)
{
  return vtkSurfaceMapsSettingAccess::Get<Access>(this, i);
}

void vtkSphereEmbeddingFilter::SetSetting(int i, double value)
{
  vtkSurfaceMapsSettingAccess::Set<Access>(this, i, value);
}
