// SurfaceMaps engine: one embedding of the common triangulation set through
// another map, T refined by splits where that would fold it.
#pragma once

#include "map/CommonTriangulation.h"
#include "map/SurfaceMap.h"

namespace surfacemaps
{

struct ComposedEmbeddingOptions
{
  /// Rounds of splits at most (each splits the longest edge, on sphere i, of
  /// every triangle still not positively oriented there).
  int maxRounds = 20;
};

struct ComposedEmbeddingResult
{
  int splits = 0;
  int rounds = 0;
};

/// Sets T's embedding on sphere i to psi o g_0, psi the map from sphere 0 to
/// sphere 1 of `map` (a map of two inputs whose sphere 0 is T's sphere 0 and
/// whose sphere 1 is T's sphere i, e.g. the same inputs mapped alone):
/// g_i(v) = psi(g_0(v)) at every vertex. psi is bijective, but T's triangles
/// sampled at their corners only fold where psi bends within one of them:
/// there T's longest edge (on sphere i) is split, the new vertex at the
/// edge's midpoint on every sphere but i and at psi of it on sphere i, until
/// every triangle is positively oriented on sphere i (the exact predicate:
/// psi's own triangles may be thinner than the minimum an edit must leave)
/// and the embedding's degree is 1.
/// Splits keep T's existing vertices and put new ones on T's triangles on
/// every other sphere. Throws NoResultError when folds remain after
/// maxRounds rounds.
ComposedEmbeddingResult composeEmbedding(CommonTriangulation& T,
  int i,
  const SurfaceMapResult& map,
  const ComposedEmbeddingOptions& options = ComposedEmbeddingOptions());

} // namespace surfacemaps
