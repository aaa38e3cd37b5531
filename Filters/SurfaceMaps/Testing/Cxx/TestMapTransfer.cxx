// Points carried between the inputs of a computed map (MapTransfer.h).
#include "MapTestInputs.h"
#include "geometry/SphereLocator.h"
#include "map/MapTransfer.h"
#include "map/SurfaceMap.h"

#include <gtest/gtest.h>

#include <stdexcept>

using namespace surfacemaps;
using namespace surfacemaps::testing;

namespace
{

// Three inputs of different sizes, a short schedule: about a second.
struct ThreeInputMap
{
  std::vector<MapInput> inputs{ icosphereInput(2, 0.0, { 1.0, 1.0, 1.0 }, 0.3),
    icosphereInput(3, 0.3, { 1.4, 1.0, 0.8 }),
    icosphereInput(2, -0.2, { 0.8, 1.2, 1.0 }, 0.2) };
  SurfaceMapResult map;

  ThreeInputMap()
  {
    SurfaceMapOptions options;
    options.coarseIterations = 3;
    options.fineIterations = 4;
    options.targetError = 5e-3;
    options.pairs = PairScheme::All;
    this->map = computeSurfaceMap(this->inputs, options);
  }
};

const ThreeInputMap& threeInputMap()
{
  static const ThreeInputMap m;
  return m;
}

double boundingBoxDiagonal(const std::vector<Eigen::Vector3d>& points)
{
  Eigen::Vector3d lo = points[0], hi = points[0];
  for (const Eigen::Vector3d& p : points)
  {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return (hi - lo).norm();
}

// The sphere point of a surface point of input i: the same barycentric
// coordinates on the chord triangle of f_i, normalised (DESIGN.md 1.1).
Eigen::Vector3d spherePoint(const SurfaceMapResult& map,
  const MapInput& input,
  int i,
  const SurfacePoint& p)
{
  return evaluateSurfacePoint(map.inputSpherePositions[i], input.mesh.triangles(), p).normalized();
}

} // namespace

TEST(MapTransfer, MappedVerticesAreTheTransferredPointsOnTheTarget)
{
  const ThreeInputMap& m = threeInputMap();
  for (int j = 0; j < 3; ++j)
  {
    SCOPED_TRACE("input " + std::to_string(j));
    const std::vector<SurfacePoint> points = transferVertices(m.map, m.inputs, 0, j);
    const std::vector<Eigen::Vector3d> mapped = mappedVertices(m.map, m.inputs, 0, j);
    ASSERT_EQ(points.size(), m.inputs[0].mesh.points.size());
    ASSERT_EQ(mapped.size(), points.size());
    const auto triangles = m.inputs[j].mesh.triangles();
    for (std::size_t w = 0; w < points.size(); ++w)
    {
      ASSERT_GE(points[w].triangle, 0);
      ASSERT_LT(points[w].triangle, static_cast<int>(triangles.size()));
      EXPECT_NEAR(points[w].barycentric.sum(), 1.0, 1e-12);
      EXPECT_GE(points[w].barycentric.minCoeff(), -1e-9);
      // Bit for bit: the filter's "input 0 on input j" goes through transferVertices too.
      ASSERT_EQ(evaluateSurfacePoint(m.inputs[j].mesh.points, triangles, points[w]), mapped[w]);
    }
  }
}

TEST(MapTransfer, IdentityIsExactAtTheVertices)
{
  const ThreeInputMap& m = threeInputMap();
  const std::vector<SurfacePoint> points = transferVertices(m.map, m.inputs, 1, 1);
  const auto triangles = m.inputs[1].mesh.triangles();
  ASSERT_EQ(points.size(), m.inputs[1].mesh.points.size());
  for (std::size_t v = 0; v < points.size(); ++v)
  {
    ASSERT_EQ(evaluateSurfacePoint(m.inputs[1].mesh.points, triangles, points[v]),
      m.inputs[1].mesh.points[v]);
  }
}

TEST(MapTransfer, ThereAndBackReturnsToTheStart)
{
  // Input k's vertices mapped onto input 0 and back. Every stage (locate in a
  // spherical triangulation, the same barycentric coordinates on the chord
  // triangle of another embedding, normalise) is a bijection of the sphere
  // whose inverse is the same stage the other way, so Phi_0k o Phi_k0 is the
  // identity up to rounding, not just up to the piecewise linearity of T (a
  // wrong triangle anywhere would be off by a good part of an edge, ~0.1).
  // Measured: 7e-16 here (diagonal ~3); the bound leaves room for rounding
  // amplified by thin triangles: 1e-10 of the bounding-box diagonal.
  const ThreeInputMap& m = threeInputMap();
  for (int k : { 1, 2 })
  {
    SCOPED_TRACE("input " + std::to_string(k));
    const std::vector<SurfacePoint> onFirst = transferVertices(m.map, m.inputs, k, 0);
    std::vector<Eigen::Vector3d> spherePoints;
    for (const SurfacePoint& p : onFirst)
    {
      spherePoints.push_back(spherePoint(m.map, m.inputs[0], 0, p));
    }
    const auto triangles = m.inputs[k].mesh.triangles();
    const std::vector<SurfacePoint> back = transferPoints(spherePoints,
      m.map.triangles,
      m.map.spherePositions[0],
      m.map.spherePositions[k],
      m.map.inputSpherePositions[k],
      triangles);
    const double tolerance = 1e-10 * boundingBoxDiagonal(m.inputs[k].mesh.points);
    double largest = 0.0;
    for (std::size_t v = 0; v < back.size(); ++v)
    {
      const Eigen::Vector3d p = evaluateSurfacePoint(m.inputs[k].mesh.points, triangles, back[v]);
      largest = std::max(largest, (p - m.inputs[k].mesh.points[v]).norm());
    }
    EXPECT_LT(largest, tolerance);
    // Not trivially: the intermediate points lie elsewhere, on input 0.
    double moved = 0.0;
    const auto first = m.inputs[0].mesh.triangles();
    for (std::size_t v = 0; v < onFirst.size(); ++v)
    {
      moved = std::max(moved,
        (evaluateSurfacePoint(m.inputs[0].mesh.points, first, onFirst[v]) -
          m.inputs[k].mesh.points[v])
          .norm());
    }
    EXPECT_GT(moved, 0.05);
  }
}

TEST(MapTransfer, PointsLandWhereTheSphereMapSays)
{
  // Independently of the locators: psi_12(f_1(v)) by brute force over T's
  // triangles on sphere 1, compared with the sphere point of v's landing point.
  const ThreeInputMap& m = threeInputMap();
  const auto& g1 = m.map.spherePositions[1];
  const auto& g2 = m.map.spherePositions[2];
  const std::vector<SurfacePoint> points = transferVertices(m.map, m.inputs, 1, 2);
  for (std::size_t v = 0; v < points.size(); ++v)
  {
    const Eigen::Vector3d& p = m.map.inputSpherePositions[1][v];
    Eigen::Vector3d expected = Eigen::Vector3d::Zero();
    double best = -1.0;
    for (const auto& t : m.map.triangles)
    {
      if (p.dot(g1[t[0]] + g1[t[1]] + g1[t[2]]) <= 0.0)
      {
        continue; // the far side of the sphere
      }
      const auto w = SphereLocator::barycentric(p, g1[t[0]], g1[t[1]], g1[t[2]]);
      const double smallest = std::min({ w[0], w[1], w[2] });
      if (smallest > best)
      {
        best = smallest;
        expected = (w[0] * g2[t[0]] + w[1] * g2[t[1]] + w[2] * g2[t[2]]).normalized();
      }
    }
    ASSERT_GE(best, -1e-12) << "vertex " << v << " in no triangle of T";
    ASSERT_LT((spherePoint(m.map, m.inputs[2], 2, points[v]) - expected).norm(), 1e-9)
      << "vertex " << v;
  }
}

TEST(MapTransfer, InconsistentArgumentsAreRejected)
{
  const ThreeInputMap& m = threeInputMap();
  const auto triangles = m.inputs[1].mesh.triangles();
  const std::vector<Eigen::Vector3d> points{ Eigen::Vector3d::UnitZ() };
  MapTransferOptions options;
  options.startTriangles = { 0, 1 }; // not one per T vertex
  EXPECT_THROW(transferPoints(points,
                 m.map.triangles,
                 m.map.spherePositions[0],
                 m.map.spherePositions[1],
                 m.map.inputSpherePositions[1],
                 triangles,
                 options),
    std::invalid_argument);
  std::vector<Eigen::Vector3d> shorter = m.map.spherePositions[1];
  shorter.pop_back();
  EXPECT_THROW(transferPoints(points,
                 m.map.triangles,
                 m.map.spherePositions[0],
                 shorter,
                 m.map.inputSpherePositions[1],
                 triangles),
    std::invalid_argument);
  EXPECT_THROW(transferVertices(m.map, m.inputs, 0, 3), std::invalid_argument);
  EXPECT_THROW(transferVertices(m.map, m.inputs, -1, 0), std::invalid_argument);
}

TEST(MapTransfer, CornerValuesAreInterpolatedInTheirTriangle)
{
  // Two triangles sharing a vertex with different values there (a seam).
  const std::vector<Eigen::Vector2d> corners{
    { 0, 0 }, { 1, 0 }, { 0, 1 }, { 5, 5 }, { 6, 5 }, { 5, 6 }
  };
  SurfacePoint p;
  p.triangle = 1;
  p.barycentric = Eigen::Vector3d(0.2, 0.3, 0.5);
  EXPECT_TRUE(evaluateCornerValues(corners, p).isApprox(Eigen::Vector2d(5.3, 5.5), 1e-15));
  p.triangle = 0;
  EXPECT_TRUE(evaluateCornerValues(corners, p).isApprox(Eigen::Vector2d(0.3, 0.5), 1e-15));
}
