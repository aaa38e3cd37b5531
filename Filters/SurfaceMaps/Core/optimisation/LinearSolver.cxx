#include "optimisation/LinearSolver.h"

#include <mutex>

#include <Eigen/CholmodSupport>

#include <dlfcn.h>
#include <omp.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <memory>
#include <new>
#include <sstream>
#include <stdexcept>
#include <thread>
#include <vector>

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

// The rows of a simplicial factor split over threads along the elimination
// tree. Row k of L depends only on the rows of k's subtree, and with a
// postordered tree (CHOLMOD's default) a subtree is a contiguous range of
// rows. So complete subtrees can be factorised by different threads at once,
// and the rows above them (the remainder, closed under taking parents) after
// them. CHOLMOD computes every row the same way whoever computes it, in the
// same order within each column, so the factor is the serial one bit for bit.
// CHOLMOD's simplicial factorisation runs on one thread. Its supernodal one
// can use threads inside BLAS, but the map's Newton systems (about 115 flops
// per factor entry) factorise faster simplicial than supernodal. With AMD
// orderings the rows near the root (the remainder) hold about half of the
// work; RemainderPipeline computes them on two threads.
struct RowSplit
{
  /// Each list's rows, ascending and linked through `next` (CHOLMOD's
  /// RLinkUp): first row and one past the last. Lists [0, threads) run at
  /// once; the last list is the remainder.
  std::vector<std::array<int, 2>> lists;
  std::vector<int> next;
  /// The elimination tree and the remainder's rows, ascending.
  std::vector<int> parent;
  std::vector<int> remainder;
  /// The thread count it was made for; whether it is up to date.
  int threads = 0;
  bool valid = false;
};

