#include "geometry/MapMetrics.h"
#include "mesh/Primitives.h"

#include <Eigen/Geometry>
#include <Eigen/SVD>
#include <gtest/gtest.h>

#include <cmath>

using namespace surfacemaps;

namespace
{
// A flat n x n grid in the xy-plane (open; metrics do not need closed meshes).
PolygonMesh grid(int n)
{
  PolygonMesh m;
  for (int j = 0; j <= n; ++j)
  {
    for (int i = 0; i <= n; ++i)
    {
      m.points.emplace_back(i, j, 0.0);
    }
  }
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      const int a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
      m.addFace({ a, b, d });
      m.addFace({ a, d, c });
    }
  }
  return m;
}
} // namespace

TEST(MapMetrics, IdentityIsDistortionFree)
{
  const PolygonMesh ico = makeIcosphere(2);
  const MapMetrics m = measureMap(ico.points, ico.points, ico.triangles());
  EXPECT_NEAR(m.symmetricDirichlet, 1.0, 1e-12);
  EXPECT_NEAR(m.maxDistortion, 1.0, 1e-12);
  EXPECT_EQ(m.fractionBelow.size(), 2u);
  EXPECT_DOUBLE_EQ(m.fractionBelow[0], 1.0);
  EXPECT_EQ(m.degenerateTriangles, 0);
  for (std::size_t f = 0; f < m.s1.size(); ++f)
  {
    EXPECT_NEAR(m.s1[f], 1.0, 1e-12);
    EXPECT_NEAR(m.s2[f], 1.0, 1e-12);
  }
}

TEST(MapMetrics, UniformScalingAndMotionsAreNormalisedAway)
{
  const PolygonMesh ico = makeIcosphere(2);
  std::vector<Eigen::Vector3d> moved;
  const Eigen::Matrix3d R =
    Eigen::AngleAxisd(1.1, Eigen::Vector3d(1, -2, 0.5).normalized()).toRotationMatrix();
  for (const auto& p : ico.points)
  {
    moved.push_back(3.7 * (R * p) + Eigen::Vector3d(5, -1, 2));
  }
  const MapMetrics m = measureMap(ico.points, moved, ico.triangles());
  EXPECT_NEAR(m.symmetricDirichlet, 1.0, 1e-12);
  EXPECT_NEAR(m.maxDistortion, 1.0, 1e-9);
}

TEST(MapMetrics, StretchHasTheKnownValues)
{
  // x scaled by 2; after unit-area scaling J = diag(sqrt 2, 1/sqrt 2):
  // distortion sqrt 2 everywhere, SD = 1/4 (2.5 + 2.5) = 1.25.
  const PolygonMesh g = grid(6);
  std::vector<Eigen::Vector3d> stretched = g.points;
  for (auto& p : stretched)
  {
    p.x() *= 2.0;
  }
  const MapMetrics m = measureMap(g.points, stretched, g.triangles());
  EXPECT_NEAR(m.symmetricDirichlet, 1.25, 1e-12);
  EXPECT_NEAR(m.maxDistortion, std::sqrt(2.0), 1e-12);
  EXPECT_DOUBLE_EQ(m.areaFractionBelow(1.5), 1.0);
  EXPECT_DOUBLE_EQ(m.areaFractionBelow(1.4), 0.0);
  const std::vector<double> curve = m.cumulativeCurve({ 1.0, 1.41, 1.42, 3.0 });
  EXPECT_EQ(curve, (std::vector<double>{ 0.0, 0.0, 1.0, 1.0 }));
}

TEST(MapMetrics, DegenerateTrianglesAreReported)
{
  const PolygonMesh g = grid(3);
  std::vector<Eigen::Vector3d> collapsed = g.points;
  collapsed[5] = collapsed[6]; // triangles using both 5 and 6 lose their area
  const MapMetrics m = measureMap(g.points, collapsed, g.triangles());
  EXPECT_GT(m.degenerateTriangles, 0);
  EXPECT_TRUE(std::isinf(m.symmetricDirichlet));
  EXPECT_TRUE(std::isinf(m.maxDistortion));
  EXPECT_LT(m.areaFractionBelow(1e9), 1.0);
}

TEST(MapMetrics, AgreesWithAnIndependentSvdOnADeformationPair)
{
  // A sphere and a smoothly deformed copy; the independent computation maps
  // the 3D edge vectors with the pseudo-inverse and takes a full SVD.
  const PolygonMesh ico = makeIcosphere(3);
  std::vector<Eigen::Vector3d> deformed;
  for (const auto& p : ico.points)
  {
    deformed.emplace_back(p.x() * (1.0 + 0.3 * p.z()),
      0.7 * p.y() + 0.2 * p.x() * p.x(),
      p.z() + 0.25 * std::sin(3 * p.x()));
  }
  const auto triangles = ico.triangles();
  const MapMetrics m = measureMap(ico.points, deformed, triangles);

  auto unitArea = [&](std::vector<Eigen::Vector3d> x)
  {
    double area = 0.0;
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (const auto& t : triangles)
    {
      const double a = 0.5 * (x[t[1]] - x[t[0]]).cross(x[t[2]] - x[t[0]]).norm();
      area += a;
      c += a * (x[t[0]] + x[t[1]] + x[t[2]]) / 3.0;
    }
    for (auto& p : x)
    {
      p = (p - c / area) / std::sqrt(area);
    }
    return x;
  };
  const auto P = unitArea(ico.points), Q = unitArea(deformed);
  double sd = 0.0;
  for (std::size_t f = 0; f < triangles.size(); ++f)
  {
    const auto& t = triangles[f];
    Eigen::Matrix<double, 3, 2> EP, EQ;
    EP << P[t[1]] - P[t[0]], P[t[2]] - P[t[0]];
    EQ << Q[t[1]] - Q[t[0]], Q[t[2]] - Q[t[0]];
    const Eigen::Matrix<double, 2, 3> pinv = (EP.transpose() * EP).inverse() * EP.transpose();
    const Eigen::Matrix3d J3 = EQ * pinv;
    const Eigen::Vector3d s = Eigen::JacobiSVD<Eigen::Matrix3d>(J3).singularValues();
    const double aP = 0.5 * EP.col(0).cross(EP.col(1)).norm();
    const double aQ = 0.5 * EQ.col(0).cross(EQ.col(1)).norm();
    sd += 0.25 * (aQ * (s[0] * s[0] + s[1] * s[1]) + aP * (1 / (s[0] * s[0]) + 1 / (s[1] * s[1])));
    EXPECT_NEAR(m.s1[f], s[0], 1e-9 * s[0]);
    EXPECT_NEAR(m.s2[f], s[1], 1e-9 * s[0]);
  }
  EXPECT_NEAR(m.symmetricDirichlet, sd, 1e-3 * sd);  // the issue asks for 0.1 %
  EXPECT_NEAR(m.symmetricDirichlet, sd, 1e-10 * sd); // and it is far closer
  EXPECT_GT(m.symmetricDirichlet, 1.01);
}
