// SurfaceMaps engine: runs one phase of the map's schedule on T.
#pragma once

#include "map/CommonTriangulation.h"
#include "map/MapEnergy.h"
#include "map/MapOptions.h"
#include "map/MapPhase.h"
#include "map/Remeshing.h"
#include "optimisation/NewtonSolver.h"

#include <Eigen/Core>

#include <map>
#include <vector>

namespace surfacemaps
{

/// Runs phases on a common triangulation: per iteration the improving
/// splits, collapses and flips, then one projected-Newton step on every
/// embedding of T (DESIGN.md section 1.4), until the phase's cap or its end
/// condition. Reports progress per iteration and throws Aborted when the
/// progress callback says so.
class PhaseRunner
{
public:
  /// `targets`: landmark id -> target point on each input's sphere;
  /// `plannedIterations`: the whole schedule's, for the progress fraction.
  PhaseRunner(CommonTriangulation& T,
    std::vector<PreparedInput>& surfaces,
    const SurfaceMapOptions& options,
    std::vector<std::map<int, Eigen::Vector3d>> targets,
    int plannedIterations);

  /// Sets the phase's sizing, then iterates on the phase's energy.
  MapPhaseReport run(const MapPhase& phase);

  /// The weights of the last phase run: the final energy's.
  const MapEnergyWeights& weights() const { return this->Weights; }

  /// Largest sphere distance of a landmark vertex from its target.
  double landmarkError() const;

  /// Puts every landmark vertex exactly on its input vertex on every sphere
  /// where its star stays positively oriented (exact); returns how many
  /// (vertex, sphere) pairs could not be snapped.
  int snapLandmarks();

private:
  /// Target lengths, then the improving splits, collapses and flips the
  /// phase allows (only flips when `relaxing`), counted into the report.
  RemeshingResult remeshing(const MapPhase& phase,
    const MapEnergy& energy,
    bool relaxing,
    MapPhaseReport& report);
  /// One projected-Newton step on every embedding of T, written back;
  /// times and T's size into the report.
  NewtonStepResult newtonIteration(const MapPhase& phase,
    const MapEnergy& energy,
    LinearSolver& solver,
    Objective& objective,
    MapPhaseReport& report);
  /// Whether the phase ends after this iteration (its StopRule); updates the
  /// report's landmark error and whether the landmarks were `reached`.
  bool stops(const MapPhase& phase,
    const RemeshingResult& edits,
    const NewtonStepResult& step,
    MapPhaseReport& report,
    bool& reached) const;
  /// Throws when T has more vertices than the budget.
  void checkVertexBudget(const MapPhase& phase, int iteration) const;
  void logIteration(const MapPhase& phase,
    const MapPhaseReport& report,
    const NewtonStepResult& step,
    const RemeshingResult& edits) const;
  void logPhase(const MapPhase& phase, const MapPhaseReport& report) const;
  void reportProgress(const MapPhase& phase, int iteration, int vertices, double energy);

  CommonTriangulation& T;
  std::vector<PreparedInput>& Surfaces;
  const SurfaceMapOptions& Options;
  std::vector<std::map<int, Eigen::Vector3d>> Targets;
  int PlannedIterations;
  int Done = 0;
  MapEnergyWeights Weights;
  /// T's vertex count at most (SurfaceMapOptions::maxVertices).
  std::size_t VertexBudget = 0;
};

} // namespace surfacemaps
