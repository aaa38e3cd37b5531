// SurfaceMaps engine: one input of a surface map.
#pragma once

#include "mesh/PolygonMesh.h"

#include <Eigen/Core>

#include <vector>

namespace surfacemaps
{

/// One input surface with its fixed sphere embedding.
struct MapInput
{
  /// Closed genus-0 triangle mesh (validated), in the input's own units.
  PolygonMesh mesh;
  /// Certified bijective sphere embedding f_i, one unit vector per vertex.
  std::vector<Eigen::Vector3d> spherePositions;
  /// Landmark id per vertex, -1 for none (empty: no landmarks). The same id
  /// on two inputs means the two vertices correspond.
  std::vector<int> landmarks;
  /// Target edge length per vertex in the input's own units (empty: from
  /// curvature, DESIGN.md section 1.7).
  std::vector<double> sizing;
};

} // namespace surfacemaps
