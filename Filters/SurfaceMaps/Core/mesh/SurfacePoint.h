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

} // namespace surfacemaps
