#include "map/ErrorBound.h"
#include "base/Error.h"
#include "geometry/MapMetrics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

namespace surfacemaps
{

namespace
{

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

/// Where input vertices are too far from their base points: shrinks the
/// sizing around them (the vertex and its one-ring; distance grows like the
/// edge length squared, so by sqrt(margin / ratio), at least by 0.7 and at
/// most by 0.25) so that the mesh-quality term asks for smaller triangles
/// there, and weights those samples 4 times more in the soft term.
void refineAround(std::vector<PreparedInput>& surfaces,
  const BoundViolations& violations,
  double margin)
{
  for (std::size_t i = 0; i < surfaces.size(); ++i)
  {
    PreparedInput& s = surfaces[i];
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

} // namespace

ErrorBound::ErrorBound(const SurfaceMapOptions& options,
  const ScheduleContext& context,
  std::vector<PreparedInput>& surfaces)
  : Options(options)
  , Context(context)
  , Surfaces(surfaces)
{
  for (const PreparedInput& s : surfaces)
  {
    this->Bounds.push_back(options.maxError * boundingBoxDiagonal(s.points));
    this->SampleWeights.push_back(s.samples.weights);
  }
  if (options.fineIterations <= 0)
  {
    setCurvatureSizing(surfaces, options.targetError, options.minEdgeLength, options.maxEdgeLength);
  }
}

std::optional<MapPhase> ErrorBound::next(CommonTriangulation& T)
{
  const SurfaceMapOptions& options = this->Options;
  if (this->Bounding)
  {
    return std::nullopt;
  }
  // Refine where the bound does not hold yet (with a margin, so that the
  // barrier starts finite), with the soft term of the fine phase.
  const BoundViolations violations = boundViolations(T, this->Bounds, options.boundMargin);
  std::ostringstream message;
  message << "error bound " << options.maxError
          << " of the bounding-box diagonal: " << violations.count << " input vertices beyond "
          << options.boundMargin << " of it (largest " << violations.worst
          << " of the bound, input " << violations.worstInput << " vertex "
          << violations.worstVertex << ")";
  options.log(Logger::Info, message.str());
  // Out of rounds with every vertex inside the bound, only short of the
  // margin: the barrier starts finite, so the bound phase can run.
  const bool withinBound = violations.worst < 1.0;
  if (violations.count > 0 && !(this->Round == options.boundRefinementRounds && withinBound))
  {
    if (this->Round == options.boundRefinementRounds)
    {
      throw NoResultError("the error bound " + std::to_string(options.maxError) +
        " of the bounding-box diagonal could not be met after " + std::to_string(this->Round) +
        " refinement rounds: input " + std::to_string(violations.worstInput) + " vertex " +
        std::to_string(violations.worstVertex) + " is at " + std::to_string(violations.worst) +
        " times the bound");
    }
    ++this->Round;
    refineAround(this->Surfaces, violations, options.boundMargin);
    T.invalidateFaceEnergies();
    return finePhase(PhaseKind::Refine, options.boundRefinementIterations, options, this->Context);
  }
  for (std::size_t i = 0; i < this->Surfaces.size(); ++i)
  {
    this->Surfaces[i].samples.weights = this->SampleWeights[i]; // the boosts were for the soft term
  }
  T.invalidateFaceEnergies();
  this->Bounding = true;
  return finePhase(PhaseKind::Bound, options.boundIterations, options, this->Context, this->Bounds);
}

void certifyBaseDistances(const CommonTriangulation& T,
  const std::vector<PreparedInput>& surfaces,
  const std::vector<double>& bounds,
  std::vector<double>& largest,
  std::vector<double>& bound)
{
  largest.clear();
  bound.clear();
  for (int i = 0; i < T.numberOfInputs(); ++i)
  {
    double d = 0.0;
    for (const double distance : T.baseDistances(i))
    {
      d = std::max(d, distance);
    }
    if (!bounds.empty() && !(d < bounds[i]))
    {
      throw NoResultError("input " + std::to_string(surfaces[i].label) +
        " is not within the error bound: " + std::to_string(d / bounds[i]) + " times the bound");
    }
    largest.push_back(d / surfaces[i].scale);
    bound.push_back(bounds.empty() ? 0.0 : bounds[i] / surfaces[i].scale);
  }
}

} // namespace surfacemaps
