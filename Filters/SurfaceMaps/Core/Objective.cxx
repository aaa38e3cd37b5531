#include "Objective.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
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

void Objective::addTerm(std::shared_ptr<ObjectiveTerm> term, double weight)
{
  if (!(weight >= 0.0))
  {
    throw std::invalid_argument("objective term weights must be >= 0");
  }
  Entry entry;
  entry.Term = std::move(term);
  entry.Weight = weight;
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

double Objective::gradient(const SpherePoints& points, Eigen::VectorXd& gradient)
{
  for (Entry& entry : this->Terms)
  {
    const std::size_t ne = entry.Term->numberOfElements();
    const std::size_t n = 2 * entry.Term->pointsPerElement();
    entry.Values.resize(ne);
    entry.Gradients.resize(ne * n);
    entry.Term->evaluateDerivatives(
      points, 0.0, entry.Values.data(), entry.Gradients.data(), nullptr);
  }
  return this->assembleGradient(points, gradient);
}

void Objective::buildPattern(const SpherePoints& points)
{
  const int nvars = points.numberOfVariables();
  // Upper-triangle entries (row <= col) as 64-bit keys col * nvars + row, so
  // sorting orders them column-major.
  std::vector<std::int64_t> keys;
  std::vector<int> idx;
  for (int v = 0; v < nvars; ++v)
  {
    keys.push_back(static_cast<std::int64_t>(v) * nvars + v); // keep the diagonal
  }
  for (Entry& entry : this->Terms)
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
          if (vb < 0)
          {
            continue;
          }
          for (int i = 0; i < 2; ++i)
          {
            for (int j = 0; j < 2; ++j)
            {
              const int row = va + i, col = vb + j;
              if (row <= col)
              {
                keys.push_back(static_cast<std::int64_t>(col) * nvars + row);
              }
            }
          }
        }
      }
    }
  }
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());

  this->Pattern.resize(nvars, nvars);
  this->Pattern.resizeNonZeros(static_cast<Eigen::Index>(keys.size()));
  int* outer = this->Pattern.outerIndexPtr();
  int* inner = this->Pattern.innerIndexPtr();
  std::fill(outer, outer + nvars + 1, 0);
  for (std::size_t k = 0; k < keys.size(); ++k)
  {
    const int col = static_cast<int>(keys[k] / nvars);
    inner[k] = static_cast<int>(keys[k] % nvars);
    ++outer[col + 1];
  }
  for (int c = 0; c < nvars; ++c)
  {
    outer[c + 1] += outer[c];
  }
  std::fill(this->Pattern.valuePtr(), this->Pattern.valuePtr() + keys.size(), 0.0);

  auto position = [&](int row, int col)
  {
    const int* begin = inner + outer[col];
    const int* end = inner + outer[col + 1];
    return static_cast<int>(std::lower_bound(begin, end, row) - inner);
  };
  for (Entry& entry : this->Terms)
  {
    const int ne = entry.Term->numberOfElements();
    const int nv = entry.Term->pointsPerElement();
    const int n = 2 * nv;
    entry.Scatter.assign(static_cast<std::size_t>(ne) * n * n, -1);
    idx.resize(nv);
    for (int e = 0; e < ne; ++e)
    {
      entry.Term->elementPoints(e, idx.data());
      int* scatter = entry.Scatter.data() + static_cast<std::size_t>(e) * n * n;
      for (int a = 0; a < n; ++a)
      {
        const int va = points.variable(idx[a / 2]);
        for (int b = 0; b < n && va >= 0; ++b)
        {
          const int vb = points.variable(idx[b / 2]);
          if (vb < 0)
          {
            continue;
          }
          const int row = va + a % 2, col = vb + b % 2;
          if (row <= col)
          {
            scatter[a + b * n] = position(row, col);
          }
        }
      }
    }
  }
  this->PatternVariables = nvars;
  this->PatternValid = true;
}

double Objective::hessian(const SpherePoints& points,
  double projectionEps,
  Eigen::VectorXd& gradient,
  Eigen::SparseMatrix<double>& hessian,
  bool* patternChanged)
{
  const bool rebuild = !this->PatternValid || this->PatternVariables != points.numberOfVariables();
  if (rebuild)
  {
    this->buildPattern(points);
  }
  if (patternChanged)
  {
    *patternChanged = rebuild;
  }
  for (Entry& entry : this->Terms)
  {
    const std::size_t ne = entry.Term->numberOfElements();
    const std::size_t n = 2 * entry.Term->pointsPerElement();
    entry.Values.resize(ne);
    entry.Gradients.resize(ne * n);
    entry.Hessians.resize(ne * n * n);
    entry.Term->evaluateDerivatives(
      points, projectionEps, entry.Values.data(), entry.Gradients.data(), entry.Hessians.data());
  }
  const double total = this->assembleGradient(points, gradient);

  hessian = this->Pattern; // same structure, zero values
  double* values = hessian.valuePtr();
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
