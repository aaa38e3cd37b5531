// SurfaceMaps engine: landmarks as guides, checked against the shapes before
// they bind the map.
#pragma once

#include "map/MapInput.h"
#include "map/MapOptions.h"
#include "map/SurfaceMap.h"

#include <functional>
#include <map>
#include <vector>

namespace surfacemaps
{

/// Which landmark ids the shapes confirm: those whose partner lies within
/// options.landmarkGuideTolerance (% of that input's bounding-box diagonal,
/// the largest over the inputs after the first) of where a short map
/// without landmarks carries them.
struct LandmarkCheck
{
  std::vector<int> confirmed, unconfirmed;
  std::map<int, double> distance;
  /// The map without landmarks confirmed fewer than three: nothing could be
  /// judged, every landmark is confirmed.
  bool undecided = false;
};

using MapFunction =
  std::function<SurfaceMapResult(const std::vector<MapInput>&, const SurfaceMapOptions&)>;

/// The first half of landmarks as guides: a short map without landmarks
/// (the coarse phase, its start turned by the rotation search) confirms the
/// landmarks that agree with the shapes. The map is then computed with the
/// confirmed ones locked and the others free; an unconfirmed landmark the
/// map finds (landmarkDistances within the tolerance) was right, one it
/// does not (swapped, on the wrong finger or leg, far off) is set aside.
/// `map` computes the probe (computeSurfaceMap without the guide check).
LandmarkCheck confirmLandmarks(const std::vector<MapInput>& inputs,
  const SurfaceMapOptions& options,
  const MapFunction& map);

/// Per landmark id: how far the map carries input 0's landmark vertex from
/// its partner (% of the partner's input's bounding-box diagonal, the
/// largest over the inputs after the first).
std::map<int, double> landmarkDistances(const std::vector<MapInput>& inputs,
  const SurfaceMapResult& map);

/// The inputs with only the landmark ids in `kept` (the others -1).
std::vector<MapInput> keepLandmarkIds(std::vector<MapInput> inputs, const std::vector<int>& kept);

} // namespace surfacemaps
