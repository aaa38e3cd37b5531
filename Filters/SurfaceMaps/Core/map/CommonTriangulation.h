// SurfaceMaps engine: the common triangulation T with its N sphere embeddings
// (DESIGN.md section 1.2): connectivity, per-vertex data (sphere points,
// lifts, landmarks), per-face data (target lengths, samples, barrier raises,
// the cached face energies) and the flat copy the Newton step works on
// (CommonTriangulationSnapshot.cxx). The energy over it is MapEnergy's.
#pragma once

#include "energy/ApproximationEnergy.h"
#include "energy/LiftedPoint.h"
#include "geometry/SphereLocator.h"
#include "map/MapEnergyWeights.h"
#include "map/PreparedInput.h"
#include "mesh/HalfedgeMesh.h"
#include "optimisation/SpherePoints.h"

#include <Eigen/Core>

#include <boost/container/small_vector.hpp>

#include <array>
#include <map>
#include <memory>
#include <vector>

namespace surfacemaps
{

/// Per-input values of one vertex. Remeshing copies vertex data for every
/// candidate edit it evaluates, so the values of up to four inputs live
/// inside the object instead of on the heap (Boost comes with CGAL; the
/// standard library has no small vector).
template<typename Value>
using PerInput = boost::container::small_vector<Value, 4>;

/// A vertex of T as the local energy sees it: per input its sphere point, its
/// lift triangle on that input and its lifted position.
struct MapVertex
{
  PerInput<Eigen::Vector3d> g, lifted;
  PerInput<int> liftTriangle;
  int landmark = -1;
};

/// Where the samples of each input lie in a local set of triangles.
using LocalAssignment = std::vector<std::vector<int>>;

/// The common triangulation and everything its energy needs. Vertex and face
/// data live in OpenMesh properties so that edits and garbage collection keep
/// them consistent.
class CommonTriangulation
{
public:
  /// T := copy of input 0 with g_i := f_0 for every input i.
  CommonTriangulation(std::vector<PreparedInput>& surfaces, std::vector<std::array<int, 2>> pairs);

  int numberOfInputs() const { return static_cast<int>(this->Surfaces.size()); }
  PreparedInput& surface(int i) { return this->Surfaces[i]; }
  const PreparedInput& surface(int i) const { return this->Surfaces[i]; }
  const std::vector<std::array<int, 2>>& pairs() const { return this->Pairs; }
  HalfedgeMesh& mesh() { return this->Mesh; }
  const HalfedgeMesh& mesh() const { return this->Mesh; }

  const Eigen::Vector3d& g(OpenMesh::VertexHandle v, int i) const
  {
    return this->Mesh.property(this->G[i], v);
  }
  int liftTriangle(OpenMesh::VertexHandle v, int i) const
  {
    return this->Mesh.property(this->LiftTriangle[i], v);
  }
  int landmark(OpenMesh::VertexHandle v) const { return this->Mesh.property(this->Landmark, v); }
  void setLandmark(OpenMesh::VertexHandle v, int id)
  {
    this->Mesh.property(this->Landmark, v) = id;
  }
  double targetLength(OpenMesh::FaceHandle f) const { return this->Mesh.property(this->Length, f); }
  void setTargetLength(OpenMesh::FaceHandle f, double length)
  {
    this->Mesh.property(this->Length, f) = length;
  }
  std::vector<int>& faceSamples(OpenMesh::FaceHandle f, int i)
  {
    return this->Mesh.property(this->Samples[i], f);
  }
  const std::vector<int>& faceSamples(OpenMesh::FaceHandle f, int i) const
  {
    return this->Mesh.property(this->Samples[i], f);
  }

