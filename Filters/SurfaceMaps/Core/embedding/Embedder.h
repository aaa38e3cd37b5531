// SurfaceMaps engine: Embedder, one attempt at a sphere embedding: the
// decimation hierarchy undone level by level (the coarsest level as a
// regular tetrahedron, each level's vertices placed, then global Newton
// iterations), and the final global iterations.
#pragma once

#include "embedding/Decimation.h"
#include "embedding/SphereEmbedding.h"

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace surfacemaps
{

struct EmbeddingEnergy;

/// The weights of one attempt (embedOnSphere's retries change them).
struct Attempt
{
  double barrierWeight;
  double distortionWeight;
  /// A level whose distortion ends above this abandons the attempt (only
  /// where a retry with a stronger barrier follows).
  double abandonAbove;
};

/// Thrown inside one attempt when it cannot continue; the next attempt runs.
struct AttemptFailed
{
  std::string reason;
};

/// The smallest ratio of a triangle's share of the sphere's chord area to its
/// share of the input's area (SphereEmbeddingResult::smallestAreaRatio).
double smallestAreaRatioOf(const std::vector<Eigen::Vector3d>& input,
  const std::vector<Eigen::Vector3d>& sphere,
  const std::vector<std::array<int, 3>>& triangles);

class Embedder
{
public:
  Embedder(const PolygonMesh& mesh,
    const DecimationResult& hierarchy,
    const SphereEmbeddingOptions& options);

  /// Fills result's positions, levels, Newton iterations, energy and times;
  /// throws AttemptFailed (or Aborted when options.progress says so).
  void run(const Attempt& attempt, SphereEmbeddingResult& result);

private:
  void placeTetrahedron();
  double undoLevel(int level,
    const Attempt& attempt,
    EmbeddingEnergy& energy,
    std::size_t& inserted,
    double levelEnergy,
    SphereEmbeddingResult& result);
  void placeLevel(int level, const EmbeddingEnergy& energy, SphereEmbeddingResult& result);
  void report(double fraction);
  double optimise(EmbeddingEnergy& energy,
    int iterations,
    double tolerance,
    SphereEmbeddingResult& result,
    std::array<double, 2> fractions,
    int extendedIterations = 0,
    double extendAbove = std::numeric_limits<double>::infinity(),
    int squeezedIterations = 0);

  const PolygonMesh& Mesh;
  const DecimationResult& Hierarchy;
  const SphereEmbeddingOptions& Options;
  std::vector<Eigen::Vector3d> Positions;
  std::vector<char> Active;
};

} // namespace surfacemaps
