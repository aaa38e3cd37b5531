// SurfaceMaps engine: turning one sphere embedding onto another without
// landmarks.
#pragma once

#include "base/Log.h"
#include "map/PreparedInput.h"

#include <Eigen/Core>

#include <vector>

namespace surfacemaps
{

/// How the rotation is searched (the defaults hold on the benchmark corpus's
/// four-legs and hands; the search costs about a second per input there).
struct RotationSearchOptions
{
  /// Sample vertices scored on each surface (an even stride over its
  /// approximation samples, weighted by area).
  int samples = 400;
  /// Grid: axis directions (a Fibonacci sphere) times turns about each.
  int directions = 96;
  int turns = 18;
  /// Grid minima at least `distinctAngle` (degrees) apart refined locally.
  int candidates = 4;
  double distinctAngle = 45.0;
  /// The local refinement stops below this step (degrees).
  double finestStep = 0.5;
};

struct RotationSearchResult
{
  /// Turns the moving embedding onto the fixed one (apply to its sphere points).
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  /// Rigid misfit of the initial map under `rotation` (unit-area units squared).
  double misfit = 0.0;
  /// The best refined candidate at least distinctAngle from `rotation`: its
  /// misfit (infinity if none) and its angle to `rotation` (degrees).
  double runnerUpMisfit = 0.0;
  double runnerUpAngle = 0.0;
};

/// The rotation R of `moving`'s sphere under which the initial map between
/// the two surfaces (the point at sphere point s of `fixed` to the point at
/// s of `moving`'s rotated sphere, and back) is most nearly a rigid motion:
/// the weighted Procrustes misfit of the mapped samples of both surfaces,
/// minimised over a grid of rotations and refined from its distinct best
/// cells. Without landmarks the embeddings' relative rotation is arbitrary
/// (each is built from its own decimation), and the optimisation only finds
/// the correspondence from a start in its basin; shapes of one kind are
/// nearly rigid copies of each other under the right correspondence, and a
/// rotation cannot mirror, so a symmetric shape cannot be matched back to
/// front. Needs both surfaces' locators and lifts (prepareInputs).
RotationSearchResult searchRotation(const PreparedInput& fixed,
  const PreparedInput& moving,
  const RotationSearchOptions& options = RotationSearchOptions());

/// Turns every input's embedding after the first onto input 0's by
/// searchRotation (keeping the embedding unrotated where the rotated one
/// does not certify), and warns, naming the input, when a distinct
/// rotation fits within `closeCall` (relative) of the chosen one: the
/// correspondence is then uncertain and a landmark or two would settle it.
void alignWithoutLandmarks(std::vector<PreparedInput>& surfaces,
  const Logger& log,
  double closeCall = 0.05,
  const RotationSearchOptions& options = RotationSearchOptions());

} // namespace surfacemaps
