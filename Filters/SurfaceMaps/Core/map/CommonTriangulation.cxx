#include "map/CommonTriangulation.h"

#include "energy/BarrierEnergy.h"
#include "energy/BijectivityBarrier.h"
#include "energy/LandmarkEnergy.h"
#include "energy/MapDistortionEnergy.h"
#include "energy/MeshQualityEnergy.h"
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

int group(MapTerm term)
{
  return static_cast<int>(term);
}
} // namespace

CommonTriangulation::CommonTriangulation(std::vector<MapSurface>& surfaces,
  std::vector<std::array<int, 2>> pairs)
  : Surfaces(surfaces)
  , Pairs(std::move(pairs))
{
  const int n = this->numberOfInputs();
  for (const MapSurface& s : surfaces)
  {
    this->SurfaceNeighbours.push_back(triangleNeighbours(s.triangles));
  }
  this->G.resize(n);
  this->LiftTriangle.resize(n);
  this->Samples.resize(n);
  for (int i = 0; i < n; ++i)
  {
    this->Mesh.add_property(this->G[i]);
    this->Mesh.add_property(this->LiftTriangle[i]);
    this->Mesh.add_property(this->Samples[i]);
  }
  this->Mesh.add_property(this->Landmark);
  this->Mesh.add_property(this->Length);
  this->Mesh.add_property(this->Energy);

  const MapSurface& first = surfaces[0];
  for (const Eigen::Vector3d& p : first.points)
  {
    this->Mesh.add_vertex(SurfaceMesh::Point(p[0], p[1], p[2]));
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
      this->Mesh.property(this->G[i], v) = p;
      this->Mesh.property(this->LiftTriangle[i], v) =
        i == 0 ? vertexTriangle[v.idx()] : surfaces[i].locator->locate(p).triangle;
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
    data.lifted[i] = this->Surfaces[i].lifts[data.liftTriangle[i]](data.g[i]);
  }
  data.landmark = this->Mesh.property(this->Landmark, v);
  return data;
}

void CommonTriangulation::setVertex(OpenMesh::VertexHandle v, const MapVertex& data)
{
  // The faces around v change energy; remeshing rewrites them after an edit.
  for (int i = 0; i < this->numberOfInputs(); ++i)
  {
    this->Mesh.property(this->G[i], v) = data.g[i];
    this->Mesh.property(this->LiftTriangle[i], v) = data.liftTriangle[i];
  }
  this->Mesh.property(this->Landmark, v) = data.landmark;
  const Eigen::Vector3d& p = data.lifted[0];
  this->Mesh.set_point(v, SurfaceMesh::Point(p[0], p[1], p[2]));
}

void CommonTriangulation::relocate(MapVertex& data) const
{
  for (int i = 0; i < this->numberOfInputs(); ++i)
  {
    const MapSurface& s = this->Surfaces[i];
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
    m.g[i] = (m.g[i] + this->Mesh.property(this->G[i], v)).normalized();
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
    const ApproximationSamples& samples = this->Surfaces[i].samples;
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
    const MapSurface& s = this->Surfaces[i];
    const Eigen::Vector3d centroid = (a.g[i] + b.g[i] + c.g[i]).normalized();
    const SphereLocation loc = walkOnSphere(
      centroid, a.liftTriangle[i], s.triangles, this->SurfaceNeighbours[i], s.sphere.data());
    length = std::min(length, s.sizingAt(loc.triangle, { loc.alpha, loc.beta, loc.gamma }));
  }
  return length;
}

template<typename Function>
void CommonTriangulation::forEachFace(Function function)
{
  std::vector<OpenMesh::FaceHandle> faces;
  faces.reserve(this->Mesh.n_faces());
  for (auto f : this->Mesh.faces())
  {
    faces.push_back(f);
  }
#pragma omp parallel for schedule(dynamic, 256)
  for (long long k = 0; k < static_cast<long long>(faces.size()); ++k)
  {
    auto it = this->Mesh.cfv_iter(faces[k]);
    const MapVertex a = this->vertex(*it);
    const MapVertex b = this->vertex(*++it);
    const MapVertex c = this->vertex(*++it);
    function(faces[k], a, b, c);
  }
}

void CommonTriangulation::updateTargetLengths()
{
  this->forEachFace(
    [this](OpenMesh::FaceHandle f, const MapVertex& a, const MapVertex& b, const MapVertex& c)
    { this->Mesh.property(this->Length, f) = this->targetLength(a, b, c); });
}

