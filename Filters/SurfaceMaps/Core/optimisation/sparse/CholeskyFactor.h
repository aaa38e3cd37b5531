// SurfaceMaps engine: CholeskyFactor, CHOLMOD's Cholesky factor of one sparse
// symmetric matrix: analysis, numeric factorisation, solves, and the
// diagonal shift that rescues a matrix that is not numerically positive
// definite.
#pragma once

#include "optimisation/sparse/LinearSolver.h"

#include <cholmod.h>

#include <Eigen/Core>
#include <Eigen/SparseCore>


namespace surfacemaps
{

/// The direct solves of LinearSolver (its class comment says what they
/// guarantee): cholmod_analyze, cholmod_factorize and cholmod_solve. A
/// simplicial factorisation runs on one thread (a hand-written split of it
/// over threads along the elimination tree saved under 5 % of the corpus'
/// time on two cores: Testing/Benchmarks/README.md, tricks on and off).
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
    const Logger& log,
    LinearSolveResult& result);
  bool factorise(const Eigen::SparseMatrix<double>& H);
  bool solveWith(const Eigen::VectorXd& b, Eigen::VectorXd& x);

  cholmod_common Common;
  cholmod_factor* Factor = nullptr;
  // analyseAhead() was called for the next solve's pattern.
  bool AnalysedAhead = false;
};

} // namespace surfacemaps
