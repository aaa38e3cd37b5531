// SurfaceMaps engine: principal modes of variation of aligned shapes that
// share one connectivity.
#pragma once

#include "statistics/Procrustes.h"

#include <Eigen/Core>

#include <vector>

namespace surfacemaps
{

struct ShapeModesOptions
{
  /// Modes computed at most; a population of N shapes has at most N - 1.
  int modes = 3;
};

/// Every figure uses the area-weighted inner product <u, w> = sum_v A_v
/// u_v . w_v (A_v the vertex weights, sum 1) and second moments with 1/N:
/// sqrt(variance) is then an RMS displacement over the surface, in length
/// units, whatever the mesh resolution.
struct ShapeModesResult
{
  /// The mean of the shapes (1/N each).
  ShapePoints mean;
  /// Per vertex: sqrt of the mean squared distance of the shapes to the mean.
  std::vector<double> standardDeviation;
  /// sum_v A_v standardDeviation_v^2 = the sum of all N - 1 variances.
  double totalVariance = 0.0;
  /// Per mode m, descending: (1/N) sum_i scores(i, m)^2.
  std::vector<double> variances;
  /// variances[m] / totalVariance (0 when the total is 0).
  std::vector<double> explainedFractions;
  /// Per mode: a displacement per vertex with <u, u> = 1 (all zero for a
  /// mode of variance 0), its largest coordinate positive so that the sign
  /// does not depend on the order of the shapes.
  std::vector<ShapePoints> modes;
  /// N x modes: <x_i - mean, u_m>, so x_i ~ mean + sum_m scores(i, m) u_m.
  Eigen::MatrixXd scores;
};

/// PCA of `shapes` (already aligned, e.g. by alignProcrustes) through the N x
/// N Gram matrix of their deviations from the mean: N is small (tens), the
/// points many, so the eigenproblem is N x N instead of 3V x 3V. Needs N >= 2
/// shapes of equal size and one weight per vertex.
ShapeModesResult principalModes(const std::vector<ShapePoints>& shapes,
  const std::vector<double>& vertexWeights,
  const ShapeModesOptions& options = {});

/// mean + coefficient * sqrt(variances[mode]) * modes[mode] (mode 0-based).
ShapePoints shapeAlongMode(const ShapeModesResult& statistics, int mode, double coefficient);

} // namespace surfacemaps
