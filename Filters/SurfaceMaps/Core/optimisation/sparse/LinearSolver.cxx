// SurfaceMaps engine: LinearSolver, which sends each solve to the direct
// Cholesky factor or, with two or more blocks, to the block-preconditioned
// conjugate gradients.
#include "optimisation/sparse/LinearSolver.h"

#include "optimisation/sparse/BlockPreconditionedCG.h"
#include "optimisation/sparse/CholeskyFactor.h"

namespace surfacemaps
{

struct LinearSolver::Internals
{
  explicit Internals(Ordering ordering)
    : Factor(ordering)
  {
  }
  CholeskyFactor Factor;
  BlockPreconditionedCG Blocks;
};

LinearSolver::LinearSolver(Ordering ordering)
  : Impl(new Internals(ordering))
{
}

LinearSolver::~LinearSolver() = default;

void LinearSolver::analyse(const Eigen::SparseMatrix<double>& pattern)
{
  if (this->Impl->Blocks.active())
  {
    return; // block solves analyse each block in solve()
  }
  this->Impl->Factor.analyseAhead(pattern);
}

LinearSolveResult LinearSolver::solve(const Eigen::SparseMatrix<double>& H,
  const Eigen::VectorXd& b,
  Eigen::VectorXd& x,
  bool patternChanged,
  const Logger& log)
{
  if (this->Impl->Blocks.active())
  {
    return this->Impl->Blocks.solve(H, b, x, patternChanged, log);
  }
  return this->Impl->Factor.solve(H, b, x, patternChanged, log);
}

void LinearSolver::setBlocks(std::vector<int> offsets)
{
  this->Impl->Blocks.setBlocks(std::move(offsets));
}

} // namespace surfacemaps
