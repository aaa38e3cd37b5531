#include "map/AddToMap.h"

#include "base/Error.h"
#include "geometry/SphereLocator.h"
#include "geometry/SphericalTriangulation.h"
#include "map/CommonTriangulation.h"
#include "map/ComposedEmbedding.h"
#include "map/ErrorBound.h"
#include "map/MapTransfer.h"
#include "map/PhaseRunner.h"
#include "map/PreparedInput.h"
#include "map/Schedule.h"
#include "statistics/Procrustes.h"

#include <chrono>
#include <limits>
#include <map>
#include <memory>
#include <set>
#include <stdexcept>
#include <string>

namespace surfacemaps
{

namespace
{

std::string inputName(std::size_t i)
{
  return "input " + std::to_string(i);
}

/// Throws InputError when the existing map does not fit itself or the inputs.
void checkExisting(const ExistingMap& map, const std::vector<MapInput>& inputs)
{
  const std::size_t m = map.spherePositions.size();
  if (m == 0 || map.lifted.size() != m)
  {
    throw InputError("the existing map has " + std::to_string(m) + " embeddings of T and " +
      std::to_string(map.lifted.size()) + " lifts of it (one of each per input, at least one)");
  }
  if (inputs.size() <= m)
  {
    throw InputError("nothing to add: " + std::to_string(inputs.size()) +
      " inputs given, the existing map has " + std::to_string(m));
  }
  const std::size_t nv = map.spherePositions[0].size();
  for (const auto& t : map.triangles)
  {
    for (const int v : t)
    {
      if (v < 0 || static_cast<std::size_t>(v) >= nv)
      {
        throw InputError("the existing map's triangle corner " + std::to_string(v) +
          " is not one of its " + std::to_string(nv) + " vertices");
      }
    }
  }
  if (!map.landmarks.empty() && map.landmarks.size() != nv)
  {
    throw InputError("the existing map has " + std::to_string(map.landmarks.size()) +
      " landmark ids for " + std::to_string(nv) + " vertices of T");
  }
  for (std::size_t j = 0; j < m; ++j)
  {
    if (map.spherePositions[j].size() != nv || map.lifted[j].size() != nv)
    {
      throw InputError("the existing map's T on " + inputName(j) + " has " +
        std::to_string(map.spherePositions[j].size()) + " sphere points and " +
        std::to_string(map.lifted[j].size()) + " lifted points, on input 0 " + std::to_string(nv) +
        " vertices");
    }
    const BijectivityCertificate certificate =
      certifyBijective(map.spherePositions[j], map.triangles);
    if (!certificate.bijective)
    {
      throw InputError("the existing map's embedding of T on sphere " + std::to_string(j) +
        " is not bijective: " + certificate.reason);
    }
    if (inputs[j].spherePositions.size() != inputs[j].mesh.points.size())
    {
      throw InputError(inputName(j) + " has no sphere embedding (the one the existing map used)");
    }
  }
}

/// Landmark id -> vertex of one input (its "Landmarks" array).
std::map<int, int> landmarkIds(const std::vector<int>& landmarks)
{
  std::map<int, int> ids;
  for (std::size_t v = 0; v < landmarks.size(); ++v)
  {
    if (landmarks[v] >= 0)
    {
      ids.emplace(landmarks[v], static_cast<int>(v));
    }
  }
  return ids;
}

/// Throws InputError unless input `label` has exactly T's landmark ids.
void checkLandmarks(const ExistingMap& map, const MapInput& added, std::size_t label)
{
  const std::map<int, int> ids = landmarkIds(map.landmarks);
  const std::map<int, int> own = landmarkIds(added.landmarks);
  if (ids.empty() != own.empty())
  {
    throw InputError(inputName(label) + " has " + std::to_string(own.size()) +
      " landmarks, the map it is added to " + std::to_string(ids.size()) +
      " (an added input needs the map's landmark ids)");
  }
  for (const auto& [id, v] : ids)
  {
    if (own.count(id) == 0)
    {
      throw InputError(inputName(label) + " has no landmark " + std::to_string(id) +
        ", which the map it is added to has");
    }
  }
  for (const auto& [id, v] : own)
  {
    if (ids.count(id) == 0)
    {
      throw InputError(inputName(label) + " has landmark " + std::to_string(id) + " (vertex " +
        std::to_string(v) + "), which the map it is added to has not");
    }
  }
}

/// The existing inputs' mean shape on T as an input of the two-input
/// problem: T with the mean's points, g_0 as its fixed embedding, T's
/// landmark ids.
MapInput meanShapeInput(const ExistingMap& map)
{
  MapInput mean;
  if (map.lifted.size() == 1)
  {
    mean.mesh.points = map.lifted[0];
  }
  else
  {
    ProcrustesOptions procrustes;
    procrustes.kind = AlignmentKind::Similarity;
    mean.mesh.points = alignProcrustes(
      map.lifted, std::vector<double>(map.lifted.size(), 1.0), map.triangles, procrustes)
                         .mean;
  }
  for (const auto& t : map.triangles)
  {
    mean.mesh.addFace({ t[0], t[1], t[2] });
  }
  mean.spherePositions = map.spherePositions[0];
  if (!landmarkIds(map.landmarks).empty())
  {
    mean.landmarks = map.landmarks;
  }
  return mean;
}

/// The settings of the two-input problems: the new input against the mean
/// shape, the map weight halved so that it weighs as much against the
/// per-input terms as in the mean pairing over N inputs.
SurfaceMapOptions pairOptions(const SurfaceMapOptions& options)
{
  SurfaceMapOptions pair = options;
  pair.pairs = PairScheme::Star;
  pair.mapWeight = options.mapWeight / 2.0;
  return pair;
}

/// Runs the schedule of the two-input problem on T from g_1 = g_0, splits
/// only (the fallback start); the phases' reports go to `phases`. Returns
/// the last phase's weights.
MapEnergyWeights runSchedule(CommonTriangulation& T,
  std::vector<PreparedInput>& surfaces,
  const SurfaceMapOptions& options,
  bool landmarks,
  std::vector<MapPhaseReport>& phases)
{
  const SurfaceMapOptions pair = pairOptions(options);
  ScheduleContext context;
  context.inputs = 2;
  context.pairs = 1;
  context.landmarks = landmarks;
  const std::vector<MapStage> plan = mapPlan(pair, context);
  PhaseRunner runner(T, surfaces, pair, landmarkTargets(surfaces), plannedIterations(plan, pair));
  for (MapStage stage : plan)
  {
    if (stage.kind == StageKind::Phase)
    {
      stage.phase.collapses = false;
      stage.phase.flips = false;
      phases.push_back(runner.run(stage.phase));
    }
    else if (stage.kind == StageKind::SnapLandmarks)
    {
      if (const int missed = runner.snapLandmarks(); missed > 0)
      {
        options.log(Logger::Warning,
          std::to_string(missed) +
            " landmark positions of the added input could not be snapped "
            "exactly (the embedding would fold)");
      }
    }
    else if (stage.kind == StageKind::TrackSamples)
    {
      T.setTrackSamples(true);
    }
  }
  return runner.weights();
}

/// T's points on each existing sphere j: the existing g_j on T's first
/// vertices (which stayed), psi_0j of their point on sphere 0 on the ones
/// the splits added.
std::vector<std::vector<Eigen::Vector3d>> existingEmbeddings(const ExistingMap& map,
  const CommonTriangulation& T)
{
  const std::size_t nvOld = map.spherePositions[0].size();
  const HalfedgeMesh& mesh = T.mesh();
  SphereLocator locator(map.spherePositions[0], map.triangles);
  std::vector<std::vector<Eigen::Vector3d>> g = map.spherePositions;
  for (auto& points : g)
  {
    points.resize(mesh.n_vertices());
  }
  int start = -1;
  for (std::size_t v = 0; v < mesh.n_vertices(); ++v)
  {
    const Eigen::Vector3d& p = T.g(OpenMesh::VertexHandle(static_cast<int>(v)), 0);
    if (v < nvOld)
    {
      if ((p - map.spherePositions[0][v]).norm() > 1e-12)
      {
        throw std::logic_error("vertex " + std::to_string(v) +
          " of the existing map moved on sphere 0 while an input was added");
      }
      continue;
    }
    const SphereLocation l = start < 0 ? locator.locate(p) : locator.locateFrom(p, start);
    start = l.triangle;
    const auto& t = map.triangles[l.triangle];
    for (std::size_t j = 0; j < g.size(); ++j)
    {
      const auto& s = map.spherePositions[j];
      g[j][v] = (l.alpha * s[t[0]] + l.beta * s[t[1]] + l.gamma * s[t[2]]).normalized();
    }
  }
  return g;
}

/// T lifted onto an input with embedding `sphere` at T's sphere points `g`.
void liftOnto(const MapInput& input,
  const std::vector<Eigen::Vector3d>& sphere,
  const std::vector<Eigen::Vector3d>& g,
  std::vector<SurfacePoint>& located,
  std::vector<Eigen::Vector3d>& lifted)
{
  const auto triangles = input.mesh.triangles();
  const SphereLocator locator(sphere, triangles);
  located.resize(g.size());
  lifted.resize(g.size());
  int start = -1;
  for (std::size_t v = 0; v < g.size(); ++v)
  {
    located[v] = locateSurfacePoint(locator, sphere, triangles, g[v], start);
    start = located[v].triangle;
    lifted[v] = evaluateSurfacePoint(input.mesh.points, triangles, located[v]);
  }
}

/// Input `k` added to the map of inputs 0..k-1 (`map`, with the embeddings
/// `spheres` as used); the map of inputs 0..k.
SurfaceMapResult addOne(const ExistingMap& map,
  const std::vector<std::vector<Eigen::Vector3d>>& spheres,
  const std::vector<MapInput>& inputs,
  std::size_t k,
  const SurfaceMapOptions& options)
{
  checkLandmarks(map, inputs[k], k);
  const std::vector<MapInput> problem{ meanShapeInput(map), inputs[k] };
  const std::vector<std::map<int, int>> ids = landmarkVertices(problem);
  std::vector<PreparedInput> surfaces = prepareInputs(
    problem, ids, options.approximationSamples, options.log, { 0, static_cast<int>(k) });
  requireUsableSizing(surfaces, options.minEdgeLength);
  // The new input mapped alone against the mean shape (the whole schedule:
  // landmark phase, collapses, flips), composed onto T.
  const SurfaceMapResult alone = computeSurfaceMap(problem, pairOptions(options));
  SurfaceMapResult result;
  result.phases = alone.phases;
  result.energy = alone.energy;
  auto T =
    std::make_unique<CommonTriangulation>(surfaces, std::vector<std::array<int, 2>>{ { 0, 1 } });
  T->setFrozenInputs(1);
  try
  {
    composeEmbedding(*T, 1, alone);
    T->setTrackSamples(true);
  }
  catch (const NoResultError& e)
  {
    options.log(Logger::Warning,
      "adding " + inputName(k) + ": " + e.what() +
        "; optimising it on the common triangulation from the mean shape's embedding instead");
    T =
      std::make_unique<CommonTriangulation>(surfaces, std::vector<std::array<int, 2>>{ { 0, 1 } });
    T->setFrozenInputs(1);
    const MapEnergyWeights weights =
      runSchedule(*T, surfaces, options, !ids[0].empty(), result.phases);
    result.energy = energyByTerm(*T, weights);
  }
  T->mesh().garbage_collection();

  result.triangles = faceTriangles(T->mesh());
  result.spherePositions = existingEmbeddings(map, *T);
  result.spherePositions.emplace_back();
  for (auto v : T->mesh().vertices())
  {
    result.spherePositions.back().push_back(T->g(v, 1));
    result.landmarks.push_back(T->landmark(v));
  }
  result.inputSpherePositions = spheres;
  result.inputSpherePositions.push_back(surfaces[1].sphere);
  const std::size_t n = k + 1;
  result.lifted.resize(n);
  result.sourcePoints.resize(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    result.certificates.push_back(certifyBijective(result.spherePositions[i], result.triangles));
    if (!result.certificates.back().bijective)
    {
      throw NoResultError("the common triangulation's embedding on sphere " + std::to_string(i) +
        " is not bijective after adding " + inputName(k) + ": " +
        result.certificates.back().reason);
    }
    liftOnto(inputs[i],
      result.inputSpherePositions[i],
      result.spherePositions[i],
      result.sourcePoints[i],
      result.lifted[i]);
  }
  // The existing inputs' base distances are not measured again (NaN).
  std::vector<double> largest, bound;
  certifyBaseDistances(*T, surfaces, {}, largest, bound);
  result.baseDistance.assign(n, std::numeric_limits<double>::quiet_NaN());
  result.baseDistance[k] = largest[1];
  result.errorBound.assign(n, 0.0);
  return result;
}

/// Largest distance of a landmark vertex of T lifted onto an input from
/// that input's landmark (original units, over the inputs with landmarks).
double landmarkDistance(const SurfaceMapResult& result, const std::vector<MapInput>& inputs)
{
  double error = 0.0;
  for (std::size_t i = 0; i < result.lifted.size(); ++i)
  {
    const std::map<int, int> ids = landmarkIds(inputs[i].landmarks);
    for (std::size_t v = 0; v < result.landmarks.size() && !ids.empty(); ++v)
    {
      const auto it = ids.find(result.landmarks[v]);
      if (it != ids.end())
      {
        error = std::max(error, (result.lifted[i][v] - inputs[i].mesh.points[it->second]).norm());
      }
    }
  }
  return error;
}

} // namespace

SurfaceMapResult addToSurfaceMap(const ExistingMap& existing,
  const std::vector<MapInput>& inputs,
  const SurfaceMapOptions& options)
{
  if (options.refinementRounds > 0 || options.maxError > 0.0)
  {
    throw InputError("adding inputs to a map keeps the existing maps, while refinement rounds "
                     "and an error bound re-run every input's map: set the refinement rounds and "
                     "the error bound to 0 (the population preset does)");
  }
  checkExisting(existing, inputs);
  const auto start = std::chrono::steady_clock::now();
  ExistingMap map = existing;
  std::vector<std::vector<Eigen::Vector3d>> spheres;
  for (std::size_t j = 0; j < existing.spherePositions.size(); ++j)
  {
    spheres.push_back(inputs[j].spherePositions);
  }
  SurfaceMapResult result;
  std::vector<MapPhaseReport> phases;
  for (std::size_t k = existing.spherePositions.size(); k < inputs.size(); ++k)
  {
    result = addOne(map, spheres, inputs, k, options);
    phases.insert(phases.end(), result.phases.begin(), result.phases.end());
    map = { result.triangles, result.spherePositions, result.lifted, result.landmarks };
    spheres = result.inputSpherePositions;
  }
  result.phases = std::move(phases);
  if (options.keepLandmarks)
  {
    result.landmarkError = landmarkDistance(result, inputs);
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

} // namespace surfacemaps
