// SurfaceMaps engine: curvature-based target edge lengths (DESIGN.md section
// 1.7, "Sizing").
#pragma once

#include <Eigen/Core>

#include <array>
#include <vector>

namespace surfacemaps
{

struct SizingOptions
{
  /// Approximation tolerance eps (same units as the mesh).
  double targetError = 1e-3;
  /// Clamp of the target edge length.
  double minEdgeLength = 1e-3;
  double maxEdgeLength = 100.0;
};

/// Largest absolute principal curvature per vertex of a closed triangle mesh
/// (mean curvature from the cotangent Laplacian, Gaussian curvature from the angle defect,
/// both over mixed Voronoi areas; kappa_max = |H| + sqrt(max(H^2 - K, 0))).
///
/// Mixed areas follow Meyer et al. 2003 ("Discrete Differential-Geometry
/// Operators for Triangulated 2-Manifolds"), so obtuse triangles give positive
/// areas. Triangles of zero area add their angles but no cotangent weights or
/// area; a vertex without area (unreferenced, or only in degenerate triangles)
/// gets 0, and the result is never NaN for finite input. Values at boundary
/// vertices of an open mesh are meaningless. Throws std::invalid_argument on
/// a vertex index out of range.
std::vector<double> maxAbsCurvature(const std::vector<Eigen::Vector3d>& points,
  const std::vector<std::array<int, 3>>& triangles);

/// Target edge length per vertex (Dunyach et al. 2013): l = sqrt(6 eps / kappa - 3 eps^2), clamped
/// to [min, max]; where kappa > 2 / eps (formula undefined) the minimum; where kappa == 0 the
/// maximum; +inf curvature gives the minimum. Throws std::invalid_argument unless eps is finite and
/// positive and 0 < min <= max (min finite).
std::vector<double> curvatureSizing(const std::vector<Eigen::Vector3d>& points,
  const std::vector<std::array<int, 3>>& triangles,
  const SizingOptions& options = SizingOptions());

} // namespace surfacemaps
