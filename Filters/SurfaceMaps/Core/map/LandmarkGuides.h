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

/// Which landmark ids the shapes confirm, and how far each one's partner was
/// from where the checking map put it (% of that input's bounding-box
/// diagonal, the largest over the inputs after the first).
struct LandmarkCheck
{
  std::vector<int> kept, setAside;
  std::map<int, double> distance;
  /// The map without landmarks confirmed fewer than three: nothing could be
  /// checked, every landmark is kept.
  bool undecided = false;
};

using MapFunction =
  std::function<SurfaceMapResult(const std::vector<MapInput>&, const SurfaceMapOptions&)>;

/// Checks landmarks against the shapes with two short maps (the coarse phase
/// only): first without landmarks (its start turned by the rotation search),
/// which confirms the landmarks whose partners lie within
/// options.landmarkGuideTolerance of where it carries them; then with the
/// confirmed ones locked, which judges the others the same way. A landmark
/// the shapes disagree with (swapped, on the wrong finger or leg, far off)
/// is set aside; the landmarks bind the map only where the shapes agree. A
/// set-aside landmark that was right is still found by the map (its partner
/// lies where the others and the shapes put it). `map` computes the probes
/// (computeSurfaceMap without the guide check).
LandmarkCheck checkLandmarkGuides(const std::vector<MapInput>& inputs,
  const SurfaceMapOptions& options,
  const MapFunction& map);

/// The inputs with only the landmark ids in `kept` (the others -1).
std::vector<MapInput> keepLandmarkIds(std::vector<MapInput> inputs, const std::vector<int>& kept);

} // namespace surfacemaps
