// SurfaceMaps engine: CholeskyFactor, the CHOLMOD calls: settings, analysis
// (serialised for METIS), the numeric factorisation, solves and the
// diagonal shift.
#include "optimisation/sparse/CholeskyFactor.h"

#include "optimisation/sparse/BlasThreadGuard.h"

#include <Eigen/CholmodSupport>

#include <algorithm>
#include <cmath>
#include <mutex>
#include <new>
#include <sstream>

namespace surfacemaps
{

namespace
{
void quietCholmod(cholmod_common& common)
{
  // Failures are handled (and logged) by the solver; CHOLMOD must not print them.
  common.print = 0;
  common.error_handler = nullptr;
}
} // namespace

CholeskyFactor::CholeskyFactor(LinearSolver::Ordering ordering)
{
  cholmod_start(&this->Common);
  cholmod_common& common = this->Common;
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
  common.method[0].ordering = ordering == LinearSolver::Ordering::Amd ? CHOLMOD_AMD : CHOLMOD_METIS;
  quietCholmod(common);
}

CholeskyFactor::~CholeskyFactor()
{
  cholmod_free_factor(&this->Factor, &this->Common);
  cholmod_finish(&this->Common);
}

void CholeskyFactor::analyseAhead(const Eigen::SparseMatrix<double>& pattern)
{
  this->analyseLocked(pattern);
  this->AnalysedAhead = true;
}

LinearSolveResult CholeskyFactor::solve(const Eigen::SparseMatrix<double>& H,
  const Eigen::VectorXd& b,
  Eigen::VectorXd& x,
  bool patternChanged,
  const Logger& log)
{
  LinearSolveResult result;
  const BlasThreadGuard blasThreads;
  const bool ahead = this->AnalysedAhead;
  this->AnalysedAhead = false;
  if ((patternChanged && !ahead) || !this->Factor)
  {
    this->analyseLocked(H);
    result.analysed = true;
  }
  result.analysed = result.analysed || (patternChanged && ahead);
  if (this->factorise(H))
  {
    result.success = this->solveWith(b, x);
    if (result.success)
    {
      return result;
    }
  }
  if (!this->solveShifted(H, b, x, log, result))
  {
    log(Logger::Warning, "Cholesky factorisation failed even with a diagonal shift");
  }
  return result;
}

bool CholeskyFactor::solveAgain(const Eigen::VectorXd& b, Eigen::VectorXd& x)
{
  const BlasThreadGuard blasThreads;
  return this->solveWith(b, x);
}

void CholeskyFactor::analyse(const Eigen::SparseMatrix<double>& H)
{
  cholmod_free_factor(&this->Factor, &this->Common);
  cholmod_sparse A = Eigen::viewAsCholmod(H.selfadjointView<Eigen::Upper>());
  this->Factor = cholmod_analyze(&A, &this->Common);
  if (!this->Factor)
  {
    throw std::bad_alloc();
  }
}

void CholeskyFactor::analyseLocked(const Eigen::SparseMatrix<double>& H)
{
  // METIS (nested dissection orderings) keeps its random state in globals
  // and reseeds per call: concurrent analyses (several embeddings at once)
  // would draw from each other's sequence and give orderings, hence
  // rounding, that change from run to run.
  static std::mutex orderingMutex;
  std::lock_guard<std::mutex> lock(orderingMutex);
  this->analyse(H);
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
bool CholeskyFactor::solveShifted(const Eigen::SparseMatrix<double>& H,
  const Eigen::VectorXd& b,
  Eigen::VectorXd& x,
  const Logger& log,
  LinearSolveResult& result)
{
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
    if (this->factorise(shifted) && this->solveWith(b, x))
    {
      std::ostringstream message;
      message << "Cholesky factorisation failed; solved with the diagonal scaled by 1 + " << shift;
      log(Logger::Detail, message.str());
      result.success = true;
      result.shift = shift;
      return true;
    }
  }
  return false;
}

/// Numeric factorisation of H (the analysed pattern); false if H is not
/// numerically positive definite.
bool CholeskyFactor::factorise(const Eigen::SparseMatrix<double>& H)
{
  cholmod_sparse A = Eigen::viewAsCholmod(H.selfadjointView<Eigen::Upper>());
  return cholmod_factorize(&A, this->Factor, &this->Common) && this->Factor->minor == this->Factor->n;
}

bool CholeskyFactor::solveWith(const Eigen::VectorXd& b, Eigen::VectorXd& x)
{
  Eigen::VectorXd rhs = b;
  cholmod_dense B = Eigen::viewAsCholmod(rhs);
  cholmod_dense* X = cholmod_solve(CHOLMOD_A, this->Factor, &B, &this->Common);
  if (!X)
  {
    return false;
  }
  x = Eigen::Map<const Eigen::VectorXd>(static_cast<const double*>(X->x), rhs.size());
  cholmod_free_dense(&X, &this->Common);
  return x.allFinite();
}

} // namespace surfacemaps
