#include "mesh/MeshValidation.h"
#include "mesh/Primitives.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace surfacemaps;

namespace
{
// True if exactly one defect was reported and it contains `part`.
::testing::AssertionResult onlyDefect(const MeshValidationResult& r, const std::string& part)
{
  std::string all;
  for (const auto& d : r.defects)
  {
    all += "[" + d + "] ";
  }
  if (r.defects.size() != 1 || r.defects[0].find(part) == std::string::npos)
  {
    return ::testing::AssertionFailure() << "expected only '" << part << "', got " << all;
  }
  return ::testing::AssertionSuccess();
}

PolygonMesh glued(const PolygonMesh& a, const PolygonMesh& b, const Eigen::Vector3d& shift)
{
  PolygonMesh m = a;
  const int offset = static_cast<int>(a.points.size());
  for (const auto& p : b.points)
  {
    m.points.push_back(p + shift);
  }
  for (std::size_t f = 0; f < b.numberOfFaces(); ++f)
  {
    m.addFace({ b.face(f)[0] + offset, b.face(f)[1] + offset, b.face(f)[2] + offset });
  }
  return m;
}
} // namespace

TEST(MeshValidation, IcosphereIsValidAndMeasured)
{
  const MeshValidationResult r = validateMesh(makeIcosphere(2));
  EXPECT_TRUE(r.valid());
  const MeshStatistics& s = r.statistics;
  EXPECT_EQ(s.vertices, 162);
  EXPECT_EQ(s.faces, 320);
  EXPECT_EQ(s.edges, 480);
  EXPECT_EQ(s.genus, 0);
  EXPECT_EQ(s.components, 1);
  EXPECT_EQ(s.boundaryEdges, 0);
  EXPECT_EQ(s.orientation, 1);
  EXPECT_NEAR(s.area, 4 * M_PI, 0.3); // inscribed: a little less than the sphere
  EXPECT_NEAR(s.boundingBoxDiagonal, 2 * std::sqrt(3.0), 0.3);
  EXPECT_GT(s.minAngle, 50.0);
  EXPECT_LE(s.minAngle, s.meanMinAngle);
}

TEST(MeshValidation, TetrahedronAngles)
{
  const MeshValidationResult r = validateMesh(makeTetrahedron());
  ASSERT_TRUE(r.valid());
  EXPECT_NEAR(r.statistics.minAngle, 60.0, 1e-9);
  EXPECT_NEAR(r.statistics.meanMinAngle, 60.0, 1e-9);
}

TEST(MeshValidation, InwardOrientationIsReportedNotRejected)
{
  PolygonMesh m = makeOctahedron();
  for (std::size_t f = 0; f < m.numberOfFaces(); ++f)
  {
    std::swap(m.faceVertices[m.faceOffsets[f] + 1], m.faceVertices[m.faceOffsets[f] + 2]);
  }
  const MeshValidationResult r = validateMesh(m);
  EXPECT_TRUE(r.valid());
  EXPECT_EQ(r.statistics.orientation, -1);
}

TEST(MeshValidation, Empty)
{
  EXPECT_TRUE(onlyDefect(validateMesh(PolygonMesh()), "contains no vertices"));
  PolygonMesh points;
  points.points = { { 0, 0, 0 } };
  EXPECT_TRUE(onlyDefect(validateMesh(points), "contains no triangles"));
}

TEST(MeshValidation, PillowOfTwoTrianglesIsNoSurface)
{
  PolygonMesh pillow;
  pillow.points = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 } };
  pillow.addFace({ 0, 1, 2 });
  pillow.addFace({ 0, 2, 1 });
  const MeshValidationResult r = validateMesh(pillow);
  EXPECT_TRUE(onlyDefect(r, "has only 2 triangles; a closed surface needs at least 4"));
  EXPECT_EQ(r.statistics.genus, 0);
}

TEST(MeshValidation, Torus)
{
  const MeshValidationResult r = validateMesh(makeTorus(12, 6));
  EXPECT_TRUE(onlyDefect(r, "has genus 1"));
  EXPECT_EQ(r.statistics.genus, 1);
}

TEST(MeshValidation, NonTriangles)
{
  PolygonMesh m;
  m.points = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 } };
  m.addFace({ 0, 1, 2, 3 });
  m.addFace({ 0, 3, 2, 1 });
  EXPECT_TRUE(
    onlyDefect(validateMesh(m), "2 of 2 polygons are not triangles (first: face 0 with 4"));
}

