#include "ExistingMapFiles.h"

#include "Commands.h"
#include "MapDirectory.h"
#include "MeshFiles.h"

#include "vtkSurfaceMapFilter.h"
#include "vtkSurfaceMapsSettings.h"

#include "vtkAbstractArray.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkPolyData.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace surfacemap
{

const char* const AddToHelp =
  "  --add-to MAPDIR      add the meshes given to the map in MAPDIR (written by\n"
  "                       'surfacemap map') without mapping its inputs again:\n"
  "                       their embeddings and maps are kept, T is refined by\n"
  "                       edge splits only where a new mesh needs it; the\n"
  "                       settings are MAPDIR's unless given as flags (needs\n"
  "                       refinement rounds and error bound 0, as the\n"
  "                       population preset has). Writes the map of all inputs,\n"
  "                       MAPDIR's first, to -o DIR; MAPDIR stays as it is\n"
  "                       unless DIR is MAPDIR and --overwrite is given\n";

std::string addToDirectory(const std::vector<std::string>& args)
{
  std::string directory;
  for (std::size_t i = 0; i < args.size(); ++i)
  {
    if (args[i] == "--add-to")
    {
      if (!directory.empty())
      {
        throw UsageError{ "--add-to given twice" };
      }
      if (i + 1 >= args.size() || args[i + 1].empty() || args[i + 1][0] == '-')
      {
        throw UsageError{ "--add-to needs a map directory" };
      }
      directory = args[++i];
    }
  }
  return directory;
}

namespace
{

/// A setting's value in report.json as the text its flag would take.
std::string settingText(const Json::Value& value)
{
  if (value.isBool())
  {
    return value.asBool() ? "1" : "0";
  }
  if (value.isString())
  {
    return value.asString();
  }
  std::ostringstream text;
  text.precision(17);
  text << value.asDouble();
  return text.str();
}

/// Sets every map setting that report.json's "settings" hold on `map`.
void applySettings(const Json::Value& settings, const std::string& path, vtkSurfaceMapFilter* map)
{
  if (!settings.isObject())
  {
    throw std::runtime_error(path + " has no \"settings\": not a report 'surfacemap map' wrote");
  }
  using Settings = vtkSurfaceMapsSettings;
  for (int k = 0; k < Settings::GetNumberOfSettings(Settings::MAP_SETTINGS); ++k)
  {
    const std::string key = Settings::GetJsonKey(Settings::MAP_SETTINGS, k);
    if (!settings.isMember(key))
    {
      continue; // a setting newer than the map: its default
    }
    const double value =
      Settings::Parse(Settings::MAP_SETTINGS, k, settingText(settings[key]).c_str());
    if (std::isnan(value))
    {
      throw std::runtime_error(path + ": settings." + key + " is " +
        settings[key].toStyledString() + "which is no value of that setting");
    }
    map->SetSetting(k, value);
  }
  if (settings["sizing_mode"].isString())
  {
    map->SetSizingMode(settings["sizing_mode"].asString() == "curvature"
        ? vtkSurfaceMapFilter::SIZING_CURVATURE
        : vtkSurfaceMapFilter::SIZING_ARRAY_OR_CURVATURE);
  }
}

/// Map file `name` of `directory`, read; throws naming it.
vtkSmartPointer<vtkPolyData> readMapMesh(const std::string& directory, const std::string& name)
{
  vtkSmartPointer<vtkPolyData> mesh = readMesh(directory + "/" + name);
  if (!mesh)
  {
    throw std::runtime_error(directory + "/" + name + " does not read as a mesh");
  }
  return mesh;
}

} // namespace

ExistingMapFiles readExistingMap(const std::string& directory, vtkSurfaceMapFilter* map)
{
  ExistingMapFiles existing;
  existing.directory = directory;
  const int m = mapInputCount(directory);
  std::vector<std::string> names;
  for (int j = 0; j < m; ++j)
  {
    names.push_back(mapFileName("common", j));
    names.push_back(mapFileName("embedding", j));
  }
  verifyMapFiles(directory, names);
  const std::string path = directory + "/report.json";
  existing.report = readJsonFile(path, "the map to add to");
  applySettings(existing.report["settings"], path, map);
  for (int j = 0; j < m; ++j)
  {
    existing.common.push_back(readMapMesh(directory, mapFileName("common", j)));
    vtkSmartPointer<vtkPolyData> embedding = readMapMesh(directory, mapFileName("embedding", j));
    // The input's own field data only: the stamps and figures of the
    // existing map do not belong to the new one.
    vtkNew<vtkFieldData> fields;
    if (vtkAbstractArray* file = embedding->GetFieldData()->GetAbstractArray("FileName"))
    {
      fields->AddArray(file);
    }
    embedding->SetFieldData(fields);
    existing.embeddings.push_back(embedding);
  }
  return existing;
}

void mergeExistingReport(Json::Value& report, const ExistingMapFiles& existing)
{
  const Json::Value& inputs = existing.report["inputs"];
  for (Json::ArrayIndex j = 0; j < inputs.size() && j < report["inputs"].size(); ++j)
  {
    report["inputs"][j] = inputs[j];
  }
  report["added_to"]["directory"] = existing.directory;
  report["added_to"]["map_id"] = existing.report["map_id"];
  report["added_to"]["inputs"] = static_cast<Json::UInt>(inputs.size());
  if (report["preset"].isNull())
  {
    report["preset"] = existing.report["preset"];
  }
}

std::vector<std::string> existingInputFiles(const ExistingMapFiles& existing)
{
  return mapReportInputs(existing.directory + "/report.json");
}

} // namespace surfacemap
