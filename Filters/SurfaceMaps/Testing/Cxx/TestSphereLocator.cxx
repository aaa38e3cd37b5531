#include "io/OffReader.h"
#include "geometry/Predicates.h"
#include "mesh/Primitives.h"
#include "embedding/SphereEmbedding.h"
#include "geometry/SphereLocator.h"

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

TEST(SphereLocator, WalkThatCirclesStillFindsTheTriangle)
{
  // Sixteen triangles of a real, certified embedding (the vulcan hand's,
  // where it is strongly compressed), far from Delaunay: from triangle 0 the
  // rotating visibility walk towards p circles through triangles 0-14 around
  // triangle 15, which contains p. Neighbours outside the patch (never
  // crossed) point back to their own triangle.
  const std::vector<Eigen::Vector3d> points{
    { -0.320734287939757, -0.69156867324808724, -0.64719570975220286 },
    { -0.65499177092611183, -0.54270524053998326, -0.52579159551053578 },
    { -0.58536831293138925, -0.5681100553635946, -0.57844178895601317 },
    { -0.53224618964714931, -0.60782177696032413, -0.58929337435515505 },
    { -0.73587796088758395, -0.48895260090586412, -0.46841112363747534 },
    { -0.64329070449964665, -0.5238118651005268, -0.55838893209326412 },
    { -0.75010121289633069, -0.4449849486432686, -0.48922036536963703 },
    { -0.78578006840987724, -0.41671540897962556, -0.45705355485841281 },
    { -0.46407769268964838, -0.63075850407730649, -0.62191285939592122 },
    { -0.66980041748799934, -0.5158255929907043, -0.53412672499013769 },
    { -0.70159423883523853, -0.49791758082147941, -0.50974857208440305 },
    { -0.62080121248433395, -0.55698475678084858, -0.55170085670747326 },
    { -0.37033661523126327, -0.66038279116282306, -0.65325749942503564 },
    { -0.75541931606003188, -0.46062611217135707, -0.46600991589159801 },
    { -0.25816022511082859, -0.69606639208223486, -0.66995886141191296 },
  };
  const std::vector<std::array<int, 3>> triangles{
    { 9, 2, 11 },
    { 5, 2, 9 },
    { 11, 2, 12 },
    { 12, 8, 11 },
    { 14, 8, 12 },
    { 8, 14, 0 },
    { 3, 8, 0 },
    { 4, 8, 3 },
    { 4, 1, 8 },
    { 1, 4, 13 },
    { 7, 1, 13 },
    { 10, 1, 7 },
    { 10, 7, 6 },
    { 10, 6, 9 },
    { 9, 6, 5 },
    { 8, 1, 11 },
  };
  const std::vector<std::array<int, 3>> neighbours{
    { 2, 0, 1 },
    { 0, 14, 1 },
    { 2, 3, 0 },
    { 15, 2, 4 },
    { 3, 4, 5 },
    { 5, 6, 4 },
    { 5, 6, 7 },
    { 6, 7, 8 },
    { 15, 7, 9 },
    { 9, 10, 8 },
    { 9, 10, 11 },
    { 10, 12, 11 },
    { 12, 13, 11 },
    { 14, 13, 12 },
    { 14, 1, 13 },
    { 15, 3, 8 },
  };
  const Eigen::Vector3d p(-0.56512944909529939, -0.58918163854177374, -0.57748913632247167);
  long long visited = 0;
  const SphereLocation location =
    walkOnSphere(p, 0, triangles, neighbours, points.data(), &visited);
  EXPECT_EQ(location.triangle, 15);
  EXPECT_GT(visited, 4 * static_cast<long long>(triangles.size()) + 16); // it did circle
  for (const double w : { location.alpha, location.beta, location.gamma })
  {
    EXPECT_GE(w, 0.0);
    EXPECT_LE(w, 1.0);
  }
  // A point in no triangle of the patch (the opposite side of the sphere).
  EXPECT_THROW(walkOnSphere(-p, 0, triangles, neighbours, points.data()), std::runtime_error);
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
