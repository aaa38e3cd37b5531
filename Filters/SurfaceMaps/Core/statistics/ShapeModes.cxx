#include "statistics/ShapeModes.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace surfacemaps
{

namespace
{

// The unweighted mean of the shapes, vertex by vertex.
ShapePoints meanShape(const std::vector<ShapePoints>& shapes)
{
  const int n = static_cast<int>(shapes.size());
  const std::size_t np = shapes[0].size();
  ShapePoints mean(np, Eigen::Vector3d::Zero());
  for (const ShapePoints& x : shapes)
  {
    for (std::size_t v = 0; v < np; ++v)
    {
      mean[v] += x[v] / n;
    }
  }
  return mean;
}

// x_i - mean per shape; `standardDeviation` receives the per-vertex RMS
// distance of the shapes from the mean.
std::vector<ShapePoints> deviationsFromMean(const std::vector<ShapePoints>& shapes,
  const ShapePoints& mean,
  std::vector<double>& standardDeviation)
{
  const int n = static_cast<int>(shapes.size());
  const std::size_t np = shapes[0].size();
  std::vector<ShapePoints> deviations(n, ShapePoints(np));
  standardDeviation.assign(np, 0.0);
  for (int i = 0; i < n; ++i)
  {
    for (std::size_t v = 0; v < np; ++v)
    {
      deviations[i][v] = shapes[i][v] - mean[v];
      standardDeviation[v] += deviations[i][v].squaredNorm() / n;
    }
  }
  for (double& s : standardDeviation)
  {
    s = std::sqrt(s);
  }
  return deviations;
}

// G_ij = sum_v A_v <d_iv, d_jv>: the N x N Gram matrix, whose eigenvectors
// give the modes without the 3P x 3P covariance.
Eigen::MatrixXd weightedGram(const std::vector<ShapePoints>& deviations,
  const std::vector<double>& A)
{
  const int n = static_cast<int>(deviations.size());
  const std::size_t np = deviations[0].size();
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
  return gram;
}

// u = sum_i (a_i / norm) d_i.
ShapePoints combinedDeviations(const std::vector<ShapePoints>& deviations,
  const Eigen::VectorXd& a,
  double norm)
{
  ShapePoints mode(deviations[0].size(), Eigen::Vector3d::Zero());
  for (std::size_t i = 0; i < deviations.size(); ++i)
  {
    for (std::size_t v = 0; v < mode.size(); ++v)
    {
      mode[v] += (a(i) / norm) * deviations[i][v];
    }
  }
  return mode;
}

// The sign of an eigenvector is arbitrary: flip the mode (and its
// coefficients `a`) so that its largest component is positive.
void orientMode(ShapePoints& mode, Eigen::VectorXd& a)
{
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
}

} // namespace

ShapeModesResult principalModes(const std::vector<ShapePoints>& shapes,
  const std::vector<double>& vertexWeights,
  const ShapeModesOptions& options)
{
  const int n = static_cast<int>(shapes.size());
  const std::size_t np = shapes[0].size();
  ShapeModesResult result;
  result.mean = meanShape(shapes);
  const std::vector<ShapePoints> deviations =
    deviationsFromMean(shapes, result.mean, result.standardDeviation);
  const Eigen::MatrixXd gram = weightedGram(deviations, vertexWeights);
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
      mode = combinedDeviations(deviations, a, norm);
      orientMode(mode, a);
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
