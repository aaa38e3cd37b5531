#include "SettingFlags.h"

#include "Arguments.h"
#include "Commands.h"
#include "Json.h"

#include "vtkSurfaceMapFilter.h"

#include <cmath>
#include <sstream>

namespace surfacemap
{

namespace
{

std::vector<std::string> choiceNames(int k)
{
  std::vector<std::string> names;
  const char* choices = vtkSurfaceMapFilter::GetSettingChoices(k);
  std::istringstream text(choices ? choices : "");
  for (std::string name; std::getline(text, name, '|');)
  {
    names.push_back(name);
  }
  return names;
}

std::string number(double value)
{
  std::ostringstream text;
  text << value;
  return text.str();
}

std::string formatted(int k, double value)
{
  switch (vtkSurfaceMapFilter::GetSettingType(k))
  {
    case vtkSurfaceMapFilter::SETTING_SWITCH:
      return value != 0.0 ? "on" : "off";
    case vtkSurfaceMapFilter::SETTING_CHOICE:
      return choiceNames(k).at(static_cast<std::size_t>(value));
    default:
      return number(value);
  }
}

/// The value of flag `option` for setting k; UsageError naming the range.
double parseValue(int k, const std::string& option, const std::string& text)
{
  double value = 0.0;
  if (vtkSurfaceMapFilter::ParseSettingValue(k, text.c_str(), &value))
  {
    return value;
  }
  const int type = vtkSurfaceMapFilter::GetSettingType(k);
  if (type == vtkSurfaceMapFilter::SETTING_CHOICE)
  {
    const std::vector<std::string> names = choiceNames(k);
    std::string list;
    for (std::size_t c = 0; c < names.size(); ++c)
    {
      list += (c == 0 ? "" : c + 1 == names.size() ? " or " : ", ") + names[c];
    }
    throw UsageError{ option + " is " + list + ", not '" + text + "'" };
  }
  throw UsageError{ option +
    (type == vtkSurfaceMapFilter::SETTING_COUNT ? " needs a whole number from "
                                                : " needs a number from ") +
    number(vtkSurfaceMapFilter::GetSettingMinimum(k)) + " to " +
    number(vtkSurfaceMapFilter::GetSettingMaximum(k)) + ", not '" + text + "'" };
}

/// `text` wrapped to `width` columns, every line indented by `indent`.
std::string wrapped(const std::string& text, std::size_t indent, std::size_t width)
{
  std::istringstream words(text);
  std::string out, line;
  for (std::string word; words >> word;)
  {
    if (!line.empty() && indent + line.size() + 1 + word.size() > width)
    {
      out += std::string(indent, ' ') + line + "\n";
      line.clear();
    }
    line += (line.empty() ? "" : " ") + word;
  }
  if (!line.empty())
  {
    out += std::string(indent, ' ') + line + "\n";
  }
  return out;
}

} // namespace

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

std::string presetsHelp()
{
  std::string help = "  --preset";
  for (int p = 0; p < vtkSurfaceMapFilter::GetNumberOfPresets(); ++p)
  {
    help += (p == 0 ? " " : "|") + std::string(vtkSurfaceMapFilter::GetPresetName(p));
  }
  help += "\n";
  help += wrapped("Sets a group of the settings below for a kind of study, wherever the flag "
                  "stands; the settings given as flags override it.",
    6,
    79);
  for (int p = 0; p < vtkSurfaceMapFilter::GetNumberOfPresets(); ++p)
  {
    help += wrapped(std::string(vtkSurfaceMapFilter::GetPresetName(p)) + ": " +
        vtkSurfaceMapFilter::GetPresetDocumentation(p),
      6,
      79);
  }
  return help;
}

bool parseSettingFlag(vtkSurfaceMapFilter* map,
  const std::vector<std::string>& args,
  std::size_t& i)
{
  const std::string& arg = args[i];
  if (arg == "--preset")
  {
    ++i; // applied by applyPresetFlag before every other flag
    return true;
  }
  for (int k = 0; k < vtkSurfaceMapFilter::GetNumberOfSettings(); ++k)
  {
    const char* off = vtkSurfaceMapFilter::GetSettingOffFlag(k);
    if (vtkSurfaceMapFilter::GetSettingType(k) == vtkSurfaceMapFilter::SETTING_SWITCH)
    {
      if (arg == std::string("--") + vtkSurfaceMapFilter::GetSettingFlag(k) ||
        (off && arg == std::string("--") + off))
      {
        map->SetSetting(k, arg == std::string("--") + vtkSurfaceMapFilter::GetSettingFlag(k));
        return true;
      }
      continue;
    }
    if (arg != std::string("--") + vtkSurfaceMapFilter::GetSettingFlag(k))
    {
      continue;
    }
    if (i + 1 >= args.size())
    {
      throw UsageError{ arg + " needs a value" };
    }
    map->SetSetting(k, parseValue(k, arg, args[++i]));
    return true;
  }
  return false;
}

std::string settingsHelp()
{
  std::string help;
  for (int k = 0; k < vtkSurfaceMapFilter::GetNumberOfSettings(); ++k)
  {
    const int type = vtkSurfaceMapFilter::GetSettingType(k);
    std::string flag = std::string("  --") + vtkSurfaceMapFilter::GetSettingFlag(k);
    std::string range;
    switch (type)
    {
      case vtkSurfaceMapFilter::SETTING_SWITCH:
        flag += std::string(" | --") + vtkSurfaceMapFilter::GetSettingOffFlag(k);
        break;
      case vtkSurfaceMapFilter::SETTING_CHOICE:
        flag += " " + std::string(vtkSurfaceMapFilter::GetSettingChoices(k));
        break;
      default:
        flag += type == vtkSurfaceMapFilter::SETTING_COUNT ? " N" : " X";
        range = "; " + number(vtkSurfaceMapFilter::GetSettingMinimum(k)) + " to " +
          number(vtkSurfaceMapFilter::GetSettingMaximum(k));
    }
    help += flag + "\n";
    help += wrapped(std::string(vtkSurfaceMapFilter::GetSettingDocumentation(k)) + " (default " +
        formatted(k, vtkSurfaceMapFilter::GetSettingDefault(k)) + range + ")",
      6,
      79);
  }
  return help;
}

Json::Value settingsJson(vtkSurfaceMapFilter* map)
{
  Json::Value settings(Json::objectValue);
  for (int k = 0; k < vtkSurfaceMapFilter::GetNumberOfSettings(); ++k)
  {
    std::string key = vtkSurfaceMapFilter::GetSettingFlag(k);
    for (char& c : key)
    {
      c = c == '-' ? '_' : c;
    }
    const double value = map->GetSetting(k);
    switch (vtkSurfaceMapFilter::GetSettingType(k))
    {
      case vtkSurfaceMapFilter::SETTING_SWITCH:
        settings[key] = value != 0.0;
        break;
      case vtkSurfaceMapFilter::SETTING_CHOICE:
        settings[key] = formatted(k, value);
        break;
      default:
        settings[key] = jsonNumber(value);
    }
  }
  settings["sizing_mode"] = map->GetSizingMode() == vtkSurfaceMapFilter::SIZING_CURVATURE
    ? "curvature"
    : "array_or_curvature";
  return settings;
}

} // namespace surfacemap
