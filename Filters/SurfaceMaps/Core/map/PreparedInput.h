// SurfaceMaps engine: an input as the map's energy sees it.
#pragma once

#include "base/Log.h"
#include "energy/ApproximationEnergy.h"
#include "energy/LiftedPoint.h"
#include "geometry/SphereLocator.h"
#include "map/MapInput.h"

#include <Eigen/Core>

#include <array>
#include <map>
#include <memory>
#include <vector>

namespace surfacemaps
{

/// One input, centred and scaled to unit area, with its fixed embedding.
struct PreparedInput
{
  std::vector<Eigen::Vector3d> points;
  std::vector<std::array<int, 3>> triangles;
  std::vector<Eigen::Vector3d> sphere;
  /// The lift of every triangle (sphere -> surface), built once.
  std::vector<Lift> lifts;
  /// Per triangle: its area on the input over its chord triangle's area on
  /// the sphere (how much input a unit of sphere carries there).
  std::vector<double> density;
  std::unique_ptr<SphereLocator> locator;
  /// Target edge length per vertex, unit-area units (set per phase).
  std::vector<double> sizing;
  /// The sizing is the user's (MapInput::sizing): no phase replaces it.
  bool userSizing = false;
  /// Landmark id per vertex (-1 none), may be empty.
  std::vector<int> landmarks;
  ApproximationSampleSet samples;
  /// original = points / scale + centre.
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double scale = 1.0;
  /// The caller's index of this input (the engine may map the inputs in
  /// another order, MappingOrder.h): what messages call it.
  int label = 0;

  /// Sizing at a point of triangle t with barycentric weights w.
  double sizingAt(int t, const std::array<double, 3>& w) const;
};

/// The inputs as the energy sees them: centred, unit area, the embeddings
/// of inputs 1.. rotated onto input 0's through the landmarks, lifts and
/// approximation samples (at most `samples` per input; 0: every vertex).
/// `landmarks`: landmarkVertices(inputs); `labels`: the caller's index of
/// each input (PreparedInput::label; empty: their places).
/// The surfaces refer to their own members: keep the returned vector as it
/// is (no insertion) while a CommonTriangulation uses it. Throws
/// std::invalid_argument when an input's arrays do not fit its mesh, it has
/// no area, or the landmark ids do not correspond.
std::vector<PreparedInput> prepareInputs(const std::vector<MapInput>& inputs,
  const std::vector<std::map<int, int>>& landmarks,
  int samples,
  const Logger& log = Logger(),
  const std::vector<int>& labels = {});

/// Turns the embedding of a prepared input by `rotation` (its sphere
/// points, samples, lifts and locator) if the turned embedding certifies
/// bijective; false (and the input unchanged) otherwise.
bool rotateEmbedding(PreparedInput& s, const Eigen::Matrix3d& rotation);

/// Landmark id -> vertex of each input; every id must be on every input
/// (std::invalid_argument otherwise, naming the input and the id).
std::vector<std::map<int, int>> landmarkVertices(const std::vector<MapInput>& inputs);

/// Throws InputError naming the input, the vertex and both lengths when a
/// user sizing asks for edges shorter than minEdgeLength (unit-area units):
/// far below it the mesh-quality term overflows and nothing can be
/// optimised, and just below it T outgrows any vertex budget; the curvature
/// sizing is clamped to the same length.
void requireUsableSizing(const std::vector<PreparedInput>& surfaces, double minEdgeLength);

/// Recomputes the curvature sizing of every surface without a user sizing
/// for the approximation error eps (DESIGN.md section 1.7), edge lengths
/// clamped to [minEdgeLength, maxEdgeLength].
void setCurvatureSizing(std::vector<PreparedInput>& surfaces,
  double eps,
  double minEdgeLength,
  double maxEdgeLength);

/// Multiplies each vertex's sizing by the smallest factor on its one-ring
/// (factor: per vertex, 1 = unchanged).
void scaleSizingAround(PreparedInput& surface, const std::vector<double>& factor);

/// Landmark id -> the landmark's point on each input's (aligned) sphere.
std::vector<std::map<int, Eigen::Vector3d>> landmarkTargets(
  const std::vector<PreparedInput>& surfaces);

} // namespace surfacemaps
