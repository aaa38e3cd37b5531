// Test helper: small inputs for the surface map with known bijective
// embeddings (icospheres, whose vertices are their own sphere points).
#pragma once

#include "mesh/Primitives.h"
#include "map/SurfaceMap.h"

#include <Eigen/Geometry>

namespace surfacemaps
{
namespace testing
{

/// An icosphere of the given level, rotated by `angle` about (1, 2, 3) on the
/// sphere, deformed into an ellipsoid with semi-axes `axes` plus a bump of
/// height `bump` at +z; its embedding is the rotated icosphere itself.
inline MapInput icosphereInput(int level,
  double angle,
  const Eigen::Vector3d& axes,
  double bump = 0.0)
{
  MapInput input;
  input.mesh = makeIcosphere(level);
  const Eigen::Matrix3d R =
    Eigen::AngleAxisd(angle, Eigen::Vector3d(1, 2, 3).normalized()).matrix();
  for (Eigen::Vector3d& p : input.mesh.points)
  {
    p = R * p;
    input.spherePositions.push_back(p);
    const double z = std::max(0.0, p.z());
    p = p.cwiseProduct(axes) * (1.0 + bump * z * z * z * z);
  }
  return input;
}

/// The vertex of `input` whose sphere point is closest to direction d.
inline int closestVertex(const MapInput& input, const Eigen::Vector3d& d)
{
  int best = 0;
  for (std::size_t v = 0; v < input.spherePositions.size(); ++v)
  {
    if (input.spherePositions[v].dot(d) > input.spherePositions[best].dot(d))
    {
      best = static_cast<int>(v);
    }
  }
  return best;
}

/// Landmarks 0..k-1 at the vertices closest to the given directions.
inline void setLandmarks(MapInput& input, const std::vector<Eigen::Vector3d>& directions)
{
  input.landmarks.assign(input.mesh.points.size(), -1);
  for (std::size_t k = 0; k < directions.size(); ++k)
  {
    input.landmarks[closestVertex(input, directions[k].normalized())] = static_cast<int>(k);
  }
}

} // namespace testing
} // namespace surfacemaps
