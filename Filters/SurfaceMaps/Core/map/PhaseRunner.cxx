#include "map/PhaseRunner.h"
#include "base/Error.h"

#include "base/Aborted.h"
#include "geometry/Predicates.h"
#include "map/MapNewtonProblem.h"
#include "map/MapSettings.h"
#include "map/Remeshing.h"
#include "optimisation/NewtonSolver.h"

#include <algorithm>
#include <chrono>
#include <sstream>
#include <stdexcept>

namespace surfacemaps
{

namespace
{
using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}
} // namespace

PhaseRunner::PhaseRunner(CommonTriangulation& T,
  std::vector<PreparedInput>& surfaces,
  const SurfaceMapOptions& options,
  std::vector<std::map<int, Eigen::Vector3d>> targets,
  int plannedIterations)
  : T(T)
  , Surfaces(surfaces)
  , Options(options)
  , Targets(std::move(targets))
  , PlannedIterations(std::max(1, plannedIterations))
{
  std::size_t largest = 0;
  for (const PreparedInput& s : surfaces)
  {
    largest = std::max(largest, s.points.size());
  }
  this->VertexBudget = options.maxVertices > 0 ? static_cast<std::size_t>(options.maxVertices)
                                               : std::max<std::size_t>(20000, 20 * largest);
}

double PhaseRunner::landmarkError() const
{
  double error = 0.0;
  for (auto v : this->T.mesh().vertices())
  {
    const int id = this->T.landmark(v);
    for (int i = 0; id >= 0 && i < this->T.numberOfInputs(); ++i)
    {
      const auto it = this->Targets[i].find(id);
      if (it != this->Targets[i].end())
      {
        error = std::max(error, (this->T.g(v, i) - it->second).norm());
      }
    }
  }
  return error;
}

MapPhaseReport PhaseRunner::run(const MapPhase& phase)
{
  const auto start = Clock::now();
  if (phase.sizingError > 0.0)
  {
    setCurvatureSizing(
      this->Surfaces, phase.sizingError, this->Options.minEdgeLength, this->Options.maxEdgeLength);
  }
  this->Weights = phase.weights;
  const MapEnergy energy(this->T, phase.weights);
  MapPhaseReport report;
  report.kind = phase.kind;
  // Kept across iterations: an unchanged Hessian pattern (no edit that
  // changed T) lets the solver keep its symbolic analysis.
  LinearSolver solver;
  Objective objective;
  bool reached = false;
  for (int it = 0; it < phase.iterations && !report.converged; ++it)
  {
    // Once the landmarks are reached, T keeps its vertices (StopRule).
    const RemeshingResult edits = this->remeshing(phase, energy, reached, report);
    this->checkVertexBudget(phase, it);
    const NewtonStepResult step = this->newtonIteration(phase, energy, solver, objective, report);
    report.iterations = it + 1;
    report.energy = step.energyAfter;
    report.derivativeSeconds += step.derivativeSeconds;
    report.solveSeconds += step.solveSeconds;
    report.lineSearchSeconds += step.lineSearchSeconds;
    report.stalledIterations += step.stalled ? 1 : 0;
    this->logIteration(phase, report, step, edits);
    this->reportProgress(phase, it + 1, report.vertices, step.energyAfter);
    report.converged = this->stops(phase, edits, step, report, reached);
  }
  report.seconds = secondsSince(start);
  this->logPhase(phase, report);
  return report;
}

bool PhaseRunner::stops(const MapPhase& phase,
  const RemeshingResult& edits,
  const NewtonStepResult& step,
  MapPhaseReport& report,
  bool& reached) const
{
  const bool settled = edits.splits + edits.collapses + edits.flips == 0 &&
    step.decrement < this->Options.decrementTolerance;
  if (phase.stop == StopRule::Settled)
  {
    return settled;
  }
  report.landmarkError = this->landmarkError();
  const bool within = report.landmarkError < this->Options.landmarkTolerance;
  reached = reached || within;
  return within && (phase.stop == StopRule::LandmarksReached || settled);
}

void PhaseRunner::checkVertexBudget(const MapPhase& phase, int iteration) const
{
  if (this->T.mesh().n_vertices() > this->VertexBudget)
  {
    // The setting's property name and flag come from the list.
    const MapSetting& budget = *findSettingFlag(mapSettings(), "--max-vertices");
    throw NoResultError("the common triangulation reached its vertex budget in the " +
      std::string(phaseName(phase.kind)) + " phase (iteration " + std::to_string(iteration + 1) +
      "): " + std::to_string(this->T.mesh().n_vertices()) + " vertices, budget " +
      std::to_string(this->VertexBudget) + " (" + budget.name + ", --" + budget.flag +
      "); the target error or error bound asks for a finer T");
  }
}

