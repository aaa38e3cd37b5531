#include "vtkSurfaceMapInputs.h"

#include "vtkSurfaceMapsConversion.h"

#include "base/Aborted.h"
#include "base/Error.h"
#include "embedding/SphereEmbedding.h"
#include "geometry/SphericalTriangulation.h"
#include "mesh/LandmarkValidation.h"
#include "mesh/MeshValidation.h"

#include "vtkDataArray.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace
{
const char* const SizingName = "Sizing";
const char* const SpherePositionName = "SpherePosition";

std::string joined(const std::vector<std::string>& messages)
{
  std::string text;
  for (const std::string& m : messages)
  {
    text += (text.empty() ? "" : "; ") + m;
  }
  return text;
}

// The "Sizing" array of an input (empty if absent); defects are reported.
std::vector<double> readSizing(vtkPolyData* input,
  const std::string& name,
  std::vector<std::string>& defects)
{
  std::vector<double> sizing;
  vtkDataArray* array = input->GetPointData()->GetArray(SizingName);
  if (!array)
  {
    return sizing;
  }
  if (array->GetNumberOfComponents() != 1 ||
    array->GetNumberOfTuples() != input->GetNumberOfPoints())
  {
    defects.push_back(name + " has a Sizing array of the wrong shape (" +
      std::to_string(array->GetNumberOfTuples()) + " x " +
      std::to_string(array->GetNumberOfComponents()) + " values for " +
      std::to_string(input->GetNumberOfPoints()) + " points)");
    return sizing;
  }
  sizing.resize(static_cast<std::size_t>(array->GetNumberOfTuples()));
  for (vtkIdType v = 0; v < array->GetNumberOfTuples(); ++v)
  {
    sizing[v] = array->GetComponent(v, 0);
    if (!std::isfinite(sizing[v]) || sizing[v] <= 0.0)
    {
      defects.push_back(name + " has a Sizing value that is not a positive length (" +
        std::to_string(sizing[v]) + " at point " + std::to_string(v) + ")");
      sizing.clear();
      break;
    }
  }
  return sizing;
}

// A present "SpherePosition" array, normalised and certified; empty if absent.
std::vector<Eigen::Vector3d> givenEmbedding(vtkPolyData* input,
  const surfacemaps::MapInput& mapInput,
  const std::string& name)
{
  vtkDataArray* array = input->GetPointData()->GetArray(SpherePositionName);
  if (!array)
  {
    return {};
  }
  std::vector<Eigen::Vector3d> positions = vtkSurfaceMapsConversion::SpherePositions(input);
  if (positions.empty())
  {
    throw surfacemaps::InputError(name + " has a SpherePosition array of the wrong shape (" +
      std::to_string(array->GetNumberOfTuples()) + " x " +
      std::to_string(array->GetNumberOfComponents()) + " values for " +
      std::to_string(input->GetNumberOfPoints()) + " points)");
  }
  for (std::size_t v = 0; v < positions.size(); ++v)
  {
    const double length = positions[v].norm();
    if (!std::isfinite(length) || length == 0.0)
    {
      throw surfacemaps::InputError(
        name + " has a SpherePosition that is not a direction at point " + std::to_string(v));
    }
    positions[v] /= length;
  }
  const surfacemaps::BijectivityCertificate certificate =
    surfacemaps::certifyBijective(positions, mapInput.mesh.triangles());
  if (!certificate.bijective)
  {
    throw surfacemaps::InputError(name +
      " has a SpherePosition array that is not a bijective embedding: " + certificate.reason);
  }
  return positions;
}

} // namespace

std::string vtkSurfaceMapInputs::Name(vtkPolyData* input, int index)
{
  const std::string plain = "input " + std::to_string(index);
  const std::string name = vtkSurfaceMapsConversion::InputName(input, index);
  return name == plain ? plain : plain + " (" + name + ")";
}

