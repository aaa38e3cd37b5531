#include "embedding/Decimation.h"
#include "base/Error.h"

#include "mesh/HalfedgeMesh.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace surfacemaps
{

namespace
{

using Mesh = HalfedgeMesh;
using Quadric = Eigen::Matrix4d;

Eigen::Vector3d point(const Mesh& mesh, Mesh::VertexHandle v)
{
  const auto& p = mesh.point(v);
  return { p[0], p[1], p[2] };
}

// Plane quadrics of the faces around each vertex, area weighted.
std::vector<Quadric> vertexQuadrics(const Mesh& mesh)
{
  std::vector<Quadric> Q(mesh.n_vertices(), Quadric::Zero());
  for (const auto f : mesh.faces())
  {
    auto fv = mesh.cfv_iter(f);
    const Eigen::Vector3d a = point(mesh, *fv), b = point(mesh, *++fv), c = point(mesh, *++fv);
    const Eigen::Vector3d n2 = (b - a).cross(c - a);
    const double area2 = n2.norm();
    if (area2 <= 0.0)
    {
      continue;
    }
    const Eigen::Vector3d n = n2 / area2;
    const Eigen::Vector4d plane(n.x(), n.y(), n.z(), -n.dot(a));
    const Quadric K = 0.5 * area2 * plane * plane.transpose();
    for (const auto v : mesh.fv_range(f))
    {
      Q[v.idx()] += K;
    }
  }
  return Q;
}

// The one-ring of v in orientation order: (v, ring[i], ring[i+1]) are faces.
std::vector<int> orientedRing(const Mesh& mesh, Mesh::VertexHandle v)
{
  std::vector<int> ring;
  const Mesh::HalfedgeHandle h0 = mesh.halfedge_handle(v);
  Mesh::HalfedgeHandle h = h0;
  do
  {
    ring.push_back(mesh.to_vertex_handle(h).idx());
    h = mesh.opposite_halfedge_handle(mesh.prev_halfedge_handle(h));
  } while (h != h0 && ring.size() <= mesh.n_vertices());
  return ring;
}

// Checks a collapse v -> u geometrically: the triangles around v that survive
// (those not containing u) keep a reasonable area and do not turn over.
bool geometryOk(const Mesh& mesh, Mesh::HalfedgeHandle h, double minArea, double minCos)
{
  const Mesh::VertexHandle v = mesh.from_vertex_handle(h);
  const Mesh::VertexHandle u = mesh.to_vertex_handle(h);
  const Eigen::Vector3d pu = point(mesh, u);
  for (const auto f : mesh.vf_range(v))
  {
    std::array<Eigen::Vector3d, 3> before, after;
    int k = 0;
    bool hasU = false;
    for (const auto w : mesh.fv_range(f))
    {
      before[k] = point(mesh, w);
      after[k] = w == v ? pu : before[k];
      hasU = hasU || w == u;
      ++k;
    }
    if (hasU)
    {
      continue; // this face disappears
    }
    const Eigen::Vector3d n0 = (before[1] - before[0]).cross(before[2] - before[0]);
    const Eigen::Vector3d n1 = (after[1] - after[0]).cross(after[2] - after[0]);
    const double a1 = 0.5 * n1.norm();
    if (!(a1 > minArea))
    {
      return false;
    }
    if (n0.dot(n1) < minCos * n0.norm() * n1.norm())
    {
      return false;
    }
  }
  return true;
}

// The total area of `triangles` on `points`.
double surfaceArea(const std::vector<Eigen::Vector3d>& points,
  const std::vector<std::array<int, 3>>& triangles)
{
  double totalArea = 0.0;
  for (const auto& t : triangles)
  {
    totalArea += 0.5 * (points[t[1]] - points[t[0]]).cross(points[t[2]] - points[t[0]]).norm();
  }
  return totalArea;
}

// Collapses `mesh` level by level: in each level the halfedges in order of
// quadric error (of moving the removed vertex onto the kept one), as long
// as they keep the mesh valid and the level independent.
class LevelCollapser
{
public:
  LevelCollapser(Mesh& mesh, double minArea, const DecimationOptions& options)
    : M(mesh)
    , Options(options)
    , MinArea(minArea)
    , MinCos(std::cos(options.maxNormalChange * M_PI / 180.0))
    , Q(vertexQuadrics(mesh))
    , Alive(static_cast<int>(mesh.n_vertices()))
    , LevelStamp(mesh.n_vertices(), -1)
  {
  }

  int alive() const { return this->Alive; }

  // The collapses of level `level` (none when every one is blocked);
  // `geometric` applies the shape checks of geometryOk.
  DecimationLevel collapseLevel(int level, bool geometric)
  {
    this->rankCandidates();
    DecimationLevel current;
    for (const Candidate& c : this->Candidates)
    {
      if (this->Alive <= this->Options.targetVertices)
      {
        break;
      }
      if (this->collapsible(c.h, level, geometric))
      {
        current.collapses.push_back(this->collapse(c.h, level));
      }
    }
    return current;
  }

private:
  struct Candidate
  {
    double cost;
    Mesh::HalfedgeHandle h;
  };

  // Every live halfedge v -> u, cheapest first.
  void rankCandidates()
  {
    this->Candidates.clear();
    for (const auto h : this->M.halfedges())
    {
      if (this->M.status(h).deleted())
      {
        continue;
      }
      const Mesh::VertexHandle v = this->M.from_vertex_handle(h), u = this->M.to_vertex_handle(h);
      const Eigen::Vector3d pu = point(this->M, u);
      const Eigen::Vector4d x(pu.x(), pu.y(), pu.z(), 1.0);
      this->Candidates.push_back({ x.dot((this->Q[v.idx()] + this->Q[u.idx()]) * x), h });
    }
    std::sort(this->Candidates.begin(),
      this->Candidates.end(),
      [](const Candidate& a, const Candidate& b) { return a.cost < b.cost; });
  }

  bool collapsible(Mesh::HalfedgeHandle h, int level, bool geometric)
  {
    if (this->M.status(h).deleted())
    {
      return false;
    }
    // Independence: a removed vertex must not be next to a vertex removed
    // earlier in this level (whose ring vertices are stamped), so every
    // ring below is also the vertex's ring in the finer level, and the
    // vertices of one level can be reinserted in any order, in parallel.
    const Mesh::VertexHandle v = this->M.from_vertex_handle(h);
    if (this->LevelStamp[v.idx()] == level || !this->M.is_collapse_ok(h))
    {
      return false;
    }
    // Keep every vertex of the result at valence >= 3 (a tetrahedron at the end).
    if (this->M.valence(this->M.opposite_vh(h)) <= 3 ||
      this->M.valence(this->M.opposite_vh(this->M.opposite_halfedge_handle(h))) <= 3)
    {
      return false;
    }
    return !geometric || geometryOk(this->M, h, this->MinArea, this->MinCos);
  }

  // Collapses h = v -> u, stamping v's ring for this level.
  Collapse collapse(Mesh::HalfedgeHandle h, int level)
  {
    const Mesh::VertexHandle v = this->M.from_vertex_handle(h);
    const Mesh::VertexHandle u = this->M.to_vertex_handle(h);
    Collapse collapse;
    collapse.removed = v.idx();
    collapse.kept = u.idx();
    collapse.ring = orientedRing(this->M, v);
    this->LevelStamp[v.idx()] = level;
    for (int w : collapse.ring)
    {
      this->LevelStamp[w] = level;
    }
    this->Q[u.idx()] += this->Q[v.idx()];
    this->M.collapse(h);
    --this->Alive;
    return collapse;
  }

  Mesh& M;
  const DecimationOptions& Options;
  const double MinArea;
  const double MinCos;
  std::vector<Quadric> Q;
  int Alive;
  std::vector<int> LevelStamp;
  std::vector<Candidate> Candidates;
};

} // namespace

DecimationResult decimateToTetrahedron(const PolygonMesh& input, const DecimationOptions& options)
{
  Mesh mesh = toHalfedgeMesh(input);
  DecimationResult result;
  result.triangles = input.triangles();
  LevelCollapser collapser(
    mesh, options.minAreaFraction * surfaceArea(input.points, result.triangles), options);

  bool geometric = true;
  while (collapser.alive() > options.targetVertices)
  {
    DecimationLevel current =
      collapser.collapseLevel(static_cast<int>(result.levels.size()), geometric);
    if (current.collapses.empty())
    {
      if (geometric)
      {
        // Only shape checks block the remaining collapses: drop them.
        geometric = false;
        result.relaxed = true;
        options.log(Logger::Detail,
          "decimation: geometric checks relaxed at " + std::to_string(collapser.alive()) +
            " vertices");
        continue;
      }
      throw NoResultError("decimation stalled at " + std::to_string(collapser.alive()) +
        " vertices (is the mesh genus 0?)");
    }
    current.triangles = faceTriangles(mesh);
    result.levels.push_back(std::move(current));
  }
  return result;
}

} // namespace surfacemaps
