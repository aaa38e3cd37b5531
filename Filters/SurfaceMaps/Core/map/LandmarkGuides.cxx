#include "map/LandmarkGuides.h"

#include "geometry/MapMetrics.h"
#include "map/MapTransfer.h"
#include "map/PreparedInput.h"

#include <algorithm>
#include <set>

namespace surfacemaps
{

std::map<int, double> landmarkDistances(const std::vector<MapInput>& inputs,
  const SurfaceMapResult& map)
{
  const std::vector<std::map<int, int>> ids = landmarkVertices(inputs);
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
    const double diagonal = boundingBoxDiagonal(inputs[i].mesh.points);
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

LandmarkCheck confirmLandmarks(const std::vector<MapInput>& inputs,
  const SurfaceMapOptions& options,
  const MapFunction& map)
{
  // The coarse phase alone, without landmarks and without a guide check.
  SurfaceMapOptions probe = options;
  probe.fineIterations = 0;
  probe.refinementRounds = 0;
  probe.maxError = 0.0;
  probe.landmarksAsGuides = false;
  LandmarkCheck check;
  check.distance = landmarkDistances(inputs, map(keepLandmarkIds(inputs, {}), probe));
  for (const auto& [id, d] : check.distance)
  {
    (d <= options.landmarkGuideTolerance ? check.confirmed : check.unconfirmed).push_back(id);
  }
  if (check.confirmed.size() < 3 && !check.unconfirmed.empty())
  {
    // Too few to hold the map: the shapes alone cannot judge the landmarks.
    check.undecided = true;
    check.confirmed.clear();
    check.unconfirmed.clear();
    for (const auto& entry : check.distance)
    {
      check.confirmed.push_back(entry.first);
    }
  }
  return check;
}

} // namespace surfacemaps