std::vector<surfacemaps::MapInput> vtkSurfaceMapInputs::Read(
  const std::vector<vtkPolyData*>& inputs,
  bool useSizing,
  std::vector<std::string>& warnings)
{
  const int n = static_cast<int>(inputs.size());
  std::vector<surfacemaps::MapInput> result(n);
  std::vector<std::string> defects, names(n);
  std::vector<std::vector<int>> landmarks(n);
  bool anyLandmarks = false;
  for (int i = 0; i < n; ++i)
  {
    names[i] = vtkSurfaceMapInputs::Name(inputs[i], i);
    vtkSurfaceMapsConversion::ValidatedInput validated =
      vtkSurfaceMapsConversion::Validate(inputs[i]);
    for (const std::string& d : validated.validation.defects)
    {
      defects.push_back(names[i] + " " + d);
    }
    result[i].mesh = std::move(validated.mesh);
    landmarks[i] = std::move(validated.landmarkIds);
    anyLandmarks = anyLandmarks ||
      std::any_of(landmarks[i].begin(), landmarks[i].end(), [](int id) { return id >= 0; });

    if (useSizing)
    {
      result[i].sizing = readSizing(inputs[i], names[i], defects);
    }
  }
  if (anyLandmarks && n > 1)
  {
    for (const auto& perInput : surfacemaps::checkLandmarkCorrespondence(landmarks, names))
    {
      defects.insert(defects.end(), perInput.begin(), perInput.end());
    }
  }
  if (!defects.empty())
  {
    throw surfacemaps::InputError(joined(defects));
  }
  for (int i = 0; i < n && anyLandmarks; ++i)
  {
    result[i].landmarks = landmarks[i].empty() ? std::vector<int>(result[i].mesh.points.size(), -1)
                                               : std::move(landmarks[i]);
  }
  if (anyLandmarks && n > 1)
  {
    std::vector<const surfacemaps::PolygonMesh*> meshes;
    std::vector<std::vector<int>> ids;
    for (const surfacemaps::MapInput& input : result)
    {
      meshes.push_back(&input.mesh);
      ids.push_back(input.landmarks);
    }
    warnings = surfacemaps::checkLandmarkMirroring(meshes, ids, names);
  }
  return result;
}

std::vector<double> vtkSurfaceMapInputs::Embed(const std::vector<vtkPolyData*>& inputs,
  std::vector<surfacemaps::MapInput>& mapInputs,
  const std::function<bool(double, const std::string&)>& progress)
{
  const int n = static_cast<int>(inputs.size());
  std::vector<double> seconds(n, 0.0);
  std::vector<int> missing;
  for (int i = 0; i < n; ++i)
  {
    mapInputs[i].spherePositions = givenEmbedding(inputs[i], mapInputs[i], Name(inputs[i], i));
    if (mapInputs[i].spherePositions.empty())
    {
      missing.push_back(i);
    }
  }
  if (missing.empty())
  {
    return seconds;
  }
  // All missing embeddings at once, one per thread.
  const std::string text = missing.size() == 1
    ? "Sphere embedding of " + Name(inputs[missing[0]], missing[0])
    : "Sphere embeddings of " + std::to_string(missing.size()) + " inputs";
  if (!progress(0.0, text))
  {
    throw surfacemaps::Aborted();
  }
  std::vector<const surfacemaps::PolygonMesh*> meshes;
  for (int i : missing)
  {
    meshes.push_back(&mapInputs[i].mesh);
  }
  surfacemaps::SphereEmbeddingOptions options;
  options.progress = [&](double fraction) { return progress(fraction, text); };
  options.log = vtkSurfaceMapsConversion::EngineLog();
  try
  {
    std::vector<surfacemaps::SphereEmbeddingResult> embeddings =
      surfacemaps::embedAllOnSphere(meshes, options);
    for (std::size_t k = 0; k < missing.size(); ++k)
    {
      mapInputs[missing[k]].spherePositions = std::move(embeddings[k].positions);
      seconds[missing[k]] = embeddings[k].seconds;
    }
  }
  catch (const surfacemaps::EmbeddingFailure& e)
  {
    const int i = missing[e.index];
    throw surfacemaps::NoResultError(Name(inputs[i], i) + ": " + e.what());
  }
  return seconds;
}

surfacemaps::ExistingMap vtkSurfaceMapInputs::Existing(const std::vector<vtkPolyData*>& common)
{
  surfacemaps::ExistingMap map;
  for (std::size_t j = 0; j < common.size(); ++j)
  {
    const std::string name = "existing map's T on input " + std::to_string(j);
    const surfacemaps::PolygonMesh mesh = vtkSurfaceMapsConversion::ToPolygonMesh(common[j]);
    std::vector<Eigen::Vector3d> sphere = vtkSurfaceMapsConversion::SpherePositions(common[j]);
    if (sphere.empty() || sphere.size() != mesh.points.size())
    {
      throw surfacemaps::InputError(
        "the " + name + " has no \"SpherePosition\" array (3 components per point)");
    }
    if (j == 0)
    {
      map.triangles = mesh.triangles();
      std::vector<std::string> defects;
      map.landmarks = vtkSurfaceMapsConversion::LandmarkIds(common[0], defects);
      if (!defects.empty())
      {
        throw surfacemaps::InputError("the " + name + ": " + joined(defects));
      }
    }
    else if (mesh.points.size() != map.lifted[0].size() || mesh.triangles() != map.triangles)
    {
      throw surfacemaps::InputError("the " + name + " is not the triangulation of input 0's (" +
        std::to_string(mesh.points.size()) + " points, " + std::to_string(mesh.numberOfFaces()) +
        " triangles; input 0's: " + std::to_string(map.lifted[0].size()) + ", " +
        std::to_string(map.triangles.size()) + ")");
    }
    map.spherePositions.push_back(std::move(sphere));
    map.lifted.push_back(mesh.points);
  }
  return map;
}
