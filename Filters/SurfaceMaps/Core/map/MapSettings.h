// SurfaceMaps engine: the settings tables of the list (settings/SettingList.def)
// bound to the options they set: the surface map's (SurfaceMapOptions) and
// the sphere embedding's (SphereEmbeddingOptions, which the map uses for
// every embedding it computes).
#pragma once

#include "embedding/SphereEmbedding.h"
#include "map/MapOptions.h"
#include "settings/Setting.h"

#include <string>
#include <vector>

namespace surfacemaps
{

using MapSetting = BoundSetting<SurfaceMapOptions>;
using EmbeddingSetting = BoundSetting<SphereEmbeddingOptions>;

/// Every map setting, in the list's order.
const std::vector<MapSetting>& mapSettings();
/// Every sphere-embedding setting, in the list's order.
const std::vector<EmbeddingSetting>& embeddingSettings();

/// The map setting with this name (the filter's Set<name>); nullptr if none.
const MapSetting* findMapSetting(const std::string& name);

/// If args[i] is a map setting's flag ("--target-error", a switch's
/// "--keep-landmarks" or "--release-landmarks"), sets it in `options`
/// (consuming its value: i then points at it) and returns true; false for
/// any other argument. Throws std::invalid_argument naming the flag and what
/// it takes for a missing or bad value.
bool parseSettingFlag(const std::vector<std::string>& args,
  std::size_t& i,
  SurfaceMapOptions& options);
/// The same for the sphere embedding's settings ("--final-iterations").
bool parseSettingFlag(const std::vector<std::string>& args,
  std::size_t& i,
  SphereEmbeddingOptions& options);

} // namespace surfacemaps
