/**
 * @class   vtkSurfaceMapsSettingAccess
 * @brief   A filter's settings by index, through the engine's options (private).
 *
 * vtkSurfaceMapFilter and vtkSphereEmbeddingFilter keep each setting of the
 * list (Core/settings/SettingList.def) in a member of its name, which their
 * headers spell out for VTK's wrappers. Their GetSetting(i), SetSetting(i)
 * and PrintSelf go through the engine's options instead of through the
 * members one by one: `Access` names the options type and the filter's two
 * expansions of the list, OptionsOf(filter) (members to options) and
 * SetAll(filter, options) (options to members, Modified() only for the
 * values that change), and the table (surfacemaps::BoundSetting<Options>).
 */
#ifndef vtkSurfaceMapsSettingAccess_h
#define vtkSurfaceMapsSettingAccess_h

#include "base/Error.h"
#include "settings/Setting.h"

#include "vtkIndent.h"

#include <cmath>
#include <ostream>

namespace vtkSurfaceMapsSettingAccess
{

template<class Access, class Filter>
double Get(Filter* filter, int i)
{
  const auto& table = Access::Table();
  return i >= 0 && i < static_cast<int>(table.size()) ? table[i].get(Access::OptionsOf(filter))
                                                      : std::nan("");
}

/// Setting i clamped into its range (NaN: its default); nothing out of range.
template<class Access, class Filter>
void Set(Filter* filter, int i, double value)
{
  const auto& table = Access::Table();
  if (i >= 0 && i < static_cast<int>(table.size()))
  {
    auto options = Access::OptionsOf(filter);
    table[i].set(options, table[i].clamp(value));
    Access::SetAll(filter, options);
  }
}

/// One line per setting: "Name: value" as the codec writes the value.
template<class Access, class Filter>
void Print(Filter* filter, std::ostream& os, vtkIndent indent)
{
  const auto options = Access::OptionsOf(filter);
  for (const auto& setting : Access::Table())
  {
    os << indent << setting.name << ": " << setting.format(setting.get(options)) << "\n";
  }
}

/// Throws surfacemaps::InputError naming the first setting outside its range
/// (NaN, which the Set macros let through): bad input, found before the
/// engine runs.
template<class Access, class Options>
void CheckRanges(const Options& options)
{
  for (const auto& s : Access::Table())
  {
    const double value = s.get(options);
    if (!(value >= s.minimum && value <= s.maximum))
    {
      throw surfacemaps::InputError(s.valueError(s.name, s.format(value).c_str()));
    }
  }
}

} // namespace vtkSurfaceMapsSettingAccess

#endif