TEST(MeshValidation, NonPolygonCells)
{
  PolygonMesh m = makeTetrahedron();
  m.nonPolygonCells = 2;
  EXPECT_TRUE(onlyDefect(validateMesh(m), "2 cells that are not polygons"));
}

TEST(MeshValidation, BadIndexAndRepeatedVertex)
{
  PolygonMesh m = makeTetrahedron();
  m.addFace({ 0, 1, 7 });
  EXPECT_TRUE(onlyDefect(validateMesh(m), "1 face corner referring to missing vertices"));
  PolygonMesh n = makeTetrahedron();
  n.addFace({ 0, 1, 1 });
  EXPECT_TRUE(onlyDefect(validateMesh(n), "using the same vertex twice (first: face 4)"));
}

TEST(MeshValidation, NonFiniteVertex)
{
  PolygonMesh m = makeOctahedron();
  m.points[4].x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(onlyDefect(validateMesh(m), "non-finite coordinates (first: vertex 4"));
  m.points[4].x() = std::numeric_limits<double>::infinity();
  EXPECT_TRUE(onlyDefect(validateMesh(m), "non-finite coordinates (first: vertex 4"));
}

TEST(MeshValidation, UnusedVertex)
{
  PolygonMesh m = makeOctahedron();
  m.points.emplace_back(5, 5, 5);
  EXPECT_TRUE(onlyDefect(validateMesh(m), "1 vertex not used by any triangle (first: vertex 6)"));
}

TEST(MeshValidation, DuplicateVertexPositions)
{
  // Two coincident copies of a tetrahedron: every vertex has a twin at the
  // same position (the surface passes through one point twice).
  PolygonMesh m = glued(makeTetrahedron(), makeTetrahedron(), Eigen::Vector3d(0, 0, 0));
  const MeshValidationResult r = validateMesh(m);
  ASSERT_FALSE(r.valid());
  EXPECT_NE(
    r.defects[0].find("4 duplicate vertices (first: vertices 3 and 7 both at"), std::string::npos)
    << r.defects[0];
}

TEST(MeshValidation, ZeroAreaTriangle)
{
  // Tetrahedron a, c, d, e with edge a-c split at its midpoint b and edge b-d
  // flipped: triangle (a, b, c) is flat, everything else is fine.
  PolygonMesh m;
  m.points = { { 0, 0, 0 }, { 1, 0, 0 }, { 2, 0, 0 }, { 1, 1.5, 0.5 }, { 1, -0.5, 1.5 } };
  for (auto t : { std::array<int, 3>{ 0, 1, 2 },
         { 0, 2, 3 },
         { 2, 1, 4 },
         { 1, 0, 4 },
         { 0, 3, 4 },
         { 2, 4, 3 } })
  {
    m.addFace(t.begin(), t.end());
  }
  EXPECT_TRUE(onlyDefect(validateMesh(m), "1 zero-area triangle (first: face 0, vertices 0 1 2"));
}

TEST(MeshValidation, OpenMesh)
{
  PolygonMesh m = makeIcosphere(1);
  m.faceVertices.resize(m.faceVertices.size() - 3);
  m.faceOffsets.pop_back();
  const MeshValidationResult r = validateMesh(m);
  EXPECT_TRUE(onlyDefect(r, "is not closed: 3 boundary edges"));
  EXPECT_EQ(r.statistics.boundaryEdges, 3);
  EXPECT_EQ(r.statistics.genus, -1);
}

TEST(MeshValidation, NonManifoldEdge)
{
  // Two tetrahedra sharing edge 0-1: that edge has four triangles.
  PolygonMesh m = makeTetrahedron();
  m.points.emplace_back(-2, 2, -2);
  m.points.emplace_back(-2, -2, 2);
  for (auto t : { std::array<int, 3>{ 0, 1, 4 }, { 0, 5, 1 }, { 0, 4, 5 }, { 1, 5, 4 } })
  {
    m.addFace(t.begin(), t.end());
  }
  const MeshValidationResult r = validateMesh(m);
  ASSERT_FALSE(r.valid());
  EXPECT_NE(
    r.defects[0].find("1 non-manifold edge shared by more than two triangles (first: edge 0-1)"),
    std::string::npos)
    << r.defects[0];
}

