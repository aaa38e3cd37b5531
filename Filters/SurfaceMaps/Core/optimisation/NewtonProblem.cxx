// SurfaceMaps engine: NewtonProblem's defaults and ObjectiveProblem.
#include "optimisation/NewtonProblem.h"

#include <stdexcept>

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

std::unique_ptr<NewtonProblem> NewtonProblem::trialCopy()
{
  return nullptr;
}

void NewtonProblem::adopt(NewtonProblem&, const SpherePoints& points)
{
  if (!this->accept(points))
  {
    throw std::logic_error("a Newton step's accepted points failed their trial check again");
  }
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
