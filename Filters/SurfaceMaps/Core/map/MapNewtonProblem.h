// SurfaceMaps engine: a Newton step of the map as a NewtonProblem. Owns the
// snapshot of T the step runs on (points, lifts, sample assignment), the
// objective over it, the trial check (every triangle positive and degree 1,
// lifts and samples re-located), the barrier raise at the step's full trial,
// the variable blocks (one per embedding) and the copies for trials at once.
#pragma once

#include "map/CommonTriangulation.h"
#include "map/MapEnergy.h"
#include "optimisation/NewtonProblem.h"

#include <Eigen/Core>

#include <map>
#include <memory>
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

  Objective& objective() override { return *this->InUse; }
  bool accept(const SpherePoints& trial) override;
  /// The corners of triangles that invert on a sphere; the first call of a
  /// step (its full trial) raises their barrier weights for later steps.
  std::vector<int> blockingPoints(const SpherePoints& trial) override;
  std::vector<int> variableBlocks(const SpherePoints& points) const override;
  std::unique_ptr<NewtonProblem> trialCopy() override;
  bool adopt(NewtonProblem& copy, const SpherePoints& points) override;

  /// Writes the points, lifts and sample assignment back into T.
  void writeBack(const SpherePoints& points);
  /// T's vertex count.
  int vertices() const { return this->State.vertices; }

private:
  /// A trial copy: the same snapshot and targets, its own objective.
  explicit MapNewtonProblem(const MapNewtonProblem& problem);

  CommonTriangulation& T;
  const MapEnergy& Energy;
  const std::vector<std::map<int, Eigen::Vector3d>>& Targets;
  CommonTriangulation::Snapshot State;
  std::unique_ptr<Objective> OwnObjective;
  /// The caller's objective, or a copy's own.
  Objective* InUse = nullptr;
  int BlockInputs = 0;
  bool Raised = false;
};

} // namespace surfacemaps
