// SurfaceMaps engine: a point on a triangle mesh.
#pragma once

#include <Eigen/Core>

namespace surfacemaps
{

/// A point of a mesh given by one of its triangles and barycentric
/// coordinates (alpha, beta, gamma) of that triangle's corners.
struct SurfacePoint
{
  int triangle = -1;
  Eigen::Vector3d barycentric = Eigen::Vector3d::Zero();
};

/// The corner (0, 1 or 2) of p's triangle with the largest barycentric
/// coordinate, the first of equal ones: where categorical data (labels) is
/// read, so a transferred value is always one of the triangle's own.
inline int nearestCorner(const SurfacePoint& p)
{
  int best = 0;
  for (int k = 1; k < 3; ++k)
  {
    if (p.barycentric[k] > p.barycentric[best])
    {
      best = k;
    }
  }
  return best;
}

} // namespace surfacemaps
