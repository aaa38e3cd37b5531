// The list of settings and its text codec (Core/settings): every setting of
// both tables formats and parses back to the same value, names itself once,
// and the flags, help and presets come from the entries.
#include "map/MapPresets.h"
#include "map/MapSettings.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>
#include <vector>

using namespace surfacemaps;

namespace
{
/// Values of `s` worth a round trip: the ends of the range, the default, and
/// numbers whose shortest text has many digits.
std::vector<double> sampleValues(const Setting& s)
{
  std::vector<double> values = { s.minimum, s.maximum, s.defaultValue };
  if (s.kind == SettingKind::Real)
  {
    values.push_back(s.minimum + (s.maximum - s.minimum) / 3.0);
    values.push_back(s.minimum + (s.maximum - s.minimum) * 1e-7 / 7.0);
    values.push_back(std::nextafter(s.maximum, s.minimum));
  }
  else if (s.maximum > s.minimum)
  {
    values.push_back(std::floor((s.minimum + s.maximum) / 2.0));
  }
  return values;
}

template<class S>
void checkRoundTrips(const std::vector<S>& table)
{
  for (const S& s : table)
  {
    for (double value : sampleValues(s))
    {
      double parsed = std::nan("");
      const std::string text = s.format(value);
      EXPECT_TRUE(s.parse(text, parsed)) << s.name << ": '" << text << "'";
      EXPECT_EQ(parsed, value) << s.name << ": '" << text << "'";
      EXPECT_EQ(s.clamp(value), value) << s.name;
      // The flag reads the same text, and JSON holds the same value.
      const double viaFlag = s.flagValue(std::string("--") + s.flag, text.c_str());
      EXPECT_EQ(viaFlag, s.kind == SettingKind::Switch ? 1.0 : value) << s.name;
      const std::string json = s.json(value);
      if (s.kind == SettingKind::Real || s.kind == SettingKind::Count)
      {
        EXPECT_EQ(std::stod(json), value) << s.name << ": " << json;
      }
      else if (s.kind == SettingKind::Choice)
      {
        EXPECT_EQ(json, "\"" + text + "\"") << s.name;
      }
      else
      {
        EXPECT_EQ(json, value != 0.0 ? "true" : "false") << s.name;
      }
    }
  }
}

template<class S>
void checkEntries(const std::vector<S>& table, std::set<std::string>& names)
{
  std::set<std::string> flags;
  for (const S& s : table)
  {
    EXPECT_TRUE(names.insert(s.name).second) << s.name << " is in the list twice";
    EXPECT_TRUE(flags.insert(s.flag).second) << s.flag;
    EXPECT_TRUE(s.topic != nullptr) << s.name;
    EXPECT_GT(std::string(s.doc).size(), 20u) << s.name;
    EXPECT_LE(s.minimum, s.defaultValue) << s.name;
    EXPECT_LE(s.defaultValue, s.maximum) << s.name;
    EXPECT_EQ(s.offFlag != nullptr, s.kind == SettingKind::Switch) << s.name;
    EXPECT_EQ(s.choices != nullptr, s.kind == SettingKind::Choice) << s.name;
    if (s.kind == SettingKind::Choice)
    {
      EXPECT_EQ(s.minimum, 0.0) << s.name;
      EXPECT_EQ(s.maximum + 1.0, static_cast<double>(s.choiceNames().size())) << s.name;
    }
    // The help entry names the flag and the default as the codec writes it.
    const std::string help = s.help();
    EXPECT_EQ(help.rfind(std::string("  --") + s.flag, 0), 0u) << help;
    EXPECT_NE(s.describe().find("Default " + s.format(s.defaultValue)), std::string::npos)
      << s.describe();
  }
}
} // namespace

TEST(Settings, EveryValueFormatsAndParsesBackExactly)
{
  checkRoundTrips(mapSettings());
  checkRoundTrips(embeddingSettings());
}

TEST(Settings, EveryEntryIsCompleteAndNamedOnce)
{
  std::set<std::string> names;
  checkEntries(mapSettings(), names);
  checkEntries(embeddingSettings(), names);
  EXPECT_GE(mapSettings().size(), 30u);
  EXPECT_GE(embeddingSettings().size(), 10u);
}

TEST(Settings, TheBindingReachesTheOptionsField)
{
  // Each setting's accessor reads the field the options' default holds and
  // writes only that field.
  for (const MapSetting& s : mapSettings())
  {
    EXPECT_EQ(s.get(SurfaceMapOptions()), s.defaultValue) << s.name;
    SurfaceMapOptions options;
    const double other = s.defaultValue == s.maximum ? s.minimum : s.maximum;
    s.set(options, other);
    for (const MapSetting& t : mapSettings())
    {
      EXPECT_EQ(t.get(options), &t == &s ? other : t.defaultValue) << s.name << " " << t.name;
    }
  }
  for (const EmbeddingSetting& s : embeddingSettings())
  {
    EXPECT_EQ(s.get(SphereEmbeddingOptions()), s.defaultValue) << s.name;
  }
}

