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

/// One step of a surface map's plan.
enum class StageKind
{
  Phase,         ///< run `phase`
  SnapLandmarks, ///< put every kept landmark exactly on its input vertex
  TrackSamples,  ///< assign the approximation samples to T's faces from now on
  Refinement,    ///< DistortionRefinement's rounds, each a Refine phase
  ErrorBound,    ///< ErrorBound's rounds, each a Refine or Bound phase
};

struct MapStage
{
  StageKind kind = StageKind::Phase;
  /// The phase of a StageKind::Phase stage.
  MapPhase phase;
};

/// The plan of a surface map, in order (DESIGN.md section 1.6): the
/// landmark phase (with landmarks), snapping kept landmarks, the coarse and
/// fine phases, the distortion refinement, the error bound (with maxError).
std::vector<MapStage> mapPlan(const SurfaceMapOptions& options, const ScheduleContext& context);

/// The iterations a plan is expected to run (for progress): every phase,
/// the first refinement round (which nearly always runs) and the bound
/// phase.
int plannedIterations(const std::vector<MapStage>& plan, const SurfaceMapOptions& options);

} // namespace surfacemaps
