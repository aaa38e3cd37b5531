#include "mesh/HalfedgeMesh.h"
#include "mesh/MeshValidation.h"
#include "mesh/Primitives.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <set>

using namespace surfacemaps;

namespace
{
// Triangles as vertex triples rotated to start at their smallest index, so
// two meshes compare equal if they have the same oriented triangles.
std::multiset<std::array<int, 3>> orientedTriangles(const PolygonMesh& m)
{
  std::multiset<std::array<int, 3>> set;
  for (std::size_t f = 0; f < m.numberOfFaces(); ++f)
  {
    std::array<int, 3> t{ m.face(f)[0], m.face(f)[1], m.face(f)[2] };
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    set.insert(t);
  }
  return set;
}
} // namespace

TEST(HalfedgeMesh, RoundTripKeepsIndicesAndOrientation)
{
  const PolygonMesh ico = makeIcosphere(2);
  const HalfedgeMesh mesh = toHalfedgeMesh(ico);
  EXPECT_EQ(mesh.n_vertices(), ico.points.size());
  EXPECT_EQ(mesh.n_faces(), ico.numberOfFaces());
  EXPECT_EQ(mesh.n_edges(), 480u);
  for (const auto vh : mesh.vertices())
  {
    EXPECT_FALSE(mesh.is_boundary(vh));
  }
  const PolygonMesh back = toPolygonMesh(mesh);
  ASSERT_EQ(back.points.size(), ico.points.size());
  for (std::size_t i = 0; i < ico.points.size(); ++i)
  {
    EXPECT_EQ(back.points[i], ico.points[i]);
  }
  EXPECT_EQ(orientedTriangles(back), orientedTriangles(ico));
  EXPECT_TRUE(validateMesh(back).valid());
}

TEST(HalfedgeMesh, RejectsNonManifoldInput)
{
  PolygonMesh m = makeTetrahedron();
  m.addFace({ 0, 1, 2 }); // the same oriented triangle twice
  EXPECT_THROW(toHalfedgeMesh(m), std::invalid_argument);
  PolygonMesh quad;
  quad.points = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 } };
  quad.addFace({ 0, 1, 2, 3 });
  EXPECT_THROW(toHalfedgeMesh(quad), std::invalid_argument);
}
