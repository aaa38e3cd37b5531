// SurfaceMaps engine: the table of the surface map's settings.
#pragma once

#include "map/MapOptions.h"

#include <functional>
#include <string>
#include <vector>

namespace surfacemaps
{

/// What values a setting takes.
enum class SettingKind
{
  Real,   ///< any number in [minimum, maximum]
  Count,  ///< a whole number in [minimum, maximum]
  Switch, ///< 0 (off) or 1 (on)
  Choice, ///< the index of one of `choices`
};

/// One setting of SurfaceMapOptions: the one place that names it, bounds it
/// and documents it. Its default is the field's initialiser in
/// SurfaceMapOptions. vtkSurfaceMapFilter (Set/Get methods of the same name,
/// clamped to the range), the command line (`surfacemap map`, BenchmarkMap:
/// --flag VALUE), report.json and the documentation derive from this table.
struct MapSetting
{
  /// The filter's property: vtkSurfaceMapFilter::Set<name>, Get<name>.
  const char* name;
  /// The command-line flag without "--"; its report.json key is the same
  /// with '_' for '-'. A Switch takes no value: `flag` turns it on,
  /// `offFlag` off.
  const char* flag;
  const char* offFlag;
  SettingKind kind;
  double minimum, maximum;
  /// Choice: the names of the values 0, 1, ... separated by '|'.
  const char* choices;
  /// What it does, in one or two sentences (no default, no range: both are
  /// printed from the table).
  const char* doc;
  std::function<double(const SurfaceMapOptions&)> get;
  std::function<void(SurfaceMapOptions&, double)> set;
  /// The group it belongs to, e.g. "Landmark phase" (GUIs show the settings
  /// by topic; the table's order keeps each topic together).
  const char* topic = nullptr;

  double defaultValue() const { return this->get(SurfaceMapOptions()); }
  /// `value` clamped into the range (and rounded for counts).
  double clamp(double value) const;
  /// The value as a person reads it: a choice's name, "on"/"off", a number.
  std::string format(double value) const;
  /// The choice names, in value order (empty unless a Choice).
  std::vector<std::string> choiceNames() const;
  /// Reads a value as a person writes it: a choice's name, a number in the
  /// range (whole for counts), for a switch 0 or 1. False if `text` is none.
  bool parse(const std::string& text, double& value) const;
};

/// Every setting, in the order of SurfaceMapOptions.
const std::vector<MapSetting>& mapSettings();

/// The setting with this name (e.g. "RefinementDistortion"); nullptr if none.
const MapSetting* findMapSetting(const std::string& name);

/// If args[i] is a setting's flag ("--refinement-distortion", a switch's
/// "--keep-landmarks" or "--release-landmarks"), sets it in `options`
/// (consuming its value: i then points at it) and returns true; false for
/// any other argument. Throws std::invalid_argument naming the flag and its
/// range for a missing or bad value. (The command line `surfacemap map` does
/// the same through vtkSurfaceMapFilter's copy of this table.)
bool parseSettingFlag(const std::vector<std::string>& args,
  std::size_t& i,
  SurfaceMapOptions& options);

} // namespace surfacemaps
