// Test helper: small inputs for the surface map with known bijective
// embeddings (icospheres, whose vertices are their own sphere points).
#pragma once

#include "mesh/Primitives.h"
#include "map/SurfaceMap.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <vector>

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

/// Semi-axes and bump directions of bumpyEllipsoid.
inline Eigen::Vector3d bumpyAxes()
{
  return Eigen::Vector3d(1.0, 1.4, 1.9);
}
inline std::vector<Eigen::Vector3d> bumpyTips()
{
  return { Eigen::Vector3d(0.6, 0.0, 0.8).normalized(),
    Eigen::Vector3d(-0.3, -1.0, 0.2).normalized() };
}

/// An icosphere deformed into an ellipsoid with two bumps off its axes (no
/// symmetry left), its embedding the icosphere turned by `sphereTurn`, its
/// points moved by `motion`. `bumps` false: the plain ellipsoid.
inline MapInput bumpyEllipsoid(int level,
  const Eigen::Matrix3d& sphereTurn,
  const Eigen::Affine3d& motion,
  bool bumps = true)
{
  MapInput input;
  input.mesh = makeIcosphere(level);
  const std::vector<Eigen::Vector3d> tips = bumpyTips();
  for (Eigen::Vector3d& p : input.mesh.points)
  {
    input.spherePositions.push_back(sphereTurn * p);
    const double a = std::max(0.0, p.dot(tips[0])), b = std::max(0.0, p.dot(tips[1]));
    const double lift = bumps ? 1.0 + 0.6 * std::pow(a, 6) + 0.4 * std::pow(b, 6) : 1.0;
    p = motion * Eigen::Vector3d(p.cwiseProduct(bumpyAxes()) * lift);
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
