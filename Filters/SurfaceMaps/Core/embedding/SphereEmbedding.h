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

/// Every setting of embedOnSphere: one field per embedding setting of the
/// list (settings/SettingList.def), which holds its type, default, range and
/// documentation.
struct SphereEmbeddingOptions
{
#define SURFACEMAPS_EMBEDDING_SETTING(Name, field, Type, Kind, Default, ...) Type field = Default;
#include "settings/SettingList.def"

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
