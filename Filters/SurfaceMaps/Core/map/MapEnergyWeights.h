// SurfaceMaps engine: the terms of the map's energy and one phase's weights
// of them (DESIGN.md section 1.3), as plain values.
#pragma once

#include <vector>

namespace surfacemaps
{

/// The terms of the map's energy (DESIGN.md section 1.3), as the objective
/// groups them (Objective::group).
enum class MapTerm
{
  Barrier,
  MeshQuality, ///< with the coverage term (CoverageEnergy)
  Approximation,
  Landmarks,
  Distortion,
};

/// Weights of the energy's terms, already divided by the number of inputs
/// (or pairs) as in DESIGN.md section 1.3 (0: term off).
struct MapEnergyWeights
{
  double barrier = 0.0;
  double mesh = 0.0;
  double approximation = 0.0; // includes 1 / eps^2 for the soft term
  double landmark = 0.0;
  double map = 0.0;
  /// The distortion term measures each input's lifted triangles against the
  /// inputs' mean shape (PairScheme::Mean: per triangle the mean of the
  /// lifted triangles' Gram matrices, held within a Newton step) instead of
  /// the pairs; `map` is then divided by the number of inputs.
  bool mapToMean = false;
  /// Coverage (CoverageEnergy), in the mesh-quality group.
  double coverage = 0.0;
  /// Hard approximation bound per input (unit-area units of that input);
  /// empty: the soft term. With a bound, `approximation` is the barrier's
  /// weight (no 1 / eps^2).
  std::vector<double> bounds;
  double bound(int i) const { return this->bounds.empty() ? 0.0 : this->bounds[i]; }
  /// > 1: a triangle that inverts on a sphere at the full Newton step gets
  /// its barrier weight on that sphere multiplied by this, up to
  /// MaxBarrierRaises times (see CommonTriangulation::raiseBarrier); 1: one
  /// weight for every triangle.
  double barrierRaise = 1.0;
  /// Project the barrier's exact Hessian (eigenvalue clamp) instead of using
  /// its cheap Gauss-Newton form; worth it where the barrier dominates (the
  /// landmark phase), not where its weight is tiny.
  bool exactBarrierHessian = false;
};

} // namespace surfacemaps
