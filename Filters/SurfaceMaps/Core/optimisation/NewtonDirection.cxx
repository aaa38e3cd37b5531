// SurfaceMaps engine: newtonDirection.
#include "optimisation/NewtonDirection.h"

namespace surfacemaps
{

NewtonDirection newtonDirection(const Eigen::VectorXd& g,
  const Eigen::SparseMatrix<double>& H,
  LinearSolver& solver,
  bool patternChanged,
  const Logger& log)
{
  NewtonDirection direction;
  const LinearSolveResult solve = solver.solve(H, -g, direction.d, patternChanged, log);
  direction.regularised = solve.shift > 0.0;
  direction.slope = solve.success ? direction.d.dot(g) : 0.0;
  if (!solve.success || !(direction.slope < 0.0))
  {
    direction.d = -g;
    direction.slope = -g.squaredNorm();
    direction.gradientFallback = true;
    log(Logger::Detail, "Newton direction is no descent direction; using -gradient");
  }
  return direction;
}

} // namespace surfacemaps
