// Test helper: central finite differences of a scalar function of a vector.
#pragma once

#include <Eigen/Core>

#include <functional>

namespace surfacemaps
{
namespace testing
{

inline Eigen::VectorXd finiteDifferenceGradient(
  const std::function<double(const Eigen::VectorXd&)>& f,
  const Eigen::VectorXd& x,
  double h = 1e-6)
{
  Eigen::VectorXd g(x.size());
  for (Eigen::Index i = 0; i < x.size(); ++i)
  {
    Eigen::VectorXd a = x, b = x;
    a[i] += h;
    b[i] -= h;
    g[i] = (f(a) - f(b)) / (2 * h);
  }
  return g;
}

inline Eigen::MatrixXd finiteDifferenceHessian(
  const std::function<double(const Eigen::VectorXd&)>& f,
  const Eigen::VectorXd& x,
  double h = 1e-4)
{
  const Eigen::Index n = x.size();
  Eigen::MatrixXd H(n, n);
  for (Eigen::Index i = 0; i < n; ++i)
  {
    for (Eigen::Index j = 0; j < n; ++j)
    {
      auto at = [&](double si, double sj)
      {
        Eigen::VectorXd y = x;
        y[i] += si * h;
        y[j] += sj * h;
        return f(y);
      };
      H(i, j) = (at(1, 1) - at(1, -1) - at(-1, 1) + at(-1, -1)) / (4 * h * h);
    }
  }
  return H;
}

/// Max |a - b| relative to max(1, |b|_inf).
inline double relativeError(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b)
{
  return (a - b).cwiseAbs().maxCoeff() / std::max(1.0, b.cwiseAbs().maxCoeff());
}

} // namespace testing
} // namespace surfacemaps
