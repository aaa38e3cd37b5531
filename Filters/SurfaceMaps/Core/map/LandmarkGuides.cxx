#include "map/LandmarkGuides.h"

#include "map/MapTransfer.h"
#include "map/PreparedInput.h"

#include <algorithm>
#include <set>

namespace surfacemaps
{

namespace
{

double boxDiagonal(const std::vector<Eigen::Vector3d>& points)
{
  Eigen::Vector3d lo = points.front(), hi = points.front();
  for (const Eigen::Vector3d& p : points)
  {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return (hi - lo).norm();
}

/// Per landmark id: how far (% of the diagonal, largest over inputs 1..)
/// the map carries input 0's landmark vertex from its partner.
std::map<int, double> carriedDistances(const std::vector<MapInput>& inputs,
  const std::vector<std::map<int, int>>& ids,
  const SurfaceMapResult& map)
{
  std::vector<int> order;
  std::vector<Eigen::Vector3d> points;
  for (const auto& [id, v] : ids[0])
  {
    order.push_back(id);
    points.push_back(map.inputSpherePositions[0][static_cast<std::size_t>(v)]);
  }
  std::map<int, double> distance;
  for (std::size_t i = 1; i < inputs.size(); ++i)
  {
    const std::vector<std::array<int, 3>> triangles = inputs[i].mesh.triangles();
    const std::vector<SurfacePoint> carried = transferPoints(points,
      map.triangles,
      map.spherePositions[0],
      map.spherePositions[i],
      map.inputSpherePositions[i],
      triangles);
    const double diagonal = boxDiagonal(inputs[i].mesh.points);
    for (std::size_t k = 0; k < order.size(); ++k)
    {
      const Eigen::Vector3d image = evaluateSurfacePoint(inputs[i].mesh.points, triangles, carried[k]);
      const Eigen::Vector3d& partner = inputs[i].mesh.points[static_cast<std::size_t>(ids[i].at(order[k]))];
      double& d = distance[order[k]];
      d = std::max(d, 100.0 * (image - partner).norm() / diagonal);
    }
  }
  return distance;
}

/// The coarse phase alone, its landmarks locked, no guide check.
SurfaceMapOptions probeOptions(const SurfaceMapOptions& options)
{
  SurfaceMapOptions probe = options;
  probe.fineIterations = 0;
  probe.refinementRounds = 0;
  probe.maxError = 0.0;
  probe.keepLandmarks = true;
  probe.landmarksAsGuides = false;
  return probe;
}

} // namespace

std::vector<MapInput> keepLandmarkIds(std::vector<MapInput> inputs, const std::vector<int>& kept)
{
  const std::set<int> keep(kept.begin(), kept.end());
  for (MapInput& input : inputs)
  {
    for (int& id : input.landmarks)
    {
      id = keep.count(id) ? id : -1;
    }
  }
  return inputs;
}

LandmarkCheck checkLandmarkGuides(const std::vector<MapInput>& inputs,
  const SurfaceMapOptions& options,
  const MapFunction& map)
{
  const std::vector<std::map<int, int>> ids = landmarkVertices(inputs);
  const SurfaceMapOptions probe = probeOptions(options);
  LandmarkCheck check;
  const std::map<int, double> free = carriedDistances(inputs, ids, map(keepLandmarkIds(inputs, {}), probe));
  std::vector<int> confirmed;
  for (const auto& [id, d] : free)
  {
    (d <= options.landmarkGuideTolerance ? confirmed : check.setAside).push_back(id);
  }
  check.distance = free;
  if (confirmed.size() < 3 && confirmed.size() < free.size())
  {
    // Too few to hold the second map: the shapes alone cannot judge them.
    check.undecided = true;
    check.setAside.clear();
    for (const auto& entry : free)
    {
      check.kept.push_back(entry.first);
    }
    return check;
  }
  check.kept = confirmed;
  if (check.setAside.empty())
  {
    return check;
  }
  const std::map<int, double> guided =
    carriedDistances(inputs, ids, map(keepLandmarkIds(inputs, confirmed), probe));
  std::vector<int> rejected;
  for (const int id : check.setAside)
  {
    check.distance[id] = guided.at(id);
    (guided.at(id) <= options.landmarkGuideTolerance ? check.kept : rejected).push_back(id);
  }
  std::sort(check.kept.begin(), check.kept.end());
  check.setAside = rejected;
  return check;
}

} // namespace surfacemaps
