// SurfaceMaps engine: the common triangulation T with its N sphere embeddings
// and the energy of DESIGN.md section 1.3 (defined in CommonTriangulation.cxx:
// connectivity, vertex data, samples; CommonTriangulationEnergy.cxx: local
// energies and the objective; CommonTriangulationSnapshot.cxx: the flat copy
// the Newton step works on).
#pragma once

#include "energy/ApproximationEnergy.h"
#include "energy/LiftedPoint.h"
#include "geometry/SphereLocator.h"
#include "map/PreparedInput.h"
#include "mesh/HalfedgeMesh.h"
#include "optimisation/Objective.h"
#include "optimisation/SpherePoints.h"

#include <Eigen/Core>

#include <boost/container/small_vector.hpp>

#include <array>
#include <map>
#include <memory>
#include <vector>

namespace surfacemaps
{

/// The terms of the map's energy (DESIGN.md section 1.3), as the objective
/// groups them (Objective::group).
enum class MapTerm
{
  Barrier,
  MeshQuality, ///< with the coverage term (CoverageEnergy)
  Approximation,
  Landmarks,
  Distortion,
};

/// Weights of the energy's terms, already divided by the number of inputs
/// (or pairs) as in DESIGN.md section 1.3 (0: term off).
struct MapEnergyWeights
{
  double barrier = 0.0;
  double mesh = 0.0;
  double approximation = 0.0; // includes 1 / eps^2 for the soft term
  double landmark = 0.0;
  double map = 0.0;
  /// Coverage (CoverageEnergy), in the mesh-quality group.
  double coverage = 0.0;
  /// Hard approximation bound per input (unit-area units of that input);
  /// empty: the soft term. With a bound, `approximation` is the barrier's
  /// weight (no 1 / eps^2).
  std::vector<double> bounds;
  double bound(int i) const { return this->bounds.empty() ? 0.0 : this->bounds[i]; }
  /// > 1: a triangle that inverts on a sphere at the full Newton step gets
  /// its barrier weight on that sphere multiplied by this, up to
  /// MaxBarrierRaises times (see CommonTriangulation::raiseBarrier); 1: one
  /// weight for every triangle.
  double barrierRaise = 1.0;
  /// Project the barrier's exact Hessian (eigenvalue clamp) instead of using
  /// its cheap Gauss-Newton form; worth it where the barrier dominates (the
  /// landmark phase), not where its weight is tiny.
  bool exactBarrierHessian = false;
};

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

  /// The energy weights in use; changing them changes every energy below.
  MapEnergyWeights weights;
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

  /// The weighted per-triangle terms of one triangle that do not depend on
  /// its target length, and its lifted triangles' Gram entries (which the
  /// mesh-quality term needs with the length). Remeshing computes them once
  /// and asks two questions: triangleEnergyBound before it walks on the
  /// spheres for the length, triangleEnergy after.
  struct TriangleTerms
  {
    bool valid = true; ///< false: a barrier term is infinite
    PerInput<double> barrier, coverage;
    PerInput<std::array<double, 3>> lifted;
    /// Per pair of the map distortion term.
    PerInput<double> map;
  };
  TriangleTerms triangleTerms(const MapVertex& a, const MapVertex& b, const MapVertex& c) const;

  /// Energy of the per-triangle terms (barrier, mesh quality, coverage, map
  /// distortion) of one triangle, weighted; +inf if invalid.
  double triangleEnergy(const TriangleTerms& terms, double length) const;
  double triangleEnergy(const MapVertex& a,
    const MapVertex& b,
    const MapVertex& c,
    double length) const
  {
    return this->triangleEnergy(this->triangleTerms(a, b, c), length);
  }
  /// A lower bound of triangleEnergy(terms, length) over every length, with
  /// the same terms summed in the same order (so it holds in floating point
  /// as well): the mesh-quality term at its smallest value over lengths
  /// (meshQualityBound). Every term is >= 0, so a sum of bounds that already
  /// exceeds what an edit may cost rejects it without any target length.
  double triangleEnergyBound(const TriangleTerms& terms) const;
  /// Weighted approximation energy of sample s of input i in a triangle.
  double sampleEnergy(int i,
    int s,
    const MapVertex& a,
    const MapVertex& b,
    const MapVertex& c) const;

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