  /// A vertex's data, and setting it (the vertex moves on every sphere).
  MapVertex vertex(OpenMesh::VertexHandle v) const;
  void setVertex(OpenMesh::VertexHandle v, const MapVertex& data);
  /// A new vertex at the normalised midpoint of u and v on every sphere.
  MapVertex midpoint(OpenMesh::VertexHandle u, OpenMesh::VertexHandle v) const;
  /// That midpoint's point on sphere i.
  Eigen::Vector3d sphereMidpoint(OpenMesh::VertexHandle u, OpenMesh::VertexHandle v, int i) const
  {
    return (this->Mesh.property(this->G[i], u) + this->Mesh.property(this->G[i], v)).normalized();
  }
  /// Moves vertex data to sphere points g (per input), locating them on the
  /// inputs by a walk from the current lift triangles.
  void relocate(MapVertex& vertex) const;

  /// The first `count` inputs' embeddings are fixed: snapshot() locks their
  /// points, so only the other inputs' embeddings move (AddToMap.h).
  void setFrozenInputs(int count) { this->FrozenInputs = count; }
  int frozenInputs() const { return this->FrozenInputs; }

  /// Whether samples are assigned to faces (off while the approximation term
  /// is off: the landmark phase). Turning it on assigns them from scratch.
  bool tracksSamples() const { return this->TrackSamples; }
  void setTrackSamples(bool track);

  /// Target length of a triangle with these corners: the smallest over the
  /// inputs of the sizing at its centroid on each sphere (DESIGN.md 1.3).
  double targetLength(const MapVertex& a, const MapVertex& b, const MapVertex& c) const;
  /// Recomputes every face's target length (once per iteration).
  void updateTargetLengths();

  /// Input i's area per sphere area under a triangle of T: the mean over its
  /// corners' lift triangles a, b, c of input i (CoverageEnergy's density).
  double coverageDensity(int i, int a, int b, int c) const;

  /// Distance of every approximation sample of input i from its base point
  /// on T (unit-area units), in the faces the samples are assigned to.
  std::vector<double> baseDistances(int i) const;

  /// Whether a triangle is positively oriented (exact predicate) with
  /// det > minDet on every sphere: what a new triangle must be.
  bool validTriangle(const MapVertex& a, const MapVertex& b, const MapVertex& c) const;
  /// The same test on one sphere.
  static bool validOnSphere(const Eigen::Vector3d& a,
    const Eigen::Vector3d& b,
    const Eigen::Vector3d& c);
  /// Vertex v's point on sphere i.
  const Eigen::Vector3d& spherePoint(OpenMesh::VertexHandle v, int i) const
  {
    return this->Mesh.property(this->G[i], v);
  }

  /// Energy of each face (its per-triangle terms plus its samples' terms)
  /// under one phase's energy, cached for a remeshing round
  /// (MapEnergy::updateFaceEnergies): remeshing reads the energy an edit
  /// removes from here instead of recomputing it, and stores the new faces'
  /// energies. Valid only while no vertex moves and the phase stays.
  void setFaceEnergiesValid() { this->FaceEnergiesValid = true; }
  void invalidateFaceEnergies() { this->FaceEnergiesValid = false; }
  bool faceEnergiesValid() const { return this->FaceEnergiesValid; }
  double faceEnergy(OpenMesh::FaceHandle f) const { return this->Mesh.property(this->Energy, f); }
  void setFaceEnergy(OpenMesh::FaceHandle f, double energy)
  {
    this->Mesh.property(this->Energy, f) = energy;
  }
  static constexpr double minDet = 1e-16;

