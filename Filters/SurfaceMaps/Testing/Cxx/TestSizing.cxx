#include "mesh/Primitives.h"
#include "geometry/Sizing.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <stdexcept>

using namespace surfacemaps;

namespace
{

PolygonMesh scaled(PolygonMesh mesh, double r)
{
  for (auto& p : mesh.points)
  {
    p *= r;
  }
  return mesh;
}

// The formula of DESIGN.md 1.7, written out independently of the engine.
double dunyach(double kappa, double eps)
{
  return std::sqrt(6.0 * eps / kappa - 3.0 * eps * eps);
}

// Closed cube [0, n]^3 whose faces are n x n grids of split squares. Vertices
// strictly inside a face are flat; `kind` tells face interior (0), cube edge
// (1) and cube corner (2) apart.
PolygonMesh subdividedCube(int n, std::vector<int>& kind)
{
  PolygonMesh mesh;
  std::map<std::array<int, 3>, int> index;
  auto vertex = [&](std::array<int, 3> x)
  {
    auto it = index.find(x);
    if (it != index.end())
    {
      return it->second;
    }
    int boundaryCoordinates = 0;
    for (int c : x)
    {
      boundaryCoordinates += (c == 0 || c == n) ? 1 : 0;
    }
    kind.push_back(boundaryCoordinates - 1);
    mesh.points.emplace_back(x[0], x[1], x[2]);
    index.emplace(x, static_cast<int>(mesh.points.size()) - 1);
    return static_cast<int>(mesh.points.size()) - 1;
  };
  for (int a = 0; a < 3; ++a)
  {
    const int b = (a + 1) % 3, c = (a + 2) % 3;
    for (int side : { 0, n })
    {
      for (int u = 0; u < n; ++u)
      {
        for (int v = 0; v < n; ++v)
        {
          int q[4];
          const int corners[4][2] = { { u, v }, { u + 1, v }, { u + 1, v + 1 }, { u, v + 1 } };
          for (int k = 0; k < 4; ++k)
          {
            std::array<int, 3> x;
            x[a] = side;
            x[b] = corners[k][0];
            x[c] = corners[k][1];
            q[k] = vertex(x);
          }
          // e_b x e_c = e_a: counter-clockwise seen from outside on the far side.
          if (side == n)
          {
            mesh.addFace({ q[0], q[1], q[2] });
            mesh.addFace({ q[0], q[2], q[3] });
          }
          else
          {
            mesh.addFace({ q[0], q[2], q[1] });
            mesh.addFace({ q[0], q[3], q[2] });
          }
        }
      }
    }
  }
  return mesh;
}

bool allFinite(const std::vector<double>& values)
{
  return std::all_of(values.begin(), values.end(), [](double x) { return std::isfinite(x); });
}

} // namespace

TEST(Sizing, SphereCurvatureIsInverseRadius)
{
  const double r = 2.5;
  const PolygonMesh sphere = scaled(makeIcosphere(3), r);
  const std::vector<double> kappa = maxAbsCurvature(sphere.points, sphere.triangles());
  ASSERT_EQ(kappa.size(), sphere.points.size());
  for (std::size_t v = 0; v < kappa.size(); ++v)
  {
    EXPECT_NEAR(kappa[v] * r, 1.0, 1e-3) << "vertex " << v;
  }
}

TEST(Sizing, TorusCurvatureIsInverseMinorRadius)
{
  // Principal curvatures 1/r and cos(w)/(R + r cos(w)); with R = 1, r = 0.35
  // the first dominates everywhere, while K changes sign: this exercises the
  // H +- sqrt(H^2 - K) split rather than |H| alone.
  const double r = 0.35;
  const PolygonMesh torus = makeTorus(128, 48, 1.0, r);
  const std::vector<double> kappa = maxAbsCurvature(torus.points, torus.triangles());
  for (std::size_t v = 0; v < kappa.size(); ++v)
  {
    EXPECT_NEAR(kappa[v] * r, 1.0, 2e-3) << "vertex " << v;
  }
}

TEST(Sizing, FlatFacesHaveNoCurvature)
{
  std::vector<int> kind;
  const PolygonMesh cube = subdividedCube(6, kind);
  const std::vector<double> kappa = maxAbsCurvature(cube.points, cube.triangles());
  int flat = 0, edges = 0;
  for (std::size_t v = 0; v < kappa.size(); ++v)
  {
    if (kind[v] == 0)
    {
      ++flat;
      EXPECT_LT(kappa[v], 1e-6) << "vertex " << v;
    }
    else
    {
      ++edges;
      // A 90 degree crease over one grid cell: curvature of order 1.
      EXPECT_GT(kappa[v], 0.5) << "vertex " << v;
    }
  }
  EXPECT_EQ(flat, 6 * 5 * 5);
  EXPECT_EQ(edges, 12 * 5 + 8);
}

