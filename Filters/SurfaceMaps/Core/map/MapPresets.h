// SurfaceMaps engine: named sets of settings for kinds of study, and their
// text (what a preset sets, the --preset help).
#pragma once

#include "map/MapSettings.h"

#include <string>
#include <vector>

namespace surfacemaps
{

/// A kind of study, each with the settings that suit it.
enum class MapPreset
{
  /// Two (or a few) surfaces, the finest map: the defaults of SurfaceMapOptions.
  Pair,
  /// Many surfaces for statistics over the common triangulation: a coarser
  /// T, a stronger approximation term, no refinement rounds.
  Population,
};

/// One setting a preset sets, and its value.
struct PresetValue
{
  const MapSetting* setting;
  double value;
};

/// "pair" or "population".
const char* presetName(MapPreset preset);
/// What the preset is for and why it sets what it sets (one paragraph).
const char* presetDocumentation(MapPreset preset);
/// The preset named `name`; false if there is none.
bool parsePreset(const std::string& name, MapPreset& preset);
/// Every preset, in enum order.
std::vector<MapPreset> presets();

/// The settings the preset sets, with their values, in the list's order.
/// Every preset lists the same settings, so applying one undoes another;
/// Pair's values are the defaults.
std::vector<PresetValue> presetValues(MapPreset preset);

/// Sets the preset's settings in `options`; the others stay.
void applyPreset(SurfaceMapOptions& options, MapPreset preset);

/// presetDocumentation followed by "Sets Name value, ...".
std::string presetDescription(MapPreset preset);

/// The --preset entry of a --help: the flag with the presets' names, what a
/// preset does, then each preset's description (wrapped like Setting::help).
std::string presetHelp();

} // namespace surfacemaps
