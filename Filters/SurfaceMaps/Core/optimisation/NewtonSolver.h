// SurfaceMaps engine: projected Newton on sphere points. Owns the step as a
// composition of its pieces (NewtonDirection, HeldPoints, TrialSearch) and
// the loop of steps (minimize).
#pragma once

#include "base/Log.h"
#include "optimisation/LineSearch.h"
#include "optimisation/NewtonProblem.h"
#include "optimisation/sparse/LinearSolver.h"
#include "optimisation/SpherePoints.h"

#include <functional>

namespace surfacemaps
{

struct NewtonOptions
{
  /// Element Hessian eigenvalues are clamped to at least this.
  double projectionEps = 1e-9;
  /// Largest tangent step of any single point in one Newton step; the whole
  /// step is scaled down (never clamped per point, which would change its
  /// direction) to respect it. 0 = no cap.
  double maxPointStep = 0.0;
  LineSearchOptions lineSearch;
  Logger log;
};

struct NewtonStepResult
{
  double energyBefore = 0.0;
  double energyAfter = 0.0;
  /// Newton decrement sqrt(-d.g) of the (possibly fallback) direction.
  double decrement = 0.0;
  /// Accepted step length (0 if the line search failed).
  double step = 0.0;
  /// Line-search trials.
  int lineSearchTrials = 0;
  /// The Newton direction was no descent direction; -gradient was used.
  bool gradientFallback = false;
  /// The linear solve needed a diagonal shift.
  bool regularised = false;
  /// The points moved (line search succeeded).
  bool moved = false;
  /// Points held still in the step taken (0: the plain Newton step).
  int heldPoints = 0;
  /// The line search failed or cut its first trial by more than 100 times
  /// (of the step taken, plain or with points held). On a surface map the
  /// cause is mostly a few triangles that invert on a sphere early in the
  /// step (the terms measure lifted triangles and do not see them closing;
  /// NewtonProblem::blockingPoints names their corners), otherwise a kink: elements whose
  /// energy leaves their derivatives' model within the step (T's vertices
  /// are lifted onto the inputs' flat triangles, so the mesh and map terms
  /// bend where a vertex crosses an input edge on the sphere).
  bool stalled = false;
  /// Wall time of the parts: element derivatives with Hessian projection and
  /// assembly, the linear solve, the line search.
  double derivativeSeconds = 0.0;
  double solveSeconds = 0.0;
  double lineSearchSeconds = 0.0;
};

/// One projected-Newton step on all unlocked points: derivatives with
/// projected element Hessians (newtonDirection), the Armijo line search on
/// the retraction (TrialSearch), when its first trial fails a second one with
/// the blocking points held (holdBlockingPoints) and the better step taken,
/// bases re-centred. Points stay where they are if no trial is accepted. The
/// problem's state is left that of the final points.
NewtonStepResult newtonStep(NewtonProblem& problem,
  SpherePoints& points,
  LinearSolver& solver,
  const NewtonOptions& options = NewtonOptions());

struct MinimizeOptions
{
  NewtonOptions newton;
  int maxIterations = 50;
  /// Converged when the Newton decrement is below this.
  double decrementTolerance = 1e-4;
  /// Called after every iteration with the iteration number (from 0) and its
  /// step result; return false to stop (abort).
  std::function<bool(int, const NewtonStepResult&)> callback;
};

struct MinimizeResult
{
  int iterations = 0;
  bool converged = false;
  bool aborted = false;
  double initialEnergy = 0.0;
  double finalEnergy = 0.0;
};

/// Newton steps until the decrement is below the tolerance, no step is
/// possible, the iteration cap is reached, or the callback aborts.
MinimizeResult minimize(NewtonProblem& problem,
  SpherePoints& points,
  const MinimizeOptions& options);

} // namespace surfacemaps
