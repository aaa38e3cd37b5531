// SurfaceMaps engine: the settings of a surface map.
#pragma once

#include "base/Log.h"
#include "map/MapPairs.h"

#include <functional>
#include <string>

namespace surfacemaps
{

/// Reported once per iteration of the schedule.
struct SurfaceMapProgress
{
  /// The running phase: "landmarks", "coarse", "fine", "refine" or "bound".
  std::string phase;
  int iteration = 0;
  /// Fraction of the whole schedule's iterations done (0..1).
  double fraction = 0.0;
  int vertices = 0;
  double energy = 0.0;
};

/// Every setting of computeSurfaceMap: one field per map setting of the list
/// (settings/SettingList.def), which holds its type, default, range and
/// documentation; everything else derives from there. Lengths and errors
/// are in unit-area units (each input centred and scaled to unit area).
struct SurfaceMapOptions
{
#define SURFACEMAPS_MAP_SETTING(Name, field, Type, Kind, Default, ...) Type field = Default;
#include "settings/SettingList.def"

  /// Called once per iteration; return false to abort (throws Aborted).
  std::function<bool(const SurfaceMapProgress&)> progress;
  Logger log;
};

} // namespace surfacemaps
