#include "map/MapSettings.h"

namespace surfacemaps
{

namespace
{

/// One entry of the list with its accessors on `Options`.
template<class Options>
BoundSetting<Options> bound(Setting setting,
  double (*get)(const Options&),
  void (*set)(Options&, double))
{
  BoundSetting<Options> s;
  static_cast<Setting&>(s) = setting;
  s.get = get;
  s.set = set;
  return s;
}

// The expansion of one entry: its description, then its field's accessors.
#define SURFACEMAPS_BIND(                                                                          \
  Options, Name, field, Type, Kind, Default, Minimum, Maximum, Flag, OffFlag, Choices, Panel, Doc) \
  bound<Options>(                                                                                  \
    Setting{ #Name,                                                                                \
      Flag,                                                                                        \
      OffFlag,                                                                                     \
      SettingKind::Kind,                                                                           \
      Minimum,                                                                                     \
      Maximum,                                                                                     \
      settingNumber(Default),                                                                      \
      Choices,                                                                                     \
      Doc,                                                                                         \
      topic,                                                                                       \
      SettingPanel::Panel },                                                                       \
    [](const Options& o) { return settingNumber(o.field); },                                       \
    [](Options& o, double value) { o.field = settingValue<Type>(value); })

struct Tables
{
  std::vector<MapSetting> map;
  std::vector<EmbeddingSetting> embedding;
};

// Both tables from one pass over the list.
Tables buildTables()
{
  Tables tables;
  const char* topic = nullptr;
#define SURFACEMAPS_MAP_TOPIC(Title) topic = Title;
#define SURFACEMAPS_EMBEDDING_TOPIC(Title) topic = Title;
#define SURFACEMAPS_MAP_SETTING(...)                                                               \
  tables.map.push_back(SURFACEMAPS_BIND(SurfaceMapOptions, __VA_ARGS__));
#define SURFACEMAPS_EMBEDDING_SETTING(...)                                                         \
  tables.embedding.push_back(SURFACEMAPS_BIND(SphereEmbeddingOptions, __VA_ARGS__));
#include "settings/SettingList.def"
  return tables;
}

#undef SURFACEMAPS_BIND

const Tables& tables()
{
  static const Tables all = buildTables();
  return all;
}

template<class Options>
bool setFromFlag(const std::vector<BoundSetting<Options>>& table,
  const std::vector<std::string>& args,
  std::size_t& i,
  Options& options)
{
  double value = 0.0;
  const BoundSetting<Options>* s = readSettingFlag(table, args, i, value);
  if (s)
  {
    s->set(options, value);
  }
  return s != nullptr;
}

} // namespace

const std::vector<MapSetting>& mapSettings()
{
  return tables().map;
}

const std::vector<EmbeddingSetting>& embeddingSettings()
{
  return tables().embedding;
}

const MapSetting* findMapSetting(const std::string& name)
{
  return findSetting(mapSettings(), name);
}

bool parseSettingFlag(const std::vector<std::string>& args,
  std::size_t& i,
  SurfaceMapOptions& options)
{
  return setFromFlag(mapSettings(), args, i, options);
}

bool parseSettingFlag(const std::vector<std::string>& args,
  std::size_t& i,
  SphereEmbeddingOptions& options)
{
  return setFromFlag(embeddingSettings(), args, i, options);
}

} // namespace surfacemaps