  /// A flat copy of T for the Newton step and for global evaluations.
  struct Snapshot
  {
    int vertices = 0;
    std::vector<std::array<int, 3>> triangles;
    std::vector<std::array<int, 3>> neighbours;
    /// Triangles with point indices of each embedding (offset i * vertices).
    std::vector<std::vector<std::array<int, 3>>> embeddedTriangles;
    std::vector<double> lengths;
    /// Per input and triangle: the coverage density (held within a step).
    std::vector<std::vector<double>> densities;
    /// Per point (i * vertices + v): lift triangle on input i and its lift.
    std::vector<int> liftTriangle;
    std::vector<const Lift*> lifts;
    /// Per input and sample: the T triangle containing it (if tracked).
    std::vector<std::vector<int>> sampleTriangle;
    /// Per input and triangle: the barrier weight's multiplier (empty when
    /// weights.barrierRaise is off).
    std::vector<std::vector<double>> barrierScales;
    /// Per triangle: the inputs' mean shape (meanGram of its lifted copies;
    /// filled when weights.mapToMean), held within a step.
    std::vector<std::array<double, 3>> meanGrams;
  };
  /// Garbage-collects the mesh and fills a snapshot and the sphere points
  /// (g of input i at i * vertices + v); landmark vertices are locked when
  /// `lockLandmarks`, every point of the frozen inputs always. The coverage densities, barrier
  /// scales and mean shape are filled where `weights` use them.
  void snapshot(Snapshot& snapshot,
    SpherePoints& points,
    bool lockLandmarks,
    const MapEnergyWeights& weights);
  /// Re-locates lifts and sample triangles for moved points (parallel
  /// walks); false if an embedding's degree is not 1.
  bool update(Snapshot& snapshot, const SpherePoints& points) const;
  /// The points (snapshot numbering) of the triangles that are not positively
  /// oriented on their sphere at `points` (exact predicate, as update()
  /// decides), ascending and unique.
  std::vector<int> invertedCorners(const Snapshot& snapshot, const SpherePoints& points) const;
  /// How often a triangle's barrier weight on one sphere is raised at most.
  static constexpr int MaxBarrierRaises = 3;
  /// Raises the barrier weight (by `raise` > 1, up to
  /// MaxBarrierRaises times per triangle and sphere) of the snapshot's
  /// triangles that are not positively oriented at `points`, a Newton step's
  /// full trial. The step is cut by the few triangles it runs through: their
  /// barrier at the fine phase's tiny weight is too flat for the Newton model
  /// to see the wall, so step after step aims through it. Raised where it
  /// blocked, the barrier's curvature steers the next steps along the wall;
  /// the barrier stays tiny everywhere else. A triangle made by an edit
  /// starts unraised (clearBarrierRaise); remeshing compares energies without
  /// the raise.
  void raiseBarrier(const Snapshot& snapshot, const SpherePoints& points, double raise);
  void clearBarrierRaise(OpenMesh::FaceHandle f);
  /// Writes moved points, lifts and sample assignments back into the mesh.
  void writeBack(const Snapshot& snapshot, const SpherePoints& points);

  /// Calls function(face, a, b, c) for every face with its corners' data,
  /// in parallel: function may write that face's properties only.
  template<typename Function>
  void forEachFace(Function function)
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

private:
  /// Moves vertex v on sphere i to g in input i's triangle liftTriangle
  /// (the only writer of a vertex's sphere point, lift triangle and lift,
  /// and of its mesh point: the lift onto input 0).
  void setSpherePoint(OpenMesh::VertexHandle v, int i, const Eigen::Vector3d& g, int liftTriangle);
  void assignSamplesFromScratch();
  std::vector<PreparedInput>& Surfaces;
  std::vector<std::array<int, 2>> Pairs;
  HalfedgeMesh Mesh;
  std::vector<OpenMesh::VPropHandleT<Eigen::Vector3d>> G;
  std::vector<OpenMesh::VPropHandleT<int>> LiftTriangle;
  // Per input, each vertex's lifted position, kept with G and LiftTriangle
  // by setSpherePoint: remeshing reads every vertex many times per pass.
  std::vector<OpenMesh::VPropHandleT<Eigen::Vector3d>> Lifted;
  OpenMesh::VPropHandleT<int> Landmark;
  OpenMesh::FPropHandleT<double> Length;
  // Per input, how often each face's barrier weight was raised.
  std::vector<OpenMesh::FPropHandleT<int>> BarrierRaises;
  OpenMesh::FPropHandleT<double> Energy;
  bool FaceEnergiesValid = false;
  std::vector<OpenMesh::FPropHandleT<std::vector<int>>> Samples;
  bool TrackSamples = false;
  int FrozenInputs = 0;
  // The surfaces' triangle neighbours, for walks.
  std::vector<std::vector<std::array<int, 3>>> SurfaceNeighbours;
};

} // namespace surfacemaps
