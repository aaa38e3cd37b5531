#include "statistics/ShapeModes.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace surfacemaps
{

ShapeModesResult principalModes(const std::vector<ShapePoints>& shapes,
  const std::vector<double>& vertexWeights,
  const ShapeModesOptions& options)
{
  const int n = static_cast<int>(shapes.size());
  const std::size_t np = shapes[0].size();
  const std::vector<double>& A = vertexWeights;
  ShapeModesResult result;

  result.mean.assign(np, Eigen::Vector3d::Zero());
  for (const ShapePoints& x : shapes)
  {
    for (std::size_t v = 0; v < np; ++v)
    {
      result.mean[v] += x[v] / n;
    }
  }
  std::vector<ShapePoints> deviations(n, ShapePoints(np));
  result.standardDeviation.assign(np, 0.0);
  for (int i = 0; i < n; ++i)
  {
    for (std::size_t v = 0; v < np; ++v)
    {
      deviations[i][v] = shapes[i][v] - result.mean[v];
      result.standardDeviation[v] += deviations[i][v].squaredNorm() / n;
    }
  }
  for (double& s : result.standardDeviation)
  {
    s = std::sqrt(s);
  }

  Eigen::MatrixXd gram(n, n);
  for (int i = 0; i < n; ++i)
  {
    for (int j = 0; j <= i; ++j)
    {
      double sum = 0.0;
      for (std::size_t v = 0; v < np; ++v)
      {
        sum += A[v] * deviations[i][v].dot(deviations[j][v]);
      }
      gram(i, j) = gram(j, i) = sum;
    }
  }
  result.totalVariance = gram.trace() / n;

  // Eigenvalues in ascending order; mode m takes the (m+1)-th largest.
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(gram / n);
  const int k = std::max(0, std::min(options.modes, n - 1));
  result.scores = Eigen::MatrixXd::Zero(n, k);
  // Below this a variance is rounding noise of the Gram matrix: no direction.
  const double negligible = 1e-12 * result.totalVariance;
  for (int m = 0; m < k; ++m)
  {
    const double variance = std::max(0.0, eigen.eigenvalues()(n - 1 - m));
    Eigen::VectorXd a = eigen.eigenvectors().col(n - 1 - m);
    ShapePoints mode(np, Eigen::Vector3d::Zero());
    if (variance > negligible && variance > 0.0)
    {
      // u = D a / sqrt(N lambda) has <u, u> = a^T G a / (N lambda) = 1.
      const double norm = std::sqrt(n * variance);
      for (int i = 0; i < n; ++i)
      {
        for (std::size_t v = 0; v < np; ++v)
        {
          mode[v] += (a(i) / norm) * deviations[i][v];
        }
      }
      double largest = 0.0;
      for (const Eigen::Vector3d& u : mode)
      {
        for (int c = 0; c < 3; ++c)
        {
          if (std::abs(u(c)) > std::abs(largest))
          {
            largest = u(c);
          }
        }
      }
      if (largest < 0.0)
      {
        a = -a;
        for (Eigen::Vector3d& u : mode)
        {
          u = -u;
        }
      }
      // <x_i - mean, u> = (G a)_i / sqrt(N lambda) = sqrt(N lambda) a_i.
      result.scores.col(m) = norm * a;
    }
    result.variances.push_back(variance);
    result.explainedFractions.push_back(
      result.totalVariance > 0.0 ? variance / result.totalVariance : 0.0);
    result.modes.push_back(std::move(mode));
  }
  return result;
}

ShapePoints shapeAlongMode(const ShapeModesResult& statistics, int mode, double coefficient)
{
  ShapePoints x = statistics.mean;
  const double step = coefficient * std::sqrt(statistics.variances[mode]);
  for (std::size_t v = 0; v < x.size(); ++v)
  {
    x[v] += step * statistics.modes[mode][v];
  }
  return x;
}

} // namespace surfacemaps
