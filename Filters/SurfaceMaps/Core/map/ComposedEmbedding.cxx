#include "map/ComposedEmbedding.h"

#include "base/Error.h"
#include "geometry/Predicates.h"
#include "geometry/SphereLocator.h"
#include "geometry/SphericalTriangulation.h"

#include <cmath>
#include <set>
#include <string>

namespace surfacemaps
{

namespace
{

/// psi: sphere 0 -> sphere 1 of a map of two inputs, piecewise linear on
/// its triangles' chords.
class SphereMap
{
public:
  explicit SphereMap(const SurfaceMapResult& map)
    : Map(map)
    , Locator(map.spherePositions[0], map.triangles)
  {
  }

  Eigen::Vector3d operator()(const Eigen::Vector3d& p)
  {
    const SphereLocation l =
      this->Start < 0 ? this->Locator.locate(p) : this->Locator.locateFrom(p, this->Start);
    this->Start = l.triangle;
    const auto& t = this->Map.triangles[l.triangle];
    const auto& g = this->Map.spherePositions[1];
    return (l.alpha * g[t[0]] + l.beta * g[t[1]] + l.gamma * g[t[2]]).normalized();
  }

private:
  const SurfaceMapResult& Map;
  SphereLocator Locator;
  int Start = -1;
};

/// Moves vertex v's point on sphere i to `p` (its lift located by a walk).
void moveOnSphere(CommonTriangulation& T, OpenMesh::VertexHandle v, int i, const Eigen::Vector3d& p)
{
  MapVertex data = T.vertex(v);
  data.g[i] = p;
  T.relocate(data);
  T.setVertex(v, data);
}

/// The edges to split: the longest edge on sphere 0 of every face that is
/// not positively oriented on sphere i.
std::set<int> foldedEdges(const CommonTriangulation& T, int i)
{
  const HalfedgeMesh& mesh = T.mesh();
  std::set<int> edges;
  for (auto f : mesh.faces())
  {
    auto h = mesh.halfedge_handle(f);
    const auto a = mesh.from_vertex_handle(h), b = mesh.to_vertex_handle(h),
               c = mesh.to_vertex_handle(mesh.next_halfedge_handle(h));
    if (orient3dOrigin(T.g(a, i), T.g(b, i), T.g(c, i)) > 0)
    {
      continue;
    }
    OpenMesh::HalfedgeHandle longest = h;
    double length = -1.0;
    for (int k = 0; k < 3; ++k, h = mesh.next_halfedge_handle(h))
    {
      const double l =
        (T.g(mesh.from_vertex_handle(h), i) - T.g(mesh.to_vertex_handle(h), i)).squaredNorm();
      if (l > length)
      {
        length = l;
        longest = h;
      }
    }
    edges.insert(mesh.edge_handle(longest).idx());
  }
  return edges;
}

} // namespace

ComposedEmbeddingResult composeEmbedding(CommonTriangulation& T,
  int i,
  const SurfaceMapResult& map,
  const ComposedEmbeddingOptions& options)
{
  SphereMap psi(map);
  HalfedgeMesh& mesh = T.mesh();
  for (auto v : mesh.vertices())
  {
    moveOnSphere(T, v, i, psi(T.g(v, 0)));
  }
  ComposedEmbeddingResult result;
  for (std::set<int> edges = foldedEdges(T, i); !edges.empty(); edges = foldedEdges(T, i))
  {
    if (result.rounds == options.maxRounds)
    {
      throw NoResultError(std::to_string(edges.size()) + " triangles of the common " +
        "triangulation still fold on sphere " + std::to_string(i) + " after " +
        std::to_string(result.rounds) + " rounds of splits");
    }
    ++result.rounds;
    for (const int e : edges)
    {
      const OpenMesh::EdgeHandle edge(e);
      const auto h = mesh.halfedge_handle(edge, 0);
      MapVertex m = T.midpoint(mesh.from_vertex_handle(h), mesh.to_vertex_handle(h));
      m.g[i] = psi(m.g[0]);
      T.relocate(m);
      const Eigen::Vector3d& p = m.lifted[0];
      const auto vertex = mesh.add_vertex(HalfedgeMesh::Point(p[0], p[1], p[2]));
      mesh.split(edge, vertex);
      T.setVertex(vertex, m);
      ++result.splits;
    }
  }
  T.invalidateFaceEnergies();
  mesh.garbage_collection();
  const std::vector<std::array<int, 3>> triangles = faceTriangles(mesh);
  std::vector<Eigen::Vector3d> points;
  for (auto v : mesh.vertices())
  {
    points.push_back(T.g(v, i));
  }
  const double degree = sphericalDegree(points, triangles);
  if (!(std::abs(degree - 1.0) < 1e-6))
  {
    throw NoResultError("the common triangulation composed onto sphere " + std::to_string(i) +
      " covers it " + std::to_string(degree) + " times");
  }
  return result;
}

} // namespace surfacemaps
