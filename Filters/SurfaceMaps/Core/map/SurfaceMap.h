// SurfaceMaps engine: bijective maps between N genus-0 surfaces through an
// adaptive common triangulation (DESIGN.md sections 1.2-1.8).
#pragma once

#include "base/Aborted.h"
#include "geometry/SphericalTriangulation.h"
#include "map/MapInput.h"
#include "map/MapOptions.h"
#include "map/MapPhase.h"
#include "mesh/SurfacePoint.h"

#include <Eigen/Core>

#include <array>
#include <string>
#include <vector>

namespace surfacemaps
{

/// Energy of the final map by term, unweighted (DESIGN.md section 1.3).
struct MapEnergies
{
  /// The weighted total of the last phase's energy.
  double total = 0.0;
  double barrier = 0.0, meshQuality = 0.0, approximation = 0.0, distortion = 0.0;
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
  MapEnergies energy;
  std::vector<MapPhaseReport> phases;
  /// Per input: the largest distance of an input vertex (of the
  /// approximation samples: every vertex with maxError) from its base point
  /// on T, and the bound it had to meet (0 without maxError); original units.
  std::vector<double> baseDistance;
  std::vector<double> errorBound;
  /// Largest distance of a kept landmark from its input vertex (original
  /// units of each input, maximum over inputs): 0 when snapped exactly.
  double landmarkError = 0.0;
  /// Landmark ids set aside as guides (landmarksAsGuides): the shapes alone
  /// did not confirm them, so they did not bind the map, and the map puts
  /// their partners farther than the tolerance from them.
  std::vector<int> setAsideLandmarks;
  double seconds = 0.0;
};

/// Computes a bijective map between the inputs through an adaptive common
/// triangulation: the schedule of phases (Schedule.h) of splits, collapses,
/// flips and projected Newton steps on the N embeddings of T, the
/// refinements after it, then T certified and lifted onto every input.
/// Inputs are centred and scaled to unit area internally; results are in the
/// inputs' own coordinates. Throws InputError on inconsistent input (sizes,
/// landmark ids), NoResultError when the result cannot be certified
/// bijective (or within the error bound), Aborted when the progress
/// callback stops it; anything else is an internal failure.
SurfaceMapResult computeSurfaceMap(const std::vector<MapInput>& inputs,
  const SurfaceMapOptions& options = SurfaceMapOptions());

/// The energy of T under `weights` (a phase's), by term.
MapEnergies energyByTerm(CommonTriangulation& T, const MapEnergyWeights& weights);

/// Distance on the unit sphere beyond which a landmark the landmark phase
/// left behind is far from its target: a phase stopped by its cap is
/// normally within about 1e-3, while landmark sets that do not correspond (a
/// permuted order) leave their landmarks about a radius away.
constexpr double FarLandmarkDistance = 0.05;

/// A warning for the user when the landmark phase of `map` ended with a
/// landmark farther than FarLandmarkDistance from its target (the landmarks
/// cannot all be reached bijectively: the sets do not correspond, e.g. one
/// is in another order); empty otherwise. The map itself goes on.
std::string landmarkPhaseWarning(const SurfaceMapResult& map);

/// The vertices of input `from` mapped onto input `to` by the exact map of
/// `map` (computed from `inputs`): transferPoints (MapTransfer.h) with
/// f_from's points, the lifts of T on `to` as start triangles, the identity
/// when from == to.
std::vector<SurfacePoint> transferVertices(const SurfaceMapResult& map,
  const std::vector<MapInput>& inputs,
  int from,
  int to);

/// The vertices of input `from` mapped onto input `to` (transferVertices),
/// as points in input `to`'s original coordinates: input `from` on input `to`.
std::vector<Eigen::Vector3d> mappedVertices(const SurfaceMapResult& map,
  const std::vector<MapInput>& inputs,
  int from,
  int to);

} // namespace surfacemaps
