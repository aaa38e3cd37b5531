// SurfaceMaps engine: what a projected-Newton step optimises. Owns the
// interface between the step (optimisation/NewtonSolver.h) and a problem:
// its energy, the check of a trial's points, the points that block a step
// and the variable blocks a solver may split the system into. The step
// knows nothing else of the problem.
#pragma once

#include "optimisation/Objective.h"
#include "optimisation/SpherePoints.h"

#include <functional>
#include <vector>

namespace surfacemaps
{

class NewtonProblem
{
public:
  virtual ~NewtonProblem() = default;

  /// The energy: value, gradient and projected Hessian at given points.
  virtual Objective& objective() = 0;

  /// Checks trial points and brings whatever the energy reads besides them
  /// (e.g. where the points lie on other surfaces) to them; false rejects
  /// the trial like an infinite energy. The step calls it for every trial
  /// before objective().value(), and leaves the problem with the last call's
  /// points being the step's final points (the start when it failed).
  virtual bool accept(const SpherePoints& trial) = 0;

  /// The points whose positions in `trial` make it invalid (e.g. the corners
  /// of triangles that invert). When the step's first trial is rejected, a
  /// second line search runs with these points held still. The first call
  /// of a step sees the full (capped) step. Default: none, no second search.
  virtual std::vector<int> blockingPoints(const SpherePoints& trial);

  /// Offsets of variable blocks a solver may split the Newton system into
  /// (LinearSolver::setBlocks); empty: one system. Default: empty.
  virtual std::vector<int> variableBlocks(const SpherePoints& points) const;
};

/// A problem given by an objective alone, with an optional trial check
/// (e.g. an embedding's degree): for optimisations that need nothing else.
class ObjectiveProblem final : public NewtonProblem
{
public:
  explicit ObjectiveProblem(Objective& objective,
    std::function<bool(const SpherePoints&)> check = {});

  Objective& objective() override { return this->Energy; }
  bool accept(const SpherePoints& trial) override;

private:
  Objective& Energy;
  std::function<bool(const SpherePoints&)> Check;
};

} // namespace surfacemaps