// Elimination-tree split for `threads` threads; an empty split (no lists)
// when it would not pay.
RowSplit splitRows(const cholmod_sparse& S, const std::vector<int>& parent, int threads)
{
  RowSplit split;
  split.valid = true;
  split.threads = threads;
  const int n = static_cast<int>(parent.size());
  // Work of row k: the updates of the up-looking factorisation, one per entry
  // above row k in each column of row k's pattern (found by walking the
  // elimination tree up from the entries of S's column k, as CHOLMOD does).
  // Summed over subtrees below. Subtree of j: rows j - size[j] + 1 .. j.
  std::vector<double> work(n, 1.0);
  std::vector<int> size(n, 1);
  {
    const int* Sp = static_cast<const int*>(S.p);
    const int* Si = static_cast<const int*>(S.i);
    std::vector<int> entries(n, 0), visited(n, -1);
    for (int k = 0; k < n; ++k)
    {
      visited[k] = k;
      for (int p = Sp[k]; p < Sp[k + 1]; ++p)
      {
        for (int i = Si[p]; i < k && i >= 0 && visited[i] != k; i = parent[i])
        {
          visited[i] = k;
          work[k] += 1.0 + entries[i]++;
        }
      }
    }
  }
  double total = 0.0;
  for (int j = 0; j < n; ++j)
  {
    total += work[j];
  }
  // Below this a factorisation takes around a millisecond: waking threads
  // and their workspaces would cost more than the split saves.
  constexpr double minimumWork = 1e6;
  if (threads < 2 || n < 2 || total < minimumWork)
  {
    return split;
  }
  for (int j = 0; j < n; ++j)
  {
    if (parent[j] >= 0)
    {
      if (parent[j] <= j)
      {
        return split; // not postordered
      }
      work[parent[j]] += work[j];
      size[parent[j]] += size[j];
    }
  }
  std::vector<int> childStart(n + 1, 0), children(n);
  for (int j = 0; j < n; ++j)
  {
    if (parent[j] >= 0)
    {
      ++childStart[parent[j] + 1];
    }
  }
  for (int j = 0; j < n; ++j)
  {
    childStart[j + 1] += childStart[j];
  }
  {
    std::vector<int> at(childStart.begin(), childStart.end() - 1);
    for (int j = 0; j < n; ++j)
    {
      if (parent[j] >= 0)
      {
        children[at[parent[j]]++] = j;
      }
    }
  }
  // Move the heaviest subtree's root into the remainder while that subtree
  // alone is more than one thread's share of the rest. The last row (a
  // root) always starts the remainder, so no thread's list spans all rows
  // (CHOLMOD restarts the whole factor for a range 0 .. n).
  std::vector<char> inRemainder(n, 0);
  auto byWork = [&](int a, int b) { return work[a] < work[b]; };
  std::vector<int> frontier; // a max-heap by subtree work
  double frontierWork = 0.0, remainderWork = 0.0;
  auto expand = [&](int j)
  {
    inRemainder[j] = 1;
    const double childWork = [&]
    {
      double w = 0.0;
      for (int c = childStart[j]; c < childStart[j + 1]; ++c)
      {
        w += work[children[c]];
        frontier.push_back(children[c]);
        std::push_heap(frontier.begin(), frontier.end(), byWork);
      }
      return w;
    }();
    remainderWork += work[j] - childWork;
    frontierWork += childWork;
  };
  for (int j = 0; j < n - 1; ++j)
  {
    if (parent[j] < 0)
    {
      frontier.push_back(j);
      std::push_heap(frontier.begin(), frontier.end(), byWork);
      frontierWork += work[j];
    }
  }
  expand(n - 1);
  while (!frontier.empty() && work[frontier.front()] * threads > frontierWork)
  {
    const int j = frontier.front();
    std::pop_heap(frontier.begin(), frontier.end(), byWork);
    frontier.pop_back();
    frontierWork -= work[j];
    expand(j);
  }
  // Largest subtrees first, each to the least loaded thread.
  std::sort(frontier.begin(), frontier.end(), [&](int a, int b) { return work[a] > work[b]; });
  std::vector<double> load(threads, 0.0);
  std::vector<std::vector<int>> assigned(threads);
  for (int j : frontier)
  {
    const int t = static_cast<int>(std::min_element(load.begin(), load.end()) - load.begin());
    load[t] += work[j];
    assigned[t].push_back(j);
  }
  const double longest = *std::max_element(load.begin(), load.end());
  if (inRemainder[0] || remainderWork + longest > 0.9 * total)
  {
    return split; // too little runs at once to pay for the threads
  }
  split.next.assign(n, n);
  auto link = [&](const std::vector<int>& rows)
  {
    for (std::size_t k = 0; k + 1 < rows.size(); ++k)
    {
      split.next[rows[k]] = rows[k + 1];
    }
    split.next[rows.back()] = rows.back() + 1;
    split.lists.push_back({ rows.front(), rows.back() + 1 });
  };
  std::vector<int> rows;
  for (int t = 0; t < threads; ++t)
  {
    if (assigned[t].empty())
    {
      continue;
    }
    std::sort(assigned[t].begin(), assigned[t].end());
    rows.clear();
    for (int j : assigned[t])
    {
      for (int k = j - size[j] + 1; k <= j; ++k)
      {
        rows.push_back(k);
      }
    }
    link(rows);
  }
  rows.clear();
  for (int k = 0; k < n; ++k)
  {
    if (inRemainder[k])
    {
      rows.push_back(k);
    }
  }
  link(rows);
  split.lists.back()[1] = n;
  split.parent = parent;
  split.remainder = rows;
  return split;
}

// The remainder's rows (about half of the work, mostly one chain of rows
// near the root that form a dense block) on two threads at once: the threads
// take the rows in turn, and a row goes on while the row before it is still
// being computed. Row k's numbers are those cholmod_rowfac computes for an
// LL^T factor, in its order: k's pattern in the order of its row-subtree
// walk (the elimination tree's parent stands for the first off-diagonal
// entry of a column, which is the parent once the rows below are done), then
// for each column i of it the same divisions and subtractions. What row k
// reads of the row before it is that row's entries in the columns of k's
// pattern and its diagonal, so a thread waits, column by column, until the
// row before has stored its entry in that column (LastRow) if that row's
// pattern holds the column (PendingRow, published in row order). Entries
// reach each column in row order, as in the serial factorisation, so the
// factor is the serial one bit for bit.
class RemainderPipeline
{
public:
  /// Whether the pipeline can factorise the remainder of L from S: an LL^T
  /// factor, S packed, sorted and upper, every column with room for its final
  /// count (the analysis allocated exactly that).
  static bool applies(const cholmod_sparse& S, const cholmod_factor& L)
  {
    if (!L.is_ll || L.is_super || L.xtype != CHOLMOD_REAL || L.itype != CHOLMOD_INT ||
      S.xtype != CHOLMOD_REAL || S.itype != CHOLMOD_INT || !S.packed || !S.sorted || S.stype <= 0)
    {
      return false;
    }
    const int n = static_cast<int>(L.n);
    const int* Lp = static_cast<const int*>(L.p);
    const int* Lnext = static_cast<const int*>(L.next);
    const int* counts = static_cast<const int*>(L.ColCount);
    for (int i = 0; i < n; ++i)
    {
      if (Lp[Lnext[i]] - Lp[i] < counts[i])
      {
        return false;
      }
    }
    return true;
  }

