// SurfaceMaps engine: newtonStep and minimize.
#include "optimisation/NewtonSolver.h"

#include "optimisation/HeldPoints.h"
#include "optimisation/NewtonDirection.h"
#include "optimisation/TrialSearch.h"

#include <chrono>
#include <cmath>
#include <limits>

namespace surfacemaps
{

namespace
{
double secondsSince(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The line search of a step along `direction` and, when its first trial
// fails and the problem names points that block it, along the step with
// those held; the better one is taken.
void searchStep(NewtonProblem& problem,
  SpherePoints& points,
  const NewtonDirection& direction,
  const Eigen::VectorXd& g,
  const NewtonOptions& options,
  NewtonStepResult& result)
{
  TrialSearch trials(problem, points);
  const double first = firstStep(points, direction.d, options.maxPointStep);
  const LineSearchResult plain =
    trials.search(direction.d, result.energyBefore, direction.slope, first, 0, options.lineSearch);
  result.lineSearchTrials = plain.trials;
  LineSearchResult taken = plain;
  double takenFirst = first;
  Eigen::VectorXd held;
  if (!(plain.success && plain.step == first))
  {
    held = direction.d;
    const int count =
      holdBlockingPoints(problem, points, trials.start(), held, options.maxPointStep);
    const double heldSlope = held.dot(g);
    if (count > 0 && heldSlope < 0.0)
    {
      const double heldFirst = firstStep(points, held, options.maxPointStep);
      const LineSearchResult search =
        trials.search(held, result.energyBefore, heldSlope, heldFirst, 1, options.lineSearch);
      result.lineSearchTrials += search.trials;
      if (search.success && (!plain.success || search.energy < plain.energy))
      {
        taken = search;
        takenFirst = heldFirst;
        result.heldPoints = count;
      }
    }
  }
  result.stalled = !taken.success || taken.step < 0.01 * takenFirst;
  if (!taken.success)
  {
    trials.restore();
    return;
  }
  const bool holding = result.heldPoints > 0;
  trials.take(holding ? held : direction.d, taken.step, holding ? 1 : 0);
  result.step = taken.step;
  result.energyAfter = taken.energy;
  result.moved = true;
}
} // namespace

NewtonStepResult newtonStep(NewtonProblem& problem,
  SpherePoints& points,
  LinearSolver& solver,
  const NewtonOptions& options)
{
  NewtonStepResult result;
  Eigen::VectorXd g;
  Eigen::SparseMatrix<double> H;
  bool patternChanged = false;
  solver.setBlocks(problem.variableBlocks(points));
  auto clock = std::chrono::steady_clock::now();
  result.energyBefore = problem.objective().hessian(points,
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

  clock = std::chrono::steady_clock::now();
  const NewtonDirection direction = newtonDirection(g, H, solver, patternChanged, options.log);
  result.solveSeconds = secondsSince(clock);
  result.regularised = direction.regularised;
  result.gradientFallback = direction.gradientFallback;
  result.decrement = newtonDecrement(direction);
  if (!(direction.slope < 0.0))
  {
    return result; // zero gradient: nothing to do
  }
  clock = std::chrono::steady_clock::now();
  searchStep(problem, points, direction, g, options, result);
  result.lineSearchSeconds = secondsSince(clock);
  return result;
}

MinimizeResult minimize(NewtonProblem& problem,
  SpherePoints& points,
  const MinimizeOptions& options)
{
  MinimizeResult result;
  LinearSolver solver;
  result.initialEnergy = problem.objective().value(points);
  result.finalEnergy = result.initialEnergy;
  for (int it = 0; it < options.maxIterations; ++it)
  {
    const NewtonStepResult step = newtonStep(problem, points, solver, options.newton);
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
