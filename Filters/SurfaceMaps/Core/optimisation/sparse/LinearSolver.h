// SurfaceMaps engine: LinearSolver, the façade of the sparse wing: sparse
// symmetric positive definite solves (CHOLMOD) for the Newton steps, direct
// (CholeskyFactor) or by blocks (BlockPreconditionedCG).
#pragma once

#include "base/Log.h"

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <memory>
#include <string>
#include <vector>

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
  /// Conjugate-gradient iterations (block solves only; 0 for a direct solve).
  int iterations = 0;
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

  /// Symbolic analysis of the sparsity pattern (upper triangle; values are
  /// not read) of the matrix the next solve() gets with patternChanged set,
  /// so that the analysis can run beside other work (Objective::hessian's
  /// newPattern). That solve() then does not analyse again. Nothing to do for
  /// block solves.
  void analyse(const Eigen::SparseMatrix<double>& pattern);

  LinearSolveResult solve(const Eigen::SparseMatrix<double>& H,
    const Eigen::VectorXd& b,
    Eigen::VectorXd& x,
    bool patternChanged,
    const Logger& log = Logger());

  /// Splits the variables into blocks [offsets[k], offsets[k + 1]) (e.g. one
  /// per sphere embedding; offsets ascending, from 0 to the number of
  /// variables). With two or more blocks, solve() runs conjugate gradients
  /// on the whole system, preconditioned with each diagonal block's own
  /// Cholesky factor (regularised like a direct solve), to a relative
  /// residual of 1e-8 or 200 iterations. Its cost is linear in the number of
  /// blocks, where one factorisation of a system of K coupled embeddings has
  /// dense fronts K times as wide (cubic cost). Every iterate of conjugate
  /// gradients from 0 is a descent direction, so a capped solve still gives
  /// Newton a usable step. Fewer than two blocks (the default): direct solves.
  void setBlocks(std::vector<int> offsets);

private:
  struct Internals;
  std::unique_ptr<Internals> Impl;
};

} // namespace surfacemaps
