// SurfaceMaps engine: bijective embedding of a genus-0 mesh on the unit sphere.
#pragma once

#include "base/Aborted.h"
#include "base/Error.h"
#include "base/Log.h"
#include "geometry/SphericalTriangulation.h"
#include "mesh/PolygonMesh.h"

#include <Eigen/Core>

#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace surfacemaps
{

struct SphereEmbeddingOptions
{
  /// Total weight of the barriers (orientation, edge length), spread evenly
  /// over the triangles, against the distortion (whose minimum is 1). The
  /// retry with a stronger barrier multiplies it by 100.
  double barrierWeight = 0.1;
  /// Newton iterations on the whole current mesh after inserting a level,
  /// and the same above 1 000 vertices; they stop earlier once the decrease
  /// a Newton step expects (decrement^2 / 2) is below levelTolerance (the
  /// distortion's minimum is 1).
  int levelIterations = 20;
  int levelIterationsLarge = 5;
  double levelTolerance = 1e-5;
  /// Newton iterations on the input mesh at the end, and their tolerance
  /// (as for the levels).
  int finalIterations = 50;
  double finalTolerance = 1e-5;
  /// The final iterations go on, up to finalIterationsSqueezed in all (and
  /// until the tolerance is met), while some triangle's share of the sphere is
  /// below squeezedRatio times its share of the input's area. The exact map
  /// inherits such a triangle: input triangles that land in it are squeezed
  /// or stretched as much. Sound embeddings of real meshes have no triangle
  /// below 0.07; after 50 iterations a few meshes still have triangles at
  /// 1e-4 to 1e-3 that more iterations remove. 0 turns the check off.
  int finalIterationsSqueezed = 150;
  double squeezedRatio = 1e-2;
  /// Newton iterations on each inserted vertex's own two variables.
  int localIterations = 10;
  /// An attempt whose final distortion exceeds this counts as failed and the
  /// next attempt runs; if every certified attempt exceeds it, the least
  /// distorted one is the result. The first attempt also gives up at the
  /// first level whose distortion ends above it. A sound embedding's
  /// distortion is of order 1-10; above 100 it is dominated by triangles
  /// squeezed thousands of times on the sphere, which the map inherits: its
  /// exact map squeezes the input there, however good T is.
  double maxDistortion = 100.0;
  /// Largest tangent step of one point per Newton step (tan 75 degrees).
  double maxPointStep = 3.7320508075688772;
  /// Called with the fraction done (0..1); return false to abort.
  std::function<bool(double)> progress;
  Logger log;
};

struct SphereEmbeddingResult
{
  /// Unit vectors, one per input vertex.
  std::vector<Eigen::Vector3d> positions;
  BijectivityCertificate certificate;
  /// Final energy (distortion + barriers) and the distortion alone (DESIGN.md
  /// section 6 symmetric Dirichlet between input and chord triangles).
  double energy = 0.0;
  double distortion = 0.0;
  /// The smallest ratio, over the triangles, of a triangle's share of the
  /// sphere (its chord triangle's area over all of them) to its share of the
  /// input's area: 1 everywhere for an area-preserving embedding.
  double smallestAreaRatio = 0.0;
  int levels = 0;
  int newtonIterations = 0;
  /// 1: default weights; 2: stronger barrier; 3: barrier alone.
  int attempt = 0;
  double seconds = 0.0;
  /// Where the time went: decimation, vertex placement (with local Newton),
  /// and the global Newton steps' derivatives, linear solves and line searches.
  double decimationSeconds = 0.0;
  double placementSeconds = 0.0;
  double derivativeSeconds = 0.0;
  double solveSeconds = 0.0;
  double lineSearchSeconds = 0.0;
};

/// Embeds a valid closed genus-0 triangle mesh bijectively on the unit sphere
/// (DESIGN.md section 1.9): decimation to a tetrahedron, regular tetrahedron
/// on the sphere, reinsertion level by level (each vertex inside its one-ring's
/// kernel, local Newton, a few global Newton iterations), final global
/// iterations; every step keeps all triangles positively oriented and the
/// degree 1. The result is certified with exact predicates; on failure the
/// embedding is retried with a stronger barrier, then with the barrier alone.
/// Throws NoResultError if no attempt certifies.
SphereEmbeddingResult embedOnSphere(const PolygonMesh& mesh,
  const SphereEmbeddingOptions& options = SphereEmbeddingOptions());

/// Thrown by embedAllOnSphere when the embedding of mesh `index` fails.
struct EmbeddingFailure : NoResultError
{
  EmbeddingFailure(int i, const std::string& message)
    : NoResultError(message)
    , index(i)
  {
  }
  int index;
};

/// Embeds several meshes at once, one mesh per thread: faster than one after
/// the other with all threads, since much of an embedding is serial. Threads
/// without a mesh left join the embeddings still running. The results equal
/// embedOnSphere's of each mesh bit for bit (they do not depend on the
/// thread count). options.progress is called from the calling thread
/// only, with the mean fraction over the meshes; false aborts every embedding
/// (Aborted). Throws EmbeddingFailure for the first mesh (by index)
/// that cannot be embedded.
std::vector<SphereEmbeddingResult> embedAllOnSphere(const std::vector<const PolygonMesh*>& meshes,
  const SphereEmbeddingOptions& options = SphereEmbeddingOptions());

/// Symmetric Dirichlet distortion (DESIGN.md section 6) between a mesh and
/// its chord triangles on the sphere, both at unit total area.
double embeddingDistortion(const std::vector<Eigen::Vector3d>& input,
  const std::vector<Eigen::Vector3d>& sphere,
  const std::vector<std::array<int, 3>>& triangles);

} // namespace surfacemaps
