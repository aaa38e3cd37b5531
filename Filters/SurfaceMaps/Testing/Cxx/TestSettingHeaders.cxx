// The filters' public headers against the list of settings
// (Core/settings/SettingList.def). VTK's wrappers read the headers as text,
// so each setting's Set/Get macros, doc comment and member are spelled out
// there, in blocks this test writes from the list: it fails while a block
// differs from what the list gives, and with
// SURFACEMAPS_UPDATE_SETTING_HEADERS=1 rewrites the blocks instead
// (`SURFACEMAPS_UPDATE_SETTING_HEADERS=1 ctest -R SettingHeaders`). A second
// test compiles every entry against the filters: names, defaults and ranges;
// a third fails while a non-test source file other than the list and the
// header names a setting.
#include "vtkSphereEmbeddingFilter.h"
#include "vtkSurfaceMapFilter.h"
#include "vtkSurfaceMapsSettings.h"

#include "FilterTestData.h"
#include "map/MapSettings.h"

#include "vtkNew.h"

#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace
{
using surfacemaps::Setting;
using surfacemaps::SettingKind;

const char* const Begin = "  // BEGIN SETTINGS";
const char* const End = "  // END SETTINGS";
const char* const BeginMembers = "  // BEGIN SETTING MEMBERS";
const char* const EndMembers = "  // END SETTING MEMBERS";
const char* const Notice = "  // Written from Core/settings/SettingList.def by TestSettingHeaders\n"
                           "  // (SURFACEMAPS_UPDATE_SETTING_HEADERS=1 ctest -R SettingHeaders):\n"
                           "  // edit the list, not these lines.\n"
                           "  // clang-format off\n";
const char* const MemberNotice = "  // clang-format off\n";

/// A literal of the setting's member type: what vtkSetClampMacro and the
/// member's initialiser take.
std::string literal(const Setting& s, double value)
{
  if (s.kind == SettingKind::Switch)
  {
    return value != 0.0 ? "true" : "false";
  }
  if (s.kind != SettingKind::Real)
  {
    return std::to_string(static_cast<long long>(value));
  }
  std::string text = s.format(value);
  return text.find_first_of(".e") == std::string::npos ? text + ".0" : text;
}

const char* memberType(const Setting& s)
{
  switch (s.kind)
  {
    case SettingKind::Real:
      return "double";
    case SettingKind::Switch:
      return "bool";
    default:
      return "int";
  }
}

/// The doc comment, "/** ... */" around the description wrapped to the
/// header's 100 columns.
std::string docComment(const Setting& s)
{
  std::istringstream lines(surfacemaps::wrapText(s.describe(), 0, 91));
  std::string comment;
  for (std::string line; std::getline(lines, line);)
  {
    comment += (comment.empty() ? "  /** " : "\n   * ") + line;
  }
  return comment + " */\n";
}

/// One setting's public declarations.
std::string declaration(const Setting& s)
{
  const std::string name = s.name;
  const std::string type = memberType(s);
  std::string text = "  ///@{\n" + docComment(s);
  text += "  vtkSetClampMacro(" + name + ", " + type + ", " + literal(s, s.minimum) + ", " +
    literal(s, s.maximum) + ");\n";
  text += "  vtkGetMacro(" + name + ", " + type + ");\n";
  if (s.kind == SettingKind::Switch)
  {
    text += "  vtkBooleanMacro(" + name + ", bool);\n";
  }
  const std::vector<std::string> choices = s.choiceNames();
  for (std::size_t c = 0; c < choices.size(); ++c)
  {
    std::string label = choices[c];
    label[0] = static_cast<char>(std::toupper(label[0]));
    text += "  void Set" + name + "To" + label + "() { this->Set" + name + "(" + std::to_string(c) +
      "); }\n";
  }
  return text + "  ///@}\n";
}

template<class S>
std::string declarations(const std::vector<S>& table)
{
  std::string text = std::string(Begin) + "\n" + Notice;
  for (const S& s : table)
  {
    text += "\n" + declaration(s);
  }
  return text + "  // clang-format on\n" + End + "\n";
}

template<class S>
std::string members(const std::vector<S>& table)
{
  std::string text = std::string(BeginMembers) + "\n" + MemberNotice;
  for (const S& s : table)
  {
    text +=
      std::string("  ") + memberType(s) + " " + s.name + " = " + literal(s, s.defaultValue) + ";\n";
  }
  return text + "  // clang-format on\n" + EndMembers + "\n";
}

/// `text` with the lines from `begin` to `end` (both included) replaced by
/// `block`; false if the markers are missing.
bool replaceBlock(std::string& text, const char* begin, const char* end, const std::string& block)
{
  const std::size_t from = text.find(begin);
  const std::size_t to = text.find(end, from == std::string::npos ? 0 : from);
  if (from == std::string::npos || to == std::string::npos)
  {
    return false;
  }
  const std::size_t lineEnd = text.find('\n', to);
  text.replace(from, lineEnd + 1 - from, block);
  return true;
}

/// The header as the list writes it; fails the test where it differs (or
/// rewrites the file on request).
template<class S>
void checkHeader(const std::string& file, const std::vector<S>& table)
{
  const std::string path = std::string(SURFACEMAPS_SOURCE_DIR) + "/Filters/SurfaceMaps/" + file;
  std::ifstream in(path);
  ASSERT_TRUE(in) << path;
  std::ostringstream read;
  read << in.rdbuf();
  const std::string actual = read.str();
  std::string expected = actual;
  ASSERT_TRUE(replaceBlock(expected, Begin, End, declarations(table))) << file << ": no block";
  ASSERT_TRUE(replaceBlock(expected, BeginMembers, EndMembers, members(table)))
    << file << ": no member block";
  const char* update = std::getenv("SURFACEMAPS_UPDATE_SETTING_HEADERS");
  if (update && std::string(update) == "1")
  {
    std::ofstream(path) << expected;
    return;
  }
  EXPECT_EQ(actual, expected) << file
                              << " differs from Core/settings/SettingList.def: "
                                 "SURFACEMAPS_UPDATE_SETTING_HEADERS=1 ctest -R SettingHeaders";
}
} // namespace

