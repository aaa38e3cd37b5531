#include "geometry/SphereLocator.h"
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

TEST(HalfedgeMesh, FaceNeighboursAreTheTrianglesNeighbours)
{
  HalfedgeMesh mesh = toHalfedgeMesh(makeIcosphere(2));
  EXPECT_EQ(faceNeighbours(mesh), triangleNeighbours(faceTriangles(mesh)));
  // After edits, with deleted faces not yet collected and after collecting.
  mesh.request_vertex_status();
  mesh.request_edge_status();
  mesh.request_face_status();
  int collapsed = 0;
  for (const auto eh : mesh.edges())
  {
    const auto h = mesh.halfedge_handle(eh, 0);
    if (collapsed < 10 && !mesh.status(eh).deleted() && mesh.is_collapse_ok(h) &&
      mesh.valence(mesh.to_vertex_handle(mesh.next_halfedge_handle(h))) > 4 &&
      mesh.valence(
        mesh.to_vertex_handle(mesh.next_halfedge_handle(mesh.opposite_halfedge_handle(h)))) > 4)
    {
      mesh.collapse(h);
      ++collapsed;
    }
  }
  ASSERT_EQ(collapsed, 10);
  EXPECT_EQ(faceNeighbours(mesh), triangleNeighbours(faceTriangles(mesh)));
  mesh.garbage_collection();
  EXPECT_EQ(faceNeighbours(mesh), triangleNeighbours(faceTriangles(mesh)));
  for (const auto& n : faceNeighbours(mesh))
  {
    EXPECT_TRUE(n[0] >= 0 && n[1] >= 0 && n[2] >= 0);
  }
}
