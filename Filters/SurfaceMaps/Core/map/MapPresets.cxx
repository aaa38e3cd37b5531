#include "map/MapPresets.h"

#include "map/MapSettings.h"

#include <stdexcept>

namespace surfacemaps
{

namespace
{

/// The population preset's values. Unit-area units, like every setting.
/// A population study wants one T for statistics over many surfaces, not the
/// finest map of each pair: the fine phase stops at the coarse phase's error
/// (a T of a few hundred to about a thousand vertices instead of several
/// thousand), the approximation term weighs four times the mesh-quality term
/// (instead of half) so that the coarse T still follows every surface, and
/// no refinement rounds run (they grow T where any one of the N - 1 exact
/// maps is distorted, so T grows with N). Landmarks stay locked: every
/// specimen's landmarks are exact in the common triangulation.
const std::vector<PresetValue>& populationValues()
{
  static const std::vector<PresetValue> values = {
    { "TargetError", 1e-2 },
    { "FineIterations", 30 },
    { "ApproximationWeight", 2.0 },
    { "RefinementRounds", 0 },
  };
  return values;
}

} // namespace

const char* presetName(MapPreset preset)
{
  return preset == MapPreset::Population ? "population" : "pair";
}

const char* presetDocumentation(MapPreset preset)
{
  if (preset == MapPreset::Population)
  {
    return "Many surfaces (a population study) in one common triangulation for statistics: the "
           "fine phase at the coarse phase's error with fewer iterations, a stronger "
           "approximation term, no refinement rounds; T stays at about a thousand vertices or "
           "less, and the time per iteration grows linearly with the number of surfaces.";
  }
  return "Two surfaces, the finest map: the default settings.";
}

bool parsePreset(const std::string& name, MapPreset& preset)
{
  for (MapPreset p : presets())
  {
    if (name == presetName(p))
    {
      preset = p;
      return true;
    }
  }
  return false;
}

std::vector<MapPreset> presets()
{
  return { MapPreset::Pair, MapPreset::Population };
}

std::vector<PresetValue> presetValues(MapPreset preset)
{
  std::vector<PresetValue> values = populationValues();
  if (preset == MapPreset::Pair)
  {
    for (PresetValue& v : values)
    {
      v.value = findMapSetting(v.setting)->defaultValue();
    }
  }
  return values;
}

void applyPreset(SurfaceMapOptions& options, MapPreset preset)
{
  for (const PresetValue& v : presetValues(preset))
  {
    const MapSetting* setting = findMapSetting(v.setting);
    if (!setting)
    {
      throw std::logic_error(std::string("preset names no setting ") + v.setting);
    }
    setting->set(options, setting->clamp(v.value));
  }
}

} // namespace surfacemaps
