// SurfaceMaps engine: distortion of a map between two meshes of equal
// connectivity (DESIGN.md section 6, "the yardstick").
#pragma once

#include <Eigen/Core>

#include <array>
#include <vector>

namespace surfacemaps
{

struct MapMetricsOptions
{
  /// Distortion thresholds for the area fractions (a1.5 and a2 by default).
  std::vector<double> thresholds{ 1.5, 2.0 };
};

/// The piecewise linear map from mesh P to mesh Q (same triangles), after
/// centring each mesh and scaling each to unit total area. Per triangle t:
/// both triangles in their own orthonormal frames, J_t = [q1-q0, q2-q0]
/// [p1-p0, p2-p0]^-1 with singular values s1 >= s2.
struct MapMetrics
{
  /// Per triangle: singular values, distortion max(s1, 1/s2) (+inf when a
  /// triangle is degenerate), and the unit-area areas on P and Q.
  std::vector<double> s1, s2, distortion, areaP, areaQ;
  /// 1/4 sum_t (area_Q (s1^2 + s2^2) + area_P (s1^-2 + s2^-2)); 1 for an
  /// isometry, +inf with a degenerate triangle.
  double symmetricDirichlet = 0.0;
  /// Largest per-triangle distortion.
  double maxDistortion = 0.0;
  /// Area fraction of P with distortion below each threshold.
  std::vector<double> thresholds, fractionBelow;
  /// Triangles degenerate on P or on Q (zero area at double precision).
  long long degenerateTriangles = 0;

  /// Area fraction of P whose distortion is below `threshold`.
  double areaFractionBelow(double threshold) const;
  /// The area-weighted cumulative distribution of the distortion at the
  /// given thresholds (sorted ascending): the curve of the paper's plots.
  std::vector<double> cumulativeCurve(const std::vector<double>& thresholds) const;
};

MapMetrics measureMap(const std::vector<Eigen::Vector3d>& P,
  const std::vector<Eigen::Vector3d>& Q,
  const std::vector<std::array<int, 3>>& triangles,
  const MapMetricsOptions& options = MapMetricsOptions());

/// Singular values (s1 >= s2 >= 0) of a 2x2 matrix, in closed form.
Eigen::Vector2d singularValues2x2(const Eigen::Matrix2d& J);

/// The length of the diagonal of the points' axis-aligned bounding box (the
/// unit of H and of every "% of the diagonal").
double boundingBoxDiagonal(const std::vector<Eigen::Vector3d>& points);

} // namespace surfacemaps
