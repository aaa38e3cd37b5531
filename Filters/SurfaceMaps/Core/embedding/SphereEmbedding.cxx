#include "embedding/SphereEmbedding.h"

#include "embedding/Decimation.h"
#include "energy/EmbeddingEnergy.h"
#include "geometry/MapMetrics.h"
#include "optimisation/NewtonSolver.h"
#include "optimisation/Objective.h"
#include "geometry/Predicates.h"
#include "mesh/Primitives.h"

#include <Eigen/Eigenvalues>

#include <omp.h>

#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>

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

// The smallest ratio of a triangle's share of the sphere's chord area to its
// share of the input's area (SphereEmbeddingResult::smallestAreaRatio).
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

// Thrown inside one attempt when it cannot continue; the next attempt runs.
struct AttemptFailed
{
  std::string reason;
};

// True if p joined to its ring gives positively oriented triangles and
// spherical edges shorter than the energy's limit, so the energy is finite.
bool validInRing(const Eigen::Vector3d& p,
  const std::vector<int>& ring,
  const std::vector<Eigen::Vector3d>& pos,
  double minEdgeCos)
{
  const std::size_t n = ring.size();
  for (std::size_t i = 0; i < n; ++i)
  {
    if (orient3dOrigin(p, pos[ring[i]], pos[ring[(i + 1) % n]]) <= 0 ||
      !(p.dot(pos[ring[i]]) > minEdgeCos))
    {
      return false;
    }
  }
  return true;
}

// The energy of the triangles around c.removed if it were at p.
double starEnergy(const Collapse& c,
  const EmbeddingEnergy& energy,
  const std::vector<Eigen::Vector3d>& pos,
  const Eigen::Vector3d& p)
{
  const std::size_t n = c.ring.size();
  double e = 0.0;
  for (std::size_t i = 0; i < n && std::isfinite(e); ++i)
  {
    const std::array<int, 3> t{ c.removed, c.ring[i], c.ring[(i + 1) % n] };
    e += energy.triangleEnergy<double>(t, { p, pos[t[1]], pos[t[2]] });
  }
  return e;
}

// A point strictly inside the kernel of the star polygon c.ring on the sphere
// (which contains c.kept as a vertex and is star-shaped with respect to it),
// with all new edges short enough: of a few candidates that qualify, the one
// with the lowest energy of the new triangles. Candidates: the ring's
// centroid, the ring's average weighted like the removed vertex's 3D
// neighbourhood, and points close to c.kept inside the angle its two ring
// edges make (which qualify for small enough distances, since the coarser
// embedding was valid).
bool placeInKernel(const Collapse& c,
  const EmbeddingEnergy& energy,
  const std::vector<Eigen::Vector3d>& pos,
  Eigen::Vector3d& out)
{
  const std::size_t n = c.ring.size();
  const std::vector<Eigen::Vector3d>& x = *energy.input;
  double best = std::numeric_limits<double>::infinity();
  auto consider = [&](const Eigen::Vector3d& candidate)
  {
    if (!(candidate.norm() > 1e-12))
    {
      return false;
    }
    const Eigen::Vector3d p = candidate.normalized();
    if (!validInRing(p, c.ring, pos, energy.minEdgeCos))
    {
      return false;
    }
    const double e = starEnergy(c, energy, pos, p);
    if (e < best)
    {
      best = e;
      out = p;
    }
    return std::isfinite(e);
  };

  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  Eigen::Vector3d weighted = Eigen::Vector3d::Zero();
  for (int w : c.ring)
  {
    centroid += pos[w];
    weighted += pos[w] / std::max(1e-300, (x[w] - x[c.removed]).norm());
  }
  consider(centroid);
  consider(weighted);

  std::size_t iu = 0;
  while (iu < n && c.ring[iu] != c.kept)
  {
    ++iu;
  }
  if (iu == n)
  {
    return std::isfinite(best);
  }
  const Eigen::Vector3d& u = pos[c.kept];
  const Eigen::Vector3d& prev = pos[c.ring[(iu + n - 1) % n]];
  const Eigen::Vector3d& next = pos[c.ring[(iu + 1) % n]];
  // Tangent directions t with det[t, prev, u] > 0 and det[t, u, next] > 0.
  Eigen::Vector3d n1 = prev.cross(u), n2 = u.cross(next);
  n1 -= n1.dot(u) * u;
  n2 -= n2.dot(u) * u;
  Eigen::Vector3d t = n1.normalized() + n2.normalized();
  if (!(t.norm() > 1e-12))
  {
    return std::isfinite(best);
  }
  t.normalize();
  double shortest = 2.0;
  for (int w : c.ring)
  {
    if (w != c.kept)
    {
      shortest = std::min(shortest, (pos[w] - u).norm());
    }
  }
  // A few distances from u; further halving only while nothing qualifies.
  int tried = 0;
  for (double eps = 0.4 * shortest; eps > 1e-14; eps *= 0.5, ++tried)
  {
    const bool ok = consider(u + eps * t);
    if (tried >= 3 && (ok || std::isfinite(best)))
    {
      break;
    }
  }
  return std::isfinite(best);
}