TEST(SettingHeaders, BlocksAreTheListsText)
{
  checkHeader("vtkSurfaceMapFilter.h", surfacemaps::mapSettings());
  checkHeader("vtkSphereEmbeddingFilter.h", surfacemaps::embeddingSettings());
}

// Every entry compiled against the filters: a Set/Get pair of its name whose
// new filter holds the list's default and whose clamp is the list's range.
TEST(SettingHeaders, FiltersHaveEveryEntrysDefaultAndRange)
{
  vtkNew<vtkSurfaceMapFilter> map;
  vtkNew<vtkSphereEmbeddingFilter> embedding;
  int mapEntries = 0;
  int embeddingEntries = 0;
#define SURFACEMAPS_CHECK(filter, entries, Name, Type, Default, Minimum, Maximum)                  \
  ++entries;                                                                                       \
  EXPECT_EQ(                                                                                       \
    surfacemaps::settingNumber(filter->Get##Name()), surfacemaps::settingNumber(Type(Default)))    \
    << #Name;                                                                                      \
  EXPECT_EQ(surfacemaps::settingNumber(filter->Get##Name##MinValue()), Minimum) << #Name;          \
  EXPECT_EQ(surfacemaps::settingNumber(filter->Get##Name##MaxValue()), Maximum) << #Name;
#define SURFACEMAPS_MAP_SETTING(Name, field, Type, Kind, Default, Minimum, Maximum, ...)           \
  SURFACEMAPS_CHECK(map, mapEntries, Name, Type, Default, Minimum, Maximum)
#define SURFACEMAPS_EMBEDDING_SETTING(Name, field, Type, Kind, Default, Minimum, Maximum, ...)     \
  SURFACEMAPS_CHECK(embedding, embeddingEntries, Name, Type, Default, Minimum, Maximum)
#include "settings/SettingList.def"
#undef SURFACEMAPS_CHECK
  EXPECT_EQ(
    mapEntries, vtkSurfaceMapsSettings::GetNumberOfSettings(vtkSurfaceMapsSettings::MAP_SETTINGS));
  EXPECT_EQ(embeddingEntries,
    vtkSurfaceMapsSettings::GetNumberOfSettings(vtkSurfaceMapsSettings::SPHERE_EMBEDDING_SETTINGS));
}

namespace
{
/// Setting i by index is the named one: set to its maximum (and minimum),
/// read back, printed as the codec writes it.
template<class Filter>
void checkByIndex(Filter* filter, int table)
{
  for (int i = 0; i < vtkSurfaceMapsSettings::GetNumberOfSettings(table); ++i)
  {
    const std::string name = vtkSurfaceMapsSettings::GetName(table, i);
    for (double value : { vtkSurfaceMapsSettings::GetMaximum(table, i),
           vtkSurfaceMapsSettings::GetMinimum(table, i) })
    {
      filter->SetSetting(i, value);
      EXPECT_EQ(filter->GetSetting(i), value) << name;
      std::ostringstream print;
      filter->Print(print);
      EXPECT_NE(
        print.str().find(name + ": " + vtkSurfaceMapsSettings::Format(table, i, value) + "\n"),
        std::string::npos)
        << name;
    }
  }
  EXPECT_TRUE(std::isnan(filter->GetSetting(-1)));
}
} // namespace

TEST(SettingHeaders, SettingsByIndexAreTheNamedOnes)
{
  vtkNew<vtkSurfaceMapFilter> map;
  checkByIndex(map.Get(), vtkSurfaceMapsSettings::MAP_SETTINGS);
  vtkNew<vtkSphereEmbeddingFilter> embedding;
  checkByIndex(embedding.Get(), vtkSurfaceMapsSettings::SPHERE_EMBEDDING_SETTINGS);
  embedding->SetSetting(vtkSurfaceMapsSettings::FindSetting(
                          vtkSurfaceMapsSettings::SPHERE_EMBEDDING_SETTINGS, "FinalTolerance"),
    2e-7);
  EXPECT_EQ(embedding->GetFinalTolerance(), 2e-7);
}

// NaN passes the clamp of a Set macro; the update names the setting and
// leaves the output empty.
TEST(SettingHeaders, ASettingOutsideItsRangeIsAnInputError)
{
  vtkNew<vtkSphereEmbeddingFilter> embedding;
  filtertest::Events events;
  filtertest::watch(embedding, events);
  embedding->SetInputData(filtertest::read("ellipsoid.obj"));
  embedding->SetFinalTolerance(std::nan(""));
  embedding->Update();
  ASSERT_EQ(events.Errors.size(), 1u);
  EXPECT_NE(events.Errors[0].find("FinalTolerance needs a number from 0 to 1, not 'nan'"),
    std::string::npos)
    << events.Errors[0];
  EXPECT_EQ(embedding->GetOutput()->GetNumberOfPoints(), 0);

  vtkNew<vtkSurfaceMapFilter> map;
  filtertest::Events mapEvents;
  filtertest::watch(map, mapEvents);
  map->AddInputData(filtertest::read("ellipsoid.obj"));
  map->SetMapWeight(std::nan(""));
  map->Update();
  ASSERT_EQ(mapEvents.Errors.size(), 1u);
  EXPECT_NE(mapEvents.Errors[0].find("MapWeight needs a number"), std::string::npos)
    << mapEvents.Errors[0];
  EXPECT_EQ(map->GetErrorCode(), vtkSurfaceMapFilter::InvalidInputError);
}

namespace
{
/// Whether `text` holds `word` with no identifier character either side.
bool holdsWord(const std::string& text, const std::string& word)
{
  auto identifier = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  for (std::size_t at = text.find(word); at != std::string::npos; at = text.find(word, at + 1))
  {
    const std::size_t end = at + word.size();
    if ((at == 0 || !identifier(text[at - 1])) && (end == text.size() || !identifier(text[end])))
    {
      return true;
    }
  }
  return false;
}

/// The project's non-test source files (C++, Python, CMake, XML): every
/// file under the source tree but build trees, hidden folders, Testing/ and
/// examples (Examples/, examples/).
std::vector<std::filesystem::path> nonTestSources()
{
  namespace fs = std::filesystem;
  const fs::path root = SURFACEMAPS_SOURCE_DIR;
  std::vector<fs::path> found;
  for (auto it = fs::recursive_directory_iterator(root); it != fs::recursive_directory_iterator(); ++it)
  {
    const std::string name = it->path().filename().string();
    // Tests and examples use the settings as a user does, by name.
    if (it->is_directory() &&
      (name.rfind("build", 0) == 0 || name[0] == '.' || name == "Testing" || name == "Examples" ||
        name == "examples"))
    {
      it.disable_recursion_pending();
      continue;
    }
    const std::string ext = it->path().extension().string();
    if (it->is_regular_file() &&
      (ext == ".h" || ext == ".cxx" || ext == ".def" || ext == ".py" || ext == ".xml" ||
        ext == ".cmake" || ext == ".in" || name == "CMakeLists.txt"))
    {
      found.push_back(it->path());
    }
  }
  return found;
}
} // namespace

// A setting is named in the list and, where VTK's wrappers need it spelled
// out, in its filter's public header; everything else reaches it through
// the list (its name, flag and doc from the table). A third file naming it
// is a second definition about to drift.
TEST(SettingHeaders, EveryNameLivesInTheListAndOneHeaderAtMost)
{
  std::vector<std::pair<std::string, std::string>> texts;
  for (const auto& path : nonTestSources())
  {
    std::ifstream in(path);
    std::ostringstream text;
    text << in.rdbuf();
    texts.emplace_back(path.string(), text.str());
  }
  ASSERT_GT(texts.size(), 50u) << "the source tree was not found under " << SURFACEMAPS_SOURCE_DIR;
  std::vector<std::string> names;
  for (const auto& s : surfacemaps::mapSettings())
  {
    names.push_back(s.name);
  }
  for (const auto& s : surfacemaps::embeddingSettings())
  {
    names.push_back(s.name);
  }
  for (const std::string& name : names)
  {
    std::string files;
    int count = 0;
    for (const auto& [path, text] : texts)
    {
      if (holdsWord(text, name))
      {
        ++count;
        files += "\n  " + path;
      }
    }
    EXPECT_LE(count, 2) << name << " is named in " << count << " non-test source files:" << files;
  }
}
