#include "optimisation/NewtonSolver.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>

namespace surfacemaps
{

namespace
{
double secondsSince(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}
} // namespace

NewtonStepResult newtonStep(Objective& objective,
  SpherePoints& points,
  LinearSolver& solver,
  const NewtonOptions& options)
{
  NewtonStepResult result;
  Eigen::VectorXd g;
  Eigen::SparseMatrix<double> H;
  bool patternChanged = false;
  auto clock = std::chrono::steady_clock::now();
  result.energyBefore = objective.hessian(points,
    options.projectionEps,
    g,
    H,
    &patternChanged,
    [&solver](const Eigen::SparseMatrix<double>& pattern) { solver.analyse(pattern); });
  result.derivativeSeconds = secondsSince(clock);
  result.energyAfter = result.energyBefore;
  if (!std::isfinite(result.energyBefore))
  {
    // Not converged, not movable: the caller must not take this for a minimum.
    result.decrement = std::numeric_limits<double>::infinity();
    options.log(Logger::Warning, "Newton step from an invalid state (infinite energy)");
    return result;
  }
  if (points.numberOfVariables() == 0)
  {
    return result;
  }

  Eigen::VectorXd d;
  clock = std::chrono::steady_clock::now();
  const LinearSolveResult solve = solver.solve(H, -g, d, patternChanged, options.log);
  result.solveSeconds = secondsSince(clock);
  result.regularised = solve.shift > 0.0;
  double slope = solve.success ? d.dot(g) : 0.0;
  if (!solve.success || !(slope < 0.0))
  {
    d = -g;
    slope = -g.squaredNorm();
    result.gradientFallback = true;
    options.log(Logger::Detail, "Newton direction is no descent direction; using -gradient");
  }
  result.decrement = std::sqrt(std::max(0.0, -slope));
  if (!(slope < 0.0))
  {
    return result; // zero gradient: nothing to do
  }

  // The first trial step: 1, or less where a point would move farther than the cap.
  auto firstStep = [&](const Eigen::VectorXd& direction)
  {
    double largest = 0.0;
    for (int i = 0; options.maxPointStep > 0.0 && i < points.size(); ++i)
    {
      const int v = points.variable(i);
      if (v >= 0)
      {
        largest = std::max(largest, std::hypot(direction[v], direction[v + 1]));
      }
    }
    return largest > options.maxPointStep ? options.maxPointStep / largest : 1.0;
  };

  const std::vector<Eigen::Vector3d> start = points.positions();
  const int slots = options.trialSlots.objective && options.trialSlots.accept
    ? std::max(1, options.trialSlots.count)
    : 1;
  // Slot s >= 1 retracts its own copy of the points (same bases as slot 0's).
  std::vector<SpherePoints> slotPoints(slots - 1, points);
  // Per slot, the last trial it evaluated: along the plain or the held step,
  // its step, and whether its check passed (so whatever it computed is
  // current).
  struct LastTrial
  {
    bool held = false;
    double step = 0.0;
    bool accepted = false;
  };
  std::vector<LastTrial> last(slots);
  auto trialIn = [&](int slot, const Eigen::VectorXd& direction, double t)
  {
    SpherePoints& trial = slot == 0 ? points : slotPoints[slot - 1];
    trial.setPositions(start);
    trial.retract(direction, t);
    LastTrial& record = last[slot];
    record.held = &direction != &d;
    record.step = t;
    record.accepted = slot == 0 ? !options.acceptTrial || options.acceptTrial(trial)
                                : options.trialSlots.accept(slot, trial);
    if (!record.accepted)
    {
      return std::numeric_limits<double>::infinity();
    }
    return (slot == 0 ? objective : options.trialSlots.objective(slot)).value(trial);
  };
  auto search = [&](const Eigen::VectorXd& direction, double directionSlope, double first)
  {
    return armijoBacktracking([&](int slot, double t) { return trialIn(slot, direction, t); },
      slots,
      result.energyBefore,
      directionSlope,
      first,
      options.lineSearch);
  };
  clock = std::chrono::steady_clock::now();
  const double initialStep = firstStep(d);
  const LineSearchResult ls = search(d, slope, initialStep);
  result.lineSearchTrials = ls.trials;
  LineSearchResult taken = ls;
  double takenFirst = initialStep;
  bool takenHeld = false;

  if (options.blockingPoints && !(ls.success && ls.step == initialStep))
  {
    // Hold the points that make the first trial invalid, and those that do
    // once these are held, and so on; then search along what is left.
    Eigen::VectorXd held = d;
    int count = 0;
    const int rounds = 20;
    for (int round = 0; round < rounds; ++round)
    {
      points.setPositions(start);
      points.retract(held, firstStep(held));
      int added = 0;
      for (const int i : options.blockingPoints(points))
      {
        const int v = points.variable(i);
        if (v >= 0 && (held[v] != 0.0 || held[v + 1] != 0.0))
        {
          held[v] = held[v + 1] = 0.0;
          ++added;
        }
      }
      count += added;
      if (added == 0)
      {
        break;
      }
    }
    const double heldSlope = held.dot(g);
    if (count > 0 && heldSlope < 0.0)
    {
      const double heldFirst = firstStep(held);
      const LineSearchResult heldSearch = search(held, heldSlope, heldFirst);
      result.lineSearchTrials += heldSearch.trials;
      if (heldSearch.success && (!ls.success || heldSearch.energy < ls.energy))
      {
        taken = heldSearch;
        takenFirst = heldFirst;
        d = held;
        takenHeld = true;
        result.heldPoints = count;
      }
    }
  }
  result.stalled = !taken.success || taken.step < 0.01 * takenFirst;

  points.setPositions(start);
  if (taken.success)
  {
    // The same operations as the trial's, so the same points bit for bit.
    points.retract(d, taken.step);
    for (int slot = 0; slot < slots; ++slot)
    {
      const LastTrial& record = last[slot];
      if (record.accepted && record.held == takenHeld && record.step == taken.step)
      {
        result.takenTrialSlot = slot;
      }
    }
    points.recentreBases();
    result.step = taken.step;
    result.energyAfter = taken.energy;
    result.moved = true;
  }
  result.lineSearchSeconds = secondsSince(clock);
  return result;
}

MinimizeResult minimize(Objective& objective, SpherePoints& points, const MinimizeOptions& options)
{
  MinimizeResult result;
  LinearSolver solver;
  result.initialEnergy = objective.value(points);
  result.finalEnergy = result.initialEnergy;
  for (int it = 0; it < options.maxIterations; ++it)
  {
    const NewtonStepResult step = newtonStep(objective, points, solver, options.newton);
    result.iterations = it + 1;
    result.finalEnergy = step.energyAfter;
    if (options.callback && !options.callback(it, step))
    {
      result.aborted = true;
      break;
    }
    if (step.decrement < options.decrementTolerance)
    {
      result.converged = true;
      break;
    }
    if (!step.moved)
    {
      break;
    }
  }
  return result;
}

} // namespace surfacemaps
