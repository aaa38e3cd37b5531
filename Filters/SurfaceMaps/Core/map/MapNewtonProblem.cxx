// SurfaceMaps engine: MapNewtonProblem.
#include "map/MapNewtonProblem.h"

namespace surfacemaps
{

MapNewtonProblem::MapNewtonProblem(CommonTriangulation& T,
  const MapEnergy& energy,
  const std::vector<std::map<int, Eigen::Vector3d>>& targets,
  Objective& objective,
  SpherePoints& points,
  bool lockLandmarks,
  int blockInputs)
  : T(T)
  , Energy(energy)
  , Targets(targets)
  , InUse(&objective)
  , BlockInputs(blockInputs)
{
  T.snapshot(this->State, points, lockLandmarks, energy.weights());
  energy.buildObjective(this->State, targets, objective);
}

MapNewtonProblem::MapNewtonProblem(const MapNewtonProblem& problem)
  : T(problem.T)
  , Energy(problem.Energy)
  , Targets(problem.Targets)
  , State(problem.State)
  , OwnObjective(std::make_unique<Objective>())
  , BlockInputs(problem.BlockInputs)
{
  // The objective reads the snapshot it is built over: this copy's own.
  this->InUse = this->OwnObjective.get();
  this->Energy.buildObjective(this->State, this->Targets, *this->InUse);
}

bool MapNewtonProblem::accept(const SpherePoints& trial)
{
  return this->T.update(this->State, trial);
}

std::vector<int> MapNewtonProblem::blockingPoints(const SpherePoints& trial)
{
  if (!this->Raised)
  {
    this->T.raiseBarrier(this->State, trial, this->Energy.weights().barrierRaise);
    this->Raised = true;
  }
  return this->T.invertedCorners(this->State, trial);
}

std::vector<int> MapNewtonProblem::variableBlocks(const SpherePoints& points) const
{
  const int n = this->T.numberOfInputs();
  std::vector<int> blocks;
  if (n < 2 || this->BlockInputs <= 0 || n < this->BlockInputs)
  {
    return blocks;
  }
  // SpherePoints numbers the variables in point order, and the snapshot
  // holds embedding i's points at [i nv, (i + 1) nv).
  blocks.assign(n + 1, 0);
  int variables = 0;
  for (int k = 0; k < points.size(); ++k)
  {
    if (k % this->State.vertices == 0)
    {
      blocks[k / this->State.vertices] = variables;
    }
    variables += points.locked(k) ? 0 : 2;
  }
  blocks[n] = variables;
  return blocks;
}

std::unique_ptr<NewtonProblem> MapNewtonProblem::trialCopy()
{
  return std::unique_ptr<NewtonProblem>(new MapNewtonProblem(*this));
}

bool MapNewtonProblem::adopt(NewtonProblem& copy, const SpherePoints&)
{
  // Only copies of this problem are ever adopted (TrialSearch's slots).
  auto& other = static_cast<MapNewtonProblem&>(copy);
  this->State.liftTriangle.swap(other.State.liftTriangle);
  this->State.lifts.swap(other.State.lifts);
  this->State.sampleTriangle.swap(other.State.sampleTriangle);
  return true;
}

void MapNewtonProblem::writeBack(const SpherePoints& points)
{
  this->T.writeBack(this->State, points);
}

} // namespace surfacemaps
