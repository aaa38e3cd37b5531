// SurfaceMaps engine: properties of triangulations of the unit sphere.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <string>
#include <vector>

namespace surfacemaps
{

/// Signed area of the spherical triangle abc (unit vectors), in (-2 pi, 2 pi):
/// positive for a positively oriented triangle (det[a, b, c] > 0).
double signedSphericalArea(const Eigen::Vector3d& a,
  const Eigen::Vector3d& b,
  const Eigen::Vector3d& c);

/// Sum of the signed spherical areas divided by 4 pi: 1 for a bijective
/// embedding of a closed surface, k for a k-fold cover. Not rounded; the last
/// bits may differ between thread counts.
double sphericalDegree(const std::vector<Eigen::Vector3d>& points,
  const std::vector<std::array<int, 3>>& triangles);

/// The indices of the triangles whose exact orientation is not positive,
/// ascending.
std::vector<int> invertedTriangles(const std::vector<Eigen::Vector3d>& points,
  const std::vector<std::array<int, 3>>& triangles);

struct BijectivityCertificate
{
  bool bijective = false;
  /// Triangles whose exact orientation is not positive.
  long long nonPositiveTriangles = 0;
  int firstNonPositive = -1;
  double degree = 0.0;
  /// Why not bijective (empty if bijective).
  std::string reason;
};

/// Certifies that the triangles, with vertices at the given unit-sphere
/// points, form a bijective embedding of a closed genus-0 mesh: every
/// triangle positively oriented by the exact predicate and degree 1.
BijectivityCertificate certifyBijective(const std::vector<Eigen::Vector3d>& points,
  const std::vector<std::array<int, 3>>& triangles);

} // namespace surfacemaps
