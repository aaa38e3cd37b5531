#include "optimisation/LinearSolver.h"

#include <mutex>

#include <Eigen/CholmodSupport>

#include <dlfcn.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <sstream>

namespace surfacemaps
{

namespace
{
// CHOLMOD's supernodal factorisation calls BLAS on many small dense blocks.
// A multithreaded OpenBLAS slows that down by an order of magnitude (its
// threads fight the engine's OpenMP threads over 2 cores), so BLAS runs on
// one thread while any factorisation runs and is restored when the last one
// ends. The thread count is global: concurrent solvers (several embeddings at
// once) share one count of active guards, or one of them would restore the
// old count while another factorises, with results that change from run to
// run. Looked up at run time: with another BLAS there is nothing to do.
// OpenBLAS' OpenMP build sets the calling thread's OpenMP thread count in
// openblas_set_num_threads, so each guard also restores the count its own
// thread had (otherwise omp_set_num_threads(1) or a per-rank thread count
// would be overridden by OpenBLAS' count after the first solve).
class SingleThreadedBlas
{
public:
  SingleThreadedBlas()
    : OpenMPThreads(omp_get_max_threads())
  {
    std::lock_guard<std::mutex> lock(mutex());
    State& s = state();
    if (s.active++ == 0)
    {
      using Get = int (*)();
      auto get = reinterpret_cast<Get>(dlsym(RTLD_DEFAULT, "openblas_get_num_threads"));
      s.set = reinterpret_cast<void (*)(int)>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
      s.previous = get && s.set ? get() : 0;
      if (s.previous > 0)
      {
        s.set(1);
      }
    }
  }
  ~SingleThreadedBlas()
  {
    std::lock_guard<std::mutex> lock(mutex());
    State& s = state();
    if (--s.active == 0 && s.previous > 0)
    {
      s.set(s.previous);
    }
    omp_set_num_threads(this->OpenMPThreads);
  }

private:
  const int OpenMPThreads;
  struct State
  {
    int active = 0;
    int previous = 0;
    void (*set)(int) = nullptr;
  };
  static State& state()
  {
    static State s;
    return s;
  }
  static std::mutex& mutex()
  {
    static std::mutex m;
    return m;
  }
};
} // namespace

struct LinearSolver::Internals
{
  Eigen::CholmodDecomposition<Eigen::SparseMatrix<double>, Eigen::Upper> Cholesky;
  std::vector<int> Blocks;
  std::vector<std::unique_ptr<LinearSolver>> BlockSolvers;
  bool Analysed = false;
};

LinearSolver::LinearSolver(Ordering ordering)
  : Impl(new Internals)
{
  cholmod_common& common = this->Impl->Cholesky.cholmod();
  // LL^T (a failed factorisation means "not positive definite"), supernodal
  // when the factor is dense enough for BLAS to pay off, simplicial
  // otherwise. Measured here: the two-embedding Newton system (AMD, ~300
  // flops per factor entry) is 1.7x faster supernodal, a single embedding
  // (nested dissection, ~120 flops per entry) 1.4x faster simplicial; CHOLMOD's
  // default switch (40) would take supernodal for both.
  common.final_asis = 0;
  common.final_ll = 1;
  common.supernodal = CHOLMOD_AUTO;
  common.supernodal_switch = 200;
  common.nmethods = 1;
  common.method[0].ordering = ordering == Ordering::Amd ? CHOLMOD_AMD : CHOLMOD_METIS;
  common.postorder = 1;
  // Failures are handled (and logged) here; CHOLMOD must not print them.
  this->Impl->Cholesky.cholmod().print = 0;
  this->Impl->Cholesky.cholmod().error_handler = nullptr;
}

LinearSolver::~LinearSolver() = default;

LinearSolveResult LinearSolver::solve(const Eigen::SparseMatrix<double>& H,
  const Eigen::VectorXd& b,
  Eigen::VectorXd& x,
  bool patternChanged,
  const Logger& log)
{
  if (this->Impl->Blocks.size() > 2)
  {
    return this->solveByBlocks(H, b, x, patternChanged, log);
  }
  LinearSolveResult result;
  const SingleThreadedBlas blasThreads;
  auto& cholesky = this->Impl->Cholesky;
  if (patternChanged || !this->Impl->Analysed)
  {
    {
      // METIS (nested dissection orderings) keeps its random state in
      // globals and reseeds per call: concurrent analyses (several
      // embeddings at once) would draw from each other's sequence and give
      // orderings, hence rounding, that change from run to run.
      static std::mutex orderingMutex;
      std::lock_guard<std::mutex> lock(orderingMutex);
      cholesky.analyzePattern(H);
    }
    this->Impl->Analysed = true;
    result.analysed = true;
  }
  cholesky.factorize(H);
  if (cholesky.info() == Eigen::Success)
  {
    x = cholesky.solve(b);
    result.success = cholesky.info() == Eigen::Success && x.allFinite();
    if (result.success)
    {
      return result;
    }
  }

  // Regularise: H + mu diag(H) (Levenberg-Marquardt's scaling), mu growing
  // from a tiny value. A shift proportional to each variable's own curvature
  // keeps every variable's step in proportion. A shift of the identity sized
  // by the largest diagonal entry would not: where a few nearly degenerate
  // triangles make that entry 1e12 times the others (the case in which the
  // factorisation fails), it freezes every ordinary variable and the
  // optimisation crawls for dozens of steps. Variables without curvature get
  // a floor relative to the largest entry. The pattern already holds the
  // diagonal.
  double maxDiagonal = 0.0;
  for (Eigen::Index i = 0; i < H.rows(); ++i)
  {
    maxDiagonal = std::max(maxDiagonal, std::abs(H.coeff(i, i)));
  }
  const double floor = std::max(1e-300, 1e-14 * maxDiagonal);
  Eigen::SparseMatrix<double> shifted = H;
  double shift = 1e-10;
  for (int attempt = 0; attempt < 12; ++attempt, shift *= 10.0)
  {
    shifted = H;
    for (Eigen::Index i = 0; i < shifted.rows(); ++i)
    {
      double& h = shifted.coeffRef(i, i);
      h += shift * std::max(std::abs(h), floor);
    }
    cholesky.factorize(shifted);
    if (cholesky.info() != Eigen::Success)
    {
      continue;
    }
    x = cholesky.solve(b);
    if (cholesky.info() == Eigen::Success && x.allFinite())
    {
      std::ostringstream message;
      message << "Cholesky factorisation failed; solved with the diagonal scaled by 1 + " << shift;
      log(Logger::Detail, message.str());
      result.success = true;
      result.shift = shift;
      return result;
    }
  }
  log(Logger::Warning, "Cholesky factorisation failed even with a diagonal shift");
  return result;
}

void LinearSolver::setBlocks(std::vector<int> offsets)
{
  if (offsets != this->Impl->Blocks)
  {
    this->Impl->Blocks = std::move(offsets);
    this->Impl->BlockSolvers.clear();
  }
}

bool LinearSolver::solveAgain(const Eigen::VectorXd& b, Eigen::VectorXd& x) const
{
  const SingleThreadedBlas blasThreads;
  x = this->Impl->Cholesky.solve(b);
  return this->Impl->Cholesky.info() == Eigen::Success && x.allFinite();
}

LinearSolveResult LinearSolver::solveByBlocks(const Eigen::SparseMatrix<double>& H,
  const Eigen::VectorXd& b,
  Eigen::VectorXd& x,
  bool patternChanged,
  const Logger& log)
{
  const std::vector<int>& offsets = this->Impl->Blocks;
  const int blocks = static_cast<int>(offsets.size()) - 1;
  LinearSolveResult result;
  if (offsets.front() != 0 || offsets.back() != H.rows())
  {
    throw std::logic_error("LinearSolver: the blocks do not cover the system");
  }
  auto& solvers = this->Impl->BlockSolvers;
  if (static_cast<int>(solvers.size()) != blocks)
  {
    solvers.clear();
    for (int k = 0; k < blocks; ++k)
    {
      solvers.push_back(std::make_unique<LinearSolver>());
    }
    patternChanged = true;
  }
  result.analysed = patternChanged;

  // The preconditioner z = M^-1 r, block by block (in parallel: the blocks'
  // solvers are independent). The first application factorises each block
  // (regularised where needed) with its part of the right-hand side.
  std::vector<char> ok(blocks, 1);
  std::vector<double> shifts(blocks, 0.0);
  auto precondition = [&](const Eigen::VectorXd& r, Eigen::VectorXd& z, bool factorise)
  {
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
        const Eigen::SparseMatrix<double> diagonal = H.block(first, first, size, size);
        const LinearSolveResult block =
          solvers[k]->solve(diagonal, r.segment(first, size), zk, patternChanged, log);
        ok[k] = block.success;
        shifts[k] = block.shift;
      }
      else
      {
        ok[k] = solvers[k]->solveAgain(r.segment(first, size), zk);
      }
      if (ok[k])
      {
        z.segment(first, size) = zk;
      }
    }
    return std::all_of(ok.begin(), ok.end(), [](char c) { return c != 0; });
  };

  // Preconditioned conjugate gradients from x = 0.
  const double tolerance = 1e-8 * b.norm();
  x = Eigen::VectorXd::Zero(b.size());
  Eigen::VectorXd r = b, z, p, Hp;
  if (!precondition(r, z, true))
  {
    log(Logger::Warning, "Cholesky factorisation of a block failed even with a diagonal shift");
    return result;
  }
  result.shift = *std::max_element(shifts.begin(), shifts.end());
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
    if (!precondition(r, z, false))
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

} // namespace surfacemaps
