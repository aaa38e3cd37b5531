// SurfaceMaps engine: sparse symmetric positive definite solves (CHOLMOD).
#pragma once

#include "base/Log.h"

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <memory>
#include <string>

namespace surfacemaps
{

struct LinearSolveResult
{
  bool success = false;
  /// Relative diagonal shift mu that had to be added, H + mu diag(H) (0: the
  /// plain factorisation worked).
  double shift = 0.0;
  /// Whether the symbolic analysis was (re)done for this solve.
  bool analysed = false;
};

/// Solves H x = b for a sparse symmetric positive (semi-)definite H given by
/// its upper triangle, with CHOLMOD's Cholesky factorisation (supernodal for
/// dense factors, simplicial for sparse ones). The symbolic
/// analysis is kept while the sparsity pattern stays the same. If the
/// factorisation fails (H not numerically positive definite, or definite but
/// scaled beyond what rounding allows), H + mu diag(H) is factorised with a
/// growing mu (Levenberg-Marquardt's scaling, so that every variable keeps its
/// step in proportion); the log says which happened.
class LinearSolver
{
public:
  /// Fill-reducing orderings: AMD analyses fast (for patterns that change
  /// every step); nested dissection (METIS) takes longer to analyse but
  /// factorises mesh-like matrices with fewer operations (for patterns that
  /// stay for many steps).
  enum class Ordering
  {
    Amd,
    NestedDissection,
  };

  explicit LinearSolver(Ordering ordering = Ordering::Amd);
  ~LinearSolver();
  LinearSolver(const LinearSolver&) = delete;
  LinearSolver& operator=(const LinearSolver&) = delete;

  LinearSolveResult solve(const Eigen::SparseMatrix<double>& H,
    const Eigen::VectorXd& b,
    Eigen::VectorXd& x,
    bool patternChanged,
    const Logger& log = Logger());

private:
  struct Internals;
  std::unique_ptr<Internals> Impl;
};

} // namespace surfacemaps
