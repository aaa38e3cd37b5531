// SurfaceMaps engine: point location in a triangulation of the unit sphere.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <vector>

namespace surfacemaps
{

/// Where a point of the sphere lies in a spherical triangulation: the
/// triangle containing it and barycentric coordinates (alpha, beta, gamma =
/// 1 - alpha - beta) of the ray 0 -> p through the flat chord triangle abc,
/// so p = normalize(alpha a + beta b + gamma c) (DESIGN.md section 1.1).
struct SphereLocation
{
  int triangle = -1;
  double alpha = 0.0, beta = 0.0, gamma = 0.0;
};

/// Neighbour of each triangle across the edge opposite corner k (edge
/// (k+1, k+2)) in a closed, consistently oriented triangulation. Throws
/// std::invalid_argument when an edge has no opposite.
std::vector<std::array<int, 3>> triangleNeighbours(
  const std::vector<std::array<int, 3>>& triangles);

/// The visibility walk behind SphereLocator, on any bijective spherical
/// triangulation given by triangles, their neighbours and the corner points
/// (`points[corner index]`): starts at triangle `start`, crosses edges that
/// have p on their outer side (exact predicates); should the walk circle (a
/// triangulation far from Delaunay), scans all triangles. `visited`, if
/// given, is increased by the number of triangles visited. Throws
/// std::runtime_error if no triangle contains p (the triangulation is not
/// bijective, or p is not finite).
SphereLocation walkOnSphere(const Eigen::Vector3d& p,
  int start,
  const std::vector<std::array<int, 3>>& triangles,
  const std::vector<std::array<int, 3>>& neighbours,
  const Eigen::Vector3d* points,
  long long* visited = nullptr);

/// Locates points in a bijective embedding (every triangle positively
/// oriented, degree 1): a visibility walk across triangle edges decided by
/// exact orientation predicates, started from the triangle of the nearest
/// vertex in a cube-map grid (built once), or from a given triangle (for
/// points that moved a little: the walk is then short).
class SphereLocator
{
public:
  /// `points` must stay alive and unchanged while the locator is used.
  SphereLocator(const std::vector<Eigen::Vector3d>& points,
    const std::vector<std::array<int, 3>>& triangles);

  /// The triangle containing unit vector p (on an edge or vertex: one of the
  /// triangles sharing it) and p's barycentric coordinates in it.
  SphereLocation locate(const Eigen::Vector3d& p) const;
  /// Same, walking from triangle `start` (no grid look-up).
  SphereLocation locateFrom(const Eigen::Vector3d& p, int start) const;

  /// Barycentric coordinates of p with respect to triangle t (DESIGN.md
  /// formula; exact containment is decided separately).
  static std::array<double, 3> barycentric(const Eigen::Vector3d& p,
    const Eigen::Vector3d& a,
    const Eigen::Vector3d& b,
    const Eigen::Vector3d& c);

  /// Number of triangles visited by the last walks (for tests and tuning).
  long long visited() const { return this->Visited; }

private:
  int nearestVertexTriangle(const Eigen::Vector3d& p) const;
  int cell(const Eigen::Vector3d& p) const;

  const std::vector<Eigen::Vector3d>& Points;
  std::vector<std::array<int, 3>> Triangles;
  /// Neighbour across the edge opposite corner k (edge (k+1, k+2)).
  std::vector<std::array<int, 3>> Neighbours;
  std::vector<int> VertexTriangle;
  int Resolution = 1;
  std::vector<std::vector<int>> Cells; // vertices per cube-map cell
  mutable long long Visited = 0;
};

} // namespace surfacemaps
