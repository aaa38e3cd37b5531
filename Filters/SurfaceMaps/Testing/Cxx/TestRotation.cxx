#include "geometry/Rotation.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <random>
#include <vector>

using namespace surfacemaps;

TEST(Rotation, BestRotationRecoversARotation)
{
  std::mt19937 rng(3);
  std::normal_distribution<double> n;
  const Eigen::Matrix3d R =
    Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  std::vector<Eigen::Vector3d> from, to;
  for (int k = 0; k < 5; ++k)
  {
    from.push_back(Eigen::Vector3d(n(rng), n(rng), n(rng)).normalized());
    to.push_back(R * from.back());
  }
  const Eigen::Matrix3d found = bestRotation(from, to);
  EXPECT_LT((found - R).norm(), 1e-12);
  EXPECT_NEAR(found.determinant(), 1.0, 1e-12);
}

TEST(Rotation, NoReflectionForMirroredPoints)
{
  // A mirror image is no rotation: the best rotation keeps det +1.
  std::vector<Eigen::Vector3d> from{ { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { 1, 1, 1 } };
  std::vector<Eigen::Vector3d> to;
  for (const Eigen::Vector3d& p : from)
  {
    to.emplace_back(-p.x(), p.y(), p.z());
  }
  EXPECT_NEAR(bestRotation(from, to).determinant(), 1.0, 1e-12);
}