  /// Rows `rows` (ascending, their descendants done) of L; false if a pivot
  /// is not positive (L.minor then below L.n, as cholmod_rowfac leaves it).
  bool factorise(const cholmod_sparse& S,
    const std::vector<int>& parent,
    const std::vector<int>& rows,
    cholmod_factor& L)
  {
    const int n = static_cast<int>(L.n);
    const int m = static_cast<int>(rows.size());
    if (static_cast<int>(this->Size) != n)
    {
      this->PendingRow.reset(new std::atomic<int>[n]);
      this->LastRow.reset(new std::atomic<int>[n]);
      this->Size = n;
    }
    for (int i = 0; i < n; ++i)
    {
      this->PendingRow[i].store(-1, std::memory_order_relaxed);
      this->LastRow[i].store(-1, std::memory_order_relaxed);
    }
    std::unique_ptr<std::atomic<int>[]> published(new std::atomic<int>[m]);
    for (int j = 0; j < m; ++j)
    {
      published[j].store(0, std::memory_order_relaxed);
    }
    for (Workspace& w : this->Threads)
    {
      w.values.assign(n, 0.0);
      w.flag.assign(n, -1);
      w.stack.resize(n);
      w.wait.resize(n);
    }
    const int* Sp = static_cast<const int*>(S.p);
    const int* Si = static_cast<const int*>(S.i);
    const double* Sx = static_cast<const double*>(S.x);
    const int* Lp = static_cast<const int*>(L.p);
    int* Li = static_cast<int*>(L.i);
    double* Lx = static_cast<double*>(L.x);
    int* Lnz = static_cast<int*>(L.nz);
    std::size_t* minor = &L.minor;
    auto minorNow = [minor]() { return __atomic_load_n(minor, __ATOMIC_RELAXED); };
    auto lowerMinor = [minor](std::size_t k)
    {
      std::size_t known = __atomic_load_n(minor, __ATOMIC_RELAXED);
      while (k < known &&
        !__atomic_compare_exchange_n(minor, &known, k, true, __ATOMIC_RELAXED, __ATOMIC_RELAXED))
      {
      }
    };
#pragma omp parallel num_threads(2)
    {
      // One thread alone (no second one granted) takes every row in order;
      // its waits are then always met.
      const int stride = omp_get_num_threads();
      Workspace& w = this->Threads[omp_get_thread_num()];
      for (int j = omp_get_thread_num(); j < m; j += stride)
      {
        const int k = rows[j];
        // Scatter column k of S and walk the row subtree: cholmod_rowfac's
        // pattern order (mark j: the marks only grow).
        int top = n;
        w.flag[k] = j;
        for (int p = Sp[k]; p < Sp[k + 1]; ++p)
        {
          int i = Si[p];
          if (i > k)
          {
            break;
          }
          w.values[i] = Sx[p];
          int length = 0;
          for (; i < k && i != -1 && w.flag[i] < j; i = parent[i])
          {
            w.stack[length++] = i;
            w.flag[i] = j;
          }
          while (length > 0)
          {
            w.stack[--top] = w.stack[--length];
          }
        }
        double dk = w.values[k] + 0.0; // + beta, as cholmod_rowfac adds it
        w.values[k] = 0.0;
        // Publish the pattern after the row before has published its own,
        // noting the columns that row is still to store.
        const int previous = j > 0 ? rows[j - 1] : -1;
        if (j > 0)
        {
          for (int spins = 0; !published[j - 1].load(std::memory_order_acquire); ++spins)
          {
            pause(spins);
          }
        }
        for (int s = top; s < n; ++s)
        {
          const int pending = this->PendingRow[w.stack[s]].exchange(k, std::memory_order_acq_rel);
          w.wait[s] = previous >= 0 && pending == previous;
        }
        this->PendingRow[k].store(k, std::memory_order_relaxed);
        published[j].store(1, std::memory_order_release);

        for (int s = top; s < n; ++s)
        {
          const int i = w.stack[s];
          if (w.wait[s])
          {
            for (int spins = 0; this->LastRow[i].load(std::memory_order_acquire) < previous;
                 ++spins)
            {
              pause(spins);
            }
          }
          double y = w.values[i];
          w.values[i] = 0.0;
          const int count = Lnz[i];
          int p = Lp[i];
          const int end = p + count;
          const double di = Lx[p];
          double lki;
          if (static_cast<std::size_t>(i) >= minorNow() || di == 0)
          {
            lki = 0.0;
            p = end;
          }
          else
          {
            y = y / di;
            for (++p; p < end; ++p)
            {
              w.values[Li[p]] -= Lx[p] * y;
            }
            lki = y;
            dk -= y * y;
          }
          Li[p] = k;
          Lx[p] = lki;
          Lnz[i] = count + 1;
          this->LastRow[i].store(k, std::memory_order_release);
        }
        const int p = Lp[k];
        Li[p] = k;
        if (static_cast<std::size_t>(k) >= minorNow())
        {
          dk = 0.0;
        }
        else if (dk <= 0.0)
        {
          dk = 0.0;
          lowerMinor(static_cast<std::size_t>(k));
        }
        Lx[p] = std::sqrt(dk);
        this->LastRow[k].store(k, std::memory_order_release);
      }
    }
    return minorNow() == L.n;
  }

private:
  // Waits are short (the row before is one column ahead) unless the other
  // thread lost its core: then give the core up.
  static void pause(int spins)
  {
    if (spins > 4000)
    {
      std::this_thread::yield();
      return;
    }
#if defined(__x86_64__) || defined(__i386__)
    __builtin_ia32_pause();
#endif
  }
  struct Workspace
  {
    std::vector<double> values;
    std::vector<int> flag;
    std::vector<int> stack;
    std::vector<char> wait;
  };
  std::array<Workspace, 2> Threads;
  std::unique_ptr<std::atomic<int>[]> PendingRow;
  std::unique_ptr<std::atomic<int>[]> LastRow;
  std::size_t Size = 0;
};

