// The `surfacemap` command line: a filter's settings as flags. Everything
// about a setting (its flag, its value as text, its --help entry, its JSON)
// comes from the engine's list through vtkSurfaceMapsSettings, the one
// codec; this file only walks the arguments and the table.
#pragma once

#include <functional>
#include <string>
#include <vector>

class vtkSphereEmbeddingFilter;
class vtkSurfaceMapFilter;
namespace Json
{
class Value;
}

namespace surfacemap
{

/// If args[i] is a flag of a setting of `table` (vtkSurfaceMapsSettings::
/// Tables), gives setting k its value through set(k, value), consuming the
/// value (i then at it), and returns true; throws UsageError naming the flag
/// and what it takes for a missing or bad value. False for any other
/// argument.
bool parseSettingFlag(int table,
  const std::vector<std::string>& args,
  std::size_t& i,
  const std::function<void(int, double)>& set);

/// The map's settings on `map`, and --preset (skipped with its value: see
/// applyPresetFlag).
bool parseSettingFlag(vtkSurfaceMapFilter* map,
  const std::vector<std::string>& args,
  std::size_t& i);

/// The sphere embedding's settings on `embedding`.
bool parseSettingFlag(vtkSphereEmbeddingFilter* embedding,
  const std::vector<std::string>& args,
  std::size_t& i);

/// If args holds "--preset NAME" (anywhere), applies that preset to `map`
/// and returns NAME ("" without one), so that the other setting flags
/// override it wherever they stand; UsageError for an unknown or repeated
/// preset. parseSettingFlag then skips the flag and its value.
std::string applyPresetFlag(vtkSurfaceMapFilter* map, const std::vector<std::string>& args);

/// Every setting's --help entry of `table`, in the list's order.
std::string settingsHelp(int table);

/// The settings of `table` as one JSON object, each value get(k) under its
/// key: { "target_error": 0.001, ..., "pairs": "star", "keep_landmarks": true }.
Json::Value settingsJson(int table, const std::function<double(int)>& get);

/// The map's settings of `map` as settingsJson, with "sizing_mode".
Json::Value settingsJson(vtkSurfaceMapFilter* map);

} // namespace surfacemap
