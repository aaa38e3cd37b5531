// SurfaceMaps engine: holdBlockingPoints.
#include "optimisation/HeldPoints.h"

#include "optimisation/TrialSearch.h"

namespace surfacemaps
{

int holdBlockingPoints(NewtonProblem& problem,
  SpherePoints& points,
  const std::vector<Eigen::Vector3d>& start,
  Eigen::VectorXd& step,
  double maxPointStep)
{
  int count = 0;
  const int rounds = 20;
  for (int round = 0; round < rounds; ++round)
  {
    points.setPositions(start);
    points.retract(step, firstStep(points, step, maxPointStep));
    int added = 0;
    for (const int i : problem.blockingPoints(points))
    {
      const int v = points.variable(i);
      if (v >= 0 && (step[v] != 0.0 || step[v + 1] != 0.0))
      {
        step[v] = step[v + 1] = 0.0;
        ++added;
      }
    }
    count += added;
    if (added == 0)
    {
      break;
    }
  }
  return count;
}

} // namespace surfacemaps
