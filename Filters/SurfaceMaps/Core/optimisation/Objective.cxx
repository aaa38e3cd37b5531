#include "optimisation/Objective.h"

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <exception>
#include <stdexcept>

namespace surfacemaps
{

namespace
{
constexpr double Infinity = std::numeric_limits<double>::infinity();

// Sum in element order (deterministic); +inf if any element is not finite.
double sumOrInfinity(const std::vector<double>& values)
{
  double sum = 0.0;
  for (double v : values)
  {
    if (!std::isfinite(v))
    {
      return Infinity;
    }
    sum += v;
  }
  return sum;
}
} // namespace

void Objective::addTerm(std::shared_ptr<ObjectiveTerm> term, double weight, int group)
{
  if (!(weight >= 0.0))
  {
    throw std::invalid_argument("objective term weights must be >= 0");
  }
  Entry entry;
  entry.Term = std::move(term);
  entry.Weight = weight;
  entry.Group = group;
  this->Terms.push_back(std::move(entry));
  this->PatternValid = false;
}

void Objective::clear()
{
  this->Terms.clear();
  this->PatternValid = false;
}

std::vector<double> Objective::termValues(const SpherePoints& points) const
{
  std::vector<double> result;
  std::vector<double> values;
  for (const Entry& entry : this->Terms)
  {
    values.resize(entry.Term->numberOfElements());
    entry.Term->evaluateValues(points, values.data());
    result.push_back(sumOrInfinity(values));
  }
  return result;
}

double Objective::value(const SpherePoints& points) const
{
  const std::vector<double> perTerm = this->termValues(points);
  double total = 0.0;
  for (std::size_t t = 0; t < perTerm.size(); ++t)
  {
    if (this->Terms[t].Weight == 0.0)
    {
      continue;
    }
    if (!std::isfinite(perTerm[t]))
    {
      return Infinity;
    }
    total += this->Terms[t].Weight * perTerm[t];
  }
  return total;
}

double Objective::assembleGradient(const SpherePoints& points, Eigen::VectorXd& gradient)
{
  gradient.setZero(points.numberOfVariables());
  double total = 0.0;
  std::vector<int> idx;
  for (Entry& entry : this->Terms)
  {
    if (entry.Weight == 0.0)
    {
      continue;
    }
    const int ne = entry.Term->numberOfElements();
    const int nv = entry.Term->pointsPerElement();
    const int n = 2 * nv;
    idx.resize(nv);
    const double sum = sumOrInfinity(entry.Values);
    if (!std::isfinite(sum))
    {
      return Infinity;
    }
    total += entry.Weight * sum;
    for (int e = 0; e < ne; ++e)
    {
      entry.Term->elementPoints(e, idx.data());
      const double* g = entry.Gradients.data() + static_cast<std::size_t>(e) * n;
      for (int k = 0; k < nv; ++k)
      {
        const int var = points.variable(idx[k]);
        if (var >= 0)
        {
          gradient[var] += entry.Weight * g[2 * k];
          gradient[var + 1] += entry.Weight * g[2 * k + 1];
        }
      }
    }
  }
  return total;
}

void ObjectiveTerm::evaluateDerivatives(const SpherePoints& points,
  double projectionEps,
  double* values,
  double* gradients,
  double* hessians) const
{
  const int ne = this->numberOfElements();
  const int chunks = (ne + DerivativeChunk - 1) / DerivativeChunk;
#pragma omp parallel for schedule(dynamic, 1) if (ne > ParallelDerivativeThreshold)
  for (int c = 0; c < chunks; ++c)
  {
    this->evaluateDerivatives(points,
      projectionEps,
      c * DerivativeChunk,
      std::min(ne, (c + 1) * DerivativeChunk),
      values,
      gradients,
      hessians);
  }
}

void Objective::evaluateDerivatives(const SpherePoints& points,
  double projectionEps,
  bool withHessian,
  const std::function<void()>& alongside)
{
  // All terms' elements in one list of chunks, taken by the threads in turn:
  // one parallel region instead of one per term, so no thread waits at the
  // end of each term. Elements write their own slots, so the results do not
  // depend on which thread evaluates what.
  struct Chunk
  {
    Entry* entry;
    int first, last;
  };
  std::vector<Chunk> chunks;
  long long elements = 0;
  for (Entry& entry : this->Terms)
  {
    const int ne = entry.Term->numberOfElements();
    const std::size_t n = 2 * entry.Term->pointsPerElement();
    entry.Values.resize(ne);
    entry.Gradients.resize(ne * n);
    if (withHessian)
    {
      entry.Hessians.resize(ne * n * n);
    }
    for (int first = 0; first < ne; first += ObjectiveTerm::DerivativeChunk)
    {
      chunks.push_back({ &entry, first, std::min(ne, first + ObjectiveTerm::DerivativeChunk) });
    }
    elements += ne;
  }
  std::atomic<std::size_t> next{ 0 };
  std::exception_ptr error;
  const bool parallel = alongside || elements > ObjectiveTerm::ParallelDerivativeThreshold;
#pragma omp parallel if (parallel)
  {
    if (alongside && omp_get_thread_num() == 0)
    {
      // Exceptions must not leave the parallel region.
      try
      {
        alongside();
      }
      catch (...)
      {
        error = std::current_exception();
      }
    }
    for (std::size_t c = next++; c < chunks.size(); c = next++)
    {
      Entry& entry = *chunks[c].entry;
      entry.Term->evaluateDerivatives(points,
        projectionEps,
        chunks[c].first,
        chunks[c].last,
        entry.Values.data(),
        entry.Gradients.data(),
        withHessian ? entry.Hessians.data() : nullptr);
    }
  }
  if (error)
  {
    std::rethrow_exception(error);
  }
}

double Objective::gradient(const SpherePoints& points, Eigen::VectorXd& gradient)
{
  this->evaluateDerivatives(points, 0.0, false);
  return this->assembleGradient(points, gradient);
}

Objective::BlockColumns Objective::blockColumns(const SpherePoints& points) const
{
  // The blocks come as (column, row) pairs, most of them many times over
  // (an edge lies in many elements). Bucketing the rows by column and
  // sorting each short bucket is several times faster than one sort of all
  // pairs.
  const int nb = points.numberOfVariables() / 2;
  std::size_t count = static_cast<std::size_t>(nb);
  for (const Entry& entry : this->Terms)
  {
    const std::size_t nv = entry.Term->pointsPerElement();
    count += static_cast<std::size_t>(entry.Term->numberOfElements()) * nv * (nv + 1) / 2;
  }
  std::vector<std::array<int, 2>> pairs; // (column, row)
  pairs.reserve(count);
  std::vector<int> idx;
  for (int b = 0; b < nb; ++b)
  {
    pairs.push_back({ b, b }); // keep the diagonal
  }
  for (const Entry& entry : this->Terms)
  {
    const int ne = entry.Term->numberOfElements();
    const int nv = entry.Term->pointsPerElement();
    idx.resize(nv);
    for (int e = 0; e < ne; ++e)
    {
      entry.Term->elementPoints(e, idx.data());
      for (int a = 0; a < nv; ++a)
      {
        const int va = points.variable(idx[a]);
        for (int b = 0; b < nv && va >= 0; ++b)
        {
          const int vb = points.variable(idx[b]);
          if (vb >= va)
          {
            pairs.push_back({ vb / 2, va / 2 });
          }
        }
      }
    }
  }
  std::vector<int> bucket(static_cast<std::size_t>(nb) + 1, 0);
  for (const auto& pair : pairs)
  {
    ++bucket[pair[0] + 1];
  }
  for (int b = 0; b < nb; ++b)
  {
    bucket[b + 1] += bucket[b];
  }
  std::vector<int> rows(pairs.size());
  std::vector<int> next(bucket.begin(), bucket.end() - 1);
  for (const auto& pair : pairs)
  {
    rows[next[pair[0]]++] = pair[1];
  }
  BlockColumns result;
  result.start.assign(static_cast<std::size_t>(nb) + 1, 0);
  result.rows.reserve(pairs.size() / 4);
  for (int column = 0; column < nb; ++column)
  {
    int* begin = rows.data() + bucket[column];
    int* end = rows.data() + bucket[column + 1];
    std::sort(begin, end);
    end = std::unique(begin, end);
    result.rows.insert(result.rows.end(), begin, end);
    result.start[column + 1] = static_cast<int>(result.rows.size());
  }
  return result;
}

void Objective::layOutPattern(int nvars, const BlockColumns& blocks)
{
  const int nb = nvars / 2;
  // Block column B holds blocks rows r_0 < ... < r_k = B (the diagonal last):
  // variable column 2B has rows 2 r_j, 2 r_j + 1 (j < k) and 2B; column
  // 2B + 1 has the same plus 2B + 1.
  const std::int64_t nnz = 4 * static_cast<std::int64_t>(blocks.rows.size()) - nb;
  // Keep the previous pattern to tell whether it changed (a solver can then
  // keep its symbolic analysis).
  Eigen::SparseMatrix<double> previous;
  previous.swap(this->Pattern);
  this->Pattern.resize(nvars, nvars);
  this->Pattern.resizeNonZeros(static_cast<Eigen::Index>(nnz));
  int* outer = this->Pattern.outerIndexPtr();
  int* inner = this->Pattern.innerIndexPtr();
  outer[0] = 0;
  for (int b = 0; b < nb; ++b)
  {
    const int count = blocks.start[b + 1] - blocks.start[b];
    outer[2 * b + 1] = outer[2 * b] + 2 * count - 1;
    outer[2 * b + 2] = outer[2 * b + 1] + 2 * count;
    for (int j = 0; j < count; ++j)
    {
      const int row = blocks.rows[blocks.start[b] + j];
      for (int column = 0; column < 2; ++column)
      {
        const int at = outer[2 * b + column] + 2 * j;
        inner[at] = 2 * row;
        if (row < b || column == 1)
        {
          inner[at + 1] = 2 * row + 1;
        }
      }
    }
  }
  std::fill(this->Pattern.valuePtr(), this->Pattern.valuePtr() + nnz, 0.0);
  this->PatternUnchanged = previous.rows() == nvars && previous.nonZeros() == nnz &&
    std::equal(outer, outer + nvars + 1, previous.outerIndexPtr()) &&
    std::equal(inner, inner + nnz, previous.innerIndexPtr());
}

void Objective::buildScatter(const SpherePoints& points, const BlockColumns& blocks)
{
  const int* outer = this->Pattern.outerIndexPtr();
  // Position of block (row, column) among its block column's blocks.
  auto blockIndex = [&](int row, int column)
  {
    const int* begin = blocks.rows.data() + blocks.start[column];
    const int* end = blocks.rows.data() + blocks.start[column + 1];
    return static_cast<int>(std::lower_bound(begin, end, row) - begin);
  };
  for (Entry& entry : this->Terms)
  {
    const int ne = entry.Term->numberOfElements();
    const int nv = entry.Term->pointsPerElement();
    const int n = 2 * nv;
    entry.Scatter.assign(static_cast<std::size_t>(ne) * n * n, -1);
    // Each element writes its own slots only.
#pragma omp parallel
    {
      std::vector<int> idx(nv);
#pragma omp for schedule(static)
      for (int e = 0; e < ne; ++e)
      {
        entry.Term->elementPoints(e, idx.data());
        int* scatter = entry.Scatter.data() + static_cast<std::size_t>(e) * n * n;
        for (int a = 0; a < nv; ++a)
        {
          const int va = points.variable(idx[a]);
          for (int b = 0; b < nv && va >= 0; ++b)
          {
            const int vb = points.variable(idx[b]);
            if (vb < va)
            {
              continue; // lower triangle (or locked: vb = -1)
            }
            const int row = va / 2, column = vb / 2;
            const int j = blockIndex(row, column);
            for (int i = 0; i < 2; ++i)
            {
              for (int k = 0; k < 2; ++k)
              {
                if (row == column && i > k)
                {
                  continue; // below the diagonal inside the diagonal block
                }
                scatter[(2 * a + i) + (2 * b + k) * n] = outer[2 * column + k] + 2 * j + i;
              }
            }
          }
        }
      }
    }
  }
}

double Objective::hessian(const SpherePoints& points,
  double projectionEps,
  Eigen::VectorXd& gradient,
  Eigen::SparseMatrix<double>& hessian,
  bool* patternChanged,
  const std::function<void(const Eigen::SparseMatrix<double>&)>& newPattern)
{
  const bool rebuild = !this->PatternValid || this->PatternVariables != points.numberOfVariables();
  if (rebuild)
  {
    // Every unlocked point owns two consecutive variables, so the Hessian is
    // made of 2x2 blocks: collect the upper-triangle blocks (block row <=
    // block column) column by column (four times fewer than single entries),
    // then lay out the entries. Collecting is serial work, so one thread does
    // it (and the caller's work on a new pattern) while the others evaluate
    // the elements' derivatives; the scatter positions need both.
    const int nvars = points.numberOfVariables();
    BlockColumns blocks;
    this->evaluateDerivatives(points,
      projectionEps,
      true,
      [&]()
      {
        blocks = this->blockColumns(points);
        this->layOutPattern(nvars, blocks);
        if (!this->PatternUnchanged && newPattern)
        {
          newPattern(this->Pattern);
        }
      });
    this->buildScatter(points, blocks);
    this->PatternVariables = nvars;
    this->PatternValid = true;
  }
  else
  {
    this->evaluateDerivatives(points, projectionEps, true);
  }
  if (patternChanged)
  {
    *patternChanged = rebuild && !this->PatternUnchanged;
  }
  const double total = this->assembleGradient(points, gradient);

  hessian = this->Pattern; // same structure, zero values
  double* values = hessian.valuePtr();
  // One thread (adding in parallel, each thread into its own range of the
  // values, saved under 5 % of the corpus' time: Testing/Benchmarks/README.md,
  // tricks on and off). Entries below the diagonal or of locked points
  // scatter to -1.
  for (const Entry& entry : this->Terms)
  {
    if (entry.Weight == 0.0)
    {
      continue;
    }
    const std::size_t count = entry.Scatter.size();
    const int* scatter = entry.Scatter.data();
    const double* h = entry.Hessians.data();
    const double w = entry.Weight;
    for (std::size_t k = 0; k < count; ++k)
    {
      if (scatter[k] >= 0)
      {
        values[scatter[k]] += w * h[k];
      }
    }
  }
  return total;
}

} // namespace surfacemaps