TEST(Sizing, SphereSizingMatchesFormula)
{
  const double r = 0.1;
  SizingOptions options;
  options.targetError = 1e-3;
  const PolygonMesh sphere = scaled(makeIcosphere(3), r);
  const std::vector<double> kappa = maxAbsCurvature(sphere.points, sphere.triangles());
  const std::vector<double> sizing = curvatureSizing(sphere.points, sphere.triangles(), options);
  ASSERT_EQ(sizing.size(), sphere.points.size());
  const double exact = dunyach(1.0 / r, options.targetError);
  ASSERT_GT(exact, options.minEdgeLength);
  ASSERT_LT(exact, options.maxEdgeLength);
  for (std::size_t v = 0; v < sizing.size(); ++v)
  {
    EXPECT_NEAR(sizing[v], dunyach(kappa[v], options.targetError), 1e-12 * exact);
    EXPECT_NEAR(sizing[v], exact, 1e-3 * exact) << "vertex " << v;
  }
}

TEST(Sizing, CurvatureAboveTwoOverEpsGivesMinimum)
{
  // kappa = 1e4 > 2 / eps = 2e3: a feature smaller than the tolerance.
  SizingOptions options;
  options.targetError = 1e-3;
  options.minEdgeLength = 1e-6;
  const PolygonMesh sphere = scaled(makeIcosphere(2), 1e-4);
  const std::vector<double> sizing = curvatureSizing(sphere.points, sphere.triangles(), options);
  for (double s : sizing)
  {
    EXPECT_EQ(s, options.minEdgeLength);
  }
}

TEST(Sizing, JustBelowTwoOverEpsGivesFormulaValue)
{
  // kappa eps ~ 1.6 < 2: the formula is defined and gives about 0.87 eps, far
  // above the minimum, so the sizing must not jump to the minimum early.
  SizingOptions options;
  options.targetError = 1e-3;
  options.minEdgeLength = 1e-6;
  const PolygonMesh sphere = scaled(makeIcosphere(3), 1.0 / 1600.0);
  const std::vector<double> kappa = maxAbsCurvature(sphere.points, sphere.triangles());
  const std::vector<double> sizing = curvatureSizing(sphere.points, sphere.triangles(), options);
  for (std::size_t v = 0; v < sizing.size(); ++v)
  {
    ASSERT_LT(kappa[v], 2.0 / options.targetError);
    EXPECT_NEAR(sizing[v], dunyach(kappa[v], options.targetError), 1e-9 * options.targetError);
    EXPECT_GT(sizing[v], 100 * options.minEdgeLength);
  }
}

TEST(Sizing, SmallFormulaValueClampsToMinimum)
{
  // Formula ~ 2.4e-2 on a sphere of radius 0.1; a larger minimum wins.
  SizingOptions options;
  options.minEdgeLength = 0.05;
  const PolygonMesh sphere = scaled(makeIcosphere(2), 0.1);
  for (double s : curvatureSizing(sphere.points, sphere.triangles(), options))
  {
    EXPECT_EQ(s, 0.05);
  }
}

TEST(Sizing, LargeSphereClampsToMaximum)
{
  // kappa = 1e-7: the formula gives sqrt(6e4) ~ 245 > 100.
  const double r = 1e7;
  const PolygonMesh sphere = scaled(makeIcosphere(3), r);
  const std::vector<double> kappa = maxAbsCurvature(sphere.points, sphere.triangles());
  for (double k : kappa)
  {
    EXPECT_NEAR(k * r, 1.0, 1e-3);
  }
  for (double s : curvatureSizing(sphere.points, sphere.triangles()))
  {
    EXPECT_EQ(s, 100.0);
  }
}

TEST(Sizing, FlatFacesGetMaximum)
{
  std::vector<int> kind;
  const PolygonMesh cube = subdividedCube(6, kind);
  SizingOptions options;
  options.targetError = 0.01;
  options.minEdgeLength = 0.01;
  options.maxEdgeLength = 3.0;
  const std::vector<double> sizing = curvatureSizing(cube.points, cube.triangles(), options);
  for (std::size_t v = 0; v < sizing.size(); ++v)
  {
    if (kind[v] == 0)
    {
      EXPECT_EQ(sizing[v], 3.0) << "vertex " << v;
    }
    else
    {
      EXPECT_LT(sizing[v], 1.0) << "vertex " << v;
    }
  }
}

TEST(Sizing, UnreferencedVertexHasZeroCurvatureAndMaximumSize)
{
  PolygonMesh sphere = makeIcosphere(1);
  sphere.points.emplace_back(5.0, 0.0, 0.0);
  const std::vector<double> kappa = maxAbsCurvature(sphere.points, sphere.triangles());
  EXPECT_EQ(kappa.back(), 0.0);
  const std::vector<double> sizing = curvatureSizing(sphere.points, sphere.triangles());
  EXPECT_EQ(sizing.back(), 100.0);
  EXPECT_LT(sizing.front(), 100.0);
}

