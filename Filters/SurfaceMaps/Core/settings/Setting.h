// SurfaceMaps engine: what one setting of the list (SettingList.def) is, and
// the one text codec every front end uses for it: a value formatted and
// parsed as a person writes it, its description, its --help entry, its JSON
// value and the message for a bad value.
#pragma once

#include <cmath>
#include <stdexcept>
#include <string>
#include <type_traits>
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

/// Where a GUI shows a setting: at once, or behind an "advanced" toggle.
enum class SettingPanel
{
  Basic,
  Advanced,
};

/// One entry of the list, as the front ends read it.
struct Setting
{
  /// The filter's property (Set<name>, Get<name>).
  const char* name = nullptr;
  /// The command-line flag without "--"; a switch's `flag` turns it on and
  /// `offFlag` off (nullptr for the other kinds).
  const char* flag = nullptr;
  const char* offFlag = nullptr;
  SettingKind kind = SettingKind::Real;
  double minimum = 0.0;
  double maximum = 0.0;
  double defaultValue = 0.0;
  /// A choice's value names, '|' between them; nullptr for the other kinds.
  const char* choices = nullptr;
  /// What it does (no default, no range: describe() adds both).
  const char* doc = nullptr;
  /// The group it belongs to, e.g. "Landmark phase".
  const char* topic = nullptr;
  SettingPanel panel = SettingPanel::Advanced;

  /// `value` clamped into the range (whole for counts, choices and
  /// switches); NaN gives the default.
  double clamp(double value) const;
  /// The choice names in value order (empty unless a choice).
  std::vector<std::string> choiceNames() const;

  /// The value as a person reads and writes it: a choice's name, "on" or
  /// "off", a whole number, or the shortest decimal that reads back as the
  /// same double (1e-05 is "1e-5"). parse(format(v)) == v for every value in
  /// the range.
  std::string format(double value) const;
  /// Reads a value as a person writes it: a choice's name (or its index), a
  /// finite number in the range (whole for counts), for a switch on/off or
  /// 1/0. False if `text` is none of these.
  bool parse(const std::string& text, double& value) const;
  /// The value in JSON: a number, true/false for a switch, a choice's name as
  /// a string.
  std::string json(double value) const;
  /// The flag with '_' for '-': the setting's key in report.json.
  std::string jsonKey() const;

  /// The doc followed by the default and the range, one paragraph: what the
  /// header, --help, Python and ParaView show.
  std::string describe() const;
  /// The --help entry: "  --flag X" (a switch: "  --flag | --off-flag", a
  /// choice: "  --flag a|b|c"), then describe() wrapped to 79 columns,
  /// indented by 6; ends with a newline.
  std::string help() const;
  /// The value that `argument`, one of this setting's flags, sets with
  /// `text` after it: a switch's from the flag itself (`text` unused), else
  /// parse(text). NaN for a bad or missing (null) text.
  double flagValue(const std::string& argument, const char* text) const;
  /// Why `text` (null: none) is no value of `option` (the flag as given):
  /// what it takes.
  std::string valueError(const std::string& option, const char* text) const;
};

/// `text` wrapped to `width` columns, every line indented by `indent` spaces
/// and ended by a newline.
std::string wrapText(const std::string& text, std::size_t indent, std::size_t width);

/// The first setting of `table` for which matches(setting); nullptr if none.
template<class S, class Predicate>
const S* findSettingIf(const std::vector<S>& table, Predicate matches)
{
  for (const S& s : table)
  {
    if (matches(s))
    {
      return &s;
    }
  }
  return nullptr;
}

/// The setting of `table` whose name is `name`; nullptr if none.
template<class S>
const S* findSetting(const std::vector<S>& table, const std::string& name)
{
  return findSettingIf(table, [&name](const Setting& s) { return name == s.name; });
}

/// The setting of `table` that `argument` ("--flag" or a switch's
/// "--off-flag") names; nullptr if none.
template<class S>
const S* findSettingFlag(const std::vector<S>& table, const std::string& argument)
{
  return findSettingIf(table,
    [&argument](const Setting& s)
    {
      return argument == std::string("--") + s.flag ||
        (s.offFlag && argument == std::string("--") + s.offFlag);
    });
}

/// If args[i] is a flag of `table`: its setting, with the value it sets in
/// `value` (a switch's from the flag; else args[i + 1], i then at it);
/// nullptr for any other argument. Throws std::invalid_argument with
/// valueError() for a missing or bad value.
template<class S>
const S* readSettingFlag(const std::vector<S>& table,
  const std::vector<std::string>& args,
  std::size_t& i,
  double& value)
{
  const S* s = findSettingFlag(table, args[i]);
  if (!s)
  {
    return nullptr;
  }
  const bool takesValue = s->kind != SettingKind::Switch;
  const char* text = takesValue && i + 1 < args.size() ? args[i + 1].c_str() : nullptr;
  value = s->flagValue(args[i], text);
  if (std::isnan(value))
  {
    throw std::invalid_argument(s->valueError(args[i], text));
  }
  i += takesValue ? 1 : 0;
  return s;
}

/// A setting of the list bound to its field in `Options`.
template<class Options>
struct BoundSetting : Setting
{
  double (*get)(const Options&) = nullptr;
  void (*set)(Options&, double) = nullptr;
};

/// A value of the list's type `T` as a double (enums through int).
template<class T>
double settingNumber(T value)
{
  if constexpr (std::is_enum_v<T>)
  {
    return static_cast<double>(static_cast<int>(value));
  }
  else
  {
    return static_cast<double>(value);
  }
}

/// A value of the list's type `T` from its double (enums through int).
template<class T>
T settingValue(double value)
{
  if constexpr (std::is_enum_v<T>)
  {
    return static_cast<T>(static_cast<int>(value));
  }
  else
  {
    return static_cast<T>(value);
  }
}

} // namespace surfacemaps
