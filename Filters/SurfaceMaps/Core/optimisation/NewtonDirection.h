// SurfaceMaps engine: the Newton direction from a gradient and a projected
// Hessian (with the -gradient fallback), and the Newton decrement.
#pragma once

#include "base/Log.h"
#include "optimisation/sparse/LinearSolver.h"

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <algorithm>
#include <cmath>

namespace surfacemaps
{

struct NewtonDirection
{
  /// The direction: -H^-1 g, or -g where that is no descent direction.
  Eigen::VectorXd d;
  /// d . g (< 0 for a descent direction; 0 for a zero gradient).
  double slope = 0.0;
  /// The Newton direction was no descent direction; -gradient was used.
  bool gradientFallback = false;
  /// The linear solve needed a diagonal shift.
  bool regularised = false;
};

/// Solves H d = -g (`patternChanged`: H's sparsity pattern differs from the
/// solver's last system); falls back to d = -g when the solve fails or its d
/// is no descent direction.
NewtonDirection newtonDirection(const Eigen::VectorXd& g,
  const Eigen::SparseMatrix<double>& H,
  LinearSolver& solver,
  bool patternChanged,
  const Logger& log);

/// sqrt(-d . g) of a descent direction: the convergence measure.
inline double newtonDecrement(const NewtonDirection& direction)
{
  return std::sqrt(std::max(0.0, -direction.slope));
}

} // namespace surfacemaps
