#include "map/SurfaceMap.h"
#include "base/Error.h"

#include "map/CommonTriangulation.h"
#include "map/DistortionRefinement.h"
#include "map/ErrorBound.h"
#include "map/MapEnergy.h"
#include "map/MapTransfer.h"
#include "map/MappingOrder.h"
#include "map/PhaseRunner.h"
#include "map/PreparedInput.h"
#include "map/LandmarkGuides.h"
#include "map/RotationSearch.h"
#include "map/Schedule.h"

#include <algorithm>
#include <chrono>
#include <iomanip>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>

namespace surfacemaps
{

namespace
{

/// T certified on every sphere and lifted onto every input: the result's
/// triangles, embeddings, certificates, lifts and landmark ids.
void liftCommonTriangulation(CommonTriangulation& T,
  const std::vector<PreparedInput>& surfaces,
  const std::vector<MapInput>& inputs,
  SurfaceMapResult& result)
{
  const int n = static_cast<int>(inputs.size());
  HalfedgeMesh& mesh = T.mesh();
  mesh.garbage_collection();
  const int nv = static_cast<int>(mesh.n_vertices());
  result.triangles = faceTriangles(mesh);
  result.spherePositions.assign(n, std::vector<Eigen::Vector3d>(nv));
  result.lifted.assign(n, std::vector<Eigen::Vector3d>(nv));
  result.sourcePoints.assign(n, std::vector<SurfacePoint>(nv));
  result.landmarks.assign(nv, -1);
  for (const PreparedInput& s : surfaces)
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
      throw NoResultError("the common triangulation's embedding on sphere " +
        std::to_string(surfaces[i].label) + " is not bijective: " + result.certificates.back().reason);
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
  }
}

/// Largest distance of a kept landmark's lift from its input vertex.
double keptLandmarkError(const SurfaceMapResult& result,
  const std::vector<MapInput>& inputs,
  const std::vector<std::map<int, int>>& ids)
{
  double error = 0.0;
  for (std::size_t v = 0; v < result.landmarks.size(); ++v)
  {
    const int id = result.landmarks[v];
    for (std::size_t i = 0; id >= 0 && i < inputs.size(); ++i)
    {
      error = std::max(error, (result.lifted[i][v] - inputs[i].mesh.points[ids[i].at(id)]).norm());
    }
  }
  return error;
}

/// Runs one stage of the plan; its phases' reports go to `phases`, the
/// error bound's per-input bounds to `bounds`.
void runStage(const MapStage& stage,
  const SurfaceMapOptions& options,
  const ScheduleContext& context,
  CommonTriangulation& T,
  std::vector<PreparedInput>& surfaces,
  PhaseRunner& runner,
  std::vector<MapPhaseReport>& phases,
  std::vector<double>& bounds)
{
  switch (stage.kind)
  {
    case StageKind::Phase:
      phases.push_back(runner.run(stage.phase));
      break;
    case StageKind::SnapLandmarks:
      if (const int missed = runner.snapLandmarks(); missed > 0)
      {
        options.log(Logger::Warning,
          std::to_string(missed) +
            " landmark positions could not be snapped exactly (the embedding would fold); they "
            "stay where the landmark phase put them");
      }
      break;
    case StageKind::TrackSamples:
      T.setTrackSamples(true);
      break;
    case StageKind::Refinement:
    {
      DistortionRefinement refinement(options, context);
      while (const std::optional<MapPhase> phase = refinement.next(T, surfaces))
      {
        phases.push_back(runner.run(*phase));
      }
      break;
    }
    case StageKind::ErrorBound:
    {
      ErrorBound bound(options, context, surfaces);
      while (const std::optional<MapPhase> phase = bound.next(T))
      {
        phases.push_back(runner.run(*phase));
      }
      bounds = bound.bounds();
      break;
    }
  }
}

/// The map of `inputs` in the order given; `labels`: the caller's index of
/// each (for messages).
SurfaceMapResult computeInOrder(const std::vector<MapInput>& inputs,
  const SurfaceMapOptions& options,
  const std::vector<int>& labels)
{
  const auto start = std::chrono::steady_clock::now();
  const std::vector<std::map<int, int>> landmarks = landmarkVertices(inputs);
  // Every input vertex is a sample under an error bound, which must hold for all.
  std::vector<PreparedInput> surfaces = prepareInputs(inputs,
    landmarks,
    options.maxError > 0.0 ? 0 : options.approximationSamples,
    options.log,
    labels);
  requireUsableSizing(surfaces, options.minEdgeLength);
  if (landmarks[0].empty() && options.landmarkFreeAlignment)
  {
    alignWithoutLandmarks(surfaces, options.log);
  }
  ScheduleContext context;
  context.inputs = static_cast<int>(inputs.size());
  context.landmarks = !landmarks[0].empty();
  CommonTriangulation T(surfaces, mapPairs(options.pairs, context.inputs));
  context.pairs = static_cast<int>(T.pairs().size());
  const std::vector<MapStage> plan = mapPlan(options, context);
  PhaseRunner runner(
    T, surfaces, options, landmarkTargets(surfaces), plannedIterations(plan, options));
  SurfaceMapResult result;
  std::vector<double> bounds;
  for (const MapStage& stage : plan)
  {
    runStage(stage, options, context, T, surfaces, runner, result.phases, bounds);
  }

  certifyBaseDistances(T, surfaces, bounds, result.baseDistance, result.errorBound);
  liftCommonTriangulation(T, surfaces, inputs, result);
  if (options.keepLandmarks)
  {
    result.landmarkError = keptLandmarkError(result, inputs, landmarks);
  }
  result.energy = energyByTerm(T, runner.weights());
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

/// Entry k of `values` (the engine's order) moved to place order[k] (the caller's).
template <typename Value>
void restoreOrder(std::vector<Value>& values, const std::vector<int>& order)
{
  if (values.size() != order.size())
  {
    return; // not per input (empty: not computed)
  }
  std::vector<Value> restored(values.size());
  for (std::size_t k = 0; k < order.size(); ++k)
  {
    restored[static_cast<std::size_t>(order[k])] = std::move(values[k]);
  }
  values = std::move(restored);
}

/// Landmarks as guides (LandmarkGuides.h): the map held by the landmarks
/// the shapes confirm, the others free and set aside where the map does not
/// find their partners.
SurfaceMapResult mapWithGuides(const std::vector<MapInput>& inputs,
  const SurfaceMapOptions& options)
{
  const MapFunction map = [](const std::vector<MapInput>& in, const SurfaceMapOptions& o)
  { return computeSurfaceMap(in, o); };
  const LandmarkCheck check = confirmLandmarks(inputs, options, map);
  std::ostringstream text;
  text << std::setprecision(3) << "landmarks as guides: each partner's distance from where the "
                                  "shapes alone put it (% of the diagonal):";
  for (const auto& [id, d] : check.distance)
  {
    text << " " << id << ": " << d;
  }
  options.log(Logger::Info, text.str());
  if (check.undecided)
  {
    options.log(Logger::Warning,
      "landmarks as guides: the shapes alone confirm fewer than three landmarks, so none could "
      "be judged; every landmark binds the map");
  }
  SurfaceMapOptions guided = options;
  guided.landmarksAsGuides = false;
  SurfaceMapResult result = map(keepLandmarkIds(inputs, check.confirmed), guided);
  if (check.unconfirmed.empty())
  {
    return result;
  }
  const std::map<int, double> found = landmarkDistances(inputs, result);
  for (const int id : check.unconfirmed)
  {
    const bool setAside = found.at(id) > options.landmarkGuideTolerance;
    text.str("");
    text << "landmarks as guides: landmark " << id
         << (setAside ? " set aside" : " free (not confirmed by the shapes alone)")
         << ": the map puts its partner " << found.at(id)
         << " % of the bounding-box diagonal from it (tolerance " << options.landmarkGuideTolerance
         << " %)";
    options.log(setAside ? Logger::Warning : Logger::Info, text.str());
    if (setAside)
    {
      result.setAsideLandmarks.push_back(id);
    }
  }
  return result;
}

} // namespace

MapEnergies energyByTerm(CommonTriangulation& T, const MapEnergyWeights& weights)
{
  CommonTriangulation::Snapshot snapshot;
  SpherePoints points;
  T.snapshot(snapshot, points, false, weights);
  Objective objective;
  MapEnergy(T, weights).buildObjective(snapshot, {}, objective);
  const std::vector<double> values = objective.termValues(points);
  MapEnergies energies;
  for (std::size_t k = 0; k < values.size(); ++k)
  {
    switch (static_cast<MapTerm>(objective.group(k)))
    {
      case MapTerm::Barrier:
        energies.barrier += values[k];
        break;
      case MapTerm::MeshQuality:
        energies.meshQuality += values[k];
        break;
      case MapTerm::Approximation:
        energies.approximation += values[k];
        break;
      case MapTerm::Distortion:
        energies.distortion += values[k];
        break;
      case MapTerm::Landmarks: // not in the final energy (no targets)
        break;
    }
  }
  energies.total = objective.value(points);
  return energies;
}

SurfaceMapResult computeSurfaceMap(const std::vector<MapInput>& inputs,
  const SurfaceMapOptions& options)
{
  if (inputs.empty())
  {
    throw InputError("a surface map needs at least one input");
  }
  // Landmark ids checked in the caller's order, so that a message names the
  // caller's input.
  const std::vector<std::map<int, int>> landmarks = landmarkVertices(inputs);
  if (options.landmarksAsGuides && inputs.size() > 1 && !landmarks[0].empty())
  {
    return mapWithGuides(inputs, options);
  }
  const std::vector<int> order = mappingOrder(inputs, options.pairs);
  if (std::is_sorted(order.begin(), order.end()))
  {
    return computeInOrder(inputs, options, order);
  }
  std::vector<MapInput> ordered;
  ordered.reserve(inputs.size());
  for (const int i : order)
  {
    ordered.push_back(inputs[static_cast<std::size_t>(i)]);
  }
  SurfaceMapResult result = computeInOrder(ordered, options, order);
  restoreOrder(result.spherePositions, order);
  restoreOrder(result.lifted, order);
  restoreOrder(result.sourcePoints, order);
  restoreOrder(result.inputSpherePositions, order);
  restoreOrder(result.certificates, order);
  restoreOrder(result.baseDistance, order);
  restoreOrder(result.errorBound, order);
  return result;
}

std::vector<SurfacePoint> transferVertices(const SurfaceMapResult& map,
  const std::vector<MapInput>& inputs,
  int from,
  int to)
{
  const int n = static_cast<int>(map.spherePositions.size());
  if (from < 0 || from >= n || to < 0 || to >= n || inputs.size() != map.spherePositions.size() ||
    map.inputSpherePositions.size() != map.spherePositions.size() ||
    map.sourcePoints.size() != map.spherePositions.size())
  {
    throw std::invalid_argument("no map from input " + std::to_string(from) + " to input " +
      std::to_string(to) + " among " + std::to_string(n) + " inputs");
  }
  MapTransferOptions options;
  options.identity = from == to;
  options.startTriangles.reserve(map.sourcePoints[to].size());
  for (const SurfacePoint& p : map.sourcePoints[to])
  {
    options.startTriangles.push_back(p.triangle);
  }
  return transferPoints(map.inputSpherePositions[from],
    map.triangles,
    map.spherePositions[from],
    map.spherePositions[to],
    map.inputSpherePositions[to],
    inputs[to].mesh.triangles(),
    options);
}

std::vector<Eigen::Vector3d> mappedVertices(const SurfaceMapResult& map,
  const std::vector<MapInput>& inputs,
  int from,
  int to)
{
  const std::vector<SurfacePoint> located = transferVertices(map, inputs, from, to);
  const auto triangles = inputs[to].mesh.triangles();
  std::vector<Eigen::Vector3d> points;
  points.reserve(located.size());
  for (const SurfacePoint& p : located)
  {
    points.push_back(evaluateSurfacePoint(inputs[to].mesh.points, triangles, p));
  }
  return points;
}

std::string landmarkPhaseWarning(const SurfaceMapResult& map)
{
  for (const MapPhaseReport& phase : map.phases)
  {
    if (phase.kind == PhaseKind::Landmarks && !(phase.landmarkError <= FarLandmarkDistance))
    {
      std::ostringstream text;
      text << "the landmark phase ended with a landmark " << phase.landmarkError
           << " from its target on the unit sphere (far: beyond " << FarLandmarkDistance
           << "): the landmark sets may not correspond (the same id on corresponding points; a "
              "set in another order maps points onto the wrong ones); the map goes on with them";
      return text.str();
    }
  }
  return {};
}

} // namespace surfacemaps
