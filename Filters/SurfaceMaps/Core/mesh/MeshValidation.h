// SurfaceMaps engine: checks that a mesh is a usable input (closed, manifold,
// genus 0, clean triangles) and measures it.
#pragma once

#include "mesh/PolygonMesh.h"

#include <string>
#include <vector>

namespace surfacemaps
{

struct MeshValidationOptions
{
  /// Triangles with area <= this fraction of the total area count as zero-area
  /// (1e-12: far below anything the optimiser can resolve in unit-area units).
  double zeroAreaFraction = 1e-12;
  /// The valid dynamic range: every coordinate within +-maxCoordinate (1e50)
  /// and a bounding-box diagonal of at least minBoundingBoxDiagonal (1e-50),
  /// so that every quantity up to the fourth power of a length (squared
  /// areas, squared norms of cross products, which norm() forms) stays
  /// finite and far from the denormal range (1e+-308) in double precision.
  /// The total area must also be finite and positive.
  double maxCoordinate = 1e50;
  double minBoundingBoxDiagonal = 1e-50;
  /// True: everything validateMesh lists. False: only what any measurement
  /// of a triangle mesh needs (triangles only, vertex ids in range, finite
  /// coordinates in the dynamic range, positive finite area), for meshes that
  /// are results rather than inputs (a map's triangles may degenerate).
  bool requireSurface = true;
};

/// What a mesh is, as far as it could be determined (-1: not determined).
struct MeshStatistics
{
  long long vertices = 0;
  long long faces = 0;
  long long edges = -1;
  long long boundaryEdges = -1;
  long long nonManifoldEdges = -1;
  long long nonManifoldVertices = -1;
  /// Vertices at the same position as another one.
  long long duplicateVertices = -1;
  long long components = -1;
  /// Only for a closed, manifold, connected, orientable surface.
  int genus = -1;
  double area = 0.0;
  double boundingBoxDiagonal = 0.0;
  /// Smallest and mean per-triangle minimum interior angle, degrees.
  double minAngle = 0.0;
  double meanMinAngle = 0.0;
  /// Sign of the enclosed volume: +1 outward normals, -1 inward, 0 unknown.
  int orientation = 0;
};

struct MeshValidationResult
{
  MeshStatistics statistics;
  /// One sentence per defect, without the mesh name ("is not closed: ...").
  std::vector<std::string> defects;
  bool valid() const { return this->defects.empty(); }
};

/// Validates `mesh` as input for the sphere embedding and the map: triangles
/// only, vertex ids in range (also 64-bit ones), no unused or duplicate
/// vertices, finite coordinates within the dynamic range of `options`, finite
/// positive area, no zero-area triangles, closed, edge- and vertex-manifold, consistently
/// oriented, one connected component, genus 0. Defects name where they are
/// (first offending element and counts). Never throws on bad content.
MeshValidationResult validateMesh(const PolygonMesh& mesh,
  const MeshValidationOptions& options = MeshValidationOptions());

} // namespace surfacemaps
