// SurfaceMaps engine: refining T where the exact map is distorted.
#pragma once

#include "map/MapOptions.h"
#include "map/MapPhase.h"
#include "map/Schedule.h"

#include <optional>
#include <vector>

namespace surfacemaps
{

/// After the fine phase: rounds that measure the exact map of every pair of
/// the map term (input i -> input j through T; against the mean shape, each
/// input's map onto its own approximating mesh T_i instead) and shrink the
/// sizing around the input triangles whose distortion max(s1, 1/s2) exceeds
/// a threshold, each followed by a Refine phase. T's own map only sees T's vertices;
/// inside a T triangle the exact map follows the two sphere embeddings,
/// which can squeeze a whole input triangle where they differ.
///
/// The first round (threshold refinementDistortion) gives T more vertices
/// where the map is distorted: with a fraction `area` of input i above the
/// threshold, the sizing there shrinks by 1 / sqrt(1 + refinementGrowth /
/// area), at most by half, so a pair distorted nearly everywhere does not
/// quadruple T. The later rounds only iterate, with the sizing as it is,
/// while the exact map still squeezes an input triangle (distortion above
/// squeezeDistortion). Rounds end when none is found, after
/// refinementRounds, and never run without pairs or without a fine phase.
class DistortionRefinement
{
public:
  DistortionRefinement(const SurfaceMapOptions& options, const ScheduleContext& context);

  /// Measures, refines the sizing and returns the phase to run next, or
  /// nothing when the refinement is over.
  std::optional<MapPhase> next(CommonTriangulation& T, std::vector<PreparedInput>& surfaces);

private:
  const SurfaceMapOptions& Options;
  ScheduleContext Context;
  int Round = 0;
};

} // namespace surfacemaps
