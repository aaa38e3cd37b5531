/**
 * @class   vtkSurfaceMapsSettings
 * @brief   The settings of vtkSurfaceMapFilter and vtkSphereEmbeddingFilter for tools.
 *
 * Every setting of the two filters is one entry of one list in the engine
 * (its name, type, default, range, command-line flag and documentation);
 * this class reads that list for programs that present the settings:
 * command lines, GUIs, report files, Python's argument parsers. It is also
 * the one text codec for a setting's value: Format() and Parse() are what
 * `surfacemap map --target-error 1e-4` and report.json use, and
 * Parse(Format(v)) == v for every value in the range.
 *
 * `table` is MAP_SETTINGS (vtkSurfaceMapFilter: GetSetting(i) and
 * SetSetting(i, value) on a filter) or SPHERE_EMBEDDING_SETTINGS
 * (vtkSphereEmbeddingFilter, likewise); `i` is the setting's index in that
 * table. Indices or tables out of range give nullptr, an empty string, -1
 * or NaN.
 *
 * @sa vtkSurfaceMapFilter vtkSphereEmbeddingFilter
 */
#ifndef vtkSurfaceMapsSettings_h
#define vtkSurfaceMapsSettings_h

#include "SurfaceMapsFiltersModule.h" // for export macro
#include "vtkObject.h"

#include <string> // for std::string

class SURFACEMAPSFILTERS_EXPORT vtkSurfaceMapsSettings : public vtkObject
{
public:
  static vtkSurfaceMapsSettings* New();
  vtkTypeMacro(vtkSurfaceMapsSettings, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** The filter whose settings a table holds. */
  enum Tables
  {
    MAP_SETTINGS = 0,             ///< vtkSurfaceMapFilter
    SPHERE_EMBEDDING_SETTINGS = 1 ///< vtkSphereEmbeddingFilter
  };

  /** What values a setting takes (the same values as vtkSurfaceMapFilter::SettingTypes). */
  enum Types
  {
    REAL = 0,   ///< a number in [minimum, maximum]
    COUNT = 1,  ///< a whole number in [minimum, maximum]
    SWITCH = 2, ///< 0 (off) or 1 (on)
    CHOICE = 3  ///< the index of one of GetChoices, '|' between them
  };

  ///@{
  /**
   * The table: the number of settings, a setting's index by its name (the
   * filter's Set<Name>) or by a command-line argument naming its flag
   * ("--target-error", or a switch's off flag "--release-landmarks"); -1 if
   * none.
   */
  static int GetNumberOfSettings(int table);
  static int FindSetting(int table, const char* name);
  static int FindFlag(int table, const char* argument);
  ///@}

  ///@{
  /**
   * Setting i: its property name (Set<Name>/Get<Name> of the filter), its
   * command-line flag without "--" (a switch's flag turns it on, its off
   * flag off; nullptr for other kinds), its choices ("star|sequence|..."
   * for CHOICE, else nullptr), its documentation (what it does), its topic
   * (the group a GUI shows it in; settings of one topic are consecutive), its
   * type (Types), range and default, and whether GUIs show it at once
   * (basic) or among the advanced settings.
   */
  static const char* GetName(int table, int i);
  static const char* GetFlag(int table, int i);
  static const char* GetOffFlag(int table, int i);
  static const char* GetChoices(int table, int i);
  static const char* GetDocumentation(int table, int i);
  static const char* GetTopic(int table, int i);
  static int GetType(int table, int i);
  static double GetMinimum(int table, int i);
  static double GetMaximum(int table, int i);
  static double GetDefault(int table, int i);
  static bool IsBasic(int table, int i);
  ///@}

  ///@{
  /**
   * The text codec. Format: a value as a person reads and writes it (a
   * choice's name, "on"/"off", a whole number, the shortest decimal that
   * reads back exactly). Parse: a value as a person writes it (a choice's
   * name, on/off or 1/0 for a switch, a finite number in the range, whole
   * for counts); NaN if `text` is none. ParseFlag: the value the command-line
   * `argument` (setting i's flag) sets with `text`, the argument after it (a
   * switch's value comes from the flag; `text` may be null); NaN if bad,
   * and GetValueError says why (naming the argument and what it takes).
   * ToJson: the value in JSON (a number, true/false, a choice's name in
   * quotes) under GetJsonKey (the flag with '_' for '-').
   */
  static std::string Format(int table, int i, double value);
  static double Parse(int table, int i, const char* text);
  static double ParseFlag(int table, int i, const char* argument, const char* text);
  static std::string GetValueError(int table, int i, const char* argument, const char* text);
  static std::string ToJson(int table, int i, double value);
  static std::string GetJsonKey(int table, int i);
  ///@}

  ///@{
  /**
   * Text for people: GetDescription is the documentation with the default
   * and the range ("... Default 0.001, range 1e-6 to 1."), as every header,
   * help text and GUI shows it; GetHelp is the setting's --help entry (the
   * flag, then the description wrapped to 79 columns); GetPresetHelp is the
   * --preset entry of `surfacemap map --help` (vtkSurfaceMapFilter's
   * presets and what each sets).
   */
  static std::string GetDescription(int table, int i);
  static std::string GetHelp(int table, int i);
  static std::string GetPresetHelp();
  ///@}

protected:
  vtkSurfaceMapsSettings() = default;
  ~vtkSurfaceMapsSettings() override = default;

private:
  vtkSurfaceMapsSettings(const vtkSurfaceMapsSettings&) = delete;
  void operator=(const vtkSurfaceMapsSettings&) = delete;
};

#endif
