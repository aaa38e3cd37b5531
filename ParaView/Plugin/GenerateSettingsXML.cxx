// Build-time generator of the server-manager XML of the filters with
// settings: the surface map's and the sphere embedding's settings become
// ParaView properties straight from the engine's list of settings
// (Core/settings/SettingList.def), their one home, so a setting added there
// appears in ParaView with its range, default and documentation without
// touching the plugin.
//
// Usage: GenerateSettingsXML TEMPLATE OUTPUT
// Copies TEMPLATE to OUTPUT with the line holding @MAP_PRESET@ replaced by
// the Preset property (one entry per preset of Core/map/MapPresets.cxx), the
// line holding @MAP_SETTINGS@ by one property per map setting and one
// property group per topic, and the line holding @EMBEDDING_SETTINGS@ by the
// same for the sphere embedding's settings. Exit code 1 (and a message) if
// the template holds none of these lines or a file cannot be read or
// written.
#include "map/MapPresets.h"
#include "map/MapSettings.h"

#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace
{

std::string escaped(const std::string& text)
{
  std::string out;
  for (char c : text)
  {
    switch (c)
    {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

// Full precision, so the property's default is the table's exactly.
std::string number(double value)
{
  char text[64];
  std::snprintf(text, sizeof(text), "%.17g", value);
  return text;
}

void writeProperty(std::ostream& out, const surfacemaps::Setting& s)
{
  using surfacemaps::SettingKind;
  const bool real = s.kind == SettingKind::Real;
  const char* element = real ? "DoubleVectorProperty" : "IntVectorProperty";
  const std::string name = s.name;
  out << "      <" << element << " name=\"" << name << "\" command=\"Set" << name
      << "\" number_of_elements=\"1\" default_values=\"" << number(s.defaultValue) << "\"";
  if (s.panel == surfacemaps::SettingPanel::Advanced)
  {
    out << " panel_visibility=\"advanced\"";
  }
  out << ">\n";
  switch (s.kind)
  {
    case SettingKind::Real:
      out << "        <DoubleRangeDomain name=\"range\" min=\"" << number(s.minimum) << "\" max=\""
          << number(s.maximum) << "\"/>\n";
      break;
    case SettingKind::Count:
      out << "        <IntRangeDomain name=\"range\" min=\"" << number(s.minimum) << "\" max=\""
          << number(s.maximum) << "\"/>\n";
      break;
    case SettingKind::Switch:
      out << "        <BooleanDomain name=\"bool\"/>\n";
      break;
    case SettingKind::Choice:
    {
      out << "        <EnumerationDomain name=\"enum\">\n";
      const auto names = s.choiceNames();
      for (std::size_t c = 0; c < names.size(); ++c)
      {
        out << "          <Entry value=\"" << c << "\" text=\"" << escaped(names[c]) << "\"/>\n";
      }
      out << "        </EnumerationDomain>\n";
      break;
    }
  }
  out << "        <Documentation>" << escaped(s.describe()) << " (Command line: --"
      << escaped(s.flag) << ".)</Documentation>\n";
  out << "      </" << element << ">\n";
}

// One property per setting, then one PropertyGroup per topic of the table
// (its settings are consecutive), so the panel shows the settings under the
// list's headings.
template<class S>
void writeSettings(std::ostream& out, const std::vector<S>& table)
{
  for (const S& s : table)
  {
    writeProperty(out, s);
  }
  for (std::size_t k = 0; k < table.size();)
  {
    const std::string topic = table[k].topic ? table[k].topic : "Other settings";
    out << "      <PropertyGroup label=\"" << escaped(topic) << "\">\n";
    for (; k < table.size() && topic == (table[k].topic ? table[k].topic : "Other settings"); ++k)
    {
      out << "        <Property name=\"" << table[k].name << "\"/>\n";
    }
    out << "      </PropertyGroup>\n";
  }
}

// "population" -> "Population", as ParaView's enumerations are written.
std::string label(const char* name)
{
  std::string text = name;
  if (!text.empty() && text[0] >= 'a' && text[0] <= 'z')
  {
    text[0] = static_cast<char>(text[0] - 'a' + 'A');
  }
  return text;
}

// vtkSurfaceMapBlocksFilter::SetPreset: the preset is resolved when the map
// runs, so its place among the properties does not matter.
void writePreset(std::ostream& out)
{
  const std::vector<surfacemaps::MapPreset> all = surfacemaps::presets();
  out << "      <IntVectorProperty name=\"Preset\" command=\"SetPreset\" "
         "number_of_elements=\"1\" default_values=\"0\">\n"
      << "        <EnumerationDomain name=\"enum\">\n";
  for (std::size_t p = 0; p < all.size(); ++p)
  {
    out << "          <Entry value=\"" << p << "\" text=\""
        << escaped(label(surfacemaps::presetName(all[p]))) << "\"/>\n";
  }
  out << "        </EnumerationDomain>\n";
  std::string doc = "Named settings for a kind of study, applied when the map runs: a setting "
                    "the preset sets takes the preset's value while it is at its default, and a "
                    "value you change wins over the preset.";
  for (surfacemaps::MapPreset preset : all)
  {
    doc += std::string(" ") + label(surfacemaps::presetName(preset)) + ": " +
      surfacemaps::presetDescription(preset);
  }
  out << "        <Documentation>" << escaped(doc)
      << " Default: " << escaped(label(surfacemaps::presetName(all.front())))
      << ". (Command line: --preset.)</Documentation>\n"
      << "      </IntVectorProperty>\n";
}

// The template with each marker line replaced; false if it holds none.
bool substitute(std::istream& in, std::ostream& out)
{
  bool any = false;
  for (std::string line; std::getline(in, line);)
  {
    if (line.find("@MAP_SETTINGS@") != std::string::npos)
    {
      writeSettings(out, surfacemaps::mapSettings());
    }
    else if (line.find("@EMBEDDING_SETTINGS@") != std::string::npos)
    {
      writeSettings(out, surfacemaps::embeddingSettings());
    }
    else if (line.find("@MAP_PRESET@") != std::string::npos)
    {
      writePreset(out);
    }
    else
    {
      out << line << "\n";
      continue;
    }
    any = true;
  }
  return any;
}

} // namespace

int main(int argc, char* argv[])
{
  if (argc != 3)
  {
    std::cerr << "usage: " << argv[0] << " TEMPLATE OUTPUT\n";
    return 1;
  }
  std::ifstream in(argv[1]);
  if (!in)
  {
    std::cerr << argv[0] << ": cannot read " << argv[1] << "\n";
    return 1;
  }
  std::ostringstream out;
  if (!substitute(in, out))
  {
    std::cerr << argv[0] << ": " << argv[1]
              << " has no @MAP_SETTINGS@, @EMBEDDING_SETTINGS@ or @MAP_PRESET@ line\n";
    return 1;
  }
  std::ofstream file(argv[2]);
  file << out.str();
  file.close();
  if (!file)
  {
    std::cerr << argv[0] << ": cannot write " << argv[2] << "\n";
    return 1;
  }
  return 0;
}
