#include "mesh/MeshValidation.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>
#include <sstream>

namespace surfacemaps
{

namespace
{

class UnionFind
{
public:
  explicit UnionFind(std::size_t n)
    : Parent(n)
  {
    std::iota(this->Parent.begin(), this->Parent.end(), 0);
  }
  std::size_t find(std::size_t i)
  {
    while (this->Parent[i] != i)
    {
      this->Parent[i] = this->Parent[this->Parent[i]];
      i = this->Parent[i];
    }
    return i;
  }
  void unite(std::size_t a, std::size_t b) { this->Parent[this->find(a)] = this->find(b); }

private:
  std::vector<std::size_t> Parent;
};

std::string point(const Eigen::Vector3d& p)
{
  std::ostringstream s;
  s.precision(9);
  s << "(" << p.x() << ", " << p.y() << ", " << p.z() << ")";
  return s.str();
}

std::string plural(long long n, const char* one, const char* many)
{
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

struct DirectedEdge
{
  int from, to, face;
  int lo() const { return std::min(from, to); }
  int hi() const { return std::max(from, to); }
};

// Structural checks every later check relies on; false if the rest cannot run.
bool checkStructure(const PolygonMesh& mesh, MeshValidationResult& result)
{
  const std::size_t nv = mesh.points.size();
  const std::size_t nf = mesh.numberOfFaces();
  if (nv == 0 || nf == 0)
  {
    result.defects.push_back(nv == 0 ? "contains no vertices" : "contains no triangles");
    return false;
  }
  if (mesh.nonPolygonCells > 0)
  {
    result.defects.push_back("contains " +
      plural(static_cast<long long>(mesh.nonPolygonCells), "cell", "cells") +
      " that are not polygons (lines or points); only triangles are accepted");
  }

  long long nonTriangles = 0;
  long long firstNonTriangle = -1;
  long long badIndex = 0;
  long long firstBadFace = -1;
  long long firstBadIndex = 0;
  long long repeated = 0;
  long long firstRepeated = -1;
  for (std::size_t f = 0; f < nf; ++f)
  {
    const int n = mesh.faceSize(f);
    const int* face = mesh.face(f);
    if (n != 3)
    {
      if (nonTriangles++ == 0)
      {
        firstNonTriangle = static_cast<long long>(f);
      }
    }
    for (int k = 0; k < n; ++k)
    {
      if (face[k] < 0 || static_cast<std::size_t>(face[k]) >= nv)
      {
        if (badIndex++ == 0)
        {
          firstBadFace = static_cast<long long>(f);
          firstBadIndex = face[k];
        }
      }
      for (int l = k + 1; l < n; ++l)
      {
        if (face[k] == face[l] && repeated++ == 0)
        {
          firstRepeated = static_cast<long long>(f);
        }
      }
    }
  }
  if (nonTriangles > 0)
  {
    result.defects.push_back("is not a triangle mesh: " + std::to_string(nonTriangles) + " of " +
      plural(static_cast<long long>(nf), "polygon", "polygons") +
      " are not triangles (first: face " + std::to_string(firstNonTriangle) + " with " +
      std::to_string(mesh.faceSize(firstNonTriangle)) + " vertices)");
  }
  if (badIndex > 0)
  {
    // A 64-bit index is stored as -1: name its real value.
    if (mesh.wideIndices > 0 && mesh.firstWideIndexFace <= firstBadFace)
    {
      firstBadFace = mesh.firstWideIndexFace;
      firstBadIndex = mesh.firstWideIndex;
    }
    result.defects.push_back("has " + plural(badIndex, "face corner", "face corners") +
      " referring to missing vertices (first: face " + std::to_string(firstBadFace) +
      " uses vertex index " + std::to_string(firstBadIndex) + ", valid are 0 to " +
      std::to_string(static_cast<long long>(nv) - 1) + ")");
  }
  if (repeated > 0)
  {
    result.defects.push_back("has " + plural(repeated, "face", "faces") +
      " using the same vertex twice (first: face " + std::to_string(firstRepeated) + ")");
  }
  return nonTriangles == 0 && badIndex == 0 && repeated == 0;
}

// Finite coordinates within the dynamic range; false if any is not.
bool checkCoordinates(const PolygonMesh& mesh,
  const MeshValidationOptions& options,
  MeshValidationResult& result)
{
  const std::size_t nv = mesh.points.size();
  long long nonFinite = 0;
  long long firstNonFinite = -1;
  long long outOfRange = 0;
  long long firstOutOfRange = -1;
  for (std::size_t v = 0; v < nv; ++v)
  {
    if (!mesh.points[v].allFinite())
    {
      if (nonFinite++ == 0)
      {
        firstNonFinite = static_cast<long long>(v);
      }
    }
    else if (!(mesh.points[v].cwiseAbs().maxCoeff() <= options.maxCoordinate) && outOfRange++ == 0)
    {
      firstOutOfRange = static_cast<long long>(v);
    }
  }
  if (nonFinite > 0)
  {
    result.defects.push_back("has " + plural(nonFinite, "vertex", "vertices") +
      " with non-finite coordinates (first: vertex " + std::to_string(firstNonFinite) + " at " +
      point(mesh.points[firstNonFinite]) + ")");
  }
  if (outOfRange > 0)
  {
    std::ostringstream s;
    s << "has " << plural(outOfRange, "vertex", "vertices")
      << " outside the valid coordinate range |x|, |y|, |z| <= " << options.maxCoordinate
      << " (first: vertex " << firstOutOfRange << " at " << point(mesh.points[firstOutOfRange])
      << ")";
    result.defects.push_back(s.str());
  }
  return nonFinite == 0 && outOfRange == 0;
}

// Every vertex used, none twice at the same place.
void checkVertexUse(const PolygonMesh& mesh, MeshValidationResult& result)
{
  const std::size_t nv = mesh.points.size();

  std::vector<char> used(nv, 0);
  for (int v : mesh.faceVertices)
  {
    used[v] = 1;
  }
  const long long unused = std::count(used.begin(), used.end(), 0);
  if (unused > 0)
  {
    const long long first = std::find(used.begin(), used.end(), 0) - used.begin();
    result.defects.push_back("has " + plural(unused, "vertex", "vertices") +
      " not used by any triangle (first: vertex " + std::to_string(first) + ")");
  }

  std::vector<int> order(nv);
  std::iota(order.begin(), order.end(), 0);
  auto less = [&](int a, int b)
  {
    const auto& p = mesh.points[a];
    const auto& q = mesh.points[b];
    return std::tie(p.x(), p.y(), p.z()) < std::tie(q.x(), q.y(), q.z());
  };
  std::sort(order.begin(), order.end(), less);
  long long duplicates = 0;
  int firstA = -1, firstB = -1;
  for (std::size_t i = 1; i < nv; ++i)
  {
    if (mesh.points[order[i]] == mesh.points[order[i - 1]] && mesh.points[order[i]].allFinite())
    {
      if (duplicates++ == 0)
      {
        firstA = std::min(order[i - 1], order[i]);
        firstB = std::max(order[i - 1], order[i]);
      }
    }
  }
  result.statistics.duplicateVertices = duplicates;
  if (duplicates > 0)
  {
    result.defects.push_back("has " + plural(duplicates, "duplicate vertex", "duplicate vertices") +
      " (first: vertices " + std::to_string(firstA) + " and " + std::to_string(firstB) +
      " both at " + point(mesh.points[firstA]) + ")");
  }
}

void measureTriangles(const PolygonMesh& mesh,
  const MeshValidationOptions& options,
  MeshValidationResult& result)
{
  MeshStatistics& stats = result.statistics;
  const std::size_t nf = mesh.numberOfFaces();
  std::vector<double> areas(nf);
  double total = 0.0;
  double volume6 = 0.0;
  for (std::size_t f = 0; f < nf; ++f)
  {
    const int* t = mesh.face(f);
    const Eigen::Vector3d& a = mesh.points[t[0]];
    const Eigen::Vector3d& b = mesh.points[t[1]];
    const Eigen::Vector3d& c = mesh.points[t[2]];
    areas[f] = 0.5 * (b - a).cross(c - a).norm();
    if (std::isfinite(areas[f])) // non-finite vertices are reported on their own
    {
      total += areas[f];
      volume6 += a.dot(b.cross(c));
    }
  }
  stats.area = total;
  stats.orientation = volume6 > 0 ? 1 : (volume6 < 0 ? -1 : 0);

  Eigen::Vector3d lo = Eigen::Vector3d::Constant(INFINITY);
  Eigen::Vector3d hi = Eigen::Vector3d::Constant(-INFINITY);
  for (int v : mesh.faceVertices)
  {
    if (mesh.points[v].allFinite())
    {
      lo = lo.cwiseMin(mesh.points[v]);
      hi = hi.cwiseMax(mesh.points[v]);
    }
  }
  stats.boundingBoxDiagonal = (hi - lo).norm();

  long long zero = 0;
  long long firstZero = -1;
  double minAngle = 180.0;
  double sumMinAngle = 0.0;
  long long measured = 0;
  const double threshold = options.zeroAreaFraction * total;
  for (std::size_t f = 0; f < nf; ++f)
  {
    if (!std::isfinite(areas[f]))
    {
      continue;
    }
    if (!(areas[f] > threshold))
    {
      if (zero++ == 0)
      {
        firstZero = static_cast<long long>(f);
      }
      continue;
    }
    const int* t = mesh.face(f);
    double smallest = 180.0;
    for (int k = 0; k < 3; ++k)
    {
      const Eigen::Vector3d u = mesh.points[t[(k + 1) % 3]] - mesh.points[t[k]];
      const Eigen::Vector3d w = mesh.points[t[(k + 2) % 3]] - mesh.points[t[k]];
      const double angle = std::atan2(u.cross(w).norm(), u.dot(w)) * 180.0 / M_PI;
      smallest = std::min(smallest, angle);
    }
    minAngle = std::min(minAngle, smallest);
    sumMinAngle += smallest;
    ++measured;
  }
  stats.minAngle = measured > 0 ? minAngle : 0.0;
  stats.meanMinAngle = measured > 0 ? sumMinAngle / measured : 0.0;
  if (zero > 0 && options.requireSurface)
  {
    std::ostringstream s;
    s.precision(3);
    s << "has " << plural(zero, "zero-area triangle", "zero-area triangles") << " (first: face "
      << firstZero << ", vertices " << mesh.face(firstZero)[0] << " " << mesh.face(firstZero)[1]
      << " " << mesh.face(firstZero)[2] << ", area " << areas[firstZero] << ")";
    result.defects.push_back(s.str());
  }
}

// The halfedges of all triangles, sorted so that those of one edge are adjacent.
std::vector<DirectedEdge> sortedHalfedges(const PolygonMesh& mesh)
{
  const std::size_t nf = mesh.numberOfFaces();
  std::vector<DirectedEdge> halfedges;
  halfedges.reserve(3 * nf);
  for (std::size_t f = 0; f < nf; ++f)
  {
    const int* t = mesh.face(f);
    for (int k = 0; k < 3; ++k)
    {
      halfedges.push_back({ t[k], t[(k + 1) % 3], static_cast<int>(f) });
    }
  }
  std::sort(halfedges.begin(),
    halfedges.end(),
    [](const DirectedEdge& a, const DirectedEdge& b)
    { return std::make_pair(a.lo(), a.hi()) < std::make_pair(b.lo(), b.hi()); });
  return halfedges;
}

/// Edge counts by kind, with the first edge of each defective kind.
struct EdgeCensus
{
  long long edges = 0, boundary = 0, nonManifold = 0, misoriented = 0;
  std::array<int, 2> firstBoundary{ -1, -1 }, firstNonManifold{ -1, -1 },
    firstMisoriented{ -1, -1 };
};

EdgeCensus countEdges(const std::vector<DirectedEdge>& halfedges)
{
  EdgeCensus c;
  for (std::size_t i = 0; i < halfedges.size();)
  {
    std::size_t j = i + 1;
    while (j < halfedges.size() && halfedges[j].lo() == halfedges[i].lo() &&
      halfedges[j].hi() == halfedges[i].hi())
    {
      ++j;
    }
    const std::array<int, 2> edge{ halfedges[i].lo(), halfedges[i].hi() };
    ++c.edges;
    const std::size_t count = j - i;
    if (count == 1 && c.boundary++ == 0)
    {
      c.firstBoundary = edge;
    }
    if (count > 2 && c.nonManifold++ == 0)
    {
      c.firstNonManifold = edge;
    }
    if (count == 2 && halfedges[i].from == halfedges[i + 1].from && c.misoriented++ == 0)
    {
      c.firstMisoriented = edge;
    }
    i = j;
  }
  return c;
}

// Closed, edge-manifold, consistently oriented.
EdgeCensus checkEdges(const PolygonMesh& mesh, MeshValidationResult& result)
{
  const EdgeCensus c = countEdges(sortedHalfedges(mesh));
  MeshStatistics& stats = result.statistics;
  stats.edges = c.edges;
  stats.boundaryEdges = c.boundary;
  stats.nonManifoldEdges = c.nonManifold;

  auto edgeText = [](const std::array<int, 2>& e)
  { return "edge " + std::to_string(e[0]) + "-" + std::to_string(e[1]); };
  if (c.boundary > 0)
  {
    result.defects.push_back(
      "is not closed: " + plural(c.boundary, "boundary edge", "boundary edges") +
      " (first: " + edgeText(c.firstBoundary) + ")");
  }
  if (c.nonManifold > 0)
  {
    result.defects.push_back("has " +
      plural(c.nonManifold, "non-manifold edge", "non-manifold edges") +
      " shared by more than two triangles (first: " + edgeText(c.firstNonManifold) + ")");
  }
  if (c.misoriented > 0)
  {
    result.defects.push_back(
      "is not consistently oriented: " + plural(c.misoriented, "edge is", "edges are") +
      " traversed in the same direction by both triangles (first: " + edgeText(c.firstMisoriented) +
      ")");
  }
  return c;
}

/// Per vertex, the edges opposite it in its triangles: vertex v's are
/// edges[offsets[v] .. offsets[v+1]).
struct VertexLinks
{
  std::vector<int> offsets;
  std::vector<std::array<int, 2>> edges;
};

VertexLinks vertexLinks(const PolygonMesh& mesh)
{
  VertexLinks links;
  links.offsets.assign(mesh.points.size() + 1, 0);
  for (int v : mesh.faceVertices)
  {
    ++links.offsets[v + 1];
  }
  std::partial_sum(links.offsets.begin(), links.offsets.end(), links.offsets.begin());
  links.edges.resize(mesh.faceVertices.size());
  std::vector<int> fill(links.offsets.begin(), links.offsets.end() - 1);
  for (std::size_t f = 0; f < mesh.numberOfFaces(); ++f)
  {
    const int* t = mesh.face(f);
    for (int k = 0; k < 3; ++k)
    {
      links.edges[fill[t[k]]++] = { t[(k + 1) % 3], t[(k + 2) % 3] };
    }
  }
  return links;
}

// True when link edges [begin, end) form one connected piece; `local` is scratch.
bool linkIsConnected(const VertexLinks& links, int begin, int end, std::vector<int>& local)
{
  local.clear();
  for (int i = begin; i < end; ++i)
  {
    local.push_back(links.edges[i][0]);
    local.push_back(links.edges[i][1]);
  }
  std::sort(local.begin(), local.end());
  local.erase(std::unique(local.begin(), local.end()), local.end());
  UnionFind uf(local.size());
  auto id = [&](int w)
  {
    return static_cast<std::size_t>(
      std::lower_bound(local.begin(), local.end(), w) - local.begin());
  };
  for (int i = begin; i < end; ++i)
  {
    uf.unite(id(links.edges[i][0]), id(links.edges[i][1]));
  }
  const std::size_t root = uf.find(0);
  for (std::size_t i = 1; i < local.size(); ++i)
  {
    if (uf.find(i) != root)
    {
      return false;
    }
  }
  return true;
}

// Vertex manifoldness: the link of a vertex (the opposite edges of its
// triangles) must be connected, i.e. its triangles form one fan. Returns the
// number of non-manifold vertices.
long long checkVertexFans(const PolygonMesh& mesh, MeshValidationResult& result)
{
  const VertexLinks links = vertexLinks(mesh);
  long long nonManifoldVertices = 0;
  int firstNonManifoldVertex = -1;
  std::vector<int> local;
  for (std::size_t v = 0; v < mesh.points.size(); ++v)
  {
    const int begin = links.offsets[v], end = links.offsets[v + 1];
    if (end - begin < 2 || linkIsConnected(links, begin, end, local))
    {
      continue;
    }
    if (nonManifoldVertices++ == 0)
    {
      firstNonManifoldVertex = static_cast<int>(v);
    }
  }
  result.statistics.nonManifoldVertices = nonManifoldVertices;
  if (nonManifoldVertices > 0)
  {
    result.defects.push_back("has " +
      plural(nonManifoldVertices, "non-manifold vertex", "non-manifold vertices") +
      " where separate fans of triangles meet (first: vertex " +
      std::to_string(firstNonManifoldVertex) + " at " + point(mesh.points[firstNonManifoldVertex]) +
      ")");
  }
  return nonManifoldVertices;
}

/// Connected components over the vertices used by triangles.
struct ComponentCount
{
  long long components = 0;
  long long usedVertices = 0;
};

ComponentCount checkComponents(const PolygonMesh& mesh, MeshValidationResult& result)
{
  const std::size_t nv = mesh.points.size();
  UnionFind uf(nv);
  for (std::size_t f = 0; f < mesh.numberOfFaces(); ++f)
  {
    const int* t = mesh.face(f);
    uf.unite(t[0], t[1]);
    uf.unite(t[0], t[2]);
  }
  std::vector<char> used(nv, 0);
  for (int v : mesh.faceVertices)
  {
    used[v] = 1;
  }
  ComponentCount count;
  for (std::size_t v = 0; v < nv; ++v)
  {
    if (used[v])
    {
      ++count.usedVertices;
      if (uf.find(v) == v)
      {
        ++count.components;
      }
    }
  }
  result.statistics.components = count.components;
  if (count.components > 1)
  {
    result.defects.push_back("has " + std::to_string(count.components) +
      " connected components; a single connected surface is required");
  }
  return count;
}

void checkTopology(const PolygonMesh& mesh, MeshValidationResult& result)
{
  const EdgeCensus edges = checkEdges(mesh, result);
  const long long nonManifoldVertices = checkVertexFans(mesh, result);
  const ComponentCount count = checkComponents(mesh, result);

  // The genus is defined only for a closed, connected, orientable 2-manifold.
  if (edges.boundary == 0 && edges.nonManifold == 0 && nonManifoldVertices == 0 &&
    edges.misoriented == 0 && count.components == 1)
  {
    MeshStatistics& stats = result.statistics;
    const long long chi =
      count.usedVertices - edges.edges + static_cast<long long>(mesh.numberOfFaces());
    stats.genus = static_cast<int>((2 - chi) / 2);
    if (stats.genus != 0)
    {
      result.defects.push_back("has genus " + std::to_string(stats.genus) +
        "; a genus-0 (sphere-like) surface is required");
    }
    // Two triangles glued back to back (a pillow) are closed and genus 0
    // but enclose nothing: every triangle's chords on the sphere would be
    // one flat triangle, which no embedding can make positively oriented.
    else if (mesh.numberOfFaces() < 4)
    {
      result.defects.push_back("has only " + std::to_string(mesh.numberOfFaces()) +
        " triangles; a closed surface needs at least 4 (a tetrahedron)");
    }
  }
}

// The measured size within the dynamic range (coordinates already are).
void checkSize(const MeshValidationOptions& options, MeshValidationResult& result)
{
  const MeshStatistics& stats = result.statistics;
  std::ostringstream s;
  s.precision(3);
  if (!(std::isfinite(stats.area) && stats.area > 0.0))
  {
    s << "has total area " << stats.area << "; a finite, positive area is required";
  }
  else if (!(stats.boundingBoxDiagonal >= options.minBoundingBoxDiagonal &&
             std::isfinite(stats.boundingBoxDiagonal)))
  {
    s << "has a bounding-box diagonal of " << stats.boundingBoxDiagonal
      << ", outside the valid range (at least " << options.minBoundingBoxDiagonal << ")";
  }
  if (!s.str().empty())
  {
    result.defects.push_back(s.str());
  }
}

} // namespace

MeshValidationResult validateMesh(const PolygonMesh& mesh, const MeshValidationOptions& options)
{
  MeshValidationResult result;
  result.statistics.vertices = static_cast<long long>(mesh.points.size());
  result.statistics.faces = static_cast<long long>(mesh.numberOfFaces());
  if (!checkStructure(mesh, result))
  {
    return result;
  }
  const bool coordinatesValid = checkCoordinates(mesh, options, result);
  if (options.requireSurface)
  {
    checkVertexUse(mesh, result);
  }
  measureTriangles(mesh, options, result);
  if (coordinatesValid)
  {
    checkSize(options, result);
  }
  if (options.requireSurface)
  {
    checkTopology(mesh, result);
  }
  return result;
}

} // namespace surfacemaps
