#include "map/SurfaceMap.h"

#include "map/CommonTriangulation.h"
#include "geometry/MapMetrics.h"
#include "map/MapTransfer.h"
#include "mesh/MeshValidation.h"
#include "optimisation/NewtonSolver.h"
#include "geometry/Predicates.h"
#include "map/Remeshing.h"
#include "geometry/Sizing.h"
#include "embedding/SphereEmbedding.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>

namespace surfacemaps
{

std::vector<std::array<int, 2>> mapPairs(PairMode mode, int n)
{
  std::vector<std::array<int, 2>> pairs;
  switch (mode)
  {
    case PairMode::Star:
      for (int i = 1; i < n; ++i)
      {
        pairs.push_back({ 0, i });
      }
      break;
    case PairMode::Sequence:
    case PairMode::Cycle:
      for (int i = 0; i + 1 < n; ++i)
      {
        pairs.push_back({ i, i + 1 });
      }
      if (mode == PairMode::Cycle && n > 2)
      {
        pairs.push_back({ n - 1, 0 });
      }
      break;
    case PairMode::All:
      for (int i = 0; i < n; ++i)
      {
        for (int j = i + 1; j < n; ++j)
        {
          pairs.push_back({ i, j });
        }
      }
      break;
  }
  return pairs;
}

namespace
{
using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

std::string inputName(int i)
{
  return "input " + std::to_string(i);
}

/// Centres an input, scales it to unit area and builds what the energy needs.
MapSurface prepareSurface(const MapInput& input, int index)
{
  MapSurface s;
  s.triangles = input.mesh.triangles();
  const std::size_t nv = input.mesh.points.size();
  if (input.spherePositions.size() != nv)
  {
    throw std::invalid_argument(inputName(index) + ": " + std::to_string(nv) + " vertices but " +
      std::to_string(input.spherePositions.size()) + " sphere positions");
  }
  if (!input.landmarks.empty() && input.landmarks.size() != nv)
  {
    throw std::invalid_argument(inputName(index) + ": landmark array has " +
      std::to_string(input.landmarks.size()) + " entries, expected " + std::to_string(nv));
  }
  if (!input.sizing.empty() && input.sizing.size() != nv)
  {
    throw std::invalid_argument(inputName(index) + ": sizing array has " +
      std::to_string(input.sizing.size()) + " entries, expected " + std::to_string(nv));
  }
  double area = 0.0;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (const auto& t : s.triangles)
  {
    const Eigen::Vector3d& a = input.mesh.points[t[0]];
    const Eigen::Vector3d& b = input.mesh.points[t[1]];
    const Eigen::Vector3d& c = input.mesh.points[t[2]];
    const double A = 0.5 * (b - a).cross(c - a).norm();
    area += A;
    centre += A * (a + b + c) / 3.0;
  }
  if (!(area > 0.0))
  {
    throw std::invalid_argument(inputName(index) + " has zero area");
  }
  s.centre = centre / area;
  s.scale = 1.0 / std::sqrt(area);
  s.points.resize(nv);
  for (std::size_t v = 0; v < nv; ++v)
  {
    s.points[v] = (input.mesh.points[v] - s.centre) * s.scale;
  }
  s.sphere = input.spherePositions;
  for (Eigen::Vector3d& p : s.sphere)
  {
    p.normalize();
  }
  s.landmarks = input.landmarks;
  if (!input.sizing.empty())
  {
    s.sizing = input.sizing;
    for (double& l : s.sizing)
    {
      l *= s.scale;
    }
  }
  return s;
}

/// Approximation samples: every vertex, or an evenly strided subset of large
/// inputs; weights = barycentric vertex areas normalised to sum 1.
void buildSamples(MapSurface& s, int samples)
{
  s.samples = ApproximationSamples();
  const std::size_t nv = s.points.size();
  std::vector<double> vertexArea(nv, 0.0);
  for (const auto& t : s.triangles)
  {
    const double A =
      0.5 * (s.points[t[1]] - s.points[t[0]]).cross(s.points[t[2]] - s.points[t[0]]).norm();
    for (int k = 0; k < 3; ++k)
    {
      vertexArea[t[k]] += A / 3.0;
    }
  }
  const std::size_t limit = static_cast<std::size_t>(std::max(1, samples));
  const std::size_t stride = (nv + limit - 1) / limit;
  double weightSum = 0.0;
  for (std::size_t v = 0; v < nv; v += stride)
  {
    s.samples.vertices.push_back(static_cast<int>(v));
    s.samples.positions.push_back(s.points[v]);
    s.samples.spherePoints.push_back(s.sphere[v]);
    s.samples.weights.push_back(vertexArea[v]);
    weightSum += vertexArea[v];
  }
  for (double& w : s.samples.weights)
  {
    w /= weightSum;
  }
}

void buildLifts(MapSurface& s)
{
  s.lifts.resize(s.triangles.size());
  for (std::size_t t = 0; t < s.triangles.size(); ++t)
  {
    const auto& tri = s.triangles[t];
    s.lifts[t] = Lift(s.points[tri[0]],
      s.points[tri[1]],
      s.points[tri[2]],
      s.sphere[tri[0]],
      s.sphere[tri[1]],
      s.sphere[tri[2]]);
  }
  s.locator = std::make_unique<SphereLocator>(s.sphere, s.triangles);
}

/// Landmark id -> vertex of each input; every id must be on every input.
std::vector<std::map<int, int>> landmarkVertices(const std::vector<MapInput>& inputs)
{
  // The same checks as input validation (MeshValidation.h): ids on one
  // vertex each, and the same ids on every input.
  std::vector<std::vector<int>> landmarkIds;
  std::vector<std::string> names;
  for (std::size_t i = 0; i < inputs.size(); ++i)
  {
    names.push_back(inputName(static_cast<int>(i)));
    const std::vector<std::string> defects = checkLandmarkIds(inputs[i].landmarks);
    if (!defects.empty())
    {
      throw std::invalid_argument(names.back() + " " + defects.front());
    }
    landmarkIds.push_back(inputs[i].landmarks);
  }
  for (const std::vector<std::string>& defects : checkLandmarkCorrespondence(landmarkIds, names))
  {
    if (!defects.empty())
    {
      throw std::invalid_argument(defects.front());
    }
  }
  std::vector<std::map<int, int>> ids(inputs.size());
  for (std::size_t i = 0; i < inputs.size(); ++i)
  {
    for (std::size_t v = 0; v < inputs[i].landmarks.size(); ++v)
    {
      if (inputs[i].landmarks[v] >= 0)
      {
        ids[i].emplace(inputs[i].landmarks[v], static_cast<int>(v));
      }
    }
  }
  return ids;
}

/// Rotates each embedding onto input 0's through the landmarks (Kabsch),
/// keeping the original where the rotated one does not certify.
void alignEmbeddings(std::vector<MapSurface>& surfaces,
  const std::vector<std::map<int, int>>& ids,
  const Logger& log)
{
  for (std::size_t i = 1; i < surfaces.size(); ++i)
  {
    if (ids[0].empty())
    {
      return;
    }
    std::vector<Eigen::Vector3d> from, to;
    for (const auto& [id, v] : ids[0])
    {
      to.push_back(surfaces[0].sphere[v]);
      from.push_back(surfaces[i].sphere[ids[i].at(id)]);
    }
    const Eigen::Matrix3d R = bestRotation(from, to);
    std::vector<Eigen::Vector3d> rotated = surfaces[i].sphere;
    for (Eigen::Vector3d& p : rotated)
    {
      p = (R * p).normalized();
    }
    if (certifyBijective(rotated, surfaces[i].triangles).bijective)
    {
      surfaces[i].sphere = std::move(rotated);
    }
    else
    {
      log(Logger::Warning,
        inputName(static_cast<int>(i)) +
          ": the embedding rotated onto input 0's landmarks does "
          "not certify; using it unrotated");
    }
  }
}

void setSizing(std::vector<MapSurface>& surfaces,
  const std::vector<MapInput>& inputs,
  double eps,
  const SurfaceMapOptions& options)
{
  for (std::size_t i = 0; i < surfaces.size(); ++i)
  {
    if (!inputs[i].sizing.empty())
    {
      continue; // the user's sizing, fixed
    }
    SizingOptions sizing;
    sizing.targetError = eps;
    sizing.minEdgeLength = options.minEdgeLength;
    sizing.maxEdgeLength = options.maxEdgeLength;
    surfaces[i].sizing = curvatureSizing(surfaces[i].points, surfaces[i].triangles, sizing);
  }
}

double boundingBoxDiagonal(const std::vector<Eigen::Vector3d>& points)
{
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d hi = -lo;
  for (const Eigen::Vector3d& p : points)
  {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return (hi - lo).norm();
}

/// Input vertices whose base point is farther than margin * bound.
struct BoundViolations
{
  int count = 0;
  /// Per input: the violating samples and their distance / bound.
  std::vector<std::vector<std::pair<int, double>>> samples;
  /// The largest distance / bound, and where.
  double worst = 0.0;
  int worstInput = -1, worstVertex = -1;
};

BoundViolations boundViolations(const CommonTriangulation& T,
  const std::vector<double>& bounds,
  double margin)
{
  BoundViolations v;
  v.samples.resize(bounds.size());
  for (int i = 0; i < T.numberOfInputs(); ++i)
  {
    const std::vector<double> distances = T.baseDistances(i);
    const std::vector<int>& vertexOf = T.surface(i).samples.vertices;
    for (std::size_t s = 0; s < distances.size(); ++s)
    {
      const double ratio = distances[s] / bounds[i];
      if (ratio > margin)
      {
        v.samples[i].emplace_back(static_cast<int>(s), ratio);
        ++v.count;
      }
      if (ratio > v.worst)
      {
        v.worst = ratio;
        v.worstInput = i;
        v.worstVertex = vertexOf[s];
      }
    }
  }
  return v;
}

/// Multiplies each input vertex's sizing by the smallest factor on its
/// one-ring (factor: per vertex, 1 = unchanged).
void scaleSizingAround(MapSurface& s, const std::vector<double>& factor)
{
  std::vector<double> ring(factor);
  for (const auto& t : s.triangles)
  {
    const double f = std::min({ factor[t[0]], factor[t[1]], factor[t[2]] });
    for (int k = 0; k < 3; ++k)
    {
      ring[t[k]] = std::min(ring[t[k]], f);
    }
  }
  for (std::size_t v = 0; v < ring.size(); ++v)
  {
    s.sizing[v] *= ring[v];
  }
}

/// Where input vertices are too far from their base points: shrinks the
/// sizing around them (the vertex and its one-ring; distance grows like the
/// edge length squared, so by sqrt(margin / ratio), at least by 0.7 and at
/// most by 0.25) so that the mesh-quality term asks for smaller triangles
/// there, and weights those samples 4 times more in the soft term.
void refineAround(std::vector<MapSurface>& surfaces,
  const BoundViolations& violations,
  double margin)
{
  for (std::size_t i = 0; i < surfaces.size(); ++i)
  {
    MapSurface& s = surfaces[i];
    std::vector<double> factor(s.points.size(), 1.0);
    for (const auto& [sample, ratio] : violations.samples[i])
    {
      s.samples.weights[sample] *= 4.0;
      const int v = s.samples.vertices[sample];
      factor[v] = std::min(factor[v], std::clamp(std::sqrt(margin / ratio), 0.25, 0.7));
    }
    scaleSizingAround(s, factor);
  }
}

/// What markExactMapDistortion found.
struct DistortedTriangles
{
  int count = 0;       // over all pairs
  double worst = 0.0;  // the largest distortion
  double area = 0.0;   // the largest area fraction of one pair
  double factor = 1.0; // the smallest sizing factor applied
};

/// Where T hides a distorted exact map: for every pair (i, j) of the map
/// term, the triangles of input i whose exact-map distortion (input i ->
/// input j through T) exceeds `threshold`. T's own map only sees T's
/// vertices; inside a T triangle the exact map follows the two sphere
/// embeddings, which can squeeze a whole input triangle where they differ.
/// Lowers `factor` at their corners on input i and at the corners of the
/// input-j triangles those land in, to 1 / sqrt(1 + growth / area) (area:
/// their unit-area fraction of input i) but at least 0.5: the vertex density
/// there grows about 1 + growth / area times, at most 4 times (infinite
/// growth: halved sizing). T is garbage-collected first, for its flat
/// triangle list.
DistortedTriangles markExactMapDistortion(CommonTriangulation& T,
  const std::vector<MapSurface>& surfaces,
  const std::vector<std::array<int, 2>>& pairs,
  double threshold,
  double growth,
  std::vector<std::vector<double>>& factor)
{
  SurfaceMesh& mesh = T.mesh();
  mesh.garbage_collection();
  const std::vector<std::array<int, 3>> triangles = faceTriangles(mesh);
  DistortedTriangles found;
  for (const auto& [i, j] : pairs)
  {
    std::vector<Eigen::Vector3d> gi(mesh.n_vertices()), gj(mesh.n_vertices());
    for (auto v : mesh.vertices())
    {
      gi[v.idx()] = T.g(v, i);
      gj[v.idx()] = T.g(v, j);
    }
    const std::vector<SurfacePoint> images = transferPoints(
      surfaces[i].sphere, triangles, gi, gj, surfaces[j].sphere, surfaces[j].triangles);
    std::vector<Eigen::Vector3d> mapped(images.size());
    for (std::size_t v = 0; v < images.size(); ++v)
    {
      mapped[v] = evaluateSurfacePoint(surfaces[j].points, surfaces[j].triangles, images[v]);
    }
    const MapMetrics metrics = measureMap(surfaces[i].points, mapped, surfaces[i].triangles);
    double area = 0.0;
    std::vector<int> distorted;
    for (std::size_t t = 0; t < surfaces[i].triangles.size(); ++t)
    {
      if (metrics.distortion[t] > threshold)
      {
        distorted.push_back(static_cast<int>(t));
        area += metrics.areaP[t];
        found.worst = std::max(found.worst, metrics.distortion[t]);
      }
    }
    // Where much of the input is distorted, T must not grow by 4 times there.
    const double f = std::clamp(1.0 / std::sqrt(1.0 + growth / std::max(area, 1e-12)), 0.5, 1.0);
    found.count += static_cast<int>(distorted.size());
    found.area = std::max(found.area, area);
    if (!distorted.empty())
    {
      found.factor = std::min(found.factor, f);
    }
    for (const int t : distorted)
    {
      for (const int v : surfaces[i].triangles[t])
      {
        factor[i][v] = std::min(factor[i][v], f);
        for (const int w : surfaces[j].triangles[images[v].triangle])
        {
          factor[j][w] = std::min(factor[j][w], f);
        }
      }
    }
  }
  return found;
}

class Schedule
{
public:
  Schedule(CommonTriangulation& T,
    const SurfaceMapOptions& options,
    std::vector<std::map<int, Eigen::Vector3d>> targets,
    int totalIterations)
    : T(T)
    , Options(options)
    , Targets(std::move(targets))
    , TotalIterations(std::max(1, totalIterations))
  {
  }

  /// Largest sphere distance of a landmark vertex from its target.
  double landmarkError() const
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

  MapPhaseReport run(const std::string& name,
    int maxIterations,
    bool lockLandmarks,
    bool untilLandmarks)
  {
    const auto start = Clock::now();
    MapPhaseReport report;
    report.name = name;
    LinearSolver solver;
    // Kept across iterations: an unchanged Hessian pattern (no edit that
    // changed T) lets the solver keep its symbolic analysis.
    Objective objective;
    bool reached = false;
    for (int it = 0; it < maxIterations; ++it)
    {
      auto clock = Clock::now();
      if (this->T.weights.mesh > 0.0)
      {
        this->T.updateTargetLengths();
      }
      report.bookkeepingSeconds += secondsSince(clock);
      RemeshingOptions remeshing;
      if (untilLandmarks && reached)
      {
        // Relaxing after the landmarks were reached: T keeps its vertices.
        remeshing.collapse = false;
        remeshing.split = false;
      }
      const RemeshingResult edits = remesh(this->T, remeshing);
      report.splits += edits.splits;
      report.collapses += edits.collapses;
      report.flips += edits.flips;
      report.remeshSeconds += edits.seconds;

      clock = Clock::now();
      CommonTriangulation::Snapshot snapshot;
      SpherePoints points;
      this->T.snapshot(snapshot, points, lockLandmarks);
      this->T.buildObjective(snapshot, this->Targets, objective);
      report.bookkeepingSeconds += secondsSince(clock);
      NewtonOptions newton;
      newton.maxPointStep = snapshot.vertices >= this->Options.largeMeshVertices
        ? this->Options.maxPointStepLarge
        : this->Options.maxPointStep;
      newton.kinkRetries = untilLandmarks ? 0 : this->Options.kinkRetries;
      newton.acceptTrial = [&](const SpherePoints& trial)
      { return this->T.update(snapshot, trial); };
      newton.log = this->Options.log;
      const NewtonStepResult step = newtonStep(objective, points, solver, newton);
      clock = Clock::now();
      if (!this->T.update(snapshot, points))
      {
        throw std::logic_error("the accepted Newton step left an invalid embedding");
      }
      this->T.writeBack(snapshot, points);
      report.bookkeepingSeconds += secondsSince(clock);

      report.iterations = it + 1;
      report.energy = step.energyAfter;
      report.derivativeSeconds += step.derivativeSeconds;
      report.solveSeconds += step.solveSeconds;
      report.lineSearchSeconds += step.lineSearchSeconds;
      report.vertices = snapshot.vertices;
      ++this->Done;

      std::ostringstream message;
      message << name << " iteration " << it + 1 << ": " << snapshot.vertices << " vertices, E "
              << step.energyAfter << ", decrement " << step.decrement << ", step " << step.step
              << " (" << step.lineSearchTrials << " trials"
              << (step.gradientFallback ? ", gradient" : "");
      if (step.kinkRetries > 0)
      {
        message << ", " << step.kinkRetries << " kink retries, " << step.heldPoints << " held";
      }
      message << "), edits " << edits.splits << "/" << edits.collapses << "/" << edits.flips;
      this->Options.log(Logger::Detail, message.str());
      if (this->Options.progress)
      {
        SurfaceMapProgress progress;
        progress.phase = name;
        progress.iteration = it + 1;
        progress.fraction = std::min(1.0, static_cast<double>(this->Done) / this->TotalIterations);
        progress.vertices = snapshot.vertices;
        progress.energy = step.energyAfter;
        if (!this->Options.progress(progress))
        {
          throw Aborted();
        }
      }
      if (untilLandmarks)
      {
        report.landmarkError = this->landmarkError();
        reached = reached || report.landmarkError < this->Options.landmarkTolerance;
        const bool settled = edits.splits + edits.collapses + edits.flips == 0 &&
          step.decrement < this->Options.decrementTolerance;
        if (report.landmarkError < this->Options.landmarkTolerance &&
          (!this->Options.relaxLandmarkPhase || settled))
        {
          report.converged = true;
          break;
        }
      }
      const int edited = edits.splits + edits.collapses + edits.flips;
      if (!untilLandmarks && edited == 0 && step.decrement < this->Options.decrementTolerance)
      {
        report.converged = true;
        break;
      }
    }
    report.seconds = secondsSince(start);
    std::ostringstream message;
    message << name << " phase: " << report.iterations << " iterations"
            << (report.converged ? " (converged)" : " (iteration cap)") << ", " << report.vertices
            << " vertices, " << report.seconds << " s";
    this->Options.log(Logger::Info, message.str());
    return report;
  }

  /// Puts every landmark vertex exactly on its input vertex on every sphere
  /// where its star stays positively oriented (exact); returns how many
  /// (vertex, sphere) pairs could not be snapped.
  int snapLandmarks()
  {
    int missed = 0;
    SurfaceMesh& mesh = this->T.mesh();
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

private:
  CommonTriangulation& T;
  const SurfaceMapOptions& Options;
  std::vector<std::map<int, Eigen::Vector3d>> Targets;
  int TotalIterations;
  int Done = 0;
};

} // namespace

std::vector<MapSurface> prepareMapSurfaces(const std::vector<MapInput>& inputs,
  const SurfaceMapOptions& options)
{
  std::vector<MapSurface> surfaces;
  surfaces.reserve(inputs.size());
  for (std::size_t i = 0; i < inputs.size(); ++i)
  {
    surfaces.push_back(prepareSurface(inputs[i], static_cast<int>(i)));
  }
  alignEmbeddings(surfaces, landmarkVertices(inputs), options.log);
  for (MapSurface& s : surfaces)
  {
    // An error bound holds for every input vertex: no subsample then.
    buildSamples(
      s, options.maxError > 0.0 ? std::numeric_limits<int>::max() : options.approximationSamples);
    buildLifts(s);
  }
  return surfaces;
}

std::vector<std::map<int, Eigen::Vector3d>> landmarkTargets(const std::vector<MapSurface>& surfaces)
{
  std::vector<std::map<int, Eigen::Vector3d>> targets(surfaces.size());
  for (std::size_t i = 0; i < surfaces.size(); ++i)
  {
    const std::vector<int>& ids = surfaces[i].landmarks;
    for (std::size_t v = 0; v < ids.size(); ++v)
    {
      if (ids[v] >= 0)
      {
        targets[i][ids[v]] = surfaces[i].sphere[v];
      }
    }
  }
  return targets;
}

SurfaceMapResult computeSurfaceMap(const std::vector<MapInput>& inputs,
  const SurfaceMapOptions& options)
{
  const auto start = Clock::now();
  const int n = static_cast<int>(inputs.size());
  if (n < 1)
  {
    throw std::invalid_argument("a surface map needs at least one input");
  }
  std::vector<MapSurface> surfaces = prepareMapSurfaces(inputs, options);
  const std::vector<std::map<int, int>> ids = landmarkVertices(inputs);
  const std::vector<std::map<int, Eigen::Vector3d>> targets = landmarkTargets(surfaces);
  const bool hasLandmarks = !ids[0].empty();
  const auto pairs = mapPairs(options.pairs, n);

  CommonTriangulation T(surfaces, pairs);
  const int refinementIterations =
    std::min(options.refinementIterations, options.fine.maxIterations);
  const int total = (hasLandmarks ? options.landmarkIterations : 0) +
    (options.coarse.enabled ? options.coarse.maxIterations : 0) +
    (options.fine.enabled ? options.fine.maxIterations : 0) +
    // The first refinement round, which nearly always runs (the later ones
    // only where the exact map is squeezed).
    (options.fine.enabled && !pairs.empty() && options.refinementRounds > 0 ? refinementIterations
                                                                            : 0) +
    (options.maxError > 0.0 ? options.boundIterations : 0);
  Schedule schedule(T, options, targets, total);
  SurfaceMapResult result;

  if (hasLandmarks && options.landmarkIterations > 0)
  {
    T.weights = MapEnergyWeights();
    T.weights.barrier = options.landmarkBarrierWeight / n;
    T.weights.landmark = options.landmarkWeight / n;
    T.weights.exactBarrierHessian = true;
    MapPhaseReport report = schedule.run("landmarks", options.landmarkIterations, false, true);
    if (!report.converged)
    {
      options.log(Logger::Warning,
        "landmark phase stopped at its cap with landmark error " +
          std::to_string(report.landmarkError) + " (tolerance " +
          std::to_string(options.landmarkTolerance) + "); going on");
    }
    result.phases.push_back(report);
  }
  if (hasLandmarks && options.keepLandmarks)
  {
    const int missed = schedule.snapLandmarks();
    if (missed > 0)
    {
      options.log(Logger::Warning,
        std::to_string(missed) +
          " landmark positions could not be snapped exactly (the "
          "embedding would fold); they stay where the landmark phase put them");
    }
  }
  T.setTrackSamples(true);

  const double pairCount = std::max<std::size_t>(1, pairs.size());
  const bool lockLandmarks = hasLandmarks && options.keepLandmarks;
  // The weights of a phase; with `bounds` the approximation term is the
  // hard-bound barrier.
  auto setWeights = [&](const MapPhaseOptions& phase, const std::vector<double>& bounds)
  {
    T.weights = MapEnergyWeights();
    T.weights.barrier = phase.barrierWeight / n;
    T.weights.mesh = options.meshWeight / n;
    T.weights.map = pairs.empty() ? 0.0 : options.mapWeight / pairCount;
    T.weights.bounds = bounds;
    T.weights.approximation = options.approximationWeight / n /
      (bounds.empty() ? phase.targetError * phase.targetError : 1.0);
  };
  auto runPhase = [&](const char* name, const MapPhaseOptions& phase)
  {
    if (!phase.enabled || phase.maxIterations <= 0)
    {
      return;
    }
    setSizing(surfaces, inputs, phase.targetError, options);
    setWeights(phase, {});
    result.phases.push_back(schedule.run(name, phase.maxIterations, lockLandmarks, false));
  };
  runPhase("coarse", options.coarse);
  runPhase("fine", options.fine);
  // Refinement where the fine phase left the exact map distorted, then
  // where it is still squeezed.
  for (int round = 0; !pairs.empty() && options.fine.enabled && options.fine.maxIterations > 0 &&
       round < options.refinementRounds;
       ++round)
  {
    std::vector<std::vector<double>> factor;
    for (const MapSurface& s : surfaces)
    {
      factor.emplace_back(s.points.size(), 1.0);
    }
    const double threshold = round == 0 ? options.refinementDistortion : options.squeezeDistortion;
    const DistortedTriangles found = markExactMapDistortion(T,
      surfaces,
      pairs,
      threshold,
      round == 0 ? options.refinementGrowth : std::numeric_limits<double>::infinity(),
      factor);
    std::ostringstream message;
    message << "exact map: " << found.count << " input triangles with distortion above "
            << threshold;
    if (found.count > 0)
    {
      message << " (largest " << found.worst << ", area fraction " << found.area
              << "): sizing around them times " << found.factor;
    }
    options.log(Logger::Info, message.str());
    if (found.count == 0)
    {
      if (round == 0 && options.squeezeDistortion < options.refinementDistortion)
      {
        continue; // nothing above the first threshold, but squeezes may be
      }
      break;
    }
    for (std::size_t k = 0; k < surfaces.size(); ++k)
    {
      scaleSizingAround(surfaces[k], factor[k]);
    }
    T.invalidateFaceEnergies();
    result.phases.push_back(schedule.run("refine", refinementIterations, lockLandmarks, false));
  }

  std::vector<double> bounds;
  if (options.maxError > 0.0)
  {
    for (const MapSurface& s : surfaces)
    {
      bounds.push_back(options.maxError * boundingBoxDiagonal(s.points));
    }
    if (!options.fine.enabled || options.fine.maxIterations <= 0)
    {
      setSizing(surfaces, inputs, options.fine.targetError, options);
    }
    std::vector<std::vector<double>> sampleWeights;
    for (const MapSurface& s : surfaces)
    {
      sampleWeights.push_back(s.samples.weights);
    }
    // Refine where the bound does not hold yet (with a margin, so that the
    // barrier starts finite), with the soft term of the fine phase.
    for (int round = 0;; ++round)
    {
      const BoundViolations violations = boundViolations(T, bounds, options.boundMargin);
      std::ostringstream message;
      message << "error bound " << options.maxError
              << " of the bounding-box diagonal: " << violations.count << " input vertices beyond "
              << options.boundMargin << " of it (largest " << violations.worst
              << " of the bound, input " << violations.worstInput << " vertex "
              << violations.worstVertex << ")";
      options.log(Logger::Info, message.str());
      if (violations.count == 0)
      {
        break;
      }
      if (round == options.boundRefinementRounds)
      {
        throw std::runtime_error("the error bound " + std::to_string(options.maxError) +
          " of the bounding-box diagonal could not be met after " + std::to_string(round) +
          " refinement rounds: input " + std::to_string(violations.worstInput) + " vertex " +
          std::to_string(violations.worstVertex) + " is at " + std::to_string(violations.worst) +
          " times the bound");
      }
      refineAround(surfaces, violations, options.boundMargin);
      T.invalidateFaceEnergies();
      setWeights(options.fine, {});
      result.phases.push_back(
        schedule.run("refine", options.boundRefinementIterations, lockLandmarks, false));
    }
    for (std::size_t i = 0; i < surfaces.size(); ++i)
    {
      surfaces[i].samples.weights = sampleWeights[i]; // the boosts were for the soft term
    }
    setWeights(options.fine, bounds);
    T.invalidateFaceEnergies();
    result.phases.push_back(schedule.run("bound", options.boundIterations, lockLandmarks, false));
  }
  // Base-point distances, and the bound certified on every input vertex.
  for (int i = 0; i < n; ++i)
  {
    const std::vector<double> distances = T.baseDistances(i);
    double largest = 0.0;
    for (double d : distances)
    {
      largest = std::max(largest, d);
    }
    if (!bounds.empty() && !(largest < bounds[i]))
    {
      throw std::runtime_error("input " + std::to_string(i) + " is not within the error bound: " +
        std::to_string(largest / bounds[i]) + " times the bound");
    }
    result.baseDistance.push_back(largest / surfaces[i].scale);
    result.errorBound.push_back(bounds.empty() ? 0.0 : bounds[i] / surfaces[i].scale);
  }

  // Outputs.
  SurfaceMesh& mesh = T.mesh();
  mesh.garbage_collection();
  const int nv = static_cast<int>(mesh.n_vertices());
  result.triangles = faceTriangles(mesh);
  result.spherePositions.assign(n, std::vector<Eigen::Vector3d>(nv));
  result.lifted.assign(n, std::vector<Eigen::Vector3d>(nv));
  result.sourcePoints.assign(n, std::vector<SurfacePoint>(nv));
  result.landmarks.assign(nv, -1);
  for (const MapSurface& s : surfaces)
  {
    result.inputSpherePositions.push_back(s.sphere);
  }
  for (int i = 0; i < n; ++i)
  {
    for (auto v : mesh.vertices())
    {
      result.spherePositions[i][v.idx()] = T.g(v, i);
    }
    result.certificates.push_back(certifyBijective(result.spherePositions[i], result.triangles));
    if (!result.certificates.back().bijective)
    {
      throw std::runtime_error("the common triangulation's embedding on sphere " +
        std::to_string(i) + " is not bijective: " + result.certificates.back().reason);
    }
    for (auto v : mesh.vertices())
    {
      const SurfacePoint p = locateSurfacePoint(*surfaces[i].locator,
        surfaces[i].sphere,
        surfaces[i].triangles,
        T.g(v, i),
        T.liftTriangle(v, i));
      result.sourcePoints[i][v.idx()] = p;
      result.lifted[i][v.idx()] =
        evaluateSurfacePoint(inputs[i].mesh.points, surfaces[i].triangles, p);
    }
  }
  for (auto v : mesh.vertices())
  {
    result.landmarks[v.idx()] = T.landmark(v);
    const int id = T.landmark(v);
    if (id >= 0 && options.keepLandmarks)
    {
      for (int i = 0; i < n; ++i)
      {
        result.landmarkError = std::max(result.landmarkError,
          (result.lifted[i][v.idx()] - inputs[i].mesh.points[ids[i].at(id)]).norm());
      }
    }
  }

  // The exact map on input 0's vertices: f_0, then T's embedding 0 inverted
  // (barycentric in T), T's embedding j, f_j inverted (MapTransfer.h).
  result.mappedFirst.assign(n, {});
  result.mappedFirstSource.assign(n, {});
  for (int j = 0; j < n; ++j)
  {
    result.mappedFirstSource[j] = transferVertices(result, inputs, 0, j);
    result.mappedFirst[j].reserve(result.mappedFirstSource[j].size());
    for (const SurfacePoint& p : result.mappedFirstSource[j])
    {
      result.mappedFirst[j].push_back(
        evaluateSurfacePoint(inputs[j].mesh.points, surfaces[j].triangles, p));
    }
  }

  // Final energy by term.
  {
    CommonTriangulation::Snapshot snapshot;
    SpherePoints points;
    T.snapshot(snapshot, points, false);
    Objective objective;
    T.buildObjective(snapshot, {}, objective);
    const std::vector<double> values = objective.termValues(points);
    for (std::size_t k = 0; k < values.size(); ++k)
    {
      const std::string name = objective.term(k).name();
      double* slot = name == "barrier" ? &result.barrierEnergy
        : name == "mesh"               ? &result.meshEnergy
        : name == "approximation"      ? &result.approximationEnergy
                                       : &result.mapEnergy;
      *slot += values[k];
    }
    result.energy = objective.value(points);
  }
  result.seconds = secondsSince(start);
  return result;
}

} // namespace surfacemaps
