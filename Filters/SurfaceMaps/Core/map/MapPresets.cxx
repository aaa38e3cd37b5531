#include "map/MapPresets.h"

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
/// specimen's landmarks are exact in the common triangulation. Each specimen
/// is mapped against the specimens' mean shape: no specimen is privileged
/// (the star's centre carries the whole map term, and T misses it most),
/// and the map does not depend on the order of the specimens.
SurfaceMapOptions populationOptions()
{
  SurfaceMapOptions options;
  options.pairs = PairScheme::Mean;
  options.targetError = 1e-2;
  options.fineIterations = 30;
  options.approximationWeight = 2.0;
  options.refinementRounds = 0;
  return options;
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
    return "Many surfaces (a population study) in one common triangulation for statistics: each "
           "against the surfaces' mean shape (none privileged, the order does not matter), the "
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
  const SurfaceMapOptions population = populationOptions();
  std::vector<PresetValue> values;
  for (const MapSetting& s : mapSettings())
  {
    const double value = s.get(population);
    if (value != s.defaultValue)
    {
      values.push_back({ &s, preset == MapPreset::Population ? value : s.defaultValue });
    }
  }
  return values;
}

void applyPreset(SurfaceMapOptions& options, MapPreset preset)
{
  for (const PresetValue& v : presetValues(preset))
  {
    v.setting->set(options, v.value);
  }
}

std::string presetDescription(MapPreset preset)
{
  std::string text = std::string(presetDocumentation(preset)) + " Sets ";
  const std::vector<PresetValue> values = presetValues(preset);
  for (std::size_t k = 0; k < values.size(); ++k)
  {
    text += (k == 0 ? "" : ", ") + std::string(values[k].setting->name) + " " +
      values[k].setting->format(values[k].value);
  }
  return text + ".";
}

std::string presetHelp()
{
  std::string names;
  for (MapPreset p : presets())
  {
    names += (names.empty() ? "" : "|") + std::string(presetName(p));
  }
  std::string help = "  --preset " + names + "\n" +
    wrapText("Sets a group of the settings below for a kind of study, wherever the flag stands; "
             "the settings given as flags override it.",
      6,
      79);
  for (MapPreset p : presets())
  {
    help += wrapText(std::string(presetName(p)) + ": " + presetDescription(p), 6, 79);
  }
  return help;
}

} // namespace surfacemaps
