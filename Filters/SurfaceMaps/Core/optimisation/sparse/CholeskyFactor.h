// SurfaceMaps engine: CholeskyFactor, CHOLMOD's Cholesky factor of one sparse
// symmetric matrix: analysis, numeric factorisation (split over threads
// along the elimination tree where that pays), solves, and the diagonal
// shift that rescues a matrix that is not numerically positive definite.
#pragma once

#include "optimisation/sparse/EliminationTreeSplit.h"
#include "optimisation/sparse/LinearSolver.h"
#include "optimisation/sparse/RemainderPipeline.h"

#include <cholmod.h>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <memory>
#include <vector>

namespace surfacemaps
{

/// The direct solves of LinearSolver (its class comment says what they
/// guarantee). CHOLMOD's simplicial factorisation is serial; this class runs
/// cholmod_factorize's steps itself so that the rows can be factorised in
/// the lists of an EliminationTreeSplit and by the RemainderPipeline.
class CholeskyFactor
{
public:
  explicit CholeskyFactor(LinearSolver::Ordering ordering);
  ~CholeskyFactor();
  CholeskyFactor(const CholeskyFactor&) = delete;
  CholeskyFactor& operator=(const CholeskyFactor&) = delete;

  /// Symbolic analysis of the pattern the next solve() gets with
  /// patternChanged set (LinearSolver::analyse).
  void analyseAhead(const Eigen::SparseMatrix<double>& pattern);

  /// Factorises H (upper triangle; analysed again if patternChanged, unless
  /// analyseAhead was called) and solves H x = b, with a growing diagonal
  /// shift if the plain factorisation fails.
  LinearSolveResult solve(const Eigen::SparseMatrix<double>& H,
    const Eigen::VectorXd& b,
    Eigen::VectorXd& x,
    bool patternChanged,
    const Logger& log);

  /// Solves with the factor of the last successful solve (same matrix).
  bool solveAgain(const Eigen::VectorXd& b, Eigen::VectorXd& x);

private:
  void analyse(const Eigen::SparseMatrix<double>& H);
  void analyseLocked(const Eigen::SparseMatrix<double>& H);
  bool solveShifted(const Eigen::SparseMatrix<double>& H,
    const Eigen::VectorXd& b,
    Eigen::VectorXd& x,
    int threads,
    const Logger& log,
    LinearSolveResult& result);
  bool factorise(const Eigen::SparseMatrix<double>& H, int threads);
  cholmod_sparse* permutedUpper(cholmod_sparse& A);
  void prepareRows(cholmod_sparse*& S);
  bool factoriseSplit(cholmod_sparse& S, int threads);
  bool factoriseList(cholmod_sparse& S, int list, cholmod_common* common);
  bool finishFactor();
  bool solveWith(const Eigen::VectorXd& b, Eigen::VectorXd& x);

  cholmod_common Common;
  cholmod_factor* Factor = nullptr;
  // Workspaces of the further threads of a split factorisation.
  std::vector<std::unique_ptr<cholmod_common>> ThreadCommons;
  EliminationTreeSplit Split;
  RemainderPipeline Pipeline;
  // How many threads the last factorisation ran on.
  int FactorisationThreads = 1;
  // analyseAhead() was called for the next solve's pattern.
  bool AnalysedAhead = false;
};

} // namespace surfacemaps
