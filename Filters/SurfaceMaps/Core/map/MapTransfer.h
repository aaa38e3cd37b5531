// SurfaceMaps engine: carrying points (and with them any data) from one input
// to another through the common triangulation of a computed map
// (DESIGN.md sections 1.2 and 3).
#pragma once

#include "geometry/SphereLocator.h"
#include "mesh/SurfacePoint.h"

#include <Eigen/Core>

#include <array>
#include <vector>

namespace surfacemaps
{

struct MapTransferOptions
{
  /// Per T vertex: a triangle of input `to` at or near the vertex's lift
  /// (SurfaceMapResult::sourcePoints[to], or the "SourceCellId" of T lifted
  /// on `to`). Point location on f_to then walks from the triangle of the
  /// first corner of the T triangle that contains the point: short walks and
  /// no grid look-up. Empty: every point is located from the grid.
  std::vector<int> startTriangles;
  /// `from` and `to` are the same input: the map is the identity, and points
  /// are located on f_to directly (exactly at a vertex when a point is that
  /// vertex's sphere point) instead of through T's embeddings.
  bool identity = false;
};

/// Maps points on sphere `from` to input `to` through the common
/// triangulation T: each point is located in T's embedding g_from (triangle
/// and barycentric coordinates), the same barycentric coordinates are taken
/// on T's embedding g_to and the result normalised (psi = g_to o g_from^-1),
/// then located in the embedding f_to of input `to`. Returns, per point, the
/// triangle of input `to` and the barycentric coordinates there; with `points`
/// = f_from of input `from`'s vertices this is the exact map
/// Phi = f_to^-1 o psi o f_from on those vertices.
///
/// `commonTriangles` with `gFrom` and `gTo` are T and two of its embeddings,
/// `fTo` and `toTriangles` input `to`'s embedding, all in the map's frame
/// (SurfaceMapResult::spherePositions and inputSpherePositions) and certified
/// bijective (otherwise point location throws std::runtime_error). Throws
/// std::invalid_argument when sizes or indices do not fit together.
std::vector<SurfacePoint> transferPoints(const std::vector<Eigen::Vector3d>& points,
  const std::vector<std::array<int, 3>>& commonTriangles,
  const std::vector<Eigen::Vector3d>& gFrom,
  const std::vector<Eigen::Vector3d>& gTo,
  const std::vector<Eigen::Vector3d>& fTo,
  const std::vector<std::array<int, 3>>& toTriangles,
  const MapTransferOptions& options = MapTransferOptions());

/// Where sphere point p lies on an input, given the input's embedding
/// (`sphere`, `triangles`) and a locator built on it, walking from triangle
/// `start` (< 0: a search from scratch); exactly at a corner when p is that
/// corner's sphere point.
SurfacePoint locateSurfacePoint(const SphereLocator& locator,
  const std::vector<Eigen::Vector3d>& sphere,
  const std::vector<std::array<int, 3>>& triangles,
  const Eigen::Vector3d& p,
  int start);

/// The position of a surface point on the mesh it refers to.
Eigen::Vector3d evaluateSurfacePoint(const std::vector<Eigen::Vector3d>& points,
  const std::vector<std::array<int, 3>>& triangles,
  const SurfacePoint& p);

/// Per-corner values (e.g. PolygonMesh::cornerTexCoords, three per
/// triangle) interpolated at a surface point inside its triangle: seams
/// (corners of one vertex with different values) stay sharp.
Eigen::Vector2d evaluateCornerValues(const std::vector<Eigen::Vector2d>& cornerValues,
  const SurfacePoint& p);

/// Per-corner values (texture coordinates) of a mesh whose vertices lie on a
/// source mesh: three per triangle of `triangles`, whose vertex v lies at
/// `points[v]` on the source (`sourcePoints`, `sourceTriangles`, with
/// `cornerValues` three per source triangle).
///
/// The source's values split it into charts: triangles joined across an edge
/// whose two vertices have the same values on both sides (exactly equal, as a
/// shared OBJ `vt` index gives). A triangle whose corners lie in one chart gets
/// each corner's value evaluated where it lies, so triangles of one chart
/// agree at shared vertices. A triangle that straddles a seam takes the chart
/// of most of its corners (of its first corner when all differ), and each
/// corner outside that chart gets the value the chart's affine map would give
/// it: the corner's position projected onto the plane of a triangle of that
/// chart holding another corner of the triangle, with that triangle's values
/// extrapolated. So no triangle spans a seam in texture space (where a value
/// per vertex stretches it across the whole atlas); a seam-straddling
/// triangle shows the strip of texture just beyond its chart's border.
/// Throws std::invalid_argument when sizes or indices do not fit together.
std::vector<Eigen::Vector2d> transferCornerValues(const std::vector<Eigen::Vector3d>& sourcePoints,
  const std::vector<std::array<int, 3>>& sourceTriangles,
  const std::vector<Eigen::Vector2d>& cornerValues,
  const std::vector<std::array<int, 3>>& triangles,
  const std::vector<SurfacePoint>& points);

} // namespace surfacemaps
