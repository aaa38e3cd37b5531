// SurfaceMaps engine: CholeskyFactor, the CHOLMOD calls: settings, analysis
// (serialised for METIS), the numeric factorisation in cholmod_factorize's
// steps with its rows in thread lists, solves and the diagonal shift.
#include "optimisation/sparse/CholeskyFactor.h"

#include "optimisation/sparse/BlasThreadGuard.h"

#include <Eigen/CholmodSupport>

#include <omp.h>

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
  common.postorder = 1; // also what the split factorisation relies on
  quietCholmod(common);
}

CholeskyFactor::~CholeskyFactor()
{
  cholmod_free_factor(&this->Factor, &this->Common);
  cholmod_finish(&this->Common);
  for (auto& common : this->ThreadCommons)
  {
    cholmod_finish(common.get());
  }
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
  // Taken before the BLAS guard, which may set the OpenMP thread count to 1.
  const int threads = omp_get_max_threads();
  const BlasThreadGuard blasThreads;
  const bool ahead = this->AnalysedAhead;
  this->AnalysedAhead = false;
  if ((patternChanged && !ahead) || !this->Factor)
  {
    this->analyseLocked(H);
    result.analysed = true;
  }
  result.analysed = result.analysed || (patternChanged && ahead);
  if (this->factorise(H, threads))
  {
    result.factorisationThreads = this->FactorisationThreads;
    result.success = this->solveWith(b, x);
    if (result.success)
    {
      return result;
    }
  }
  if (!this->solveShifted(H, b, x, threads, log, result))
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
  this->Split.valid = false;
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
  int threads,
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
    if (this->factorise(shifted, threads) && this->solveWith(b, x))
    {
      result.factorisationThreads = this->FactorisationThreads;
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

/// Numeric factorisation of H (the analysed pattern) on up to `threads`
/// threads; false if H is not numerically positive definite.
bool CholeskyFactor::factorise(const Eigen::SparseMatrix<double>& H, int threads)
{
  cholmod_sparse A = Eigen::viewAsCholmod(H.selfadjointView<Eigen::Upper>());
  cholmod_factor* L = this->Factor;
  this->FactorisationThreads = 1;
  const bool splitKnown = this->Split.valid && this->Split.threads == threads;
  if (L->is_super || threads < 2 || (splitKnown && this->Split.lists.empty()))
  {
    return cholmod_factorize(&A, L, &this->Common) && L->minor == L->n;
  }
  cholmod_sparse* S = this->permutedUpper(A);
  const int n = static_cast<int>(L->n);
  if (!splitKnown)
  {
    std::vector<int> parent(n);
    cholmod_etree(S, parent.data(), &this->Common);
    this->Split = splitEliminationTree(*S, parent, threads);
  }
  this->prepareRows(S);
  const int parallelLists = std::max(0, static_cast<int>(this->Split.lists.size()) - 1);
  double beta[2] = { 0.0, 0.0 };
  bool ok = parallelLists == 0 ? cholmod_rowfac(S, nullptr, beta, 0, n, L, &this->Common)
                               : this->factoriseSplit(*S, threads);
  ok = ok && this->finishFactor();
  cholmod_free_sparse(&S, &this->Common);
  return ok && L->minor == L->n;
}

// The matrix cholmod_factorize factorises for an upper triangle:
// S = triu(A(p, p)), by two transposes.
cholmod_sparse* CholeskyFactor::permutedUpper(cholmod_sparse& A)
{
  cholmod_sparse* lower =
    cholmod_ptranspose(&A, 2, static_cast<int*>(this->Factor->Perm), nullptr, 0, &this->Common);
  cholmod_sparse* S =
    lower ? cholmod_ptranspose(lower, 2, nullptr, nullptr, 0, &this->Common) : nullptr;
  cholmod_free_sparse(&lower, &this->Common);
  if (!S)
  {
    throw std::bad_alloc();
  }
  return S;
}

// What cholmod_factorize does before its rows: LL^T as asked, a symbolic
// factor allocated (exactly the space the analysis counted) and made the
// identity, a numeric one emptied. Done here because the rows may be
// factorised in several calls. Frees S if it throws.
void CholeskyFactor::prepareRows(cholmod_sparse*& S)
{
  cholmod_factor* L = this->Factor;
  L->is_ll = this->Common.final_ll;
  if (L->xtype == CHOLMOD_PATTERN)
  {
    const double grow2 = this->Common.grow2;
    if (this->Common.final_pack)
    {
      this->Common.grow2 = 0;
    }
    const bool allocated =
      cholmod_change_factor(CHOLMOD_REAL, L->is_ll, false, false, true, L, &this->Common);
    this->Common.grow2 = grow2;
    if (!allocated)
    {
      cholmod_free_sparse(&S, &this->Common);
      throw std::bad_alloc();
    }
  }
  else
  {
    L->minor = L->n;
    std::fill(static_cast<int*>(L->nz), static_cast<int*>(L->nz) + L->n, 1);
  }
}

// The split's thread lists at once, then its remainder (pipelined on two
// threads where it applies).
bool CholeskyFactor::factoriseSplit(cholmod_sparse& S, int threads)
{
  const EliminationTreeSplit& split = this->Split;
  const int parallelLists = static_cast<int>(split.lists.size()) - 1;
  while (static_cast<int>(this->ThreadCommons.size()) < parallelLists - 1)
  {
    auto common = std::make_unique<cholmod_common>();
    cholmod_start(common.get());
    quietCholmod(*common);
    this->ThreadCommons.push_back(std::move(common));
  }
  // Each thread has workspaces of its own and writes only its subtrees'
  // columns of L. One shared word: a row that finds H not positive
  // definite sets L->minor, which rows of other threads may read; the
  // factorisation then fails whatever they read, as the serial one does.
  this->FactorisationThreads = std::min(threads, parallelLists);
  std::vector<char> listOk(parallelLists, 1);
#pragma omp parallel for schedule(static, 1) num_threads(this->FactorisationThreads)
  for (int t = 0; t < parallelLists; ++t)
  {
    cholmod_common* common = t == 0 ? &this->Common : this->ThreadCommons[t - 1].get();
    listOk[t] = this->factoriseList(S, t, common);
  }
  const bool ok = std::all_of(listOk.begin(), listOk.end(), [](char c) { return c != 0; });
  if (ok && this->FactorisationThreads > 1 && split.remainder.size() > 1 &&
    RemainderPipeline::applies(S, *this->Factor))
  {
    return this->Pipeline.factorise(S, split.parent, split.remainder, *this->Factor);
  }
  return ok && this->factoriseList(S, parallelLists, &this->Common);
}

// The rows of the split's list `list`, with the workspaces of `common`.
bool CholeskyFactor::factoriseList(cholmod_sparse& S, int list, cholmod_common* common)
{
  double beta[2] = { 0.0, 0.0 };
  return cholmod_rowfac_mask2(&S,
    nullptr,
    beta,
    this->Split.lists[list][0],
    this->Split.lists[list][1],
    nullptr,
    0,
    this->Split.next.data(),
    this->Factor,
    common);
}

// cholmod_factorize's final form.
bool CholeskyFactor::finishFactor()
{
  cholmod_factor* L = this->Factor;
  return this->Common.final_asis ||
    cholmod_change_factor(L->xtype,
      L->is_ll,
      false,
      this->Common.final_pack,
      this->Common.final_monotonic,
      L,
      &this->Common);
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
