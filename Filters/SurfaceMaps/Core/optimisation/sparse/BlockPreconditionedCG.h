// SurfaceMaps engine: BlockPreconditionedCG, conjugate gradients on a system
// of several coupled blocks (one per sphere embedding), preconditioned with
// each diagonal block's own Cholesky factor.
#pragma once

#include "optimisation/sparse/LinearSolver.h"

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <memory>
#include <vector>

namespace surfacemaps
{

class CholeskyFactor;

/// The block solves of LinearSolver (LinearSolver::setBlocks says what they
/// do). One Cholesky factorisation of K coupled embeddings has dense fronts
/// K times as wide (cubic cost); Eigen's ConjugateGradient takes one
/// preconditioner object and applies it serially, so the blocks' CHOLMOD
/// factors, regularised like direct solves and applied in parallel, are
/// wired here by hand.
class BlockPreconditionedCG
{
public:
  BlockPreconditionedCG();
  ~BlockPreconditionedCG();
  BlockPreconditionedCG(const BlockPreconditionedCG&) = delete;
  BlockPreconditionedCG& operator=(const BlockPreconditionedCG&) = delete;

  /// Two or more blocks: solve() applies (LinearSolver solves directly
  /// otherwise).
  bool active() const { return this->Offsets.size() > 2; }
  /// Block k is [offsets[k], offsets[k + 1]); a change drops the factors.
  void setBlocks(std::vector<int> offsets);

  LinearSolveResult solve(const Eigen::SparseMatrix<double>& H,
    const Eigen::VectorXd& b,
    Eigen::VectorXd& x,
    bool patternChanged,
    const Logger& log);

private:
  struct Application;
  bool makeFactors();
  bool precondition(Application& a, const Eigen::VectorXd& r, Eigen::VectorXd& z, bool factorise);

  std::vector<int> Offsets;
  std::vector<std::unique_ptr<CholeskyFactor>> Factors;
};

} // namespace surfacemaps