double CommonTriangulation::triangleEnergy(const MapVertex& a,
  const MapVertex& b,
  const MapVertex& c,
  double length) const
{
  const MapEnergyWeights& w = this->weights;
  double energy = 0.0;
  for (int i = 0; i < this->numberOfInputs(); ++i)
  {
    if (w.barrier > 0.0)
    {
      const double barrier = orientationBarrier<double>(a.g[i], b.g[i], c.g[i]);
      if (!std::isfinite(barrier))
      {
        return Infinity;
      }
      energy += w.barrier * barrier;
    }
    if (w.mesh > 0.0)
    {
      energy += w.mesh * meshQualityEnergy<double>(a.lifted[i], b.lifted[i], c.lifted[i], length);
    }
  }
  if (w.map > 0.0)
  {
    for (const auto& pair : this->Pairs)
    {
      const int i = pair[0], j = pair[1];
      energy += w.map *
        mapDistortionEnergy<double>(
          { a.lifted[i], b.lifted[i], c.lifted[i] }, { a.lifted[j], b.lifted[j], c.lifted[j] });
    }
  }
  return std::isfinite(energy) ? energy : Infinity;
}

double CommonTriangulation::sampleEnergy(int i,
  int s,
  const MapVertex& a,
  const MapVertex& b,
  const MapVertex& c) const
{
  const ApproximationSamples& samples = this->Surfaces[i].samples;
  const double d2 = squaredBaseDistance<double>(samples.spherePoints[s],
    samples.positions[s],
    { a.g[i], b.g[i], c.g[i] },
    { a.lifted[i], b.lifted[i], c.lifted[i] });
  return approximationEnergy<double>(
    d2, this->weights.approximation * samples.weights[s], this->weights.bound(i));
}

std::vector<double> CommonTriangulation::baseDistances(int i) const
{
  const ApproximationSamples& samples = this->Surfaces[i].samples;
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
    if (!(a.g[i].dot(b.g[i].cross(c.g[i])) > minDet) || orient3dOrigin(a.g[i], b.g[i], c.g[i]) <= 0)
    {
      return false;
    }
  }
  return true;
}

double CommonTriangulation::localEnergy(const std::vector<MapVertex>& vertices,
  const std::vector<std::array<int, 3>>& triangles,
  const std::vector<double>& lengths,
  const std::vector<std::vector<int>>& samples,
  bool validate,
  LocalAssignment* assignment,
  std::vector<double>* perTriangle) const
{
  const int n = this->numberOfInputs();
  double energy = 0.0;
  if (perTriangle)
  {
    perTriangle->assign(triangles.size(), 0.0);
  }
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    const MapVertex& a = vertices[triangles[t][0]];
    const MapVertex& b = vertices[triangles[t][1]];
    const MapVertex& c = vertices[triangles[t][2]];
    if (validate && !this->validTriangle(a, b, c))
    {
      return Infinity;
    }
    const double e = this->triangleEnergy(a, b, c, lengths[t]);
    energy += e;
    if (perTriangle)
    {
      (*perTriangle)[t] += e;
    }
  }
  if (assignment)
  {
    assignment->assign(n, {});
  }
  if (this->TrackSamples && !samples.empty())
  {
    for (int i = 0; i < n; ++i)
    {
      for (int s : samples[i])
      {
        const Eigen::Vector3d& q = this->Surfaces[i].samples.spherePoints[s];
        int found = -1;
        for (std::size_t t = 0; t < triangles.size() && found < 0; ++t)
        {
          const auto& tri = triangles[t];
          if (rayMeetsTriangle(
                vertices[tri[0]].g[i], vertices[tri[1]].g[i], vertices[tri[2]].g[i], q))
          {
            found = static_cast<int>(t);
          }
        }
        if (found < 0)
        {
          return Infinity;
        }
        if (assignment)
        {
          (*assignment)[i].push_back(found);
        }
        if (this->weights.approximation > 0.0)
        {
          const auto& tri = triangles[found];
          const double e =
            this->sampleEnergy(i, s, vertices[tri[0]], vertices[tri[1]], vertices[tri[2]]);
          energy += e;
          if (perTriangle)
          {
            (*perTriangle)[found] += e;
          }
        }
      }
    }
  }
  return std::isfinite(energy) ? energy : Infinity;
}

void CommonTriangulation::updateFaceEnergies()
{
  const int n = this->numberOfInputs();
  this->forEachFace(
    [this, n](OpenMesh::FaceHandle f, const MapVertex& a, const MapVertex& b, const MapVertex& c)
    {
      double energy = this->triangleEnergy(a, b, c, this->targetLength(f));
      if (this->TrackSamples && this->weights.approximation > 0.0)
      {
        for (int i = 0; i < n; ++i)
        {
          for (int s : this->faceSamples(f, i))
          {
            energy += this->sampleEnergy(i, s, a, b, c);
          }
        }
      }
      this->Mesh.property(this->Energy, f) = energy;
    });
  this->FaceEnergiesValid = true;
}

