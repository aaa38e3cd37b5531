// SurfaceMaps engine: RemainderPipeline's rows, each split into its pattern
// (scattered and published), its column updates (waiting for the row
// before) and its diagonal.
#include "optimisation/sparse/RemainderPipeline.h"

#include <omp.h>

#include <cmath>
#include <thread>

namespace surfacemaps
{

namespace
{
// Waits are short (the row before is one column ahead) unless the other
// thread lost its core: then give the core up.
void pause(int spins)
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

std::size_t minorNow(std::size_t* minor)
{
  return __atomic_load_n(minor, __ATOMIC_RELAXED);
}

void lowerMinor(std::size_t* minor, std::size_t k)
{
  std::size_t known = __atomic_load_n(minor, __ATOMIC_RELAXED);
  while (k < known &&
    !__atomic_compare_exchange_n(minor, &known, k, true, __ATOMIC_RELAXED, __ATOMIC_RELAXED))
  {
  }
}
} // namespace

bool RemainderPipeline::applies(const cholmod_sparse& S, const cholmod_factor& L)
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

bool RemainderPipeline::factorise(const cholmod_sparse& S,
  const std::vector<int>& parent,
  const std::vector<int>& rows,
  cholmod_factor& L)
{
  const int n = static_cast<int>(L.n);
  const int m = static_cast<int>(rows.size());
  this->reset(n, m);
  const Arrays a{ static_cast<const int*>(S.p),
    static_cast<const int*>(S.i),
    static_cast<const double*>(S.x),
    static_cast<const int*>(L.p),
    static_cast<int*>(L.i),
    static_cast<double*>(L.x),
    static_cast<int*>(L.nz),
    &L.minor,
    parent,
    rows,
    n };
#pragma omp parallel num_threads(2)
  {
    // One thread alone (no second one granted) takes every row in order;
    // its waits are then always met.
    const int stride = omp_get_num_threads();
    Workspace& w = this->Threads[omp_get_thread_num()];
    for (int j = omp_get_thread_num(); j < m; j += stride)
    {
      this->factoriseRow(w, a, j);
    }
  }
  return minorNow(&L.minor) == L.n;
}

void RemainderPipeline::reset(int n, int m)
{
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
  this->Published.reset(new std::atomic<int>[m]);
  for (int j = 0; j < m; ++j)
  {
    this->Published[j].store(0, std::memory_order_relaxed);
  }
  for (Workspace& w : this->Threads)
  {
    w.values.assign(n, 0.0);
    w.flag.assign(n, -1);
    w.stack.resize(n);
    w.wait.resize(n);
  }
}

// Row j of the remainder (row k of L).
void RemainderPipeline::factoriseRow(Workspace& w, const Arrays& a, int j)
{
  const int k = a.rows[j];
  const int top = this->scatterRow(w, a, j, k);
  double dk = w.values[k] + 0.0; // + beta, as cholmod_rowfac adds it
  w.values[k] = 0.0;
  // The row before, which this row's columns may wait for.
  const int previous = j > 0 ? a.rows[j - 1] : -1;
  this->publishPattern(w, a, j, k, previous, top);
  dk = this->eliminateColumns(w, a, k, previous, top, dk);
  this->storeDiagonal(a, k, dk);
}

// Scatter column k of S and walk the row subtree: cholmod_rowfac's pattern
// order (mark j: the marks only grow). The pattern is w.stack[top .. n).
int RemainderPipeline::scatterRow(Workspace& w, const Arrays& a, int j, int k) const
{
  int top = a.n;
  w.flag[k] = j;
  for (int p = a.Sp[k]; p < a.Sp[k + 1]; ++p)
  {
    int i = a.Si[p];
    if (i > k)
    {
      break;
    }
    w.values[i] = a.Sx[p];
    int length = 0;
    for (; i < k && i != -1 && w.flag[i] < j; i = a.parent[i])
    {
      w.stack[length++] = i;
      w.flag[i] = j;
    }
    while (length > 0)
    {
      w.stack[--top] = w.stack[--length];
    }
  }
  return top;
}

// Publish the pattern after the row before has published its own, noting
// the columns that row is still to store.
void RemainderPipeline::publishPattern(Workspace& w,
  const Arrays& a,
  int j,
  int k,
  int previous,
  int top)
{
  if (j > 0)
  {
    for (int spins = 0; !this->Published[j - 1].load(std::memory_order_acquire); ++spins)
    {
      pause(spins);
    }
  }
  for (int s = top; s < a.n; ++s)
  {
    const int pending = this->PendingRow[w.stack[s]].exchange(k, std::memory_order_acq_rel);
    w.wait[s] = previous >= 0 && pending == previous;
  }
  this->PendingRow[k].store(k, std::memory_order_relaxed);
  this->Published[j].store(1, std::memory_order_release);
}

// Row k's entries in the columns of its pattern, each once the row before
// has stored its own there; returns the diagonal left after them.
double RemainderPipeline::eliminateColumns(Workspace& w,
  const Arrays& a,
  int k,
  int previous,
  int top,
  double dk)
{
  for (int s = top; s < a.n; ++s)
  {
    const int i = w.stack[s];
    if (w.wait[s])
    {
      for (int spins = 0; this->LastRow[i].load(std::memory_order_acquire) < previous; ++spins)
      {
        pause(spins);
      }
    }
    double y = w.values[i];
    w.values[i] = 0.0;
    const int count = a.Lnz[i];
    int p = a.Lp[i];
    const int end = p + count;
    const double di = a.Lx[p];
    double lki;
    if (static_cast<std::size_t>(i) >= minorNow(a.minor) || di == 0)
    {
      lki = 0.0;
      p = end;
    }
    else
    {
      y = y / di;
      for (++p; p < end; ++p)
      {
        w.values[a.Li[p]] -= a.Lx[p] * y;
      }
      lki = y;
      dk -= y * y;
    }
    a.Li[p] = k;
    a.Lx[p] = lki;
    a.Lnz[i] = count + 1;
    this->LastRow[i].store(k, std::memory_order_release);
  }
  return dk;
}

void RemainderPipeline::storeDiagonal(const Arrays& a, int k, double dk)
{
  const int p = a.Lp[k];
  a.Li[p] = k;
  if (static_cast<std::size_t>(k) >= minorNow(a.minor))
  {
    dk = 0.0;
  }
  else if (dk <= 0.0)
  {
    dk = 0.0;
    lowerMinor(a.minor, static_cast<std::size_t>(k));
  }
  a.Lx[p] = std::sqrt(dk);
  this->LastRow[k].store(k, std::memory_order_release);
}

} // namespace surfacemaps
