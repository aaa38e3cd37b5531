#include "SettingFlags.h"

#include "Arguments.h"
#include "Commands.h"
#include "Json.h"

#include "vtkSphereEmbeddingFilter.h"
#include "vtkSurfaceMapFilter.h"
#include "vtkSurfaceMapsSettings.h"

#include <cmath>
#include <memory>
#include <stdexcept>

namespace surfacemap
{

using Settings = vtkSurfaceMapsSettings;

namespace
{
/// The codec's JSON text of a value as a jsoncpp value.
Json::Value jsonValue(const std::string& text)
{
  Json::Value value;
  std::string errors;
  const std::unique_ptr<Json::CharReader> reader(Json::CharReaderBuilder().newCharReader());
  if (!reader->parse(text.data(), text.data() + text.size(), &value, &errors))
  {
    throw std::logic_error("the settings' codec wrote '" + text + "', not JSON: " + errors);
  }
  return value;
}
} // namespace

bool parseSettingFlag(int table,
  const std::vector<std::string>& args,
  std::size_t& i,
  const std::function<void(int, double)>& set)
{
  const int k = Settings::FindFlag(table, args[i].c_str());
  if (k < 0)
  {
    return false;
  }
  const bool takesValue = Settings::GetType(table, k) != Settings::SWITCH;
  const char* text = takesValue && i + 1 < args.size() ? args[i + 1].c_str() : nullptr;
  const double value = Settings::ParseFlag(table, k, args[i].c_str(), text);
  if (std::isnan(value))
  {
    throw UsageError{ Settings::GetValueError(table, k, args[i].c_str(), text) };
  }
  set(k, value);
  i += takesValue ? 1 : 0;
  return true;
}

bool parseSettingFlag(vtkSurfaceMapFilter* map,
  const std::vector<std::string>& args,
  std::size_t& i)
{
  if (args[i] == "--preset")
  {
    ++i; // applied by applyPresetFlag before every other flag
    return true;
  }
  return parseSettingFlag(
    Settings::MAP_SETTINGS, args, i, [map](int k, double value) { map->SetSetting(k, value); });
}

bool parseSettingFlag(vtkSphereEmbeddingFilter* embedding,
  const std::vector<std::string>& args,
  std::size_t& i)
{
  return parseSettingFlag(Settings::SPHERE_EMBEDDING_SETTINGS,
    args,
    i,
    [embedding](int k, double value) { embedding->SetSetting(k, value); });
}

std::string applyPresetFlag(vtkSurfaceMapFilter* map, const std::vector<std::string>& args)
{
  std::string name;
  for (std::size_t i = 0; i < args.size(); ++i)
  {
    if (args[i] != "--preset")
    {
      continue;
    }
    if (!name.empty())
    {
      throw UsageError{ "--preset given twice" };
    }
    name = optionValue(args, i);
    int preset = 0;
    while (preset < vtkSurfaceMapFilter::GetNumberOfPresets() &&
      name != vtkSurfaceMapFilter::GetPresetName(preset))
    {
      ++preset;
    }
    if (preset == vtkSurfaceMapFilter::GetNumberOfPresets())
    {
      std::string list;
      for (int p = 0; p < vtkSurfaceMapFilter::GetNumberOfPresets(); ++p)
      {
        list += (p == 0 ? "" : " or ") + std::string(vtkSurfaceMapFilter::GetPresetName(p));
      }
      throw UsageError{ "--preset is " + list + ", not '" + name + "'" };
    }
    map->ApplyPreset(preset);
  }
  return name;
}

std::string settingsHelp(int table)
{
  std::string help;
  for (int k = 0; k < Settings::GetNumberOfSettings(table); ++k)
  {
    help += Settings::GetHelp(table, k);
  }
  return help;
}

Json::Value settingsJson(int table, const std::function<double(int)>& get)
{
  Json::Value settings(Json::objectValue);
  for (int k = 0; k < Settings::GetNumberOfSettings(table); ++k)
  {
    settings[Settings::GetJsonKey(table, k)] = jsonValue(Settings::ToJson(table, k, get(k)));
  }
  return settings;
}

Json::Value settingsJson(vtkSurfaceMapFilter* map)
{
  Json::Value settings =
    settingsJson(Settings::MAP_SETTINGS, [map](int k) { return map->GetSetting(k); });
  settings["sizing_mode"] = map->GetSizingMode() == vtkSurfaceMapFilter::SIZING_CURVATURE
    ? "curvature"
    : "array_or_curvature";
  return settings;
}

} // namespace surfacemap
