// SurfaceMaps engine: Embedder, the hierarchical sphere embedding of one
// attempt: the tetrahedron, each level's placement and global Newton
// iterations with their stopping rules, and the area measures they use.
#include "embedding/Embedder.h"

#include "embedding/VertexPlacement.h"
#include "energy/EmbeddingEnergy.h"
#include "geometry/Predicates.h"
#include "mesh/Primitives.h"
#include "optimisation/NewtonSolver.h"
#include "optimisation/Objective.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <sstream>

namespace surfacemaps
{

namespace
{
using Triangles = std::vector<std::array<int, 3>>;

double inputAreaOf(const std::vector<Eigen::Vector3d>& x, const Triangles& triangles)
{
  double area = 0.0;
  for (const auto& t : triangles)
  {
    area += 0.5 * (x[t[1]] - x[t[0]]).cross(x[t[2]] - x[t[0]]).norm();
  }
  return area;
}

void logIteration(const Logger& log,
  int it,
  const SpherePoints& points,
  const NewtonStepResult& step)
{
  std::ostringstream line;
  line << "embedding iteration " << it + 1 << ": " << points.numberOfVariables() / 2
       << " moving points, E " << step.energyAfter << ", decrement " << step.decrement << ", step "
       << step.step << " (" << step.lineSearchTrials << " trials"
       << (step.stalled ? ", stalled" : "") << (step.regularised ? ", shifted" : "") << ")";
  log(Logger::Detail, line.str());
}
} // namespace

double smallestAreaRatioOf(const std::vector<Eigen::Vector3d>& input,
  const std::vector<Eigen::Vector3d>& sphere,
  const Triangles& triangles)
{
  std::vector<double> inputAreas(triangles.size()), chordAreas(triangles.size());
  double inputTotal = 0.0, chordTotal = 0.0;
  for (std::size_t f = 0; f < triangles.size(); ++f)
  {
    const auto& t = triangles[f];
    inputAreas[f] = (input[t[1]] - input[t[0]]).cross(input[t[2]] - input[t[0]]).norm();
    chordAreas[f] = (sphere[t[1]] - sphere[t[0]]).cross(sphere[t[2]] - sphere[t[0]]).norm();
    inputTotal += inputAreas[f];
    chordTotal += chordAreas[f];
  }
  double smallest = std::numeric_limits<double>::infinity();
  for (std::size_t f = 0; f < triangles.size(); ++f)
  {
    // Degenerate input triangles are rejected before embedding.
    smallest = std::min(smallest, (chordAreas[f] / chordTotal) / (inputAreas[f] / inputTotal));
  }
  return smallest;
}

Embedder::Embedder(const PolygonMesh& mesh,
  const DecimationResult& hierarchy,
  const SphereEmbeddingOptions& options)
  : Mesh(mesh)
  , Hierarchy(hierarchy)
  , Options(options)
{
}

void Embedder::run(const Attempt& attempt, SphereEmbeddingResult& result)
{
  const std::size_t nv = this->Mesh.points.size();
  this->Positions.assign(nv, Eigen::Vector3d::Zero());
  this->Active.assign(nv, 0);
  const auto& levels = this->Hierarchy.levels;
  this->placeTetrahedron();

  EmbeddingEnergy energy;
  energy.input = &this->Mesh.points;
  energy.distortionWeight = attempt.distortionWeight;

  std::size_t inserted = 4;
  double levelEnergy = std::numeric_limits<double>::infinity();
  for (int level = static_cast<int>(levels.size()) - 1; level >= 0; --level)
  {
    levelEnergy = this->undoLevel(level, attempt, energy, inserted, levelEnergy, result);
  }
  if (levels.empty())
  {
    energy.triangles = this->Hierarchy.triangles;
    energy.barrierWeight = attempt.barrierWeight / static_cast<double>(energy.triangles.size());
    energy.inputArea = inputAreaOf(this->Mesh.points, energy.triangles);
    this->optimise(energy,
      this->Options.finalIterations,
      this->Options.finalTolerance,
      result,
      { 0.0, 1.0 },
      0,
      std::numeric_limits<double>::infinity(),
      this->Options.finalIterationsSqueezed);
  }
  result.positions = this->Positions;
  result.levels = static_cast<int>(levels.size());
}

// The coarsest level is a tetrahedron: place it regularly, oriented so
// that its triangles are positive.
void Embedder::placeTetrahedron()
{
  const auto& levels = this->Hierarchy.levels;
  const Triangles& base = levels.empty() ? this->Hierarchy.triangles : levels.back().triangles;
  std::vector<int> corners;
  for (const auto& t : base)
  {
    for (int v : t)
    {
      if (!this->Active[v])
      {
        this->Active[v] = 1;
        corners.push_back(v);
      }
    }
  }
  if (corners.size() != 4 || base.size() != 4)
  {
    throw AttemptFailed{ "the coarsest level is not a tetrahedron" };
  }
  const PolygonMesh tet = makeTetrahedron();
  for (int k = 0; k < 4; ++k)
  {
    this->Positions[corners[k]] = tet.points[k];
  }
  if (orient3dOrigin(
        this->Positions[base[0][0]], this->Positions[base[0][1]], this->Positions[base[0][2]]) < 0)
  {
    std::swap(this->Positions[corners[0]], this->Positions[corners[1]]);
  }
}

// Undoes the collapses of `level` (inserted: how many vertices are in so
// far) and optimises the finer mesh; returns its energy. `previous` is the
// energy the level before ended with.
double Embedder::undoLevel(int level,
  const Attempt& attempt,
  EmbeddingEnergy& energy,
  std::size_t& inserted,
  double previous,
  SphereEmbeddingResult& result)
{
  const std::size_t nv = this->Mesh.points.size();
  const auto& levels = this->Hierarchy.levels;
  const Triangles& finer = level > 0 ? levels[level - 1].triangles : this->Hierarchy.triangles;
  energy.triangles = finer;
  // The barrier's total weight is spread over the triangles, so that it
  // stays a small fraction of the distortion (>= 1) at every level.
  energy.barrierWeight = attempt.barrierWeight / static_cast<double>(finer.size());
  energy.inputArea = inputAreaOf(this->Mesh.points, finer);
  energy.chordArea = inputAreaOf(this->Positions, levels[level].triangles);
  this->placeLevel(level, energy, result);
  const double before = 0.9 * static_cast<double>(inserted) / static_cast<double>(nv);
  inserted += levels[level].collapses.size();
  const double after =
    level > 0 ? 0.9 * static_cast<double>(inserted) / static_cast<double>(nv) : 1.0;
  const int iterations =
    inserted > 1000 ? this->Options.levelIterationsLarge : this->Options.levelIterations;
  // Large levels get few iterations, unless the insertion left the energy
  // far above the previous level's: then up to levelIterations, so that
  // damage is not carried into the next levels.
  const double levelEnergy = this->optimise(energy,
    level > 0 ? iterations : this->Options.finalIterations,
    level > 0 ? this->Options.levelTolerance : this->Options.finalTolerance,
    result,
    { before, after },
    level > 0 ? std::max(iterations, this->Options.levelIterations) : 0,
    1.5 * previous,
    level > 0 ? 0 : this->Options.finalIterationsSqueezed);
  // A level left this distorted carries nearly collapsed triangles into
  // the next ones, whose vertices must then go into kernels a few
  // rounding errors wide; such an attempt fails late, at a placement or
  // at the end (README, "Sphere embedding"), so the stronger barrier
  // starts now.
  if (level > 0 &&
    !(embeddingDistortion(this->Mesh.points, this->Positions, finer) <= attempt.abandonAbove))
  {
    throw AttemptFailed{ "nearly degenerate triangles on the sphere at " +
      std::to_string(inserted) + " of " + std::to_string(nv) + " vertices" };
  }
  return levelEnergy;
}

// Places the vertices the collapses of `level` removed (in parallel: each
// one's ring is of the coarser level, whose positions stay) and makes them
// active.
void Embedder::placeLevel(int level, const EmbeddingEnergy& energy, SphereEmbeddingResult& result)
{
  const auto& collapses = this->Hierarchy.levels[level].collapses;
  const int count = static_cast<int>(collapses.size());
  const auto placementStart = std::chrono::steady_clock::now();
  bool placed = true;
#pragma omp parallel for schedule(dynamic, 16) reduction(&& : placed)
  for (int i = 0; i < count; ++i)
  {
    const Collapse& c = collapses[i];
    Eigen::Vector3d p;
    if (!placeInKernel(c, energy, this->Positions, p))
    {
      placed = false;
      continue;
    }
    this->Positions[c.removed] = p;
    relaxVertex(c, energy, this->Positions, this->Options.localIterations);
  }
  result.placementSeconds +=
    std::chrono::duration<double>(std::chrono::steady_clock::now() - placementStart).count();
  if (!placed)
  {
    throw AttemptFailed{ "a vertex could not be placed inside its one-ring" };
  }
  for (const Collapse& c : collapses)
  {
    this->Active[c.removed] = 1;
  }
}

void Embedder::report(double fraction)
{
  if (this->Options.progress && !this->Options.progress(fraction))
  {
    throw Aborted{};
  }
}

// Newton steps on the active vertices; returns the final energy. After
// `iterations` steps it goes on, up to `extendedIterations` in all, while
// the energy is above `extendAbove`, and up to `squeezedIterations` in all
// while a triangle is squeezed (Options.squeezedRatio). Progress is
// reported after every step, moving through `fractions` (at the start,
// after the last step of the first `iterations`, or of the extension).
double Embedder::optimise(EmbeddingEnergy& energy,
  int iterations,
  double tolerance,
  SphereEmbeddingResult& result,
  std::array<double, 2> fractions,
  int extendedIterations,
  double extendAbove,
  int squeezedIterations)
{
  SpherePoints points(this->Positions);
  std::vector<char> locked(this->Active.size());
  for (std::size_t i = 0; i < locked.size(); ++i)
  {
    locked[i] = this->Active[i] ? 0 : 1;
  }
  points.setLocked(locked);
  auto term = std::make_shared<ElementTerm<3, EmbeddingEnergy>>("embedding", energy);
  Objective objective;
  objective.addTerm(term);
  // The pattern stays for all iterations of a level: worth a better ordering.
  LinearSolver solver(LinearSolver::Ordering::NestedDissection);
  NewtonOptions newton;
  newton.maxPointStep = this->Options.maxPointStep;
  newton.log = this->Options.log;
  const Triangles& triangles = energy.triangles;
  ObjectiveProblem problem(objective,
    [&triangles](const SpherePoints& p)
    { return std::lround(sphericalDegree(p.positions(), triangles)) == 1; });
  double energyNow = std::numeric_limits<double>::infinity();
  const int most = std::max(iterations, extendedIterations);
  const int squeezeCap = this->Options.squeezedRatio > 0.0 ? squeezedIterations : 0;
  for (int it = 0; it < std::max(most, squeezeCap); ++it)
  {
    if (it >= iterations && !(it < most && energyNow > extendAbove) &&
      !(it < squeezeCap &&
        smallestAreaRatioOf(this->Mesh.points, points.positions(), triangles) <
          this->Options.squeezedRatio))
    {
      break;
    }
    term->energy().chordArea = inputAreaOf(points.positions(), triangles);
    const NewtonStepResult step = newtonStep(problem, points, solver, newton);
    ++result.newtonIterations;
    result.derivativeSeconds += step.derivativeSeconds;
    result.solveSeconds += step.solveSeconds;
    result.lineSearchSeconds += step.lineSearchSeconds;
    result.energy = step.energyAfter;
    energyNow = step.energyAfter;
    logIteration(this->Options.log, it, points, step);
    this->report(fractions[0] + (fractions[1] - fractions[0]) * std::min(1.0, (it + 1.0) / most));
    // Converged when the decrease a Newton step expects (decrement^2 / 2)
    // is negligible. Absolute, in units of the distortion (whose minimum is
    // 1): a relative test would stop at once when one bad triangle makes
    // the energy huge.
    if (!step.moved || 0.5 * step.decrement * step.decrement < tolerance)
    {
      break;
    }
  }
  this->Positions = points.positions();
  return energyNow;
}

} // namespace surfacemaps
