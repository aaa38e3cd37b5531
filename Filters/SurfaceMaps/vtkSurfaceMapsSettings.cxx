#include "vtkSurfaceMapsSettings.h"

#include "map/MapPresets.h"
#include "map/MapSettings.h"

#include "vtkObjectFactory.h"

#include <cmath>

vtkStandardNewMacro(vtkSurfaceMapsSettings);

namespace
{
int count(int table)
{
  switch (table)
  {
    case vtkSurfaceMapsSettings::MAP_SETTINGS:
      return static_cast<int>(surfacemaps::mapSettings().size());
    case vtkSurfaceMapsSettings::SPHERE_EMBEDDING_SETTINGS:
      return static_cast<int>(surfacemaps::embeddingSettings().size());
    default:
      return 0;
  }
}

// Setting i of the table; nullptr out of range.
const surfacemaps::Setting* at(int table, int i)
{
  if (i < 0 || i >= count(table))
  {
    return nullptr;
  }
  if (table == vtkSurfaceMapsSettings::MAP_SETTINGS)
  {
    return &surfacemaps::mapSettings()[i];
  }
  return &surfacemaps::embeddingSettings()[i];
}

// The index of `found` in the table; -1 for nullptr.
template<class S>
int indexIn(const std::vector<S>& table, const S* found)
{
  return found ? static_cast<int>(found - table.data()) : -1;
}

// The index that `find` (a function of a table) returns in `table`; -1 if none.
template<class Find>
int findIn(int table, Find find)
{
  switch (table)
  {
    case vtkSurfaceMapsSettings::MAP_SETTINGS:
      return indexIn(surfacemaps::mapSettings(), find(surfacemaps::mapSettings()));
    case vtkSurfaceMapsSettings::SPHERE_EMBEDDING_SETTINGS:
      return indexIn(surfacemaps::embeddingSettings(), find(surfacemaps::embeddingSettings()));
    default:
      return -1;
  }
}

const double NaN = std::nan("");

// A member of setting i of the table; `otherwise` out of range.
template<class T>
T member(int table, int i, T surfacemaps::Setting::*field, T otherwise)
{
  const surfacemaps::Setting* s = at(table, i);
  return s ? s->*field : otherwise;
}

// The text a member function of setting i gives; "" out of range.
template<class... Args>
std::string text(int table,
  int i,
  std::string (surfacemaps::Setting::*function)(Args...) const,
  Args... args)
{
  const surfacemaps::Setting* s = at(table, i);
  return s ? (s->*function)(args...) : std::string();
}
} // namespace

void vtkSurfaceMapsSettings::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Map settings: " << count(MAP_SETTINGS) << "\n";
  os << indent << "Sphere embedding settings: " << count(SPHERE_EMBEDDING_SETTINGS) << "\n";
}

int vtkSurfaceMapsSettings::GetNumberOfSettings(int table)
{
  return count(table);
}

int vtkSurfaceMapsSettings::FindSetting(int table, const char* name)
{
  const std::string text = name ? name : "";
  return findIn(table, [&text](const auto& t) { return surfacemaps::findSetting(t, text); });
}

int vtkSurfaceMapsSettings::FindFlag(int table, const char* argument)
{
  const std::string text = argument ? argument : "";
  return findIn(table, [&text](const auto& t) { return surfacemaps::findSettingFlag(t, text); });
}

const char* vtkSurfaceMapsSettings::GetName(int table, int i)
{
  return member<const char*>(table, i, &surfacemaps::Setting::name, nullptr);
}

const char* vtkSurfaceMapsSettings::GetFlag(int table, int i)
{
  return member<const char*>(table, i, &surfacemaps::Setting::flag, nullptr);
}

const char* vtkSurfaceMapsSettings::GetOffFlag(int table, int i)
{
  return member<const char*>(table, i, &surfacemaps::Setting::offFlag, nullptr);
}

const char* vtkSurfaceMapsSettings::GetChoices(int table, int i)
{
  return member<const char*>(table, i, &surfacemaps::Setting::choices, nullptr);
}

const char* vtkSurfaceMapsSettings::GetDocumentation(int table, int i)
{
  return member<const char*>(table, i, &surfacemaps::Setting::doc, nullptr);
}

const char* vtkSurfaceMapsSettings::GetTopic(int table, int i)
{
  return member<const char*>(table, i, &surfacemaps::Setting::topic, nullptr);
}

int vtkSurfaceMapsSettings::GetType(int table, int i)
{
  return at(table, i) ? static_cast<int>(at(table, i)->kind) : -1;
}

double vtkSurfaceMapsSettings::GetMinimum(int table, int i)
{
  return member(table, i, &surfacemaps::Setting::minimum, NaN);
}

double vtkSurfaceMapsSettings::GetMaximum(int table, int i)
{
  return member(table, i, &surfacemaps::Setting::maximum, NaN);
}

double vtkSurfaceMapsSettings::GetDefault(int table, int i)
{
  return member(table, i, &surfacemaps::Setting::defaultValue, NaN);
}

bool vtkSurfaceMapsSettings::IsBasic(int table, int i)
{
  return at(table, i) && at(table, i)->panel == surfacemaps::SettingPanel::Basic;
}

std::string vtkSurfaceMapsSettings::Format(int table, int i, double value)
{
  return text(table, i, &surfacemaps::Setting::format, value);
}

double vtkSurfaceMapsSettings::Parse(int table, int i, const char* text)
{
  double value = NaN;
  return at(table, i) && text && at(table, i)->parse(text, value) ? value : NaN;
}

double vtkSurfaceMapsSettings::ParseFlag(int table, int i, const char* argument, const char* text)
{
  return at(table, i) && argument ? at(table, i)->flagValue(argument, text) : NaN;
}

std::string vtkSurfaceMapsSettings::GetValueError(int table,
  int i,
  const char* argument,
  const char* text)
{
  return at(table, i) && argument ? at(table, i)->valueError(argument, text) : std::string();
}

std::string vtkSurfaceMapsSettings::ToJson(int table, int i, double value)
{
  return text(table, i, &surfacemaps::Setting::json, value);
}

std::string vtkSurfaceMapsSettings::GetJsonKey(int table, int i)
{
  return text(table, i, &surfacemaps::Setting::jsonKey);
}

std::string vtkSurfaceMapsSettings::GetDescription(int table, int i)
{
  return text(table, i, &surfacemaps::Setting::describe);
}

std::string vtkSurfaceMapsSettings::GetHelp(int table, int i)
{
  return text(table, i, &surfacemaps::Setting::help);
}

std::string vtkSurfaceMapsSettings::GetPresetHelp()
{
  return surfacemaps::presetHelp();
}
