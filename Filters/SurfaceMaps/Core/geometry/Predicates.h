// SurfaceMaps engine: exact geometric predicates.
#pragma once

#include <Eigen/Core>

namespace surfacemaps
{

/// Sign of det[a, b, c] (the orientation of the tetrahedron (0, a, b, c)),
/// computed exactly for the given doubles: +1, 0 or -1. For points on the
/// unit sphere, +1 means the spherical triangle abc is positively oriented.
int orient3dOrigin(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c);

/// Whether the ray 0 -> q meets the closed chord triangle abc (a, b, c
/// positively oriented), decided exactly.
bool rayMeetsTriangle(const Eigen::Vector3d& a,
  const Eigen::Vector3d& b,
  const Eigen::Vector3d& c,
  const Eigen::Vector3d& q);

} // namespace surfacemaps
