// SurfaceMaps engine: vertex placement for the sphere embedding: a vertex
// undone from a collapse placed inside its one-ring's kernel on the sphere,
// then relaxed by Newton on its own two tangent variables.
#pragma once

#include "embedding/Decimation.h"
#include "energy/EmbeddingEnergy.h"

#include <Eigen/Core>

#include <vector>

namespace surfacemaps
{

/// A point strictly inside the kernel of the star polygon c.ring on the
/// sphere (which contains c.kept as a vertex and is star-shaped with respect
/// to it), with all new edges short enough: of a few candidates that
/// qualify, the one with the lowest energy of the new triangles. Candidates:
/// the ring's centroid, the ring's average weighted like the removed
/// vertex's 3D neighbourhood, and points close to c.kept inside the angle its
/// two ring edges make (which qualify for small enough distances, since the
/// coarser embedding was valid). False if none qualifies.
bool placeInKernel(const Collapse& c,
  const EmbeddingEnergy& energy,
  const std::vector<Eigen::Vector3d>& pos,
  Eigen::Vector3d& out);

/// Newton on the two tangent variables of vertex c.removed, its ring fixed;
/// every step keeps the star valid by the exact predicates.
void relaxVertex(const Collapse& c,
  const EmbeddingEnergy& energy,
  std::vector<Eigen::Vector3d>& pos,
  int iterations);

} // namespace surfacemaps
