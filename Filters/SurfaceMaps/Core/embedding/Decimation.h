// SurfaceMaps engine: a hierarchy of half-edge collapses down to a tetrahedron.
#pragma once

#include "base/Log.h"
#include "mesh/PolygonMesh.h"

#include <array>
#include <vector>

namespace surfacemaps
{

struct DecimationOptions
{
  /// Collapses stop at this many vertices (4: a tetrahedron).
  int targetVertices = 4;
  /// Reject collapses that leave a triangle with area below this fraction of
  /// the total area (1e-10: DESIGN's unit-area threshold).
  double minAreaFraction = 1e-10;
  /// Reject collapses that turn a triangle normal by more than this angle
  /// (degrees); relaxed automatically when nothing else can be collapsed.
  double maxNormalChange = 90.0;
  Logger log;
};

/// One half-edge collapse: `removed` merged into `kept`. `ring` is the
/// one-ring of `removed` just before the collapse, in the mesh's orientation
/// (the triangles (removed, ring[i], ring[i+1]) were faces), `kept` among it.
struct Collapse
{
  int removed = -1;
  int kept = -1;
  std::vector<int> ring;
};

/// The collapses of one level (independent: no removed vertex is in the
/// one-ring of another) and the triangles that remain after them.
struct DecimationLevel
{
  std::vector<Collapse> collapses;
  std::vector<std::array<int, 3>> triangles;
};

struct DecimationResult
{
  /// The input's triangles (level 0).
  std::vector<std::array<int, 3>> triangles;
  /// Coarser and coarser; the last one has targetVertices vertices.
  std::vector<DecimationLevel> levels;
  /// True if geometric checks had to be dropped to reach the target.
  bool relaxed = false;
};

/// Decimates a valid closed genus-0 triangle mesh by half-edge collapses in
/// order of quadric error, in levels of independent collapses, down to a
/// tetrahedron. Vertex indices are the input's throughout. Throws
/// std::runtime_error if the mesh cannot be reduced (it is not genus 0).
DecimationResult decimateToTetrahedron(const PolygonMesh& mesh,
  const DecimationOptions& options = DecimationOptions());

} // namespace surfacemaps
