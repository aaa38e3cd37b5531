#include "optimisation/LineSearch.h"

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <limits>
#include <vector>

namespace surfacemaps
{

namespace
{
// Armijo's sufficient decrease at step t; a non-finite energy (an invalid
// trial) never passes. Both searches decide with it, so they take the same
// step.
bool passesArmijo(double f, double t, double f0, double slope, const LineSearchOptions& options)
{
  return std::isfinite(f) && f <= f0 + options.armijo * t * slope;
}

// Evaluates trials k = 0, 1, ... (energies[k] at steps[k]) in `slots` slots
// at once and returns the first k that `passes` (steps.size() if none).
// Trials are handed out in order; a slot takes the next one as soon as it is
// free (a trial rejected early is cheap), and none is handed out past the
// first one known to pass. Every trial before a passing one has been handed
// out, and each is finished when the loop ends, so the first passing trial
// in order is the one-by-one search's. An exception from energyAt is
// rethrown.
template<typename Passes>
int firstPassingInSlots(const SlotEnergy& energyAt,
  int slots,
  const std::vector<double>& steps,
  std::vector<double>& energies,
  Passes passes)
{
  const int trials = static_cast<int>(steps.size());
  std::atomic<int> next{ 0 };
  std::atomic<int> firstPassing{ trials };
  std::exception_ptr error;
  // The threads beyond one per slot go to the parallel loops inside each
  // trial (a nested level, for this region only).
  const int inner = std::max(1, omp_get_max_threads() / slots);
  const int levels = omp_get_max_active_levels();
  if (inner > 1)
  {
    omp_set_max_active_levels(std::max(levels, omp_get_active_level() + 2));
  }
#pragma omp parallel num_threads(slots)
  {
    omp_set_num_threads(inner);
    const int slot = omp_get_thread_num();
    for (;;)
    {
      const int k = next++;
      if (k >= trials || k > firstPassing.load())
      {
        break;
      }
      try
      {
        energies[k] = energyAt(slot, steps[k]);
      }
      catch (...)
      {
#pragma omp critical(surfacemapsLineSearchError)
        error = std::current_exception();
        firstPassing = -1;
        break;
      }
      if (passes(k))
      {
        int known = firstPassing.load();
        while (k < known && !firstPassing.compare_exchange_weak(known, k))
        {
        }
      }
    }
  }
  omp_set_max_active_levels(levels);
  if (error)
  {
    std::rethrow_exception(error);
  }
  return firstPassing.load();
}
} // namespace

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
    if (passesArmijo(f, t, f0, slope, options))
    {
      result.success = true;
      result.step = t;
      result.energy = f;
      return result;
    }
  }
  return result;
}

LineSearchResult armijoBacktracking(const SlotEnergy& energyAt,
  int slots,
  double f0,
  double slope,
  double initialStep,
  const LineSearchOptions& options)
{
  if (slots <= 1)
  {
    return armijoBacktracking(
      [&energyAt](double t) { return energyAt(0, t); }, f0, slope, initialStep, options);
  }
  LineSearchResult result;
  result.energy = f0;
  if (!(slope < 0.0) || !std::isfinite(f0) || options.maxTrials <= 0)
  {
    return result;
  }
  const int trials = options.maxTrials;
  // The same repeated multiplication as the one-by-one search: the same steps.
  std::vector<double> steps(trials);
  double t = initialStep;
  for (int k = 0; k < trials; ++k, t *= options.shrink)
  {
    steps[k] = t;
  }
  std::vector<double> energies(trials, std::numeric_limits<double>::quiet_NaN());
  const int taken = firstPassingInSlots(energyAt,
    slots,
    steps,
    energies,
    [&](int k) { return passesArmijo(energies[k], steps[k], f0, slope, options); });
  result.trials = std::min(taken + 1, trials);
  if (taken < trials)
  {
    result.success = true;
    result.step = steps[taken];
    result.energy = energies[taken];
  }
  return result;
}

} // namespace surfacemaps
