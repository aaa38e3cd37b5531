// SurfaceMaps engine: a Newton step with the points that block it held
// still. A step is cut for every point by the few points that run into a
// constraint (on surface maps, a handful of triangles that invert on a
// sphere within a few per cent of the step); holding those lets the others
// move on.
#pragma once

#include "optimisation/NewtonProblem.h"
#include "optimisation/SpherePoints.h"

#include <Eigen/Core>

#include <vector>

namespace surfacemaps
{

/// Zeroes in `step` the variables of the points problem.blockingPoints()
/// names at the first (capped) trial from `start` along it, then of those it
/// names once these are held, and so on (at most 20 rounds) until it names
/// no new one. Leaves `points` at the last trial looked at (the caller puts
/// them back). Returns how many points are held.
int holdBlockingPoints(NewtonProblem& problem,
  SpherePoints& points,
  const std::vector<Eigen::Vector3d>& start,
  Eigen::VectorXd& step,
  double maxPointStep);

} // namespace surfacemaps
