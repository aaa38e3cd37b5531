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
/// only, no bad or unused or duplicate vertices, finite coordinates, no
/// zero-area triangles, closed, edge- and vertex-manifold, consistently
/// oriented, one connected component, genus 0. Defects name where they are
/// (first offending element and counts). Never throws on bad content.
MeshValidationResult validateMesh(const PolygonMesh& mesh,
  const MeshValidationOptions& options = MeshValidationOptions());

} // namespace surfacemaps