// Newton on the two tangent variables of vertex v, its ring fixed.
void relaxVertex(const Collapse& c,
  const EmbeddingEnergy& energy,
  std::vector<Eigen::Vector3d>& pos,
  int iterations)
{
  const int v = c.removed;
  const std::size_t n = c.ring.size();
  using D = Dual<2>;
  for (int it = 0; it < iterations; ++it)
  {
    const Eigen::Vector3d p = pos[v];
    const Eigen::Matrix<double, 3, 2> B = SpherePoints::tangentBasis(p);
    Eigen::Matrix<D, 3, 1> pv;
    for (int k = 0; k < 3; ++k)
    {
      pv[k] = D(p[k]);
      pv[k].grad = B.row(k).transpose();
      pv[k].Hess = -p[k] * Eigen::Matrix2d::Identity();
    }
    D e = 0.0;
    for (std::size_t i = 0; i < n; ++i)
    {
      const std::array<int, 3> t{ v, c.ring[i], c.ring[(i + 1) % n] };
      e +=
        energy.triangleEnergy<D>(t, { pv, pos[t[1]].cast<D>().eval(), pos[t[2]].cast<D>().eval() });
    }
    if (!std::isfinite(e.val))
    {
      return;
    }
    Eigen::Matrix2d H = e.Hess;
    projectToPositiveDefinite<2>(H, 1e-12 * std::max(1.0, H.cwiseAbs().maxCoeff()));
    Eigen::Vector2d d = -H.ldlt().solve(e.grad);
    double slope = d.dot(e.grad);
    if (!(slope < 0.0))
    {
      d = -e.grad;
      slope = -e.grad.squaredNorm();
    }
    // Converged: the decrease a Newton step expects is negligible.
    if (!(-slope > 1e-10 * std::abs(e.val)))
    {
      return;
    }
    // The energy tests orientation in floating point, in the order of the
    // star's triangles; where the ring leaves a kernel only a few rounding
    // errors wide, it can call a position valid that the exact predicates
    // (the certificate's) call inverted. Such a trial is rejected here: once
    // accepted, no later step can repair it (the energy of some other corner
    // order is infinite from then on).
    LineSearchResult ls = armijoBacktracking(
      [&](double s)
      {
        const Eigen::Vector3d q = SpherePoints::retraction(p, B, s * d[0], s * d[1]);
        return validInRing(q, c.ring, pos, energy.minEdgeCos)
          ? starEnergy(c, energy, pos, q)
          : std::numeric_limits<double>::infinity();
      },
      e.val,
      slope,
      std::min(1.0, 0.5 / std::max(1e-12, d.norm())));
    if (!ls.success)
    {
      return;
    }
    pos[v] = SpherePoints::retraction(p, B, ls.step * d[0], ls.step * d[1]);
  }
}

struct Attempt
{
  double barrierWeight;
  double distortionWeight;
  /// A level whose distortion ends above this abandons the attempt (only
  /// where a retry with a stronger barrier follows).
  double abandonAbove;
};

class Embedder
{
public:
  Embedder(const PolygonMesh& mesh,
    const DecimationResult& hierarchy,
    const SphereEmbeddingOptions& options)
    : Mesh(mesh)
    , Hierarchy(hierarchy)
    , Options(options)
  {
  }

