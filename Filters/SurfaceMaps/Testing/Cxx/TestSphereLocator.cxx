#include "OffReader.h"
#include "Predicates.h"
#include "Primitives.h"
#include "SphereEmbedding.h"
#include "SphereLocator.h"

#include <gtest/gtest.h>

#include <random>

using namespace surfacemaps;

namespace
{
const std::string Data = SURFACEMAPS_DATA_DIR;

std::vector<Eigen::Vector3d> randomPoints(int n, unsigned seed)
{
  std::mt19937 rng(seed);
  std::normal_distribution<double> g;
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < n; ++i)
  {
    points.push_back(Eigen::Vector3d(g(rng), g(rng), g(rng)).normalized());
  }
  return points;
}

bool inside(const Eigen::Vector3d& p,
  const Eigen::Vector3d& a,
  const Eigen::Vector3d& b,
  const Eigen::Vector3d& c)
{
  return orient3dOrigin(a, b, p) >= 0 && orient3dOrigin(b, c, p) >= 0 &&
    orient3dOrigin(c, a, p) >= 0;
}

void checkLocations(const std::vector<Eigen::Vector3d>& sphere,
  const std::vector<std::array<int, 3>>& triangles,
  const SphereLocator& locator)
{
  for (const Eigen::Vector3d& p : randomPoints(2000, 9))
  {
    const SphereLocation l = locator.locate(p);
    ASSERT_GE(l.triangle, 0);
    const auto& t = triangles[l.triangle];
    const Eigen::Vector3d &a = sphere[t[0]], &b = sphere[t[1]], &c = sphere[t[2]];
    EXPECT_TRUE(inside(p, a, b, c));
    EXPECT_GE(l.alpha, -1e-12);
    EXPECT_GE(l.beta, -1e-12);
    EXPECT_GE(l.gamma, -1e-12);
    EXPECT_NEAR(l.alpha + l.beta + l.gamma, 1.0, 1e-12);
    const Eigen::Vector3d back = (l.alpha * a + l.beta * b + l.gamma * c).normalized();
    EXPECT_LT((back - p).norm(), 1e-12);
  }
}
} // namespace

TEST(SphereLocator, LocatesOnAnIcosphere)
{
  const PolygonMesh ico = makeIcosphere(3);
  const auto triangles = ico.triangles();
  const SphereLocator locator(ico.points, triangles);
  checkLocations(ico.points, triangles, locator);
  // Vertices themselves are found in one of their triangles.
  for (std::size_t v = 0; v < ico.points.size(); v += 37)
  {
    const SphereLocation l = locator.locate(ico.points[v]);
    const auto& t = triangles[l.triangle];
    EXPECT_TRUE(t[0] == int(v) || t[1] == int(v) || t[2] == int(v));
  }
}

TEST(SphereLocator, LocatesInAnIrregularEmbeddingAndWalksFromAnywhere)
{
  const PolygonMesh blob = readOff(Data + "/blob.off");
  const SphereEmbeddingResult e = embedOnSphere(blob);
  const auto triangles = blob.triangles();
  const SphereLocator locator(e.positions, triangles);
  checkLocations(e.positions, triangles, locator);
  // A walk from a far triangle still ends in the right one.
  const Eigen::Vector3d p = Eigen::Vector3d(0.3, -0.5, 0.8).normalized();
  const int expected = locator.locate(p).triangle;
  EXPECT_EQ(locator.locateFrom(p, 0).triangle, expected);
  EXPECT_EQ(locator.locateFrom(p, static_cast<int>(triangles.size()) - 1).triangle, expected);
}

TEST(SphereLocator, StartingFromTheGridKeepsWalksShort)
{
  const PolygonMesh ico = makeIcosphere(5); // 10 242 vertices
  const SphereLocator locator(ico.points, ico.triangles());
  const auto points = randomPoints(1000, 4);
  for (const auto& p : points)
  {
    locator.locate(p);
  }
  EXPECT_LT(locator.visited(), 10 * static_cast<long long>(points.size()));
}

TEST(SphereLocator, BarycentricFormulaOfTheDesign)
{
  const Eigen::Vector3d a(1, 0, 0), b(0, 1, 0), c(0, 0, 1);
  const auto w = SphereLocator::barycentric(Eigen::Vector3d(1, 1, 1).normalized(), a, b, c);
  EXPECT_NEAR(w[0], 1.0 / 3, 1e-15);
  EXPECT_NEAR(w[1], 1.0 / 3, 1e-15);
  const auto v = SphereLocator::barycentric(a, a, b, c);
  EXPECT_NEAR(v[0], 1.0, 1e-15);
  EXPECT_NEAR(v[2], 0.0, 1e-15);
}
