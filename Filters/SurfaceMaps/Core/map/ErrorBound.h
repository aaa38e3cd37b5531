// SurfaceMaps engine: error-bounded remeshing (paper section 8.4).
#pragma once

#include "map/MapOptions.h"
#include "map/MapPhase.h"
#include "map/Schedule.h"

#include <optional>
#include <vector>

namespace surfacemaps
{

/// After the fine phase and its refinement, with options.maxError > 0:
/// every input vertex must end within maxError times its input's
/// bounding-box diagonal of its base point on T. Rounds of Refine phases
/// with the sizing shrunk around the vertices beyond boundMargin of the
/// bound (and those samples weighted 4 times in the soft term) run until
/// none is left, then one Bound phase with the bound as a barrier instead
/// of the soft term. Throws NoResultError when the bound is still not
/// met after boundRefinementRounds.
class ErrorBound
{
public:
  /// Every input vertex must be an approximation sample (see
  /// prepareInputs). Sets the fine phase's sizing when no fine phase ran.
  ErrorBound(const SurfaceMapOptions& options,
    const ScheduleContext& context,
    std::vector<PreparedInput>& surfaces);

  /// The next phase to run, or nothing when the bound phase has run.
  std::optional<MapPhase> next(CommonTriangulation& T);

  /// Per input, the bound in its unit-area units.
  const std::vector<double>& bounds() const { return this->Bounds; }

private:
  const SurfaceMapOptions& Options;
  ScheduleContext Context;
  std::vector<PreparedInput>& Surfaces;
  std::vector<double> Bounds;
  /// The samples' weights before the refinement boosted some.
  std::vector<std::vector<double>> SampleWeights;
  int Round = 0;
  bool Bounding = false;
};

/// Distances of every input vertex from its base point on T, checked
/// against `bounds` (empty: unchecked); throws NoResultError naming the
/// input when one is not within. Per input: the largest distance and the
/// bound, both in the input's own units (0 without bounds).
void certifyBaseDistances(const CommonTriangulation& T,
  const std::vector<PreparedInput>& surfaces,
  const std::vector<double>& bounds,
  std::vector<double>& largest,
  std::vector<double>& bound);

} // namespace surfacemaps
