#include "map/PreparedInput.h"
#include "base/Error.h"

#include "geometry/Rotation.h"
#include "geometry/Sizing.h"
#include "geometry/SphericalTriangulation.h"
#include "map/MapSettings.h"
#include "mesh/LandmarkValidation.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

namespace surfacemaps
{

double PreparedInput::sizingAt(int t, const std::array<double, 3>& w) const
{
  const auto& tri = this->triangles[t];
  return w[0] * this->sizing[tri[0]] + w[1] * this->sizing[tri[1]] + w[2] * this->sizing[tri[2]];
}

namespace
{

std::string inputName(int i)
{
  return "input " + std::to_string(i);
}

std::string lengthText(double length)
{
  std::ostringstream text;
  text << std::setprecision(3) << length;
  return text.str();
}

/// Centres an input, scales it to unit area and builds what the energy needs.
PreparedInput prepareSurface(const MapInput& input, int index)
{
  PreparedInput s;
  s.label = index;
  s.triangles = input.mesh.triangles();
  const std::size_t nv = input.mesh.points.size();
  if (input.spherePositions.size() != nv)
  {
    throw InputError(inputName(index) + ": " + std::to_string(nv) + " vertices but " +
      std::to_string(input.spherePositions.size()) + " sphere positions");
  }
  if (!input.landmarks.empty() && input.landmarks.size() != nv)
  {
    throw InputError(inputName(index) + ": landmark array has " +
      std::to_string(input.landmarks.size()) + " entries, expected " + std::to_string(nv));
  }
  if (!input.sizing.empty() && input.sizing.size() != nv)
  {
    throw InputError(inputName(index) + ": sizing array has " +
      std::to_string(input.sizing.size()) + " entries, expected " + std::to_string(nv));
  }
  double area = 0.0;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (const auto& t : s.triangles)
  {
    const Eigen::Vector3d& a = input.mesh.points[t[0]];
    const Eigen::Vector3d& b = input.mesh.points[t[1]];
    const Eigen::Vector3d& c = input.mesh.points[t[2]];
    const double A = 0.5 * (b - a).cross(c - a).norm();
    area += A;
    centre += A * (a + b + c) / 3.0;
  }
  if (!(area > 0.0))
  {
    throw InputError(inputName(index) + " has zero area");
  }
  s.centre = centre / area;
  s.scale = 1.0 / std::sqrt(area);
  s.points.resize(nv);
  for (std::size_t v = 0; v < nv; ++v)
  {
    s.points[v] = (input.mesh.points[v] - s.centre) * s.scale;
  }
  s.sphere = input.spherePositions;
  for (Eigen::Vector3d& p : s.sphere)
  {
    p.normalize();
  }
  s.landmarks = input.landmarks;
  s.userSizing = !input.sizing.empty();
  if (!input.sizing.empty())
  {
    s.sizing = input.sizing;
    for (double& l : s.sizing)
    {
      l *= s.scale;
    }
  }
  return s;
}

/// Approximation samples: every vertex, or an evenly strided subset of large
/// inputs; weights = barycentric vertex areas normalised to sum 1.
void buildSamples(PreparedInput& s, int samples)
{
  s.samples = ApproximationSampleSet();
  const std::size_t nv = s.points.size();
  std::vector<double> vertexArea(nv, 0.0);
  for (const auto& t : s.triangles)
  {
    const double A =
      0.5 * (s.points[t[1]] - s.points[t[0]]).cross(s.points[t[2]] - s.points[t[0]]).norm();
    for (int k = 0; k < 3; ++k)
    {
      vertexArea[t[k]] += A / 3.0;
    }
  }
  const std::size_t limit = static_cast<std::size_t>(std::max(1, samples));
  const std::size_t stride = (nv + limit - 1) / limit;
  double weightSum = 0.0;
  for (std::size_t v = 0; v < nv; v += stride)
  {
    s.samples.vertices.push_back(static_cast<int>(v));
    s.samples.positions.push_back(s.points[v]);
    s.samples.spherePoints.push_back(s.sphere[v]);
    s.samples.weights.push_back(vertexArea[v]);
    weightSum += vertexArea[v];
  }
  for (double& w : s.samples.weights)
  {
    w /= weightSum;
  }
}

void buildLifts(PreparedInput& s)
{
  s.lifts.resize(s.triangles.size());
  s.density.resize(s.triangles.size());
  for (std::size_t t = 0; t < s.triangles.size(); ++t)
  {
    const auto& tri = s.triangles[t];
    const double surface =
      (s.points[tri[1]] - s.points[tri[0]]).cross(s.points[tri[2]] - s.points[tri[0]]).norm();
    const double chord =
      (s.sphere[tri[1]] - s.sphere[tri[0]]).cross(s.sphere[tri[2]] - s.sphere[tri[0]]).norm();
    s.density[t] = chord > 0.0 ? surface / chord : 0.0;
    s.lifts[t] = Lift(s.points[tri[0]],
      s.points[tri[1]],
      s.points[tri[2]],
      s.sphere[tri[0]],
      s.sphere[tri[1]],
      s.sphere[tri[2]]);
  }
  s.locator = std::make_unique<SphereLocator>(s.sphere, s.triangles);
}

/// Rotates each embedding onto input 0's through the landmarks (Kabsch),
/// keeping the original where the rotated one does not certify.
void alignEmbeddings(std::vector<PreparedInput>& surfaces,
  const std::vector<std::map<int, int>>& ids,
  const Logger& log)
{
  for (std::size_t i = 1; i < surfaces.size(); ++i)
  {
    if (ids[0].empty())
    {
      return;
    }
    std::vector<Eigen::Vector3d> from, to;
    for (const auto& [id, v] : ids[0])
    {
      to.push_back(surfaces[0].sphere[v]);
      from.push_back(surfaces[i].sphere[ids[i].at(id)]);
    }
    if (!rotateEmbedding(surfaces[i], bestRotation(from, to)))
    {
      log(Logger::Warning,
        inputName(surfaces[i].label) + ": the embedding rotated onto " +
          inputName(surfaces[0].label) + "'s landmarks does not certify; using it unrotated");
    }
  }
}

} // namespace

bool rotateEmbedding(PreparedInput& s, const Eigen::Matrix3d& rotation)
{
  std::vector<Eigen::Vector3d> rotated = s.sphere;
  for (Eigen::Vector3d& p : rotated)
  {
    p = (rotation * p).normalized();
  }
  if (!certifyBijective(rotated, s.triangles).bijective)
  {
    return false;
  }
  s.sphere = std::move(rotated);
  for (std::size_t k = 0; k < s.samples.vertices.size(); ++k)
  {
    s.samples.spherePoints[k] = s.sphere[s.samples.vertices[k]];
  }
  buildLifts(s);
  return true;
}

std::vector<std::map<int, int>> landmarkVertices(const std::vector<MapInput>& inputs)
{
  // The same checks as input validation (MeshValidation.h): ids on one
  // vertex each, and the same ids on every input.
  std::vector<std::vector<int>> landmarkIds;
  std::vector<std::string> names;
  for (std::size_t i = 0; i < inputs.size(); ++i)
  {
    names.push_back(inputName(static_cast<int>(i)));
    const std::vector<std::string> defects = checkLandmarkIds(inputs[i].landmarks);
    if (!defects.empty())
    {
      throw InputError(names.back() + " " + defects.front());
    }
    landmarkIds.push_back(inputs[i].landmarks);
  }
  for (const std::vector<std::string>& defects : checkLandmarkCorrespondence(landmarkIds, names))
  {
    if (!defects.empty())
    {
      throw InputError(defects.front());
    }
  }
  std::vector<std::map<int, int>> ids(inputs.size());
  for (std::size_t i = 0; i < inputs.size(); ++i)
  {
    for (std::size_t v = 0; v < inputs[i].landmarks.size(); ++v)
    {
      if (inputs[i].landmarks[v] >= 0)
      {
        ids[i].emplace(inputs[i].landmarks[v], static_cast<int>(v));
      }
    }
  }
  return ids;
}

std::vector<PreparedInput> prepareInputs(const std::vector<MapInput>& inputs,
  const std::vector<std::map<int, int>>& landmarks,
  int samples,
  const Logger& log,
  const std::vector<int>& labels)
{
  std::vector<PreparedInput> surfaces;
  surfaces.reserve(inputs.size());
  for (std::size_t i = 0; i < inputs.size(); ++i)
  {
    surfaces.push_back(prepareSurface(inputs[i], labels.empty() ? static_cast<int>(i) : labels[i]));
  }
  for (PreparedInput& s : surfaces)
  {
    buildSamples(s, samples > 0 ? samples : std::numeric_limits<int>::max());
    buildLifts(s);
  }
  alignEmbeddings(surfaces, landmarks, log);
  return surfaces;
}

void requireUsableSizing(const std::vector<PreparedInput>& surfaces, double minEdgeLength)
{
  for (const PreparedInput& s : surfaces)
  {
    if (!s.userSizing || s.sizing.empty())
    {
      continue;
    }
    const auto smallest = std::min_element(s.sizing.begin(), s.sizing.end());
    if (*smallest < minEdgeLength)
    {
      // In the input's own units, as the user gave them; the setting's
      // property name and flag come from the list.
      const MapSetting& limit = *findSettingFlag(mapSettings(), "--min-edge-length");
      throw InputError(inputName(s.label) + " has a Sizing of " +
        lengthText(*smallest / s.scale) + " at point " +
        std::to_string(smallest - s.sizing.begin()) + ", below the smallest target edge length " +
        limit.name + " (--" + limit.flag + ", " + lengthText(minEdgeLength) +
        " of the input scaled to unit area, " + lengthText(minEdgeLength / s.scale) +
        " in its units): so fine a common triangulation cannot be optimised");
    }
  }
}

void setCurvatureSizing(std::vector<PreparedInput>& surfaces,
  double eps,
  double minEdgeLength,
  double maxEdgeLength)
{
  for (PreparedInput& s : surfaces)
  {
    if (s.userSizing)
    {
      continue;
    }
    SizingOptions sizing;
    sizing.targetError = eps;
    sizing.minEdgeLength = minEdgeLength;
    sizing.maxEdgeLength = maxEdgeLength;
    s.sizing = curvatureSizing(s.points, s.triangles, sizing);
  }
}

void scaleSizingAround(PreparedInput& s, const std::vector<double>& factor)
{
  std::vector<double> ring(factor);
  for (const auto& t : s.triangles)
  {
    const double f = std::min({ factor[t[0]], factor[t[1]], factor[t[2]] });
    for (int k = 0; k < 3; ++k)
    {
      ring[t[k]] = std::min(ring[t[k]], f);
    }
  }
  for (std::size_t v = 0; v < ring.size(); ++v)
  {
    s.sizing[v] *= ring[v];
  }
}

std::vector<std::map<int, Eigen::Vector3d>> landmarkTargets(
  const std::vector<PreparedInput>& surfaces)
{
  std::vector<std::map<int, Eigen::Vector3d>> targets(surfaces.size());
  for (std::size_t i = 0; i < surfaces.size(); ++i)
  {
    const std::vector<int>& ids = surfaces[i].landmarks;
    for (std::size_t v = 0; v < ids.size(); ++v)
    {
      if (ids[v] >= 0)
      {
        targets[i][ids[v]] = surfaces[i].sphere[v];
      }
    }
  }
  return targets;
}

} // namespace surfacemaps
