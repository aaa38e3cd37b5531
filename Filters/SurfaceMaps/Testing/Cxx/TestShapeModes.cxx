#include "mesh/Primitives.h"
#include "statistics/Procrustes.h"
#include "statistics/ShapeModes.h"

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

using namespace surfacemaps;

// The N x N Gram route gives the eigenpairs of the full 3V x 3V area-weighted
// covariance, computed directly here on a small mesh.
TEST(ShapeModes, GramMatrixMatchesTheFullCovariance)
{
  const PolygonMesh base = makeIcosphere(0); // 12 vertices
  const int n = 6, v = static_cast<int>(base.points.size());
  std::mt19937 random(7);
  std::normal_distribution<double> normal(0.0, 0.1);
  std::vector<ShapePoints> shapes(n, base.points);
  for (ShapePoints& x : shapes)
  {
    for (Eigen::Vector3d& p : x)
    {
      p += Eigen::Vector3d(normal(random), normal(random), normal(random));
    }
  }
  std::vector<double> weights = vertexAreaWeights(base.points, base.triangles());
  weights[0] *= 3.0; // not uniform, still summing to 1 after the rescale
  double sum = 0.0;
  for (double w : weights)
  {
    sum += w;
  }
  for (double& w : weights)
  {
    w /= sum;
  }
  ShapeModesOptions options;
  options.modes = 10; // more than N - 1: five come out
  const ShapeModesResult result = principalModes(shapes, weights, options);
  ASSERT_EQ(result.variances.size(), 5u);

  // Direct: C = W^1/2 (1/N sum_i d_i d_i^T) W^1/2 on the stacked coordinates.
  Eigen::VectorXd mean = Eigen::VectorXd::Zero(3 * v);
  for (const ShapePoints& x : shapes)
  {
    for (int k = 0; k < v; ++k)
    {
      mean.segment<3>(3 * k) += x[k] / n;
    }
  }
  Eigen::MatrixXd covariance = Eigen::MatrixXd::Zero(3 * v, 3 * v);
  for (const ShapePoints& x : shapes)
  {
    Eigen::VectorXd d(3 * v);
    for (int k = 0; k < v; ++k)
    {
      d.segment<3>(3 * k) = std::sqrt(weights[k]) * (x[k] - mean.segment<3>(3 * k));
    }
    covariance += d * d.transpose() / n;
  }
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> direct(covariance);
  EXPECT_NEAR(result.totalVariance, covariance.trace(), 1e-14);
  for (int m = 0; m < 5; ++m)
  {
    const double lambda = direct.eigenvalues()(3 * v - 1 - m);
    EXPECT_NEAR(result.variances[m], lambda, 1e-12 * lambda) << m;
    EXPECT_NEAR(result.explainedFractions[m], lambda / covariance.trace(), 1e-12) << m;
    // The mode, weighted like the covariance, is the unit eigenvector (up to the sign).
    Eigen::VectorXd u(3 * v);
    for (int k = 0; k < v; ++k)
    {
      u.segment<3>(3 * k) = std::sqrt(weights[k]) * result.modes[m][k];
    }
    EXPECT_NEAR(u.norm(), 1.0, 1e-12) << m;
    EXPECT_NEAR(std::abs(u.dot(direct.eigenvectors().col(3 * v - 1 - m))), 1.0, 1e-9) << m;
    // Scores: the weighted projections of the deviations.
    for (int i = 0; i < n; ++i)
    {
      double score = 0.0;
      for (int k = 0; k < v; ++k)
      {
        score += weights[k] * (shapes[i][k] - mean.segment<3>(3 * k)).dot(result.modes[m][k]);
      }
      EXPECT_NEAR(result.scores(i, m), score, 1e-12) << m << " " << i;
    }
  }
}

// Identical shapes: no variance, zero modes and scores (no direction to show).
TEST(ShapeModes, IdenticalShapesHaveNoModes)
{
  const PolygonMesh base = makeIcosphere(1);
  const std::vector<ShapePoints> shapes(4, base.points);
  const ShapeModesResult result =
    principalModes(shapes, vertexAreaWeights(base.points, base.triangles()));
  ASSERT_EQ(result.variances.size(), 3u);
  EXPECT_EQ(result.totalVariance, 0.0);
  for (std::size_t m = 0; m < 3; ++m)
  {
    EXPECT_EQ(result.variances[m], 0.0);
    EXPECT_EQ(result.explainedFractions[m], 0.0);
    for (const Eigen::Vector3d& u : result.modes[m])
    {
      EXPECT_EQ(u.norm(), 0.0);
    }
  }
  EXPECT_EQ(result.scores.norm(), 0.0);
  EXPECT_EQ(shapeAlongMode(result, 1, 2.0), base.points);
}
