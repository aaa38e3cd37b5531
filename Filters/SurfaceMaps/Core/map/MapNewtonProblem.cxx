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
  , Phase(energy)
  , Energy(objective)
  , BlockInputs(blockInputs)
{
  T.snapshot(this->State, points, lockLandmarks, energy.weights());
  energy.buildObjective(this->State, targets, objective);
}

bool MapNewtonProblem::accept(const SpherePoints& trial)
{
  return this->T.update(this->State, trial);
}

std::vector<int> MapNewtonProblem::blockingPoints(const SpherePoints& trial)
{
  if (!this->Raised)
  {
    this->T.raiseBarrier(this->State, trial, this->Phase.weights().barrierRaise);
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

void MapNewtonProblem::writeBack(const SpherePoints& points)
{
  this->T.writeBack(this->State, points);
}

} // namespace surfacemaps
