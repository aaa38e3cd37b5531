#include "mesh/HalfedgeMesh.h"

#include <stdexcept>
#include <string>

namespace surfacemaps
{

HalfedgeMesh toHalfedgeMesh(const PolygonMesh& polygons)
{
  HalfedgeMesh mesh;
  mesh.reserve(polygons.points.size(), 3 * polygons.numberOfFaces() / 2, polygons.numberOfFaces());
  for (const Eigen::Vector3d& p : polygons.points)
  {
    mesh.add_vertex(HalfedgeMesh::Point(p.x(), p.y(), p.z()));
  }
  for (std::size_t f = 0; f < polygons.numberOfFaces(); ++f)
  {
    if (polygons.faceSize(f) != 3)
    {
      throw std::invalid_argument("face " + std::to_string(f) + " is not a triangle");
    }
    const int* t = polygons.face(f);
    const HalfedgeMesh::FaceHandle fh =
      mesh.add_face(mesh.vertex_handle(t[0]), mesh.vertex_handle(t[1]), mesh.vertex_handle(t[2]));
    if (!fh.is_valid())
    {
      throw std::invalid_argument("face " + std::to_string(f) + " makes the mesh non-manifold");
    }
  }
  return mesh;
}

PolygonMesh toPolygonMesh(const HalfedgeMesh& mesh)
{
  PolygonMesh polygons;
  polygons.points.reserve(mesh.n_vertices());
  for (const auto vh : mesh.vertices())
  {
    const HalfedgeMesh::Point& p = mesh.point(vh);
    polygons.points.emplace_back(p[0], p[1], p[2]);
  }
  polygons.faceVertices.reserve(3 * mesh.n_faces());
  for (const auto& t : faceTriangles(mesh))
  {
    polygons.addFace({ t[0], t[1], t[2] });
  }
  return polygons;
}

std::vector<std::array<int, 3>> faceTriangles(const HalfedgeMesh& mesh)
{
  std::vector<std::array<int, 3>> triangles;
  triangles.reserve(mesh.n_faces());
  for (const auto fh : mesh.faces())
  {
    auto fv = mesh.cfv_iter(fh);
    const int a = fv->idx();
    const int b = (++fv)->idx();
    const int c = (++fv)->idx();
    triangles.push_back({ a, b, c });
  }
  return triangles;
}

std::vector<std::array<int, 3>> faceNeighbours(const HalfedgeMesh& mesh)
{
  // Entries of faceTriangles: faces in order, deleted ones skipped.
  std::vector<int> entry(mesh.n_faces(), -1);
  int count = 0;
  for (const auto fh : mesh.faces())
  {
    entry[fh.idx()] = count++;
  }
  std::vector<std::array<int, 3>> neighbours(count, { -1, -1, -1 });
  for (const auto fh : mesh.faces())
  {
    auto fv = mesh.cfv_iter(fh);
    const std::array<OpenMesh::VertexHandle, 3> corners{ *fv, *++fv, *++fv };
    for (const auto h : mesh.fh_range(fh))
    {
      const auto from = mesh.from_vertex_handle(h), to = mesh.to_vertex_handle(h);
      int k = 0;
      while (corners[k] == from || corners[k] == to)
      {
        ++k;
      }
      const auto across = mesh.opposite_face_handle(h);
      neighbours[entry[fh.idx()]][k] = across.is_valid() ? entry[across.idx()] : -1;
    }
  }
  return neighbours;
}

} // namespace surfacemaps