void CommonTriangulation::snapshot(Snapshot& s, SpherePoints& points, bool lockLandmarks)
{
  const int n = this->numberOfInputs();
  this->Mesh.garbage_collection();
  const int nv = static_cast<int>(this->Mesh.n_vertices());
  s.vertices = nv;
  s.triangles = faceTriangles(this->Mesh);
  s.lengths.clear();
  for (auto f : this->Mesh.faces())
  {
    s.lengths.push_back(this->Mesh.property(this->Length, f));
  }
  s.neighbours = triangleNeighbours(s.triangles);
  s.embeddedTriangles.assign(n, s.triangles);
  std::vector<Eigen::Vector3d> positions(static_cast<std::size_t>(n) * nv);
  s.liftTriangle.assign(positions.size(), -1);
  s.lifts.assign(positions.size(), nullptr);
  std::vector<char> locked(positions.size(), 0);
  for (int i = 0; i < n; ++i)
  {
    for (auto& t : s.embeddedTriangles[i])
    {
      for (int& corner : t)
      {
        corner += i * nv;
      }
    }
    for (auto v : this->Mesh.vertices())
    {
      const int k = i * nv + v.idx();
      positions[k] = this->Mesh.property(this->G[i], v);
      s.liftTriangle[k] = this->Mesh.property(this->LiftTriangle[i], v);
      s.lifts[k] = &this->Surfaces[i].lifts[s.liftTriangle[k]];
      locked[k] = lockLandmarks && this->Mesh.property(this->Landmark, v) >= 0;
    }
  }
  s.sampleTriangle.assign(n, {});
  if (this->TrackSamples)
  {
    for (int i = 0; i < n; ++i)
    {
      s.sampleTriangle[i].assign(this->Surfaces[i].samples.spherePoints.size(), -1);
      for (auto f : this->Mesh.faces())
      {
        for (int sample : this->Mesh.property(this->Samples[i], f))
        {
          s.sampleTriangle[i][sample] = f.idx();
        }
      }
    }
  }
  points = SpherePoints(std::move(positions));
  points.setLocked(locked);
}

bool CommonTriangulation::update(Snapshot& s, const SpherePoints& points) const
{
  const int n = this->numberOfInputs();
  const int nv = s.vertices;
  const std::vector<Eigen::Vector3d>& positions = points.positions();
  // Every triangle positive (as the barrier sees it) before walking in T.
  const long long nt = static_cast<long long>(s.triangles.size());
  bool positive = true;
#pragma omp parallel for schedule(static) reduction(&& : positive) if (nt * n > 5000)
  for (long long k = 0; k < nt * n; ++k)
  {
    const auto& t = s.embeddedTriangles[k / nt][k % nt];
    positive = positive && positions[t[0]].dot(positions[t[1]].cross(positions[t[2]])) > 0.0;
  }
  if (!positive)
  {
    return false;
  }
  for (int i = 0; i < n; ++i)
  {
    if (std::lround(sphericalDegree(positions, s.embeddedTriangles[i])) != 1)
    {
      return false;
    }
  }
  // The walks are on the inputs' fixed, certified embeddings and end (a
  // circling walk falls back to a scan); one that still throws (a point that
  // is not finite) rejects the trial. Exceptions must not leave the parallel
  // loops.
  bool walked = true;
  const long long np = static_cast<long long>(positions.size());
#pragma omp parallel for schedule(static) reduction(&& : walked) if (np > 2000)
  for (long long k = 0; k < np; ++k)
  {
    const int i = static_cast<int>(k / nv);
    const MapSurface& surface = this->Surfaces[i];
    try
    {
      const int t = walkOnSphere(positions[k],
        s.liftTriangle[k],
        surface.triangles,
        this->SurfaceNeighbours[i],
        surface.sphere.data())
                      .triangle;
      s.liftTriangle[k] = t;
      s.lifts[k] = &surface.lifts[t];
    }
    catch (const std::runtime_error&)
    {
      walked = false;
    }
  }
  if (this->TrackSamples)
  {
    for (int i = 0; i < n && walked; ++i)
    {
      const ApproximationSamples& samples = this->Surfaces[i].samples;
      std::vector<int>& triangleOf = s.sampleTriangle[i];
      const Eigen::Vector3d* corners = positions.data() + static_cast<std::size_t>(i) * nv;
      const long long ns = static_cast<long long>(triangleOf.size());
#pragma omp parallel for schedule(static) reduction(&& : walked) if (ns > 2000)
      for (long long k = 0; k < ns; ++k)
      {
        try
        {
          triangleOf[k] =
            walkOnSphere(samples.spherePoints[k], triangleOf[k], s.triangles, s.neighbours, corners)
              .triangle;
        }
        catch (const std::runtime_error&)
        {
          walked = false;
        }
      }
    }
  }
  return walked;
}

