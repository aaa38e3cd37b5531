// SurfaceMaps engine: exact geometric predicates.
#pragma once

#include <Eigen/Core>

#include <cmath>

namespace surfacemaps
{

/// orient3dOrigin with exact arithmetic (CGAL's filtered kernel): for the
/// signs the floating-point filter cannot certify.
int orient3dOriginExact(const Eigen::Vector3d& a,
  const Eigen::Vector3d& b,
  const Eigen::Vector3d& c);

/// Sign of det[a, b, c] (the orientation of the tetrahedron (0, a, b, c)),
/// computed exactly for the given doubles: +1, 0 or -1. For points on the
/// unit sphere, +1 means the spherical triangle abc is positively oriented.
/// Inline: point location and remeshing call it hundreds of millions of
/// times per map, and almost every call ends in the filter.
inline int orient3dOrigin(const Eigen::Vector3d& a,
  const Eigen::Vector3d& b,
  const Eigen::Vector3d& c)
{
  // Semi-static filter first (Shewchuk's orient3d error bound A, which is
  // (7 + 56 eps) eps < 1e-15 times the permanent; with the fourth point at the
  // origin the coordinate differences are exact): most calls end here, far
  // cheaper than the kernel's interval arithmetic.
  const double bc = b.x() * c.y() - c.x() * b.y();
  const double ca = c.x() * a.y() - a.x() * c.y();
  const double ab = a.x() * b.y() - b.x() * a.y();
  const double det = a.z() * bc + b.z() * ca + c.z() * ab;
  const double permanent = (std::abs(b.x() * c.y()) + std::abs(c.x() * b.y())) * std::abs(a.z()) +
    (std::abs(c.x() * a.y()) + std::abs(a.x() * c.y())) * std::abs(b.z()) +
    (std::abs(a.x() * b.y()) + std::abs(b.x() * a.y())) * std::abs(c.z());
  const double bound = 1e-15 * permanent;
  if (det > bound)
  {
    return 1;
  }
  if (det < -bound)
  {
    return -1;
  }
  return orient3dOriginExact(a, b, c);
}

/// Whether the ray 0 -> q meets the closed chord triangle abc (a, b, c
/// positively oriented), decided exactly.
inline bool rayMeetsTriangle(const Eigen::Vector3d& a,
  const Eigen::Vector3d& b,
  const Eigen::Vector3d& c,
  const Eigen::Vector3d& q)
{
  return orient3dOrigin(a, b, q) >= 0 && orient3dOrigin(b, c, q) >= 0 &&
    orient3dOrigin(c, a, q) >= 0;
}

} // namespace surfacemaps