void quietCholmod(cholmod_common& common)
{
  // Failures are handled (and logged) by the solver; CHOLMOD must not print them.
  common.print = 0;
  common.error_handler = nullptr;
}
} // namespace

struct LinearSolver::Internals
{
  cholmod_common Common;
  cholmod_factor* Factor = nullptr;
  // Workspaces of the further threads of a split factorisation.
  std::vector<std::unique_ptr<cholmod_common>> ThreadCommons;
  RowSplit Split;
  RemainderPipeline Pipeline;
  // How many threads the last factorisation ran on.
  int FactorisationThreads = 1;
  // analyse() was called for the next solve's pattern.
  bool AnalysedAhead = false;
  std::vector<int> Blocks;
  std::vector<std::unique_ptr<LinearSolver>> BlockSolvers;

  Internals() { cholmod_start(&this->Common); }
  ~Internals()
  {
    cholmod_free_factor(&this->Factor, &this->Common);
    cholmod_finish(&this->Common);
    for (auto& common : this->ThreadCommons)
    {
      cholmod_finish(common.get());
    }
  }

  void analyse(const Eigen::SparseMatrix<double>& H)
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

  void analyseLocked(const Eigen::SparseMatrix<double>& H)
  {
    // METIS (nested dissection orderings) keeps its random state in globals
    // and reseeds per call: concurrent analyses (several embeddings at once)
    // would draw from each other's sequence and give orderings, hence
    // rounding, that change from run to run.
    static std::mutex orderingMutex;
    std::lock_guard<std::mutex> lock(orderingMutex);
    this->analyse(H);
  }

