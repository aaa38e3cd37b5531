// SurfaceMaps engine: the plan of phases a surface map runs.
#pragma once

#include "map/MapOptions.h"
#include "map/MapPhase.h"

#include <vector>

namespace surfacemaps
{

/// What the plan depends on besides the options.
struct ScheduleContext
{
  int inputs = 1;
  /// Pairs of the map-distortion term.
  int pairs = 0;
  /// The inputs carry landmarks.
  bool landmarks = false;
};

/// The landmark phase: barrier and landmark terms (DESIGN.md section 1.6).
MapPhase landmarkPhase(const SurfaceMapOptions& options, const ScheduleContext& context);

/// A phase with the fine phase's energy: kind Refine after a refinement, or
/// Bound with `bounds` (per input, unit-area units), whose approximation
/// term is then the hard-bound barrier.
MapPhase finePhase(PhaseKind kind,
  int iterations,
  const SurfaceMapOptions& options,
  const ScheduleContext& context,
  const std::vector<double>& bounds = {});

/// The coarse and fine phases that run (iteration cap > 0), in order.
std::vector<MapPhase> distortionPhases(const SurfaceMapOptions& options,
  const ScheduleContext& context);

/// The iterations the schedule is expected to run (for progress): every
/// planned phase and the first refinement round, which nearly always runs.
int plannedIterations(const SurfaceMapOptions& options, const ScheduleContext& context);

} // namespace surfacemaps
