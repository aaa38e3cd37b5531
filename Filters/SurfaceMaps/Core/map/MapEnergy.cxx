// SurfaceMaps engine: MapEnergy.
#include "map/MapEnergy.h"

#include "energy/BarrierEnergy.h"
#include "energy/BijectivityBarrier.h"
#include "energy/CoverageEnergy.h"
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

MapEnergy::MapEnergy(CommonTriangulation& T, MapEnergyWeights weights)
  : T(T)
  , Weights(std::move(weights))
{
}

namespace
{
constexpr double Infinity = std::numeric_limits<double>::infinity();

int group(MapTerm term)
{
  return static_cast<int>(term);
}
} // namespace

MapEnergy::TriangleTerms MapEnergy::triangleTerms(const MapVertex& a,
  const MapVertex& b,
  const MapVertex& c) const
{
  const MapEnergyWeights& w = this->Weights;
  TriangleTerms terms;
  for (int i = 0; i < this->T.numberOfInputs(); ++i)
  {
    if (w.barrier > 0.0)
    {
      const double barrier = exactOrientationBarrier(a.g[i], b.g[i], c.g[i]);
      if (!std::isfinite(barrier))
      {
        terms.valid = false;
        return terms;
      }
      terms.barrier.push_back(w.barrier * barrier);
    }
    if (w.mesh > 0.0)
    {
      terms.lifted.push_back(gramEntries(a.lifted[i], b.lifted[i], c.lifted[i]));
    }
    if (w.coverage > 0.0)
    {
      terms.coverage.push_back(w.coverage *
        coverageEnergy<double>({ a.g[i], b.g[i], c.g[i] },
          { a.lifted[i], b.lifted[i], c.lifted[i] },
          this->T.coverageDensity(i, a.liftTriangle[i], b.liftTriangle[i], c.liftTriangle[i])));
    }
  }
  if (w.map > 0.0 && w.mapToMean)
  {
    // The mesh-quality term's Gram entries are these: computed once.
    PerInput<std::array<double, 3>> grams = terms.lifted;
    for (int i = static_cast<int>(grams.size()); i < this->T.numberOfInputs(); ++i)
    {
      grams.push_back(gramEntries(a.lifted[i], b.lifted[i], c.lifted[i]));
    }
    const std::array<double, 3> mean = meanGram(grams);
    for (const auto& gram : grams)
    {
      terms.map.push_back(w.map * symmetricDirichlet(mean, gram));
    }
  }
  else if (w.map > 0.0)
  {
    for (const auto& pair : this->T.pairs())
    {
      const int i = pair[0], j = pair[1];
      terms.map.push_back(w.map *
        mapDistortionEnergy<double>(
          { a.lifted[i], b.lifted[i], c.lifted[i] }, { a.lifted[j], b.lifted[j], c.lifted[j] }));
    }
  }
  return terms;
}

namespace
{
/// The sum of a triangle's terms in one fixed order (per input: barrier,
/// mesh quality, coverage; then the pairs' distortion), the mesh-quality
/// term of input i given by meshTerm(i).
template<typename MeshTerm>
double sumOfTerms(const MapEnergy::TriangleTerms& terms, int inputs, MeshTerm meshTerm)
{
  if (!terms.valid)
  {
    return Infinity;
  }
  double energy = 0.0;
  for (int i = 0; i < inputs; ++i)
  {
    if (!terms.barrier.empty())
    {
      energy += terms.barrier[i];
    }
    if (!terms.lifted.empty())
    {
      energy += meshTerm(i);
    }
    if (!terms.coverage.empty())
    {
      energy += terms.coverage[i];
    }
  }
  for (double map : terms.map)
  {
    energy += map;
  }
  return std::isfinite(energy) ? energy : Infinity;
}
} // namespace

double MapEnergy::triangleEnergy(const TriangleTerms& terms, double length) const
{
  const double w = this->Weights.mesh;
  return sumOfTerms(terms,
    this->T.numberOfInputs(),
    [&](int i) { return w * meshQualityOfGram<double>(terms.lifted[i], length); });
}

double MapEnergy::triangleEnergyBound(const TriangleTerms& terms) const
{
  const double w = this->Weights.mesh;
  return sumOfTerms(
    terms, this->T.numberOfInputs(), [&](int i) { return w * meshQualityBound(terms.lifted[i]); });
}

double MapEnergy::sampleEnergy(int i,
  int s,
  const MapVertex& a,
  const MapVertex& b,
  const MapVertex& c) const
{
  const ApproximationSampleSet& samples = this->T.surface(i).samples;
  const double d2 = squaredBaseDistance<double>(samples.spherePoints[s],
    samples.positions[s],
    { a.g[i], b.g[i], c.g[i] },
    { a.lifted[i], b.lifted[i], c.lifted[i] });
  return approximationEnergy<double>(
    d2, this->Weights.approximation * samples.weights[s], this->Weights.bound(i));
}