  void run(const Attempt& attempt, SphereEmbeddingResult& result)
  {
    const std::size_t nv = this->Mesh.points.size();
    this->Positions.assign(nv, Eigen::Vector3d::Zero());
    this->Active.assign(nv, 0);
    const auto& levels = this->Hierarchy.levels;

    // The coarsest level is a tetrahedron: place it regularly, oriented so
    // that its triangles are positive.
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
    if (orient3dOrigin(this->Positions[base[0][0]],
          this->Positions[base[0][1]],
          this->Positions[base[0][2]]) < 0)
    {
      std::swap(this->Positions[corners[0]], this->Positions[corners[1]]);
    }

    EmbeddingEnergy energy;
    energy.input = &this->Mesh.points;
    energy.distortionWeight = attempt.distortionWeight;

    std::size_t inserted = 4;
    double levelEnergy = std::numeric_limits<double>::infinity();
    for (int level = static_cast<int>(levels.size()) - 1; level >= 0; --level)
    {
      const Triangles& finer = level > 0 ? levels[level - 1].triangles : this->Hierarchy.triangles;
      energy.triangles = finer;
      // The barrier's total weight is spread over the triangles, so that it
      // stays a small fraction of the distortion (>= 1) at every level.
      energy.barrierWeight = attempt.barrierWeight / static_cast<double>(finer.size());
      energy.inputArea = inputAreaOf(this->Mesh.points, finer);
      energy.chordArea = inputAreaOf(this->Positions, levels[level].triangles);
      const auto& collapses = levels[level].collapses;
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
      const double before = 0.9 * static_cast<double>(inserted) / static_cast<double>(nv);
      inserted += collapses.size();
      const double after =
        level > 0 ? 0.9 * static_cast<double>(inserted) / static_cast<double>(nv) : 1.0;
      const int iterations =
        inserted > 1000 ? this->Options.levelIterationsLarge : this->Options.levelIterations;
      // Large levels get few iterations, unless the insertion left the energy
      // far above the previous level's: then up to levelIterations, so that
      // damage is not carried into the next levels.
      const double previous = levelEnergy;
      levelEnergy = this->optimise(energy,
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

private:
  void report(double fraction)
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
  double optimise(EmbeddingEnergy& energy,
    int iterations,
    double tolerance,
    SphereEmbeddingResult& result,
    std::array<double, 2> fractions,
    int extendedIterations = 0,
    double extendAbove = std::numeric_limits<double>::infinity(),
    int squeezedIterations = 0)
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
      {
        std::ostringstream line;
        line << "embedding iteration " << it + 1 << ": " << points.numberOfVariables() / 2
             << " moving points, E "
             << step.energyAfter << ", decrement " << step.decrement << ", step " << step.step
             << " (" << step.lineSearchTrials << " trials" << (step.stalled ? ", stalled" : "")
             << (step.regularised ? ", shifted" : "") << ")";
        this->Options.log(Logger::Detail, line.str());
      }
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

  const PolygonMesh& Mesh;
  const DecimationResult& Hierarchy;
  const SphereEmbeddingOptions& Options;
  std::vector<Eigen::Vector3d> Positions;
  std::vector<char> Active;
};

} // namespace

double embeddingDistortion(const std::vector<Eigen::Vector3d>& input,
  const std::vector<Eigen::Vector3d>& sphere,
  const Triangles& triangles)
{
  // The map from the input to its chord triangles, measured like any map.
  return measureMap(input, sphere, triangles).symmetricDirichlet;
}

std::vector<SphereEmbeddingResult> embedAllOnSphere(const std::vector<const PolygonMesh*>& meshes,
  const SphereEmbeddingOptions& options)
{
  const int n = static_cast<int>(meshes.size());
  std::vector<SphereEmbeddingResult> results(n);
  if (n == 1)
  {
    try
    {
      results[0] = embedOnSphere(*meshes[0], options);
    }
    catch (const std::runtime_error& e)
    {
      throw EmbeddingFailure(0, e.what());
    }
    return results;
  }
  std::unique_ptr<std::atomic<double>[]> fractions(new std::atomic<double>[n]);
  for (int i = 0; i < n; ++i)
  {
    fractions[i] = 0.0;
  }
  std::atomic<bool> aborted{ false };
  std::vector<std::exception_ptr> errors(n);
  // One mesh per thread. Embeddings take unequal times (one may need a second
  // attempt), so a thread whose meshes are done lends itself to the ones still
  // running: each running embedding's own parallel regions (a nested level)
  // get an equal share of the threads, updated after every Newton step. The
  // results do not depend on the thread count, only the time does.
  const int available = omp_get_max_threads();
  const int threads = std::max(1, std::min(n, available));
  std::atomic<int> running{ 0 };
  auto share = [&]() { return std::max(1, available / std::max(1, running.load())); };
  const int previousLevels = omp_get_max_active_levels();
  omp_set_max_active_levels(std::max(previousLevels, 2));
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
  for (int i = 0; i < n; ++i)
  {
    ++running;
    omp_set_num_threads(share());
    const bool reporter = omp_get_thread_num() == 0;
    SphereEmbeddingOptions local = options;
    local.progress = [&, i, reporter](double fraction)
    {
      fractions[i] = fraction;
      omp_set_num_threads(share());
      if (aborted)
      {
        return false;
      }
      if (reporter && options.progress)
      {
        double mean = 0.0;
        for (int k = 0; k < n; ++k)
        {
          mean += fractions[k] / n;
        }
        if (!options.progress(mean))
        {
          aborted = true;
          return false;
        }
      }
      return true;
    };
    try
    {
      results[i] = embedOnSphere(*meshes[i], local);
      fractions[i] = 1.0;
    }
    catch (...)
    {
      errors[i] = std::current_exception();
    }
    --running;
  }
  omp_set_max_active_levels(previousLevels);
  if (aborted)
  {
    throw Aborted{};
  }
  for (int i = 0; i < n; ++i)
  {
    if (errors[i])
    {
      try
      {
        std::rethrow_exception(errors[i]);
      }
      catch (const Aborted&)
      {
        throw;
      }
      catch (const std::exception& e)
      {
        throw EmbeddingFailure(i, e.what());
      }
    }
  }
  return results;
}

SphereEmbeddingResult embedOnSphere(const PolygonMesh& mesh, const SphereEmbeddingOptions& options)
{
  const auto start = std::chrono::steady_clock::now();
  DecimationOptions decimation;
  decimation.log = options.log;
  const DecimationResult hierarchy = decimateToTetrahedron(mesh, decimation);
  const double decimationSeconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  options.log(Logger::Detail,
    "sphere embedding: " + std::to_string(hierarchy.levels.size()) + " decimation levels");

  const double never = std::numeric_limits<double>::infinity();
  const Attempt attempts[] = {
    { options.barrierWeight, 1.0, options.maxDistortion },
    { 100.0 * options.barrierWeight, 1.0, never }, // the last to minimise distortion: runs to the end
    { 1.0, 0.0, never },                          // barrier alone
  };
  std::string reasons;
  // Progress never goes back: a retried attempt covers what is left of the
  // range from where the failed one stopped.
  double reached = 0.0;
  std::optional<SphereEmbeddingResult> best;
  auto finish = [&](SphereEmbeddingResult result)
  {
    result.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (options.progress)
    {
      options.progress(1.0);
    }
    return result;
  };
  for (int a = 0; a < 3; ++a)
  {
    SphereEmbeddingResult result;
    result.attempt = a + 1;
    result.decimationSeconds = decimationSeconds;
    SphereEmbeddingOptions attemptOptions = options;
    if (options.progress)
    {
      const double from = reached;
      attemptOptions.progress = [&options, &reached, from](double fraction)
      {
        reached = from + (1.0 - from) * fraction;
        return options.progress(reached);
      };
    }
    Embedder embedder(mesh, hierarchy, attemptOptions);
    try
    {
      embedder.run(attempts[a], result);
    }
    catch (const AttemptFailed& failure)
    {
      reasons += (reasons.empty() ? "" : "; ") +
        ("attempt " + std::to_string(a + 1) + ": " + failure.reason);
      options.log(Logger::Warning,
        "sphere embedding attempt " + std::to_string(a + 1) + " failed: " + failure.reason);
      continue;
    }
    result.certificate = certifyBijective(result.positions, hierarchy.triangles);
    if (!result.certificate.bijective)
    {
      reasons += (reasons.empty() ? "" : "; ") +
        ("attempt " + std::to_string(a + 1) + ": " + result.certificate.reason);
      options.log(Logger::Warning,
        "sphere embedding attempt " + std::to_string(a + 1) +
          " not bijective: " + result.certificate.reason);
      continue;
    }
    result.distortion = embeddingDistortion(mesh.points, result.positions, hierarchy.triangles);
    result.smallestAreaRatio =
      smallestAreaRatioOf(mesh.points, result.positions, hierarchy.triangles);
    if (!(result.distortion <= options.maxDistortion))
    {
      const std::string reason = "nearly degenerate triangles on the sphere (distortion " +
        std::to_string(result.distortion) + ")";
      reasons +=
        (reasons.empty() ? "" : "; ") + ("attempt " + std::to_string(a + 1) + ": " + reason);
      options.log(
        Logger::Warning, "sphere embedding attempt " + std::to_string(a + 1) + ": " + reason);
      if (!best || result.distortion < best->distortion)
      {
        best = std::move(result);
      }
      continue;
    }
    return finish(std::move(result));
  }
  // Every certified attempt was too distorted: the least distorted one is
  // still a valid embedding, and better than none.
  if (best)
  {
    options.log(Logger::Warning,
      "sphere embedding: no attempt reached distortion " + std::to_string(options.maxDistortion) +
        "; keeping attempt " + std::to_string(best->attempt) + " (distortion " +
        std::to_string(best->distortion) + ")");
    return finish(std::move(*best));
  }
  throw std::runtime_error("no bijective sphere embedding found (" + reasons + ")");
}

} // namespace surfacemaps