TEST(Sizing, ObtuseTrianglesKeepSphereCurvature)
{
  // Tangential jitter on a sphere makes many obtuse triangles. Mixed areas
  // (Meyer et al.) are less exact there than circumcentric ones but must stay
  // positive and unbiased: a swapped 1/2 : 1/4 split moves the median by 3 %.
  const PolygonMesh ico = makeIcosphere(3);
  std::vector<Eigen::Vector3d> points = ico.points;
  std::mt19937 random(7);
  std::uniform_real_distribution<double> jitter(-0.35, 0.35);
  const double spacing = 1.1 / 8.0; // About the edge length of level 3.
  for (auto& p : points)
  {
    const Eigen::Vector3d t1 = p.unitOrthogonal(), t2 = p.cross(t1);
    p = (p + spacing * (jitter(random) * t1 + jitter(random) * t2)).normalized();
  }
  const std::vector<std::array<int, 3>> triangles = ico.triangles();
  int obtuse = 0;
  for (const auto& t : triangles)
  {
    for (int c = 0; c < 3; ++c)
    {
      const Eigen::Vector3d& p = points[t[c]];
      obtuse += (points[t[(c + 1) % 3]] - p).dot(points[t[(c + 2) % 3]] - p) < 0.0 ? 1 : 0;
    }
  }
  ASSERT_GT(obtuse, static_cast<int>(triangles.size()) / 10);
  std::vector<double> kappa = maxAbsCurvature(points, triangles);
  ASSERT_TRUE(allFinite(kappa));
  for (double k : kappa)
  {
    EXPECT_GT(k, 0.5);
  }
  std::nth_element(kappa.begin(), kappa.begin() + kappa.size() / 2, kappa.end());
  EXPECT_NEAR(kappa[kappa.size() / 2], 1.0, 0.02);
}

TEST(Sizing, NearlyFlatTriangleKeepsNeighboursCurved)
{
  // One sphere triangle flattened to an angle near 180 degrees: the
  // circumcentric Voronoi areas of its other two vertices turn negative
  // (curvature 0, i.e. the coarsest sizing); mixed areas stay positive.
  for (double t : { 0.01, 1e-12 })
  {
    PolygonMesh sphere = makeIcosphere(3);
    const std::array<int, 3> f = sphere.triangles()[0];
    auto& p = sphere.points;
    p[f[1]] = (1.0 - t) * 0.5 * (p[f[0]] + p[f[2]]) + t * p[f[1]];
    const std::vector<double> kappa = maxAbsCurvature(sphere.points, sphere.triangles());
    for (std::size_t v = 0; v < kappa.size(); ++v)
    {
      EXPECT_GT(kappa[v], 0.3) << "t " << t << ", vertex " << v;
      EXPECT_LT(kappa[v], 4.0) << "t " << t << ", vertex " << v;
    }
  }
}

TEST(Sizing, DegenerateTrianglesGiveNoNaN)
{
  // Vertex 4 of the octahedron moved onto the midpoint of edge 0-2 (a
  // zero-area triangle, with slivers around it), then onto vertex 0.
  for (const Eigen::Vector3d& moved : { Eigen::Vector3d(0.5, 0.5, 0.0),
         Eigen::Vector3d(1.0, 0.0, 0.0),
         Eigen::Vector3d(0.5, 0.5, 1e-12) })
  {
    PolygonMesh mesh = makeOctahedron();
    mesh.points[4] = moved;
    const std::vector<double> kappa = maxAbsCurvature(mesh.points, mesh.triangles());
    EXPECT_TRUE(allFinite(kappa));
    const SizingOptions options;
    for (double s : curvatureSizing(mesh.points, mesh.triangles(), options))
    {
      EXPECT_TRUE(std::isfinite(s));
      EXPECT_GE(s, options.minEdgeLength);
      EXPECT_LE(s, options.maxEdgeLength);
    }
  }
}

TEST(Sizing, RejectsBadInput)
{
  const PolygonMesh sphere = makeIcosphere(1);
  std::vector<std::array<int, 3>> triangles = sphere.triangles();
  triangles[3][1] = static_cast<int>(sphere.points.size());
  EXPECT_THROW(maxAbsCurvature(sphere.points, triangles), std::invalid_argument);
  triangles[3][1] = -1;
  EXPECT_THROW(maxAbsCurvature(sphere.points, triangles), std::invalid_argument);

  SizingOptions options;
  options.targetError = 0.0;
  EXPECT_THROW(curvatureSizing(sphere.points, sphere.triangles(), options), std::invalid_argument);
  options = SizingOptions();
  options.minEdgeLength = 0.0;
  EXPECT_THROW(curvatureSizing(sphere.points, sphere.triangles(), options), std::invalid_argument);
  options = SizingOptions();
  options.minEdgeLength = 2.0;
  options.maxEdgeLength = 1.0;
  EXPECT_THROW(curvatureSizing(sphere.points, sphere.triangles(), options), std::invalid_argument);
}
