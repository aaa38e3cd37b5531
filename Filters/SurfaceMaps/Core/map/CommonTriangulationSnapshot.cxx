// The flat copy of T that the Newton step works on, and writing it back.
#include "map/CommonTriangulation.h"

#include <algorithm>

#include "energy/MapDistortionEnergy.h"
#include "geometry/Predicates.h"
#include "geometry/SphericalTriangulation.h"

#include <cmath>
#include <stdexcept>

namespace surfacemaps
{

void CommonTriangulation::snapshot(Snapshot& s,
  SpherePoints& points,
  bool lockLandmarks,
  const MapEnergyWeights& weights)
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
  s.neighbours = faceNeighbours(this->Mesh);
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
      locked[k] =
        i < this->FrozenInputs || (lockLandmarks && this->Mesh.property(this->Landmark, v) >= 0);
    }
  }
  s.densities.assign(n, {});
  if (weights.coverage > 0.0)
  {
    for (int i = 0; i < n; ++i)
    {
      const int* lift = s.liftTriangle.data() + static_cast<std::size_t>(i) * nv;
      s.densities[i].reserve(s.triangles.size());
      for (const auto& t : s.triangles)
      {
        s.densities[i].push_back(this->coverageDensity(i, lift[t[0]], lift[t[1]], lift[t[2]]));
      }
    }
  }
  s.barrierScales.assign(n, {});
  if (weights.barrierRaise > 1.0)
  {
    for (int i = 0; i < n; ++i)
    {
      s.barrierScales[i].reserve(s.triangles.size());
      for (auto f : this->Mesh.faces())
      {
        s.barrierScales[i].push_back(
          std::pow(weights.barrierRaise, this->Mesh.property(this->BarrierRaises[i], f)));
      }
    }
  }
  s.meanGrams.clear();
  if (weights.mapToMean && weights.map > 0.0)
  {
    s.meanGrams.reserve(s.triangles.size());
    PerInput<std::array<double, 3>> grams(n);
    for (const auto& t : s.triangles)
    {
      for (int i = 0; i < n; ++i)
      {
        const auto lifted = [&](int corner)
        { return this->Mesh.property(this->Lifted[i], OpenMesh::VertexHandle(t[corner])); };
        grams[i] = gramEntries(lifted(0), lifted(1), lifted(2));
      }
      s.meanGrams.push_back(meanGram(grams));
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

std::vector<int> CommonTriangulation::invertedCorners(const Snapshot& s,
  const SpherePoints& points) const
{
  const std::vector<Eigen::Vector3d>& positions = points.positions();
  std::vector<int> corners;
  for (const auto& triangles : s.embeddedTriangles)
  {
    for (const int t : invertedTriangles(positions, triangles))
    {
      corners.insert(corners.end(), triangles[t].begin(), triangles[t].end());
    }
  }
  std::sort(corners.begin(), corners.end());
  corners.erase(std::unique(corners.begin(), corners.end()), corners.end());
  return corners;
}

void CommonTriangulation::raiseBarrier(const Snapshot& s, const SpherePoints& points, double raise)
{
  if (!(raise > 1.0))
  {
    return;
  }
  for (int i = 0; i < this->numberOfInputs(); ++i)
  {
    // The snapshot numbers the faces as the garbage-collected mesh does.
    for (const int t : invertedTriangles(points.positions(), s.embeddedTriangles[i]))
    {
      int& raises = this->Mesh.property(this->BarrierRaises[i], this->Mesh.face_handle(t));
      raises = std::min(MaxBarrierRaises, raises + 1);
    }
  }
}

void CommonTriangulation::clearBarrierRaise(OpenMesh::FaceHandle f)
{
  for (const auto& raises : this->BarrierRaises)
  {
    this->Mesh.property(raises, f) = 0;
  }
}

bool CommonTriangulation::update(Snapshot& s, const SpherePoints& points) const
{
  const int n = this->numberOfInputs();
  const int nv = s.vertices;
  const std::vector<Eigen::Vector3d>& positions = points.positions();
  // Every triangle positive, decided as the certificate decides it (exactly),
  // before walking in T.
  const long long nt = static_cast<long long>(s.triangles.size());
  bool positive = true;
#pragma omp parallel for schedule(static) reduction(&& : positive) if (nt * n > 5000)
  for (long long k = 0; k < nt * n; ++k)
  {
    const auto& t = s.embeddedTriangles[k / nt][k % nt];
    positive = positive && orient3dOrigin(positions[t[0]], positions[t[1]], positions[t[2]]) > 0;
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
    const PreparedInput& surface = this->Surfaces[i];
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
      const ApproximationSampleSet& samples = this->Surfaces[i].samples;
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
      this->setSpherePoint(v, i, points.position(k), s.liftTriangle[k]);
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

} // namespace surfacemaps