TEST(MeshValidation, NonManifoldVertex)
{
  // Two tetrahedra touching at one vertex (a bow tie).
  PolygonMesh a = makeTetrahedron();
  PolygonMesh m = glued(a, a, Eigen::Vector3d(2, 2, 2) * (1.0 / std::sqrt(3.0)));
  // Weld the second tetrahedron's last vertex onto vertex 0 of the first.
  const int weld = 4 + 3;
  for (int& v : m.faceVertices)
  {
    if (v == weld)
    {
      v = 0;
    }
  }
  m.points.pop_back(); // the welded vertex is the last one and now unused
  const MeshValidationResult r = validateMesh(m);
  EXPECT_TRUE(
    onlyDefect(r, "1 non-manifold vertex where separate fans of triangles meet (first: vertex 0"));
}

TEST(MeshValidation, InconsistentOrientation)
{
  PolygonMesh m = makeOctahedron();
  std::swap(m.faceVertices[1], m.faceVertices[2]);
  EXPECT_TRUE(onlyDefect(validateMesh(m), "is not consistently oriented: 3 edges"));
}

TEST(MeshValidation, TwoComponents)
{
  const MeshValidationResult r =
    validateMesh(glued(makeIcosphere(1), makeIcosphere(1), Eigen::Vector3d(3, 0, 0)));
  EXPECT_TRUE(onlyDefect(r, "has 2 connected components"));
  EXPECT_EQ(r.statistics.components, 2);
}

TEST(MeshValidation, CoordinateBeyondTheDynamicRangeIsNamed)
{
  PolygonMesh mesh = makeIcosphere(1);
  mesh.points[7].x() = 1e308;
  const MeshValidationResult r = validateMesh(mesh);
  ASSERT_FALSE(r.valid());
  EXPECT_NE(r.defects[0].find("outside the valid coordinate range"), std::string::npos)
    << r.defects[0];
  EXPECT_NE(r.defects[0].find("first: vertex 7"), std::string::npos) << r.defects[0];
}

TEST(MeshValidation, ScaledBeyondTheDynamicRangeIsRejected)
{
  PolygonMesh huge = makeIcosphere(1);
  for (auto& p : huge.points)
  {
    p *= 1e200;
  }
  EXPECT_TRUE(onlyDefect(validateMesh(huge), "outside the valid coordinate range"));

  PolygonMesh tiny = makeIcosphere(1);
  for (auto& p : tiny.points)
  {
    p *= 1e-200;
  }
  const MeshValidationResult r = validateMesh(tiny);
  ASSERT_FALSE(r.valid());
  bool named = false;
  for (const auto& d : r.defects)
  {
    named = named || d.find("area") != std::string::npos || d.find("diagonal") != std::string::npos;
  }
  EXPECT_TRUE(named);

  PolygonMesh large = makeIcosphere(1);
  for (auto& p : large.points)
  {
    p *= 1e40; // inside the range: valid
  }
  EXPECT_TRUE(validateMesh(large).valid());
}

TEST(MeshValidation, WideIndexIsNamedWithItsValue)
{
  PolygonMesh mesh = makeIcosphere(1);
  mesh.faceVertices[4] = -1; // as the conversion stores 2^32 + 3
  mesh.wideIndices = 1;
  mesh.firstWideIndexFace = 1;
  mesh.firstWideIndex = 4294967299LL;
  EXPECT_TRUE(onlyDefect(validateMesh(mesh), "face 1 uses vertex index 4294967299"));
}

TEST(MeshValidation, MeasurableOnlySkipsSurfaceChecks)
{
  PolygonMesh mesh = makeIcosphere(1);
  mesh.points[0] = mesh.points[1]; // duplicate vertex, zero-area triangles
  MeshValidationOptions options;
  options.requireSurface = false;
  EXPECT_TRUE(validateMesh(mesh, options).valid());
  EXPECT_FALSE(validateMesh(mesh).valid());

  mesh.points[2].y() = NAN;
  EXPECT_TRUE(onlyDefect(validateMesh(mesh, options), "non-finite coordinates"));
  PolygonMesh pointsOnly;
  pointsOnly.points = makeIcosphere(1).points;
  EXPECT_TRUE(onlyDefect(validateMesh(pointsOnly, options), "contains no triangles"));
}
