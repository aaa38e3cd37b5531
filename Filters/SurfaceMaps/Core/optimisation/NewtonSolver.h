// SurfaceMaps engine: projected Newton on sphere points, step by step.
#pragma once

#include "base/Log.h"
#include "optimisation/LineSearch.h"
#include "optimisation/sparse/LinearSolver.h"
#include "optimisation/Objective.h"
#include "optimisation/SpherePoints.h"

#include <functional>

namespace surfacemaps
{

/// Line-search trials evaluated concurrently, one per thread (see
/// NewtonOptions::trialSlots).
struct TrialSlots
{
  /// Trials evaluated at once; 1: one by one.
  int count = 1;
  /// Slot s >= 1's objective: the same energy as the step's objective, over
  /// the slot's own copy of whatever the trial check updates.
  std::function<const Objective&(int slot)> objective;
  /// Slot s >= 1's trial check (acceptTrial's counterpart), touching only
  /// the slot's own state, so that slots can run at once.
  std::function<bool(int slot, const SpherePoints&)> accept;
};

struct NewtonOptions
{
  /// Element Hessian eigenvalues are clamped to at least this.
  double projectionEps = 1e-9;
  /// Largest tangent step of any single point in one Newton step; the whole
  /// step is scaled down (never clamped per point, which would change its
  /// direction) to respect it. 0 = no cap.
  double maxPointStep = 0.0;
  LineSearchOptions lineSearch;
  /// Extra validity check of trial positions (e.g. the embedding degree);
  /// false rejects the trial like an infinite energy. Optional.
  std::function<bool(const SpherePoints&)> acceptTrial;
  /// Optional: the points whose trial positions make the trial invalid (e.g.
  /// the corners of triangles that invert). When the first trial of the
  /// Newton step is rejected, a second line search runs along the step with
  /// these points held still (found at the first trial, repeatedly, until
  /// that trial has none), and the better of the two steps is taken. A step
  /// is cut for every point by the few points that run into a constraint
  /// (on surface maps, a handful of triangles that invert on a sphere within
  /// a few per cent of the step); holding those lets the others move on.
  std::function<std::vector<int>(const SpherePoints&)> blockingPoints;
  /// Optional: line-search trials evaluated trialSlots.count at a time, one
  /// per thread, each slot taking the next trial in order when it is free.
  /// Slot 0 is the step's own points, objective and acceptTrial; slot s >= 1
  /// retracts its own copy of the points and calls trialSlots.accept(s, .)
  /// and trialSlots.objective(s). The first trial in order that passes is
  /// taken, so the step is the one-by-one search's (bit for bit when the
  /// slots compute what slot 0 would). Threads beyond one per slot run the
  /// parallel loops inside each slot's trial.
  TrialSlots trialSlots;
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
  /// The trial slot whose last trial is the step taken, with its check
  /// passed (acceptTrial for slot 0, trialSlots.accept otherwise): what that
  /// check computed from the trial's points (e.g. where they lie on the
  /// inputs) holds for the points as they are now. -1: no slot's.
  int takenTrialSlot = -1;
  /// Points held still in the step taken (0: the plain Newton step).
  int heldPoints = 0;
  /// The line search failed or cut its first trial by more than 100 times
  /// (of the step taken, plain or with points held). On a surface map the
  /// cause is mostly a few triangles that invert on a sphere early in the
  /// step (the terms measure lifted triangles and do not see them closing;
  /// blockingPoints holds their corners), otherwise a kink: elements whose
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
/// projected element Hessians, sparse solve H d = -g, Armijo line search on
/// the retraction, bases re-centred. Points stay where they are if no trial
/// is accepted.
NewtonStepResult newtonStep(Objective& objective,
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
MinimizeResult minimize(Objective& objective, SpherePoints& points, const MinimizeOptions& options);

} // namespace surfacemaps
