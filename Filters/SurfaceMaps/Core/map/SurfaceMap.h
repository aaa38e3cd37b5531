// SurfaceMaps engine: bijective maps between N genus-0 surfaces through an
// adaptive common triangulation (DESIGN.md sections 1.2-1.8).
#pragma once

#include "map/CommonTriangulation.h"
#include "base/Aborted.h"
#include "base/Log.h"
#include "mesh/PolygonMesh.h"
#include "geometry/SphericalTriangulation.h"

#include <Eigen/Core>

#include <array>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace surfacemaps
{

/// One input surface with its fixed sphere embedding.
struct MapInput
{
  /// Closed genus-0 triangle mesh (validated), in the input's own units.
  PolygonMesh mesh;
  /// Certified bijective sphere embedding f_i, one unit vector per vertex.
  std::vector<Eigen::Vector3d> spherePositions;
  /// Landmark id per vertex, -1 for none (empty: no landmarks). The same id
  /// on two inputs means the two vertices correspond.
  std::vector<int> landmarks;
  /// Target edge length per vertex in the input's own units (empty: from
  /// curvature, DESIGN.md section 1.7).
  std::vector<double> sizing;
};

/// Which pairs of inputs the map-distortion term measures.
enum class PairMode
{
  Star,     ///< (0, i) for every i > 0 (default)
  Sequence, ///< (i, i + 1)
  Cycle,    ///< (i, i + 1) and (N - 1, 0)
  All,      ///< every pair i < j
};

/// The pairs (i, j) of a mode for n inputs.
std::vector<std::array<int, 2>> mapPairs(PairMode mode, int n);

/// Parameters of one phase of the schedule.
struct MapPhaseOptions
{
  /// Run this phase at all.
  bool enabled = true;
  /// Iteration cap (one iteration = splits, collapses, flips, one Newton step).
  int maxIterations = 50;
  /// Approximation tolerance eps in unit-area units: weight 1/eps^2 of the
  /// approximation term, and the curvature sizing's error.
  double targetError = 1e-3;
  /// Weight of the bijectivity barrier.
  double barrierWeight = 1e-6;
};

struct SurfaceMapProgress
{
  /// "landmarks", "coarse", "fine", "refine" and "bound" (maxError),
  /// "output".
  std::string phase;
  int iteration = 0;
  /// Fraction of the whole schedule's iterations done (0..1).
  double fraction = 0.0;
  int vertices = 0;
  double energy = 0.0;
};

struct SurfaceMapOptions
{
  PairMode pairs = PairMode::Star;
  /// Landmark phase: barrier (weight landmarkBarrierWeight) + landmarks
  /// (landmarkWeight), ends when every landmark is within landmarkTolerance
  /// on its sphere or at the iteration cap. Skipped without landmarks.
  int landmarkIterations = 100;
  double landmarkWeight = 1e6;
  double landmarkBarrierWeight = 1.0;
  double landmarkTolerance = 1e-4;
  /// Once every landmark is reached, keep going in the landmark phase with
  /// Newton steps and flips only (no splits, no collapses) until it has
  /// converged or reaches its cap: the barrier then relaxes T's embeddings
  /// around the moved landmarks (a smooth initial map instead of a squeezed
  /// ring around each landmark). Otherwise the phase ends as soon as the
  /// landmarks are reached (the reference implementation's rule).
  bool relaxLandmarkPhase = true;
  /// After the landmark phase: lock the landmark vertices (snapped exactly
  /// onto their input vertices) or release them to the optimisation.
  bool keepLandmarks = true;
  /// Coarse and fine phases (DESIGN.md section 1.6).
  MapPhaseOptions coarse{ true, 50, 1e-2, 1e-3 };
  MapPhaseOptions fine{ true, 50, 1e-3, 1e-6 };
  /// Term weights (DESIGN.md section 1.3; the paper's are all 1). Mesh 0.5
  /// and approximation 0.25 gave lower distortion on both shared benchmark
  /// pairs and builds (README, "Surface map"): our approximation term fits T
  /// closer to the inputs than the reference implementation's at weight 1.
  double meshWeight = 0.5;
  double mapWeight = 1.0;
  double approximationWeight = 0.25;
  /// Error-bounded remeshing (0: off): the largest distance allowed between
  /// an input vertex and its base point on T (DESIGN.md 1.3), as a fraction
  /// of that input's bounding-box diagonal. After the fine phase, rounds of
  /// boundRefinementIterations iterations with the sizing halved around the
  /// vertices beyond boundMargin * bound run until none is left (at most
  /// boundRefinementRounds); then boundIterations iterations with the hard
  /// bound (a barrier infinite at the bound) instead of the soft term. The
  /// bound is certified on every input vertex at the end; every vertex is a
  /// sample then (approximationSamples does not apply).
  double maxError = 0.0;
  int boundRefinementRounds = 8;
  int boundRefinementIterations = 10;
  double boundMargin = 0.9;
  int boundIterations = 20;
  /// Input vertices per input the approximation term uses at most (a fixed,
  /// evenly spread subsample of larger inputs).
  int approximationSamples = 50000;
  /// Curvature sizing clamp, unit-area units.
  double minEdgeLength = 1e-3;
  double maxEdgeLength = 100.0;
  /// A phase has converged when no edit lowers the energy and the Newton
  /// decrement is below this.
  double decrementTolerance = 1e-4;
  /// Largest tangent step of one point per Newton step, and the one used
  /// once T has largeMeshVertices vertices. Both tan 10 degrees: the reference
  /// implementation's tan 75 below 4 000 vertices let single points take
  /// huge steps that the line search then cut down by 20-50 trials, and the
  /// hands pair ended at SD 1.163 instead of 1.077 (61 <-> 248: 1.265 vs
  /// 1.269, the same).
  double maxPointStep = 0.17632698070846498;
  double maxPointStepLarge = 0.17632698070846498;
  int largeMeshVertices = 4000;
  /// Newton steps of the coarse and fine phases that the line search cuts
  /// to less than a tenth are retried with the points held that make the
  /// energy leave its model (kinks of the approximation term where a sample
  /// crosses into a T triangle much smaller on the sphere than on the
  /// surface), up to this many times per iteration (0: off). With the old
  /// approximation Hessian (eigenvalue clamp) the hands pair's fine phase
  /// stopped moving at iteration 40 of 50 without it; with the Gauss-Newton
  /// one the phase keeps moving, and one retry per step cost the hands 3-4 s
  /// for no better map (README, "Surface map"), hence off by default.
  int kinkRetries = 0;
  /// After the fine phase, up to refinementRounds rounds (0: off; no round
  /// without a fine phase) of refinementIterations more iterations (at most
  /// the fine phase's cap) with the fine phase's settings, each after
  /// shrinking the sizing around the input triangles whose
  /// exact-map distortion (input i -> input j, for the map term's pairs)
  /// exceeds a threshold: refinementDistortion in the first round,
  /// squeezeDistortion in the later ones. The first round gives T more
  /// vertices where the map is distorted (a1.5 0.982 -> 0.992 on the hands,
  /// 0.776 -> 0.784 on 61 <-> 248, README "Surface map"); the later ones
  /// only repair squeezes: T's own map cannot see inside its triangles,
  /// where the two sphere embeddings can squeeze a whole input triangle
  /// (hands: one triangle at distortion 65 made the exact map's SD 1.131
  /// instead of about 1.06). Rounds stop when there is none. The first
  /// round halves the sizing only where little of the input is distorted:
  /// with a fraction `area` of it above refinementDistortion the sizing
  /// shrinks by 1 / sqrt(1 + refinementGrowth / area), at most by half (the
  /// hands: 4 % above 1.4, halved; 61 <-> 248: 34 %, times 0.76); the later
  /// rounds halve it. refinementDistortion 10 gives the behaviour before
  /// 2026-11-23 (only squeezes refined).
  int refinementRounds = 3;
  int refinementIterations = 10;
  double refinementDistortion = 1.4;
  double squeezeDistortion = 10.0;
  double refinementGrowth = 0.25;
  /// Called once per iteration; return false to abort.
  std::function<bool(const SurfaceMapProgress&)> progress;
  Logger log;
};

/// What one phase did.
struct MapPhaseReport
{
  std::string name;
  int iterations = 0;
  /// No edit lowered the energy and the decrement was below tolerance
  /// (otherwise the phase stopped at its cap, which is normal).
  bool converged = false;
  double energy = 0.0;
  int splits = 0, collapses = 0, flips = 0;
  int vertices = 0;
  /// Landmark phase: largest distance of a landmark to its target on a sphere.
  double landmarkError = 0.0;
  double seconds = 0.0;
  double remeshSeconds = 0.0;
  double derivativeSeconds = 0.0;
  double solveSeconds = 0.0;
  double lineSearchSeconds = 0.0;
  /// Everything else per iteration: target lengths, the flat copy of T and
  /// the objective, re-locating lifts and samples, writing back.
  double bookkeepingSeconds = 0.0;
};

/// A point of input i given by a triangle of input i and barycentric
/// coordinates (alpha, beta, gamma) of its corners.
struct SurfacePoint
{
  int triangle = -1;
  Eigen::Vector3d barycentric = Eigen::Vector3d::Zero();
};

struct SurfaceMapResult
{
  /// The common triangulation T (same connectivity on every input).
  std::vector<std::array<int, 3>> triangles;
  /// Per input i: T's sphere embedding g_i, T lifted onto input i (original
  /// coordinates), and where each lifted vertex lies on input i.
  std::vector<std::vector<Eigen::Vector3d>> spherePositions;
  std::vector<std::vector<Eigen::Vector3d>> lifted;
  std::vector<std::vector<SurfacePoint>> sourcePoints;
  /// Per input: the embedding f_i as used (inputs 1.. rotated onto input 0
  /// through the landmarks), in the frame of spherePositions.
  std::vector<std::vector<Eigen::Vector3d>> inputSpherePositions;
  /// Landmark id per T vertex (-1 none).
  std::vector<int> landmarks;
  /// Per input: certificate of T's embedding g_i (all must be bijective).
  std::vector<BijectivityCertificate> certificates;
  /// Per input j: the exact map applied to input 0's vertices (input 0 on
  /// input j, original coordinates of j) and where those points lie on j.
  std::vector<std::vector<Eigen::Vector3d>> mappedFirst;
  std::vector<std::vector<SurfacePoint>> mappedFirstSource;
  /// Final energy and its terms: barrier, mesh quality, approximation,
  /// map distortion (weighted as in the last phase, unweighted values).
  double energy = 0.0;
  double barrierEnergy = 0.0, meshEnergy = 0.0, approximationEnergy = 0.0, mapEnergy = 0.0;
  std::vector<MapPhaseReport> phases;
  /// Per input: the largest distance of an input vertex (of the
  /// approximation samples: every vertex with maxError) from its base point
  /// on T, and the bound it had to meet (0 without maxError); original units.
  std::vector<double> baseDistance;
  std::vector<double> errorBound;
  /// Largest distance of a kept landmark from its input vertex (original
  /// units of each input, maximum over inputs): 0 when snapped exactly.
  double landmarkError = 0.0;
  double seconds = 0.0;
};

/// Computes a bijective map between the inputs through an adaptive common
/// triangulation: landmark phase, coarse and fine phases of splits,
/// collapses, flips and projected Newton steps on the N embeddings of T.
/// Inputs are centred and scaled to unit area internally; results are in
/// the inputs' own coordinates. Throws std::invalid_argument on inconsistent
/// input (sizes, landmark ids) and std::runtime_error when the result
/// cannot be certified bijective.
SurfaceMapResult computeSurfaceMap(const std::vector<MapInput>& inputs,
  const SurfaceMapOptions& options = SurfaceMapOptions());

/// The inputs as the energy sees them (centred, unit area, embeddings of
/// inputs 1.. rotated onto input 0's through the landmarks, lifts, samples).
/// The surfaces refer to their own members: keep the returned vector as it is
/// (no insertion) while a CommonTriangulation uses it. Exposed for tests.
std::vector<MapSurface> prepareMapSurfaces(const std::vector<MapInput>& inputs,
  const SurfaceMapOptions& options = SurfaceMapOptions());

/// Landmark id -> the landmark's point on each input's (aligned) sphere.
std::vector<std::map<int, Eigen::Vector3d>> landmarkTargets(
  const std::vector<MapSurface>& surfaces);

} // namespace surfacemaps
