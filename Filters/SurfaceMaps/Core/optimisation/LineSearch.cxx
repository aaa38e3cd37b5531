#include "optimisation/LineSearch.h"

#include <cmath>

namespace surfacemaps
{

LineSearchResult armijoBacktracking(const std::function<double(double)>& energyAt,
  double f0,
  double slope,
  double initialStep,
  const LineSearchOptions& options)
{
  LineSearchResult result;
  result.energy = f0;
  if (!(slope < 0.0) || !std::isfinite(f0))
  {
    return result;
  }
  double t = initialStep;
  for (int trial = 0; trial < options.maxTrials; ++trial, t *= options.shrink)
  {
    const double f = energyAt(t);
    result.trials = trial + 1;
    // Armijo's sufficient decrease; a non-finite energy never passes.
    if (std::isfinite(f) && f <= f0 + options.armijo * t * slope)
    {
      result.success = true;
      result.step = t;
      result.energy = f;
      return result;
    }
  }
  return result;
}

} // namespace surfacemaps
