// SurfaceMaps engine: one phase of the map's schedule, as a value.
#pragma once

#include "map/CommonTriangulation.h"

namespace surfacemaps
{

/// The kinds of phase (DESIGN.md section 1.6).
enum class PhaseKind
{
  Landmarks, ///< barrier and landmarks: T coarsens, landmarks move to their targets
  Coarse,    ///< every term but the landmarks, large error
  Fine,      ///< the same at the target error
  Refine,    ///< the fine phase's energy after a sizing refinement
  Bound,     ///< the hard error bound instead of the soft approximation term
};

/// "landmarks", "coarse", "fine", "refine", "bound".
const char* phaseName(PhaseKind kind);

/// When a phase ends before its iteration cap.
enum class StopRule
{
  /// No edit lowers the energy and the Newton decrement is below tolerance.
  Settled,
  /// Every landmark is within the tolerance of its target.
  LandmarksReached,
  /// Every landmark within the tolerance, then flips and Newton steps only
  /// (T keeps its vertices) until settled as well.
  LandmarksReachedThenSettled,
};

/// Everything the phase runner needs to run one phase.
struct MapPhase
{
  PhaseKind kind = PhaseKind::Fine;
  /// Iteration cap (one iteration: improving splits, collapses, flips, then
  /// one Newton step).
  int iterations = 0;
  /// The energy during the phase.
  MapEnergyWeights weights;
  /// > 0: before the phase, the curvature sizing of every input without a
  /// user sizing is recomputed for this error; 0: the sizing stays.
  double sizingError = 0.0;
  /// Landmark vertices stay where they are (locked out of the Newton step).
  bool lockLandmarks = false;
  StopRule stop = StopRule::Settled;
  /// Edits the phase may make besides splits. Adding inputs to a map
  /// (AddToMap.h) allows splits only: a collapse or flip would change the
  /// existing inputs' maps, a split at an edge midpoint keeps them.
  bool collapses = true, flips = true;
};

/// What one phase did.
struct MapPhaseReport
{
  PhaseKind kind = PhaseKind::Fine;
  int iterations = 0;
  /// No edit lowered the energy and the decrement was below tolerance
  /// (otherwise the phase stopped at its cap, which is normal).
  bool converged = false;
  double energy = 0.0;
  int splits = 0, collapses = 0, flips = 0;
  int vertices = 0;
  /// Iterations whose Newton step stalled (NewtonStepResult::stalled).
  int stalledIterations = 0;
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

} // namespace surfacemaps
