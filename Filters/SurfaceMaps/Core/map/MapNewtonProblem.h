// SurfaceMaps engine: a Newton step of the map as a NewtonProblem. Owns the
// snapshot of T the step runs on (points, lifts, sample assignment), the
// objective over it, the trial check (every triangle positive and degree 1,
// lifts and samples re-located), the barrier raise at the step's full trial
// and the variable blocks (one per embedding).
#pragma once

#include "map/CommonTriangulation.h"
#include "map/MapEnergy.h"
#include "optimisation/NewtonProblem.h"

#include <Eigen/Core>

#include <map>
#include <vector>

namespace surfacemaps
{

class MapNewtonProblem final : public NewtonProblem
{
public:
  /// Takes a snapshot of T into `points` (landmark vertices locked when
  /// `lockLandmarks`) and builds `objective`, the phase's `energy` over it
  /// (kept by the caller
  /// across steps: an unchanged Hessian pattern keeps the solver's symbolic
  /// analysis). `blockInputs`: solve with one block per embedding from this
  /// many inputs on (0: never; SurfaceMapOptions::blockSolveInputs).
  MapNewtonProblem(CommonTriangulation& T,
    const MapEnergy& energy,
    const std::vector<std::map<int, Eigen::Vector3d>>& targets,
    Objective& objective,
    SpherePoints& points,
    bool lockLandmarks,
    int blockInputs);

  Objective& objective() override { return this->Energy; }
  bool accept(const SpherePoints& trial) override;
  /// The corners of triangles that invert on a sphere; the first call of a
  /// step (its full trial) raises their barrier weights for later steps.
  std::vector<int> blockingPoints(const SpherePoints& trial) override;
  std::vector<int> variableBlocks(const SpherePoints& points) const override;

  /// Writes the points, lifts and sample assignment back into T.
  void writeBack(const SpherePoints& points);
  /// T's vertex count.
  int vertices() const { return this->State.vertices; }

private:
  CommonTriangulation& T;
  const MapEnergy& Phase;
  CommonTriangulation::Snapshot State;
  Objective& Energy;
  int BlockInputs = 0;
  bool Raised = false;
};

} // namespace surfacemaps
