#include "mesh/LandmarkValidation.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace surfacemaps
{

std::vector<std::string> checkLandmarkIds(const std::vector<int>& landmarkIds)
{
  std::vector<std::string> defects;
  std::map<int, int> idToVertex;
  for (std::size_t v = 0; v < landmarkIds.size(); ++v)
  {
    const int id = landmarkIds[v];
    if (id < -1)
    {
      defects.push_back("has landmark id " + std::to_string(id) + " at vertex " +
        std::to_string(v) + " (ids are >= 0, -1 means none)");
      break;
    }
    if (id < 0)
    {
      continue;
    }
    auto [it, inserted] = idToVertex.emplace(id, static_cast<int>(v));
    if (!inserted)
    {
      defects.push_back("has landmark id " + std::to_string(id) + " on two vertices (" +
        std::to_string(it->second) + " and " + std::to_string(v) + ")");
      break;
    }
  }
  return defects;
}

std::vector<std::vector<std::string>> checkLandmarkCorrespondence(
  const std::vector<std::vector<int>>& landmarkIds,
  const std::vector<std::string>& names)
{
  std::vector<std::vector<std::string>> defects(landmarkIds.size());
  std::vector<std::map<int, int>> idToVertex(landmarkIds.size());
  for (std::size_t i = 0; i < landmarkIds.size(); ++i)
  {
    for (std::size_t v = 0; v < landmarkIds[i].size(); ++v)
    {
      if (landmarkIds[i][v] >= 0)
      {
        idToVertex[i].emplace(landmarkIds[i][v], static_cast<int>(v));
      }
    }
  }
  for (std::size_t i = 1; i < landmarkIds.size(); ++i)
  {
    const auto& a = idToVertex[0];
    const auto& b = idToVertex[i];
    if (a.size() != b.size())
    {
      defects[i].push_back("landmark counts do not match: " + names[0] + " has " +
        std::to_string(a.size()) + ", " + names[i] + " has " + std::to_string(b.size()));
      continue;
    }
    for (const auto& [id, vertex] : a)
    {
      if (!b.count(id))
      {
        defects[i].push_back("landmark ids do not match: id " + std::to_string(id) + " is on " +
          names[0] + " (vertex " + std::to_string(vertex) + ") but not on " + names[i]);
        break;
      }
    }
  }
  return defects;
}

namespace
{

/// Landmarks compared per input: the first ids, in id order.
constexpr std::size_t MaxOrientationLandmarks = 60;

/// The area-weighted centroid and sqrt(area) of a triangle mesh.
std::pair<Eigen::Vector3d, double> centroidAndSize(const PolygonMesh& mesh)
{
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  double area = 0.0;
  for (std::size_t f = 0; f < mesh.numberOfFaces(); ++f)
  {
    if (mesh.faceSize(f) != 3)
    {
      continue;
    }
    const int* v = mesh.face(f);
    const Eigen::Vector3d& a = mesh.points[v[0]];
    const Eigen::Vector3d& b = mesh.points[v[1]];
    const Eigen::Vector3d& c = mesh.points[v[2]];
    const double w = 0.5 * (b - a).cross(c - a).norm();
    sum += w * (a + b + c) / 3.0;
    area += w;
  }
  if (!(area > 0.0))
  {
    return { Eigen::Vector3d::Zero(), 0.0 };
  }
  return { sum / area, std::sqrt(area) };
}

/// Per triple of `ids`' landmark vertices: +1, -1 or 0 (not decisive).
std::vector<int> tripleSigns(const PolygonMesh& mesh, const std::vector<int>& vertices)
{
  const auto [o, size] = centroidAndSize(mesh);
  const double threshold = 1e-3 * size * size * size;
  std::vector<int> signs;
  const std::size_t k = vertices.size();
  for (std::size_t a = 0; a < k; ++a)
  {
    for (std::size_t b = a + 1; b < k; ++b)
    {
      for (std::size_t c = b + 1; c < k; ++c)
      {
        const Eigen::Vector3d pa = mesh.points[vertices[a]] - o;
        const Eigen::Vector3d pb = mesh.points[vertices[b]] - o;
        const Eigen::Vector3d pc = mesh.points[vertices[c]] - o;
        const double det = pa.dot(pb.cross(pc));
        // Decisive only when the triple is far from a plane through the
        // centroid, relative to its own size too: landmarks along a symmetry
        // plane (tips and a midline point of a tube) turn either way with
        // noise and are no evidence of a mirror image.
        const double relative = 0.1 * pa.norm() * pb.norm() * pc.norm();
        signs.push_back(!(std::abs(det) >= std::max(threshold, relative)) ? 0 : (det > 0 ? 1 : -1));
      }
    }
  }
  return signs;
}

std::map<int, int> vertexOfId(const std::vector<int>& ids)
{
  std::map<int, int> vertex;
  for (std::size_t v = 0; v < ids.size(); ++v)
  {
    if (ids[v] >= 0)
    {
      vertex.emplace(ids[v], static_cast<int>(v));
    }
  }
  return vertex;
}

} // namespace

LandmarkOrientation compareLandmarkOrientation(const PolygonMesh& first,
  const std::vector<int>& firstIds,
  const PolygonMesh& other,
  const std::vector<int>& otherIds)
{
  const std::map<int, int> firstVertex = vertexOfId(firstIds);
  const std::map<int, int> otherVertex = vertexOfId(otherIds);
  std::vector<int> a, b;
  for (const auto& [id, v] : firstVertex)
  {
    const auto match = otherVertex.find(id);
    if (match == otherVertex.end())
    {
      continue;
    }
    a.push_back(v);
    b.push_back(match->second);
    if (a.size() == MaxOrientationLandmarks)
    {
      break;
    }
  }
  const std::vector<int> signsA = tripleSigns(first, a);
  const std::vector<int> signsB = tripleSigns(other, b);
  LandmarkOrientation result;
  for (std::size_t t = 0; t < signsA.size(); ++t)
  {
    if (signsA[t] != 0 && signsB[t] != 0)
    {
      ++result.triples;
      result.opposite += signsA[t] != signsB[t] ? 1 : 0;
    }
  }
  return result;
}

std::vector<std::string> checkLandmarkMirroring(const std::vector<const PolygonMesh*>& meshes,
  const std::vector<std::vector<int>>& landmarkIds,
  const std::vector<std::string>& names)
{
  std::vector<std::string> warnings;
  for (std::size_t i = 1; i < meshes.size(); ++i)
  {
    const LandmarkOrientation o =
      compareLandmarkOrientation(*meshes[0], landmarkIds[0], *meshes[i], landmarkIds[i]);
    if (o.triples > 0 && 2 * o.opposite > o.triples)
    {
      warnings.push_back("the landmarks of " + names[i] + " are the mirror image of those of " +
        names[0] + " (" + std::to_string(o.opposite) + " of " + std::to_string(o.triples) +
        " landmark triples turn the other way): a map can meet them only by turning the surface "
        "inside out locally, with huge distortion. Is one mesh mirrored, or are the landmarks "
        "of the other side?");
    }
  }
  return warnings;
}

} // namespace surfacemaps