  /// Energy of a local configuration: triangles over `vertices` whose
  /// triangleEnergy values are `triangleEnergies`, plus the samples of each
  /// input (which must lie in the union of the triangles on that input's
  /// sphere). `assignment`, if given, receives the local triangle of each
  /// sample; a sample in no triangle makes the configuration invalid (+inf).
  /// `perTriangle`, if given, receives each triangle's energy with its
  /// samples'.
  double localEnergy(const std::vector<MapVertex>& vertices,
    const std::vector<std::array<int, 3>>& triangles,
    const std::vector<double>& triangleEnergies,
    const std::vector<std::vector<int>>& samples,
    LocalAssignment* assignment,
    std::vector<double>* perTriangle = nullptr) const;

  /// Energy of each face (its per-triangle terms plus its samples' terms),
  /// cached for a remeshing round: remeshing reads the energy an edit removes
  /// from here instead of recomputing it, and stores the new faces' energies.
  /// Valid only while no vertex moves and the weights stay the same.
  void updateFaceEnergies();
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
  };
  /// Garbage-collects the mesh and fills a snapshot and the sphere points
  /// (g of input i at i * vertices + v); landmark vertices are locked when
  /// `lockLandmarks`.
  void snapshot(Snapshot& snapshot, SpherePoints& points, bool lockLandmarks);
  /// Re-locates lifts and sample triangles for moved points (parallel
  /// walks); false if an embedding's degree is not 1.
  bool update(Snapshot& snapshot, const SpherePoints& points) const;
  /// The points (snapshot numbering) of the triangles that are not positively
  /// oriented on their sphere at `points` (exact predicate, as update()
  /// decides), ascending and unique.
  std::vector<int> invertedCorners(const Snapshot& snapshot, const SpherePoints& points) const;
  /// How often a triangle's barrier weight on one sphere is raised at most.
  static constexpr int MaxBarrierRaises = 3;
  /// Raises the barrier weight (by weights.barrierRaise, up to
  /// MaxBarrierRaises times per triangle and sphere) of the snapshot's
  /// triangles that are not positively oriented at `points`, a Newton step's
  /// full trial. The step is cut by the few triangles it runs through: their
  /// barrier at the fine phase's tiny weight is too flat for the Newton model
  /// to see the wall, so step after step aims through it. Raised where it
  /// blocked, the barrier's curvature steers the next steps along the wall;
  /// the barrier stays tiny everywhere else. A triangle made by an edit
  /// starts unraised (clearBarrierRaise); remeshing compares energies without
  /// the raise.
  void raiseBarrier(const Snapshot& snapshot, const SpherePoints& points);
  void clearBarrierRaise(OpenMesh::FaceHandle f);
  /// Writes moved points, lifts and sample assignments back into the mesh.
  void writeBack(const Snapshot& snapshot, const SpherePoints& points);

  /// Builds the objective of the current weights over a snapshot (the
  /// snapshot must outlive the objective's use), each term in the group of
  /// its MapTerm. Landmark targets per input.
  void buildObjective(const Snapshot& snapshot,
    const std::vector<std::map<int, Eigen::Vector3d>>& landmarkTargets,
    Objective& objective) const;

  /// Total energy (weighted) from the mesh, for tests of local changes.
  double totalEnergy();

private:
  /// Moves vertex v on sphere i to g in input i's triangle liftTriangle
  /// (the only writer of a vertex's sphere point, lift triangle and lift,
  /// and of its mesh point: the lift onto input 0).
  void setSpherePoint(OpenMesh::VertexHandle v, int i, const Eigen::Vector3d& g, int liftTriangle);
  void assignSamplesFromScratch();
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
  // The surfaces' triangle neighbours, for walks.
  std::vector<std::vector<std::array<int, 3>>> SurfaceNeighbours;
};

} // namespace surfacemaps
