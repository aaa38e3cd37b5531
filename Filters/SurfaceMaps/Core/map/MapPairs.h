// SurfaceMaps engine: which pairs of inputs the map-distortion term measures.
#pragma once

#include <array>
#include <vector>

namespace surfacemaps
{

/// Which pairs of inputs the map-distortion term measures (DESIGN.md 1.8).
enum class PairScheme
{
  Star,     ///< (0, i) for every i > 0
  Sequence, ///< (i, i + 1)
  Cycle,    ///< (i, i + 1) and (N - 1, 0)
  All,      ///< every pair i < j
  /// Each input against the inputs' mean shape, triangle by triangle (the
  /// mean of the lifted triangles' Gram matrices): one term per input, no
  /// input privileged, time linear in N. Its pairs (those of Cycle) count
  /// the map terms; the distortion refinement checks each input's map onto
  /// its own approximating mesh instead.
  Mean,
};

/// The pairs (i, j) of a mode for n inputs.
std::vector<std::array<int, 2>> mapPairs(PairScheme mode, int n);

} // namespace surfacemaps
