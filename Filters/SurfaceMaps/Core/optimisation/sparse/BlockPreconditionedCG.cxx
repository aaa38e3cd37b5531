// SurfaceMaps engine: BlockPreconditionedCG, the block factors (made once
// per block layout, refactorised per system), their parallel application
// and the conjugate-gradient iteration.
#include "optimisation/sparse/BlockPreconditionedCG.h"

#include "optimisation/sparse/CholeskyFactor.h"

#include <algorithm>
#include <sstream>
#include <stdexcept>

namespace surfacemaps
{

// What one application of the preconditioner reads, and what the blocks
// report back.
struct BlockPreconditionedCG::Application
{
  const Eigen::SparseMatrix<double>& H;
  bool patternChanged;
  const Logger& log;
  std::vector<char> ok;
  std::vector<double> shifts;
};

BlockPreconditionedCG::BlockPreconditionedCG() = default;
BlockPreconditionedCG::~BlockPreconditionedCG() = default;

void BlockPreconditionedCG::setBlocks(std::vector<int> offsets)
{
  if (offsets != this->Offsets)
  {
    this->Offsets = std::move(offsets);
    this->Factors.clear();
  }
}

LinearSolveResult BlockPreconditionedCG::solve(const Eigen::SparseMatrix<double>& H,
  const Eigen::VectorXd& b,
  Eigen::VectorXd& x,
  bool patternChanged,
  const Logger& log)
{
  const std::vector<int>& offsets = this->Offsets;
  const int blocks = static_cast<int>(offsets.size()) - 1;
  LinearSolveResult result;
  if (offsets.front() != 0 || offsets.back() != H.rows())
  {
    throw std::logic_error("LinearSolver: the blocks do not cover the system");
  }
  if (this->makeFactors())
  {
    patternChanged = true;
  }
  result.analysed = patternChanged;
  Application a{
    H, patternChanged, log, std::vector<char>(blocks, 1), std::vector<double>(blocks, 0.0)
  };

  // Preconditioned conjugate gradients from x = 0.
  const double tolerance = 1e-8 * b.norm();
  x = Eigen::VectorXd::Zero(b.size());
  Eigen::VectorXd r = b, z, p, Hp;
  if (!this->precondition(a, r, z, true))
  {
    log(Logger::Warning, "Cholesky factorisation of a block failed even with a diagonal shift");
    return result;
  }
  result.shift = *std::max_element(a.shifts.begin(), a.shifts.end());
  p = z;
  double rz = r.dot(z);
  const int maxIterations = 200;
  while (result.iterations < maxIterations && r.norm() > tolerance)
  {
    Hp = H.selfadjointView<Eigen::Upper>() * p;
    const double curvature = p.dot(Hp);
    if (!(curvature > 0.0) || !(rz > 0.0))
    {
      break;
    }
    const double alpha = rz / curvature;
    x += alpha * p;
    r -= alpha * Hp;
    ++result.iterations;
    if (!this->precondition(a, r, z, false))
    {
      break;
    }
    const double rzNext = r.dot(z);
    p = z + (rzNext / rz) * p;
    rz = rzNext;
  }
  result.success = result.iterations > 0 && x.allFinite();
  std::ostringstream message;
  message << "block solve: " << blocks << " blocks, " << result.iterations
          << " conjugate-gradient iterations, relative residual " << r.norm() / b.norm();
  log(Logger::Detail, message.str());
  return result;
}

// One factor per block (AMD, a LinearSolver's default ordering);
// true if they are new.
bool BlockPreconditionedCG::makeFactors()
{
  const int blocks = static_cast<int>(this->Offsets.size()) - 1;
  if (static_cast<int>(this->Factors.size()) == blocks)
  {
    return false;
  }
  this->Factors.clear();
  for (int k = 0; k < blocks; ++k)
  {
    this->Factors.push_back(std::make_unique<CholeskyFactor>(LinearSolver::Ordering::Amd));
  }
  return true;
}

// The preconditioner z = M^-1 r, block by block (in parallel: the blocks'
// factors are independent). The first application factorises each block
// (regularised where needed) with its part of the right-hand side.
bool BlockPreconditionedCG::precondition(Application& a,
  const Eigen::VectorXd& r,
  Eigen::VectorXd& z,
  bool factorise)
{
  const std::vector<int>& offsets = this->Offsets;
  const int blocks = static_cast<int>(offsets.size()) - 1;
  z.resize(r.size());
#pragma omp parallel for schedule(dynamic)
  for (int k = 0; k < blocks; ++k)
  {
    const int first = offsets[k];
    const int size = offsets[k + 1] - first;
    if (size == 0)
    {
      continue;
    }
    Eigen::VectorXd zk;
    if (factorise)
    {
      // The factor keeps no reference to the block it was computed from.
      const Eigen::SparseMatrix<double> diagonal = a.H.block(first, first, size, size);
      const LinearSolveResult block =
        this->Factors[k]->solve(diagonal, r.segment(first, size), zk, a.patternChanged, a.log);
      a.ok[k] = block.success;
      a.shifts[k] = block.shift;
    }
    else
    {
      a.ok[k] = this->Factors[k]->solveAgain(r.segment(first, size), zk);
    }
    if (a.ok[k])
    {
      z.segment(first, size) = zk;
    }
  }
  return std::all_of(a.ok.begin(), a.ok.end(), [](char c) { return c != 0; });
}

} // namespace surfacemaps