void CommonTriangulation::writeBack(const Snapshot& s, const SpherePoints& points)
{
  this->FaceEnergiesValid = false;
  const int n = this->numberOfInputs();
  const int nv = s.vertices;
  for (int i = 0; i < n; ++i)
  {
    for (auto v : this->Mesh.vertices())
    {
      const int k = i * nv + v.idx();
      this->Mesh.property(this->G[i], v) = points.position(k);
      this->Mesh.property(this->LiftTriangle[i], v) = s.liftTriangle[k];
      if (i == 0)
      {
        const Eigen::Vector3d p = (*s.lifts[k])(points.position(k));
        this->Mesh.set_point(v, SurfaceMesh::Point(p[0], p[1], p[2]));
      }
    }
    if (this->TrackSamples)
    {
      for (auto f : this->Mesh.faces())
      {
        this->Mesh.property(this->Samples[i], f).clear();
      }
      const std::vector<int>& triangleOf = s.sampleTriangle[i];
      for (std::size_t sample = 0; sample < triangleOf.size(); ++sample)
      {
        this->Mesh.property(this->Samples[i], this->Mesh.face_handle(triangleOf[sample]))
          .push_back(static_cast<int>(sample));
      }
    }
  }
}

void CommonTriangulation::buildObjective(const Snapshot& s,
  const std::vector<std::map<int, Eigen::Vector3d>>& landmarkTargets,
  Objective& objective) const
{
  objective.clear();
  const MapEnergyWeights& w = this->weights;
  const int nv = s.vertices;
  for (int i = 0; i < this->numberOfInputs(); ++i)
  {
    if (w.barrier > 0.0)
    {
      BarrierEnergy barrier;
      barrier.triangles = s.triangles;
      barrier.offset = i * nv;
      if (w.exactBarrierHessian)
      {
        objective.addTerm(
          std::make_shared<ElementTerm<3, BarrierEnergy>>("barrier", std::move(barrier)),
          w.barrier,
          group(MapTerm::Barrier));
      }
      else
      {
        objective.addTerm(std::make_shared<BijectivityBarrierTerm>(std::move(barrier)),
          w.barrier,
          group(MapTerm::Barrier));
      }
    }
    if (w.mesh > 0.0)
    {
      MeshQualityEnergy mesh{ &s.triangles, &s.lifts, &s.lengths, i * nv };
      objective.addTerm(std::make_shared<ElementTerm<3, MeshQualityEnergy>>("mesh", mesh),
        w.mesh,
        group(MapTerm::MeshQuality));
    }
    if (w.approximation > 0.0 && this->TrackSamples)
    {
      ApproximationEnergy approximation;
      approximation.samples = &this->Surfaces[i].samples;
      approximation.sampleTriangle = &s.sampleTriangle[i];
      approximation.triangles = &s.triangles;
      approximation.lifts = &s.lifts;
      approximation.offset = i * nv;
      approximation.bound = w.bound(i);
      objective.addTerm(std::make_shared<ApproximationTerm>(approximation),
        w.approximation,
        group(MapTerm::Approximation));
    }
    if (w.landmark > 0.0 && i < static_cast<int>(landmarkTargets.size()))
    {
      LandmarkEnergy landmarks;
      for (auto v : this->Mesh.vertices())
      {
        const auto it = landmarkTargets[i].find(this->Mesh.property(this->Landmark, v));
        if (it != landmarkTargets[i].end())
        {
          landmarks.points_.push_back(i * nv + v.idx());
          landmarks.targets.push_back(it->second);
        }
      }
      objective.addTerm(
        std::make_shared<ElementTerm<1, LandmarkEnergy>>("landmarks", std::move(landmarks)),
        w.landmark,
        group(MapTerm::Landmarks));
    }
  }
  if (w.map > 0.0)
  {
    for (const auto& pair : this->Pairs)
    {
      MapDistortionEnergy map{ &s.triangles, &s.lifts, pair[0] * nv, pair[1] * nv };
      objective.addTerm(std::make_shared<ElementTerm<6, MapDistortionEnergy>>("map", map),
        w.map,
        group(MapTerm::Distortion));
    }
  }
}

double CommonTriangulation::totalEnergy()
{
  Snapshot s;
  SpherePoints points;
  this->snapshot(s, points, false);
  Objective objective;
  this->buildObjective(s, {}, objective);
  return objective.value(points);
}

} // namespace surfacemaps
