#include "map/DistortionRefinement.h"

#include "geometry/MapMetrics.h"
#include "map/MapTransfer.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace surfacemaps
{

namespace
{

/// What markExactMapDistortion found.
struct DistortedTriangles
{
  int count = 0;       // over all pairs
  double worst = 0.0;  // the largest distortion
  double area = 0.0;   // the largest area fraction of one pair
  double factor = 1.0; // the smallest sizing factor applied
};

/// Input i's vertices mapped onto its own approximating mesh T_i (T lifted
/// onto input i): located in T on sphere i, at the same barycentric place
/// between T's lifted corners. Unit-area units.
std::vector<Eigen::Vector3d> ontoOwnApproximation(CommonTriangulation& T,
  const PreparedInput& surface,
  int i,
  const std::vector<std::array<int, 3>>& triangles,
  const std::vector<Eigen::Vector3d>& g)
{
  const HalfedgeMesh& mesh = T.mesh();
  std::vector<Eigen::Vector3d> lifted(mesh.n_vertices());
  for (auto v : mesh.vertices())
  {
    lifted[v.idx()] = evaluateSurfacePoint(surface.points,
      surface.triangles,
      locateSurfacePoint(
        *surface.locator, surface.sphere, surface.triangles, g[v.idx()], T.liftTriangle(v, i)));
  }
  // T on sphere i as the target "input": the places are (T triangle, barycentric).
  const std::vector<SurfacePoint> places = transferPoints(surface.sphere, triangles, g, g, g, triangles);
  std::vector<Eigen::Vector3d> mapped(places.size());
  for (std::size_t v = 0; v < places.size(); ++v)
  {
    mapped[v] = evaluateSurfacePoint(lifted, triangles, places[v]);
  }
  return mapped;
}

/// Where T hides a distorted exact map: for every pair (i, j) of the map
/// term, the triangles of input i whose exact-map distortion (input i ->
/// input j through T) exceeds `threshold`; for a pair (i, i), those whose
/// map onto input i's own approximating mesh T_i does (ontoOwnApproximation:
/// every exact map i -> j is that map, T's own map T_i -> T_j, and the
/// inverse of j's). T's own map only sees T's
/// vertices; inside a T triangle the exact map follows the two sphere
/// embeddings, which can squeeze a whole input triangle where they differ.
/// Lowers `factor` at their corners on input i and at the corners of the
/// input-j triangles those land in, to 1 / sqrt(1 + growth / area) (area:
/// their unit-area fraction of input i) but at least 0.5: the vertex density
/// there grows about 1 + growth / area times, at most 4 times (infinite
/// growth: halved sizing; growth 0: `factor` stays 1, only the count and the
/// worst distortion are wanted). T is garbage-collected first, for its flat
/// triangle list.
DistortedTriangles markExactMapDistortion(CommonTriangulation& T,
  const std::vector<PreparedInput>& surfaces,
  const std::vector<std::array<int, 2>>& pairs,
  double threshold,
  double growth,
  std::vector<std::vector<double>>& factor)
{
  HalfedgeMesh& mesh = T.mesh();
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
    std::vector<SurfacePoint> images;
    std::vector<Eigen::Vector3d> mapped;
    if (i == j)
    {
      mapped = ontoOwnApproximation(T, surfaces[i], i, triangles, gi);
    }
    else
    {
      images = transferPoints(
        surfaces[i].sphere, triangles, gi, gj, surfaces[j].sphere, surfaces[j].triangles);
      for (const SurfacePoint& image : images)
      {
        mapped.push_back(evaluateSurfacePoint(surfaces[j].points, surfaces[j].triangles, image));
      }
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
        for (std::size_t k = 0; i != j && k < 3; ++k)
        {
          const int w = surfaces[j].triangles[images[v].triangle][k];
          factor[j][w] = std::min(factor[j][w], f);
        }
      }
    }
  }
  return found;
}

/// The maps the refinement measures: the map term's pairs; against the mean
/// shape (no pairs), every input's map onto its own approximating mesh,
/// the (i, i) of markExactMapDistortion.
std::vector<std::array<int, 2>> measuredMaps(const SurfaceMapOptions& options, const CommonTriangulation& T)
{
  if (options.pairs != PairScheme::Mean)
  {
    return T.pairs();
  }
  std::vector<std::array<int, 2>> maps;
  for (int i = 0; i < T.numberOfInputs(); ++i)
  {
    maps.push_back({ i, i });
  }
  return maps;
}

} // namespace

DistortionRefinement::DistortionRefinement(const SurfaceMapOptions& options,
  const ScheduleContext& context)
  : Options(options)
  , Context(context)
{
}

std::optional<MapPhase> DistortionRefinement::next(CommonTriangulation& T,
  std::vector<PreparedInput>& surfaces)
{
  const SurfaceMapOptions& options = this->Options;
  if (this->Context.pairs == 0 || options.fineIterations <= 0)
  {
    return std::nullopt;
  }
  while (this->Round < options.refinementRounds)
  {
    const int round = this->Round++;
    std::vector<std::vector<double>> factor;
    for (const PreparedInput& s : surfaces)
    {
      factor.emplace_back(s.points.size(), 1.0);
    }
    // The later rounds keep the sizing: halving it around squeezed triangles
    // never repaired a squeeze on the corpus and doubled T where squeezes
    // stayed (README, "Where the corpus gap comes from").
    const double threshold = round == 0 ? options.refinementDistortion : options.squeezeDistortion;
    const DistortedTriangles found = markExactMapDistortion(
      T, surfaces, measuredMaps(options, T), threshold, round == 0 ? options.refinementGrowth : 0.0, factor);
    std::ostringstream message;
    message << "exact map: " << found.count << " input triangles with distortion above "
            << threshold;
    if (found.count > 0)
    {
      message << " (largest " << found.worst << ", area fraction " << found.area << ")";
      if (found.factor < 1.0)
      {
        message << ": sizing around them times " << found.factor;
      }
    }
    options.log(Logger::Info, message.str());
    if (found.count == 0)
    {
      if (round == 0 && options.squeezeDistortion < options.refinementDistortion)
      {
        continue; // nothing above the first threshold, but squeezes may be
      }
      this->Round = options.refinementRounds;
      return std::nullopt;
    }
    if (found.factor < 1.0)
    {
      for (std::size_t k = 0; k < surfaces.size(); ++k)
      {
        scaleSizingAround(surfaces[k], factor[k]);
      }
      T.invalidateFaceEnergies();
    }
    return finePhase(PhaseKind::Refine,
      std::min(options.refinementIterations, options.fineIterations),
      options,
      this->Context);
  }
  return std::nullopt;
}

} // namespace surfacemaps