TEST(Settings, TextThatIsNoValueIsRefused)
{
  const MapSetting& target = *findMapSetting("TargetError");
  const MapSetting& iterations = *findMapSetting("FineIterations");
  const MapSetting& pairs = *findMapSetting("PairMode");
  const MapSetting& keep = *findMapSetting("KeepLandmarks");
  double value = 0.0;
  for (const char* text : { "", "x", "nan", "inf", "1e-7", "2", "0.001x" })
  {
    EXPECT_FALSE(target.parse(text, value)) << text;
  }
  EXPECT_FALSE(iterations.parse("1.5", value));
  EXPECT_FALSE(iterations.parse("-1", value));
  EXPECT_FALSE(pairs.parse("ring", value));
  EXPECT_TRUE(pairs.parse("cycle", value) && value == 2.0);
  EXPECT_TRUE(keep.parse("off", value) && value == 0.0);
  EXPECT_EQ(target.format(1e-5), "1e-5");
  EXPECT_EQ(target.format(0.001), "0.001");
  EXPECT_EQ(findMapSetting("LandmarkWeight")->format(1e6), "1e6");
  EXPECT_EQ(target.valueError("--target-error", "x"),
    "--target-error needs a number from 1e-6 to 1, not 'x'");
  EXPECT_EQ(
    pairs.valueError("--pairs", "ring"), "--pairs is star, sequence, cycle, all or mean, not 'ring'");
  EXPECT_EQ(iterations.valueError("--fine-iterations", nullptr), "--fine-iterations needs a value");
  EXPECT_EQ(target.clamp(std::nan("")), target.defaultValue);
}

TEST(Settings, FlagsSetTheirFieldAndSayWhatTheyTake)
{
  const std::vector<std::string> args = { "--fine-iterations",
    "7",
    "--release-landmarks",
    "--pairs",
    "all",
    "--final-tolerance",
    "1e-7",
    "--target-error",
    "2" };
  SurfaceMapOptions options;
  SphereEmbeddingOptions embedding;
  std::size_t i = 0;
  EXPECT_TRUE(parseSettingFlag(args, i, options) && i == 1 && options.fineIterations == 7);
  i = 2;
  EXPECT_TRUE(parseSettingFlag(args, i, options) && i == 2 && !options.keepLandmarks);
  i = 3;
  EXPECT_TRUE(parseSettingFlag(args, i, options) && options.pairs == PairScheme::All);
  i = 5;
  EXPECT_FALSE(parseSettingFlag(args, i, options)); // the embedding's flag
  EXPECT_TRUE(parseSettingFlag(args, i, embedding) && embedding.finalTolerance == 1e-7);
  i = 7;
  EXPECT_THROW(parseSettingFlag(args, i, options), std::invalid_argument);
  const std::vector<std::string> missing = { "--coarse-error" };
  i = 0;
  EXPECT_THROW(parseSettingFlag(missing, i, options), std::invalid_argument);
}

TEST(Settings, PresetsAreWhatTheyDifferIn)
{
  const std::vector<PresetValue> population = presetValues(MapPreset::Population);
  const std::vector<PresetValue> pair = presetValues(MapPreset::Pair);
  ASSERT_EQ(population.size(), pair.size());
  ASSERT_GE(population.size(), 3u);
  SurfaceMapOptions options;
  options.mapWeight = 3.0;
  applyPreset(options, MapPreset::Population);
  EXPECT_EQ(options.targetError, 1e-2);
  EXPECT_EQ(options.mapWeight, 3.0);
  for (std::size_t k = 0; k < pair.size(); ++k)
  {
    EXPECT_EQ(pair[k].setting, population[k].setting);
    EXPECT_EQ(pair[k].value, pair[k].setting->defaultValue);
    EXPECT_NE(population[k].value, pair[k].value);
    EXPECT_NE(presetDescription(MapPreset::Population)
                .find(std::string(" ") + population[k].setting->name + " " +
                  population[k].setting->format(population[k].value)),
      std::string::npos);
  }
  applyPreset(options, MapPreset::Pair);
  EXPECT_EQ(options.targetError, findMapSetting("TargetError")->defaultValue);
  EXPECT_EQ(presetHelp().rfind("  --preset pair|population\n", 0), 0u);
}