double MapEnergy::localEnergy(const std::vector<MapVertex>& vertices,
  const std::vector<std::array<int, 3>>& triangles,
  const std::vector<double>& triangleEnergies,
  const std::vector<std::vector<int>>& samples,
  LocalAssignment* assignment,
  std::vector<double>* perTriangle) const
{
  const int n = this->T.numberOfInputs();
  double energy = 0.0;
  for (double e : triangleEnergies)
  {
    energy += e;
  }
  if (perTriangle)
  {
    *perTriangle = triangleEnergies;
  }
  if (assignment)
  {
    assignment->assign(n, {});
  }
  if (this->T.tracksSamples() && !samples.empty())
  {
    for (int i = 0; i < n; ++i)
    {
      for (int s : samples[i])
      {
        const Eigen::Vector3d& q = this->T.surface(i).samples.spherePoints[s];
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
        if (this->Weights.approximation > 0.0)
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

void MapEnergy::updateFaceEnergies() const
{
  const int n = this->T.numberOfInputs();
  this->T.forEachFace(
    [this, n](OpenMesh::FaceHandle f, const MapVertex& a, const MapVertex& b, const MapVertex& c)
    {
      double energy = this->triangleEnergy(a, b, c, this->T.targetLength(f));
      if (this->T.tracksSamples() && this->Weights.approximation > 0.0)
      {
        for (int i = 0; i < n; ++i)
        {
          for (int s : this->T.faceSamples(f, i))
          {
            energy += this->sampleEnergy(i, s, a, b, c);
          }
        }
      }
      this->T.setFaceEnergy(f, energy);
    });
  this->T.setFaceEnergiesValid();
}

void MapEnergy::addInputTerms(const CommonTriangulation::Snapshot& s,
  int i,
  const std::vector<std::map<int, Eigen::Vector3d>>& landmarkTargets,
  Objective& objective) const
{
  const MapEnergyWeights& w = this->Weights;
  const int nv = s.vertices;
  if (w.barrier > 0.0)
  {
    BarrierEnergy barrier;
    barrier.triangles = s.triangles;
    barrier.offset = i * nv;
    barrier.scales = s.barrierScales[i].empty() ? nullptr : s.barrierScales[i].data();
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
  if (w.coverage > 0.0)
  {
    CoverageEnergy coverage{ &s.triangles, &s.lifts, s.densities[i].data(), i * nv };
    objective.addTerm(std::make_shared<ElementTerm<3, CoverageEnergy>>("coverage", coverage),
      w.coverage,
      group(MapTerm::MeshQuality));
  }
  if (w.approximation > 0.0 && this->T.tracksSamples())
  {
    ApproximationEnergy approximation;
    approximation.samples = &this->T.surface(i).samples;
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
    for (auto v : this->T.mesh().vertices())
    {
      const auto it = landmarkTargets[i].find(this->T.landmark(v));
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

void MapEnergy::buildObjective(const CommonTriangulation::Snapshot& s,
  const std::vector<std::map<int, Eigen::Vector3d>>& landmarkTargets,
  Objective& objective) const
{
  objective.clear();
  const MapEnergyWeights& w = this->Weights;
  const int nv = s.vertices;
  for (int i = 0; i < this->T.numberOfInputs(); ++i)
  {
    this->addInputTerms(s, i, landmarkTargets, objective);
  }
  if (w.map > 0.0 && w.mapToMean)
  {
    for (int i = 0; i < this->T.numberOfInputs(); ++i)
    {
      MeanShapeDistortionEnergy map{ &s.triangles, &s.lifts, &s.meanGrams, i * nv };
      objective.addTerm(std::make_shared<ElementTerm<3, MeanShapeDistortionEnergy>>("map", map),
        w.map,
        group(MapTerm::Distortion));
    }
  }
  else if (w.map > 0.0)
  {
    for (const auto& pair : this->T.pairs())
    {
      MapDistortionEnergy map{ &s.triangles, &s.lifts, pair[0] * nv, pair[1] * nv };
      objective.addTerm(std::make_shared<ElementTerm<6, MapDistortionEnergy>>("map", map),
        w.map,
        group(MapTerm::Distortion));
    }
  }
}

double MapEnergy::total() const
{
  CommonTriangulation::Snapshot s;
  SpherePoints points;
  this->T.snapshot(s, points, false, this->Weights);
  Objective objective;
  this->buildObjective(s, {}, objective);
  return objective.value(points);
}

} // namespace surfacemaps
