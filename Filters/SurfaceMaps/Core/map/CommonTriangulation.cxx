#include "map/CommonTriangulation.h"

#include "geometry/Predicates.h"
#include "geometry/SphericalTriangulation.h"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace surfacemaps
{

namespace
{
constexpr double Infinity = std::numeric_limits<double>::infinity();

} // namespace

CommonTriangulation::CommonTriangulation(std::vector<PreparedInput>& surfaces,
  std::vector<std::array<int, 2>> pairs)
  : Surfaces(surfaces)
  , Pairs(std::move(pairs))
{
  const int n = this->numberOfInputs();
  for (const PreparedInput& s : surfaces)
  {
    this->SurfaceNeighbours.push_back(triangleNeighbours(s.triangles));
  }
  this->G.resize(n);
  this->LiftTriangle.resize(n);
  this->Lifted.resize(n);
  this->Samples.resize(n);
  this->BarrierRaises.resize(n);
  for (int i = 0; i < n; ++i)
  {
    this->Mesh.add_property(this->G[i]);
    this->Mesh.add_property(this->LiftTriangle[i]);
    this->Mesh.add_property(this->Lifted[i]);
    this->Mesh.add_property(this->Samples[i]);
    this->Mesh.add_property(this->BarrierRaises[i]);
  }
  this->Mesh.add_property(this->Landmark);
  this->Mesh.add_property(this->Length);
  this->Mesh.add_property(this->Energy);

  const PreparedInput& first = surfaces[0];
  for (const Eigen::Vector3d& p : first.points)
  {
    this->Mesh.add_vertex(HalfedgeMesh::Point(p[0], p[1], p[2]));
  }
  for (const auto& t : first.triangles)
  {
    const auto f = this->Mesh.add_face(this->Mesh.vertex_handle(t[0]),
      this->Mesh.vertex_handle(t[1]),
      this->Mesh.vertex_handle(t[2]));
    if (!f.is_valid())
    {
      throw std::invalid_argument("input 0 is not a manifold triangle mesh");
    }
    this->Mesh.property(this->Length, f) = 1.0;
    this->clearBarrierRaise(f);
  }
  std::vector<int> vertexTriangle(first.points.size(), -1);
  for (std::size_t t = 0; t < first.triangles.size(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      vertexTriangle[first.triangles[t][k]] = static_cast<int>(t);
    }
  }
  for (auto v : this->Mesh.vertices())
  {
    const Eigen::Vector3d& p = first.sphere[v.idx()];
    for (int i = 0; i < n; ++i)
    {
      this->setSpherePoint(
        v, i, p, i == 0 ? vertexTriangle[v.idx()] : surfaces[i].locator->locate(p).triangle);
    }
    this->Mesh.property(this->Landmark, v) =
      first.landmarks.empty() ? -1 : first.landmarks[v.idx()];
  }
}

MapVertex CommonTriangulation::vertex(OpenMesh::VertexHandle v) const
{
  const int n = this->numberOfInputs();
  MapVertex data;
  data.g.resize(n);
  data.lifted.resize(n);
  data.liftTriangle.resize(n);
  for (int i = 0; i < n; ++i)
  {
    data.g[i] = this->Mesh.property(this->G[i], v);
    data.liftTriangle[i] = this->Mesh.property(this->LiftTriangle[i], v);
    data.lifted[i] = this->Mesh.property(this->Lifted[i], v);
  }
  data.landmark = this->Mesh.property(this->Landmark, v);
  return data;
}

void CommonTriangulation::setVertex(OpenMesh::VertexHandle v, const MapVertex& data)
{
  // The faces around v change energy; remeshing rewrites them after an edit.
  for (int i = 0; i < this->numberOfInputs(); ++i)
  {
    this->setSpherePoint(v, i, data.g[i], data.liftTriangle[i]);
  }
  this->Mesh.property(this->Landmark, v) = data.landmark;
}

void CommonTriangulation::setSpherePoint(OpenMesh::VertexHandle v,
  int i,
  const Eigen::Vector3d& g,
  int liftTriangle)
{
  this->Mesh.property(this->G[i], v) = g;
  this->Mesh.property(this->LiftTriangle[i], v) = liftTriangle;
  const Eigen::Vector3d lifted = this->Surfaces[i].lifts[liftTriangle](g);
  this->Mesh.property(this->Lifted[i], v) = lifted;
  if (i == 0)
  {
    this->Mesh.set_point(v, HalfedgeMesh::Point(lifted[0], lifted[1], lifted[2]));
  }
}

void CommonTriangulation::relocate(MapVertex& data) const
{
  for (int i = 0; i < this->numberOfInputs(); ++i)
  {
    const PreparedInput& s = this->Surfaces[i];
    const SphereLocation loc = walkOnSphere(
      data.g[i], data.liftTriangle[i], s.triangles, this->SurfaceNeighbours[i], s.sphere.data());
    data.liftTriangle[i] = loc.triangle;
    data.lifted[i] = s.lifts[loc.triangle](data.g[i]);
  }
}

MapVertex CommonTriangulation::midpoint(OpenMesh::VertexHandle u, OpenMesh::VertexHandle v) const
{
  MapVertex m = this->vertex(u);
  for (int i = 0; i < this->numberOfInputs(); ++i)
  {
    m.g[i] = this->sphereMidpoint(u, v, i);
  }
  m.landmark = -1;
  this->relocate(m);
  return m;
}

void CommonTriangulation::setTrackSamples(bool track)
{
  if (track && !this->TrackSamples)
  {
    this->TrackSamples = true;
    this->assignSamplesFromScratch();
  }
  this->TrackSamples = track;
}

void CommonTriangulation::assignSamplesFromScratch()
{
  this->Mesh.garbage_collection();
  const std::vector<std::array<int, 3>> triangles = faceTriangles(this->Mesh);
  for (int i = 0; i < this->numberOfInputs(); ++i)
  {
    std::vector<Eigen::Vector3d> positions(this->Mesh.n_vertices());
    for (auto v : this->Mesh.vertices())
    {
      positions[v.idx()] = this->Mesh.property(this->G[i], v);
    }
    for (auto f : this->Mesh.faces())
    {
      this->Mesh.property(this->Samples[i], f).clear();
    }
    const SphereLocator locator(positions, triangles);
    const ApproximationSampleSet& samples = this->Surfaces[i].samples;
    std::vector<int> triangleOf(samples.spherePoints.size());
    for (std::size_t s = 0; s < triangleOf.size(); ++s)
    {
      triangleOf[s] = locator.locate(samples.spherePoints[s]).triangle;
    }
    for (std::size_t s = 0; s < triangleOf.size(); ++s)
    {
      this->Mesh.property(this->Samples[i], this->Mesh.face_handle(triangleOf[s]))
        .push_back(static_cast<int>(s));
    }
  }
}

double CommonTriangulation::targetLength(const MapVertex& a,
  const MapVertex& b,
  const MapVertex& c) const
{
  double length = Infinity;
  for (int i = 0; i < this->numberOfInputs(); ++i)
  {
    const PreparedInput& s = this->Surfaces[i];
    const Eigen::Vector3d centroid = (a.g[i] + b.g[i] + c.g[i]).normalized();
    const SphereLocation loc = walkOnSphere(
      centroid, a.liftTriangle[i], s.triangles, this->SurfaceNeighbours[i], s.sphere.data());
    length = std::min(length, s.sizingAt(loc.triangle, { loc.alpha, loc.beta, loc.gamma }));
  }
  return length;
}

void CommonTriangulation::updateTargetLengths()
{
  this->forEachFace(
    [this](OpenMesh::FaceHandle f, const MapVertex& a, const MapVertex& b, const MapVertex& c)
    { this->Mesh.property(this->Length, f) = this->targetLength(a, b, c); });
}

double CommonTriangulation::coverageDensity(int i, int a, int b, int c) const
{
  const std::vector<double>& d = this->Surfaces[i].density;
  return (d[a] + d[b] + d[c]) / 3.0;
}

std::vector<double> CommonTriangulation::baseDistances(int i) const
{
  const ApproximationSampleSet& samples = this->Surfaces[i].samples;
  std::vector<double> distances(samples.positions.size(), Infinity);
  for (auto f : this->Mesh.faces())
  {
    const std::vector<int>& inside = this->faceSamples(f, i);
    if (inside.empty())
    {
      continue;
    }
    auto fv = this->Mesh.cfv_iter(f);
    const MapVertex a = this->vertex(*fv);
    const MapVertex b = this->vertex(*++fv);
    const MapVertex c = this->vertex(*++fv);
    for (int s : inside)
    {
      distances[s] = std::sqrt(squaredBaseDistance<double>(samples.spherePoints[s],
        samples.positions[s],
        { a.g[i], b.g[i], c.g[i] },
        { a.lifted[i], b.lifted[i], c.lifted[i] }));
    }
  }
  return distances;
}

bool CommonTriangulation::validTriangle(const MapVertex& a,
  const MapVertex& b,
  const MapVertex& c) const
{
  for (int i = 0; i < this->numberOfInputs(); ++i)
  {
    if (!validOnSphere(a.g[i], b.g[i], c.g[i]))
    {
      return false;
    }
  }
  return true;
}

bool CommonTriangulation::validOnSphere(const Eigen::Vector3d& a,
  const Eigen::Vector3d& b,
  const Eigen::Vector3d& c)
{
  return a.dot(b.cross(c)) > minDet && orient3dOrigin(a, b, c) > 0;
}

} // namespace surfacemaps
