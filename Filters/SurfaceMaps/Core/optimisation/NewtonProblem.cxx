// SurfaceMaps engine: NewtonProblem's defaults and ObjectiveProblem.
#include "optimisation/NewtonProblem.h"

namespace surfacemaps
{

std::vector<int> NewtonProblem::blockingPoints(const SpherePoints&)
{
  return {};
}

std::vector<int> NewtonProblem::variableBlocks(const SpherePoints&) const
{
  return {};
}

ObjectiveProblem::ObjectiveProblem(Objective& objective,
  std::function<bool(const SpherePoints&)> check)
  : Energy(objective)
  , Check(std::move(check))
{
}

bool ObjectiveProblem::accept(const SpherePoints& trial)
{
  return !this->Check || this->Check(trial);
}

} // namespace surfacemaps
