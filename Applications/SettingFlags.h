// The `surfacemap` command line: the map's settings as flags, derived from
// vtkSurfaceMapFilter's settings table (one flag per setting, its range
// checked, its documentation and default in --help, its value in
// report.json).
#pragma once

#include <string>
#include <vector>

class vtkSurfaceMapFilter;
namespace Json
{
class Value;
}

namespace surfacemap
{

/// If args[i] is a setting's flag, sets the setting on `map` (consuming its
/// value, i then at the value) and returns true; throws UsageError naming
/// the flag and its range for a bad value. False for any other argument.
bool parseSettingFlag(vtkSurfaceMapFilter* map,
  const std::vector<std::string>& args,
  std::size_t& i);

/// If args holds "--preset NAME" (anywhere), applies that preset to `map`
/// and returns NAME ("" without one), so that the other setting flags
/// override it wherever they stand; UsageError for an unknown or repeated
/// preset. parseSettingFlag then skips the flag and its value.
std::string applyPresetFlag(vtkSurfaceMapFilter* map, const std::vector<std::string>& args);

/// --preset with every preset's name and documentation, for --help.
std::string presetsHelp();

/// Every setting's flag with its documentation, default and range, for --help.
std::string settingsHelp();

/// Every setting of `map` as one JSON object: { "target_error": 0.001, ...,
/// "pairs": "star", "keep_landmarks": true }.
Json::Value settingsJson(vtkSurfaceMapFilter* map);

} // namespace surfacemap
