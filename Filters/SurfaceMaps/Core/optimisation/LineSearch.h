// SurfaceMaps engine: backtracking line search.
#pragma once

#include <functional>

namespace surfacemaps
{

struct LineSearchOptions
{
  /// Step multiplier after a rejected trial.
  double shrink = 0.8;
  /// Armijo constant: accept f(t) <= f(0) + armijo * t * slope.
  double armijo = 1e-4;
  /// Trials before giving up (0.8^100 ~ 2e-10 of the initial step).
  int maxTrials = 100;
};

struct LineSearchResult
{
  bool success = false;
  double step = 0.0;
  double energy = 0.0;
  /// Trials up to the one taken (all of them if none passed).
  int trials = 0;
};

/// Armijo backtracking from `initialStep` along a descent direction with
/// directional derivative `slope` (< 0) at energy `f0`. `energyAt(t)` returns
/// the energy at step t; a non-finite value (an inverted element, a wrong
/// embedding degree) rejects the trial.
LineSearchResult armijoBacktracking(const std::function<double(double)>& energyAt,
  double f0,
  double slope,
  double initialStep,
  const LineSearchOptions& options = LineSearchOptions());

} // namespace surfacemaps
