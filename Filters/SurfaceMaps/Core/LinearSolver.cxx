#include "LinearSolver.h"

#include <Eigen/CholmodSupport>

#include <dlfcn.h>

#include <cmath>
#include <sstream>

namespace surfacemaps
{

namespace
{
// CHOLMOD's supernodal factorisation calls BLAS on many small dense blocks.
// A multithreaded OpenBLAS slows that down by an order of magnitude (its
// threads fight the engine's OpenMP threads over 2 cores), so BLAS runs on
// one thread for the duration of a factorisation and is restored afterwards.
// Looked up at run time: with another BLAS there is nothing to do.
class SingleThreadedBlas
{
public:
  SingleThreadedBlas()
  {
    using Get = int (*)();
    using Set = void (*)(int);
    auto get = reinterpret_cast<Get>(dlsym(RTLD_DEFAULT, "openblas_get_num_threads"));
    this->SetThreads = reinterpret_cast<Set>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
    if (get && this->SetThreads)
    {
      this->Previous = get();
      this->SetThreads(1);
    }
  }
  ~SingleThreadedBlas()
  {
    if (this->Previous > 0)
    {
      this->SetThreads(this->Previous);
    }
  }

private:
  void (*SetThreads)(int) = nullptr;
  int Previous = 0;
};
} // namespace

struct LinearSolver::Internals
{
  Eigen::CholmodDecomposition<Eigen::SparseMatrix<double>, Eigen::Upper> Cholesky;
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
  LinearSolveResult result;
  const SingleThreadedBlas blasThreads;
  auto& cholesky = this->Impl->Cholesky;
  if (patternChanged || !this->Impl->Analysed)
  {
    cholesky.analyzePattern(H);
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

  // Regularise: H + shift I, the shift growing from a tiny fraction of the
  // largest diagonal entry. The pattern already holds the diagonal.
  double maxDiagonal = 0.0;
  for (Eigen::Index i = 0; i < H.rows(); ++i)
  {
    maxDiagonal = std::max(maxDiagonal, std::abs(H.coeff(i, i)));
  }
  Eigen::SparseMatrix<double> shifted = H;
  double shift = std::max(1e-12, 1e-10 * maxDiagonal);
  for (int attempt = 0; attempt < 12; ++attempt, shift *= 10.0)
  {
    shifted = H;
    for (Eigen::Index i = 0; i < shifted.rows(); ++i)
    {
      shifted.coeffRef(i, i) += shift;
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
      message << "Cholesky factorisation failed; solved with diagonal shift " << shift;
      log(Logger::Warning, message.str());
      result.success = true;
      result.shift = shift;
      return result;
    }
  }
  log(Logger::Warning, "Cholesky factorisation failed even with a diagonal shift");
  return result;
}

} // namespace surfacemaps
