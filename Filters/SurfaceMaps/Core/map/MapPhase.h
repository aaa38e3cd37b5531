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
  /// The landmark phase's end: when every landmark is within the tolerance
  /// (otherwise: no edit helps and the Newton decrement is small).
  bool untilLandmarks = false;
  /// With untilLandmarks: once reached, go on with flips and Newton steps
  /// only (no splits or collapses) until that has settled too.
  bool relaxAfterLandmarks = false;
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