void PhaseRunner::logIteration(const MapPhase& phase,
  const MapPhaseReport& report,
  const NewtonStepResult& step,
  const RemeshingResult& edits) const
{
  std::ostringstream message;
  message << phaseName(phase.kind) << " iteration " << report.iterations << ": " << report.vertices
          << " vertices, E " << step.energyAfter << ", decrement " << step.decrement << ", step "
          << step.step << " (" << step.lineSearchTrials << " trials"
          << (step.gradientFallback ? ", gradient" : "") << (step.stalled ? ", stalled" : "")
          << (step.heldPoints > 0 ? ", " + std::to_string(step.heldPoints) + " points held" : "")
          << "), edits " << edits.splits << "/" << edits.collapses << "/" << edits.flips;
  this->Options.log(Logger::Detail, message.str());
}

void PhaseRunner::logPhase(const MapPhase& phase, const MapPhaseReport& report) const
{
  std::ostringstream message;
  message << phaseName(phase.kind) << " phase: " << report.iterations << " iterations"
          << (report.converged ? " (converged)" : " (iteration cap)") << ", " << report.vertices
          << " vertices, " << report.seconds << " s";
  this->Options.log(Logger::Info, message.str());
  if (phase.stop != StopRule::Settled && !report.converged)
  {
    this->Options.log(Logger::Warning,
      "landmark phase stopped at its cap with landmark error " +
        std::to_string(report.landmarkError) + " (tolerance " +
        std::to_string(this->Options.landmarkTolerance) + "); going on");
  }
}

RemeshingResult PhaseRunner::remeshing(const MapPhase& phase,
  const MapEnergy& energy,
  bool relaxing,
  MapPhaseReport& report)
{
  const auto clock = Clock::now();
  if (energy.weights().mesh > 0.0)
  {
    this->T.updateTargetLengths();
  }
  report.bookkeepingSeconds += secondsSince(clock);
  RemeshingOptions remeshing;
  remeshing.collapse = phase.collapses;
  remeshing.flip = phase.flips;
  if (relaxing)
  {
    // Relaxing after the landmarks were reached: T keeps its vertices.
    remeshing.collapse = false;
    remeshing.split = false;
  }
  const RemeshingResult edits = remesh(this->T, energy, remeshing);
  report.splits += edits.splits;
  report.collapses += edits.collapses;
  report.flips += edits.flips;
  report.remeshSeconds += edits.seconds;
  return edits;
}

NewtonStepResult PhaseRunner::newtonIteration(const MapPhase& phase,
  const MapEnergy& energy,
  LinearSolver& solver,
  Objective& objective,
  MapPhaseReport& report)
{
  auto clock = Clock::now();
  SpherePoints points;
  MapNewtonProblem problem(this->T,
    energy,
    this->Targets,
    objective,
    points,
    phase.lockLandmarks,
    this->Options.blockSolveInputs);
  report.bookkeepingSeconds += secondsSince(clock);
  NewtonOptions newton;
  newton.maxPointStep = this->Options.maxPointStep;
  newton.log = this->Options.log;
  const NewtonStepResult step = newtonStep(problem, points, solver, newton);
  clock = Clock::now();
  problem.writeBack(points);
  report.bookkeepingSeconds += secondsSince(clock);
  report.vertices = problem.vertices();
  return step;
}

void PhaseRunner::reportProgress(const MapPhase& phase, int iteration, int vertices, double energy)
{
  ++this->Done;
  if (!this->Options.progress)
  {
    return;
  }
  SurfaceMapProgress progress;
  progress.phase = phaseName(phase.kind);
  progress.iteration = iteration;
  progress.fraction = std::min(1.0, static_cast<double>(this->Done) / this->PlannedIterations);
  progress.vertices = vertices;
  progress.energy = energy;
  if (!this->Options.progress(progress))
  {
    throw Aborted();
  }
}

int PhaseRunner::snapLandmarks()
{
  int missed = 0;
  HalfedgeMesh& mesh = this->T.mesh();
  for (auto v : mesh.vertices())
  {
    const int id = this->T.landmark(v);
    if (id < 0)
    {
      continue;
    }
    MapVertex data = this->T.vertex(v);
    for (int i = 0; i < this->T.numberOfInputs(); ++i)
    {
      const Eigen::Vector3d target = this->Targets[i].at(id);
      bool positive = true;
      for (auto h : mesh.voh_range(v))
      {
        const auto a = mesh.to_vertex_handle(h);
        const auto b = mesh.to_vertex_handle(mesh.next_halfedge_handle(h));
        positive = positive && orient3dOrigin(target, this->T.g(a, i), this->T.g(b, i)) > 0;
      }
      if (positive)
      {
        data.g[i] = target;
      }
      else
      {
        ++missed;
      }
    }
    this->T.relocate(data);
    this->T.setVertex(v, data);
  }
  this->T.invalidateFaceEnergies();
  return missed;
}

} // namespace surfacemaps
