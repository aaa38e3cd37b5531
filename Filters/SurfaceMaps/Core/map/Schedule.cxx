#include "map/Schedule.h"

#include <algorithm>

namespace surfacemaps
{

namespace
{

/// The coarse or fine phase's energy (DESIGN.md section 1.3): per-input
/// terms averaged over the inputs, the distortion over the pairs.
MapPhase distortionPhase(PhaseKind kind,
  int iterations,
  double eps,
  double barrierWeight,
  const SurfaceMapOptions& options,
  const ScheduleContext& context,
  const std::vector<double>& bounds)
{
  const int n = context.inputs;
  const double pairCount = std::max(1, context.pairs);
  MapPhase phase;
  phase.kind = kind;
  phase.iterations = iterations;
  phase.lockLandmarks = context.landmarks && options.keepLandmarks;
  MapEnergyWeights& w = phase.weights;
  w.barrier = barrierWeight / n;
  w.mesh = options.meshWeight / n;
  w.coverage = options.coverageWeight / n;
  w.mapToMean = options.pairs == PairScheme::Mean;
  w.map = context.pairs == 0 ? 0.0 : options.mapWeight / (w.mapToMean ? n : pairCount);
  w.bounds = bounds;
  w.approximation = options.approximationWeight / n / (bounds.empty() ? eps * eps : 1.0);
  return phase;
}

} // namespace

const char* phaseName(PhaseKind kind)
{
  switch (kind)
  {
    case PhaseKind::Landmarks:
      return "landmarks";
    case PhaseKind::Coarse:
      return "coarse";
    case PhaseKind::Fine:
      return "fine";
    case PhaseKind::Refine:
      return "refine";
    case PhaseKind::Bound:
      return "bound";
  }
  return "unknown";
}

MapPhase landmarkPhase(const SurfaceMapOptions& options, const ScheduleContext& context)
{
  MapPhase phase;
  phase.kind = PhaseKind::Landmarks;
  phase.iterations = options.landmarkIterations;
  phase.weights.barrier = options.landmarkBarrierWeight / context.inputs;
  phase.weights.landmark = options.landmarkWeight / context.inputs;
  phase.weights.exactBarrierHessian = true;
  phase.stop =
    options.relaxLandmarkPhase ? StopRule::LandmarksReachedThenSettled : StopRule::LandmarksReached;
  return phase;
}

MapPhase finePhase(PhaseKind kind,
  int iterations,
  const SurfaceMapOptions& options,
  const ScheduleContext& context,
  const std::vector<double>& bounds)
{
  MapPhase phase = distortionPhase(
    kind, iterations, options.targetError, options.fineBarrierWeight, options, context, bounds);
  phase.weights.barrierRaise = options.fineBarrierRaise;
  return phase;
}

std::vector<MapPhase> distortionPhases(const SurfaceMapOptions& options,
  const ScheduleContext& context)
{
  std::vector<MapPhase> phases;
  if (options.coarseIterations > 0)
  {
    phases.push_back(distortionPhase(PhaseKind::Coarse,
      options.coarseIterations,
      options.coarseError,
      options.coarseBarrierWeight,
      options,
      context,
      {}));
    phases.back().sizingError = options.coarseError;
  }
  if (options.fineIterations > 0)
  {
    phases.push_back(finePhase(PhaseKind::Fine, options.fineIterations, options, context));
    phases.back().sizingError = options.targetError;
  }
  return phases;
}

std::vector<MapStage> mapPlan(const SurfaceMapOptions& options, const ScheduleContext& context)
{
  std::vector<MapStage> plan;
  auto add = [&plan](StageKind kind, MapPhase phase = MapPhase()) {
    plan.push_back({ kind, std::move(phase) });
  };
  if (context.landmarks && options.landmarkIterations > 0)
  {
    add(StageKind::Phase, landmarkPhase(options, context));
  }
  if (context.landmarks && options.keepLandmarks)
  {
    add(StageKind::SnapLandmarks);
  }
  add(StageKind::TrackSamples);
  for (MapPhase& phase : distortionPhases(options, context))
  {
    add(StageKind::Phase, std::move(phase));
  }
  if (options.fineIterations > 0 && context.pairs > 0 && options.refinementRounds > 0)
  {
    add(StageKind::Refinement);
  }
  if (options.maxError > 0.0)
  {
    add(StageKind::ErrorBound);
  }
  return plan;
}

int plannedIterations(const std::vector<MapStage>& plan, const SurfaceMapOptions& options)
{
  int iterations = 0;
  for (const MapStage& stage : plan)
  {
    switch (stage.kind)
    {
      case StageKind::Phase:
        iterations += stage.phase.iterations;
        break;
      case StageKind::Refinement:
        iterations += std::min(options.refinementIterations, options.fineIterations);
        break;
      case StageKind::ErrorBound:
        iterations += options.boundIterations;
        break;
      case StageKind::SnapLandmarks:
      case StageKind::TrackSamples:
        break;
    }
  }
  return iterations;
}

} // namespace surfacemaps