  /// Numeric factorisation of H (the analysed pattern) on up to `threads`
  /// threads; false if H is not numerically positive definite.
  bool factorise(const Eigen::SparseMatrix<double>& H, int threads)
  {
    cholmod_sparse A = Eigen::viewAsCholmod(H.selfadjointView<Eigen::Upper>());
    cholmod_factor* L = this->Factor;
    this->FactorisationThreads = 1;
    const bool splitKnown = this->Split.valid && this->Split.threads == threads;
    if (L->is_super || threads < 2 || (splitKnown && this->Split.lists.empty()))
    {
      return cholmod_factorize(&A, L, &this->Common) && L->minor == L->n;
    }
    // The matrix cholmod_factorize factorises for an upper triangle:
    // S = triu(A(p, p)), by two transposes.
    cholmod_sparse* lower =
      cholmod_ptranspose(&A, 2, static_cast<int*>(L->Perm), nullptr, 0, &this->Common);
    cholmod_sparse* S =
      lower ? cholmod_ptranspose(lower, 2, nullptr, nullptr, 0, &this->Common) : nullptr;
    cholmod_free_sparse(&lower, &this->Common);
    if (!S)
    {
      throw std::bad_alloc();
    }
    const int n = static_cast<int>(L->n);
    if (!splitKnown)
    {
      std::vector<int> parent(n);
      cholmod_etree(S, parent.data(), &this->Common);
      this->Split = splitRows(*S, parent, threads);
    }
    RowSplit& split = this->Split;
    const int parallelLists = std::max(0, static_cast<int>(split.lists.size()) - 1);
    // What cholmod_factorize does before its rows: LL^T as asked, a symbolic
    // factor allocated (exactly the space the analysis counted) and made the
    // identity, a numeric one emptied. Done here because the rows below may
    // be factorised in several calls.
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
      std::fill(static_cast<int*>(L->nz), static_cast<int*>(L->nz) + n, 1);
    }
    double beta[2] = { 0.0, 0.0 };
    bool ok = true;
    if (parallelLists == 0)
    {
      ok = cholmod_rowfac(S, nullptr, beta, 0, n, L, &this->Common);
    }
    else
    {
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
        listOk[t] = cholmod_rowfac_mask2(S,
          nullptr,
          beta,
          split.lists[t][0],
          split.lists[t][1],
          nullptr,
          0,
          split.next.data(),
          L,
          common);
      }
      ok = std::all_of(listOk.begin(), listOk.end(), [](char c) { return c != 0; });
      if (ok && this->FactorisationThreads > 1 && split.remainder.size() > 1 &&
        RemainderPipeline::applies(*S, *L))
      {
        ok = this->Pipeline.factorise(*S, split.parent, split.remainder, *L);
      }
      else
      {
        ok = ok &&
          cholmod_rowfac_mask2(S,
            nullptr,
            beta,
            split.lists.back()[0],
            split.lists.back()[1],
            nullptr,
            0,
            split.next.data(),
            L,
            &this->Common);
      }
    }
    // cholmod_factorize's final form.
    ok = ok &&
      (this->Common.final_asis ||
        cholmod_change_factor(L->xtype,
          L->is_ll,
          false,
          this->Common.final_pack,
          this->Common.final_monotonic,
          L,
          &this->Common));
    cholmod_free_sparse(&S, &this->Common);
    return ok && L->minor == L->n;
  }

  bool solveWith(const Eigen::VectorXd& b, Eigen::VectorXd& x)
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
};

LinearSolver::LinearSolver(Ordering ordering)
  : Impl(new Internals)
{
  cholmod_common& common = this->Impl->Common;
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
  common.postorder = 1; // also what the split factorisation relies on
  quietCholmod(common);
}

LinearSolver::~LinearSolver() = default;

void LinearSolver::analyse(const Eigen::SparseMatrix<double>& pattern)
{
  if (this->Impl->Blocks.size() > 2)
  {
    return; // block solves analyse each block in solve()
  }
  this->Impl->analyseLocked(pattern);
  this->Impl->AnalysedAhead = true;
}

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
  // Taken before the BLAS guard, which may set the OpenMP thread count to 1.
  const int threads = omp_get_max_threads();
  const SingleThreadedBlas blasThreads;
  Internals& cholesky = *this->Impl;
  const bool ahead = cholesky.AnalysedAhead;
  cholesky.AnalysedAhead = false;
  if ((patternChanged && !ahead) || !cholesky.Factor)
  {
    cholesky.analyseLocked(H);
    result.analysed = true;
  }
  result.analysed = result.analysed || (patternChanged && ahead);
  if (cholesky.factorise(H, threads))
  {
    result.factorisationThreads = cholesky.FactorisationThreads;
    result.success = cholesky.solveWith(b, x);
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
    if (cholesky.factorise(shifted, threads) && cholesky.solveWith(b, x))
    {
      result.factorisationThreads = cholesky.FactorisationThreads;
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
  return this->Impl->solveWith(b, x);
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
